// File › Export through the real menus, dialogs and keys, under a virtual X server: Shift+F2's
// image comes out at the size typed in; an image sequence of 0.1 s at 30 frames/s is three frames
// showing the steps at or after 0, 1/30 and 2/30 s, where a moving particle is drawn where the
// core puts it at those steps; with no ffmpeg the dialog and the end of the export say "ffmpeg not
// found" (and where ffmpeg is installed, the MP4 is made); Cancel stops a sequence; the trace has
// the header of springlab-sim --trace and a row per particle and exported step, with the core's
// values; no export writes over the open scene's file, whatever name reaches it; F1 lists the
// exports. Waits are on signals and frames, never fixed sleeps.

#include "ui/export/export_dialog.h"
#include "ui/dialogs/help_dialog.h"
#include "ui/export/image_sequence.h"
#include "ui/export/exporter.h"
#include "ui/window/main_window.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/export/video_encoder.h"
#include "ui/viewport/viewport.h"

#include "core/model/model.h"
#include "core/model/state.h"
#include "core/step.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTimer>
#include <QDir>
#include <QFileInfo>
#include <QtTest>

#include "help_entries.h"
#include "line_thickness.h"

#include "editor_fixture.h"
#include "tests/io/trace_read.h"

#include <cmath>

#include <unistd.h>

using namespace Qt::Literals::StringLiterals;

namespace {

// a time step that does not divide 1/30 s, and a particle fast enough to move visibly each step
constexpr double kTimeStep = 0.008;  // s
constexpr double kSpeed = 20.0;      // m/s, along x
const Eigen::Vector3d kStart{-1.0, 1.0, 0.0};

// the moving particle and a pinned one to frame against; nothing else acts
core::SceneDesc movingScene()
{
    core::SceneDesc scene;
    scene.name = "export test";
    scene.settings.timeStep = kTimeStep;
    scene.settings.gravity = Eigen::Vector3d::Zero();
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    core::ParticleDesc moving;
    moving.position = kStart;
    moving.velocity = {kSpeed, 0.0, 0.0};
    moving.radius = 0.12;
    core::ParticleDesc anchor;
    anchor.position = {1.0, 1.5, 0.0};
    anchor.radius = 0.12;
    anchor.pinned = true;
    scene.particles = {moving, anchor};
    return scene;
}

QVector3D toVector(const Eigen::Vector3d &v) { return QVector3D(float(v.x()), float(v.y()), float(v.z())); }

// where the moving particle is after n steps (no force acts: exact)
Eigen::Vector3d movingAt(std::uint64_t steps)
{
    return kStart + Eigen::Vector3d(kSpeed * kTimeStep * double(steps), 0.0, 0.0);
}

// the particle's amber, saturated and of the same hue
bool isFree(const QColor &seen)
{
    const QColor want = QColor::fromRgbF(ui::kFreeColour[0], ui::kFreeColour[1], ui::kFreeColour[2]);
    double difference = std::abs(seen.hueF() - want.hueF());
    difference = std::min(difference, 1.0 - difference);
    return seen.saturationF() > 0.3 && difference < 12.0 / 360.0;
}

// the middle of the amber run of pixels along the row through pixel, or -1 if pixel is not amber
double amberMiddle(const QImage &image, QPointF pixel)
{
    const int y = int(pixel.y());
    int left = int(pixel.x());
    int right = left;
    if (!image.rect().contains(left, y) || !isFree(image.pixelColor(left, y)))
        return -1.0;
    while (left > 0 && isFree(image.pixelColor(left - 1, y)))
        --left;
    while (right + 1 < image.width() && isFree(image.pixelColor(right + 1, y)))
        ++right;
    return 0.5 * (left + right + 1);
}

}  // namespace

class TestExport : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void shiftF2WritesAnImageOfTheTypedSize();
    void tooLargeASideIsSaidNotCut();
    void linesScaleWithTheImage();
    void dialogStartsBesideTheSceneAndRemembers();
    void sequenceShowsTheStepAtEachFrameTime();
    void sequenceSaysClearlyWhenFfmpegIsNotInstalled();
    void sequenceMakesAnMp4WhereFfmpegIsInstalled();
    void cancelStopsTheSequence();
    void traceHasARowPerParticleAndExportedStep();
    void exportsNeverWriteOverTheScene();
    void f1ListsTheExports();

private:
    ui::ExportDialog *openDialog(const char *action);
    void typeInto(QAbstractSpinBox *box, const QString &text);
    void browseAndExport(ui::ExportDialog *dialog, const QString &path);
    void exportAndWait(ui::ExportDialog *dialog, const QString &path);
    ui::Camera cameraFor(QSize size) const;

    QString m_answer;  // what the file dialog hook answers
    QList<ui::MainWindow::FileDialogMode> m_dialogModes;
    QStringList m_messages;
    bool m_exportOk = false;  // how the last export waited for ended
    QString m_exportMessage;
};

void TestExport::init()
{
    // every file dialog and message answered here; the moving scene open, paused at step 0
    m_dialogModes.clear();
    m_messages.clear();
    const auto answerHere = [this](ui::MainWindow &window) {
        window.setFileDialogFunction([this](ui::MainWindow::FileDialogMode mode, const QString &, const QString &) {
            m_dialogModes << mode;
            return m_answer;
        });
        window.setMessageBoxFunction([this](QMessageBox::Icon, const QString &, const QString &text,
                                            QMessageBox::StandardButtons, QMessageBox::StandardButton) {
            m_messages << text;
            return QMessageBox::Yes;
        });
    };
    QVERIFY2(openEditor({.setup = answerHere, .size = QSize(800, 600), .settle = false}), qPrintable(editorFailure()));
    m_window->document()->replace(movingScene(), QString());
    const auto frame = test::settledFrame(*m_window->controller());
    QVERIFY(frame && frame->snapshot);
    QCOMPARE(frame->snapshot->particleCount(), 2);
    QCOMPARE(frame->snapshot->step, std::uint64_t(0));
    QTRY_VERIFY(m_window->viewport()->snapshot() == frame->snapshot);
}

void TestExport::cleanup()
{
    closeEditor();
}

ui::ExportDialog *TestExport::openDialog(const char *action)
{
    auto *trigger = m_window->findChild<QAction *>(QString::fromLatin1(action));
    if (!trigger)
        return nullptr;
    trigger->trigger();
    ui::ExportDialog *dialog = nullptr;
    const bool shown =
        QTest::qWaitFor([&] { return (dialog = m_window->findChild<ui::ExportDialog *>()) && dialog->isVisible(); });
    return shown ? dialog : nullptr;
}

void TestExport::typeInto(QAbstractSpinBox *box, const QString &text)
{
    // select the number (not the unit) and type over it
    box->setFocus();
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Tab);
}

void TestExport::browseAndExport(ui::ExportDialog *dialog, const QString &path)
{
    m_answer = path;
    QTest::mouseClick(dialog->findChild<QPushButton *>(u"exportBrowse"_s), Qt::LeftButton);
    QCOMPARE(dialog->findChild<QLineEdit *>(u"exportPath"_s)->text(), path);
    QPushButton *ok = dialog->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isEnabled());
    QTest::mouseClick(ok, Qt::LeftButton);
}

void TestExport::exportAndWait(ui::ExportDialog *dialog, const QString &path)
{
    // the export starts from the dialog and runs to its end
    QSignalSpy finished(m_window->exporter(), &ui::Exporter::finished);
    browseAndExport(dialog, path);
    QVERIFY(finished.count() == 1 || finished.wait(120000));
    m_exportOk = finished.first().at(0).toBool();
    m_exportMessage = finished.first().at(1).toString();
}

ui::Camera TestExport::cameraFor(QSize size) const
{
    ui::Camera camera = m_window->viewport()->camera();
    camera.setViewportSize(size);
    return camera;
}

void TestExport::shiftF2WritesAnImageOfTheTypedSize()
{
    QTest::keyClick(m_window, Qt::Key_F2, Qt::ShiftModifier);
    ui::ExportDialog *dialog = nullptr;
    QTRY_VERIFY((dialog = m_window->findChild<ui::ExportDialog *>()) && dialog->isVisible());
    QCOMPARE(dialog->kind(), ui::ExportKind::Image);
    typeInto(dialog->findChild<QSpinBox *>(u"exportWidth"_s), u"640"_s);
    typeInto(dialog->findChild<QSpinBox *>(u"exportHeight"_s), u"360"_s);
    const QString path = m_files.filePath(u"view.png"_s);
    browseAndExport(dialog, path);
    QCOMPARE(m_dialogModes, QList<ui::MainWindow::FileDialogMode>{ui::MainWindow::FileDialogMode::Save});

    // the file, of that size, with the moving particle where the camera puts it
    QTRY_VERIFY(QFile::exists(path));
    const QImage image(path);
    QCOMPARE(image.size(), QSize(640, 360));
    const auto pixel = cameraFor(image.size()).project(toVector(kStart));
    QVERIFY(pixel);
    QVERIFY(isFree(image.pixelColor(pixel->toPoint())));
    QVERIFY(m_messages.isEmpty());
}

void TestExport::linesScaleWithTheImage()
{
    // one spring between two small pinned particles, exported at the view's size and at four
    // times it: the spring is about four times as thick in the large image
    core::SceneDesc scene = movingScene();
    for (core::ParticleDesc &p : scene.particles) {
        p.velocity.setZero();
        p.pinned = true;
        p.radius = 0.02;
    }
    // high over the grid, so that the sky is behind the spring
    scene.particles[0].position = {-1.0, 3.0, 0.0};
    scene.particles[1].position = {1.0, 3.0, 0.0};
    scene.springs = {{0, 1, 10.0, 0.0, 2.0}};
    m_window->document()->replace(scene, QString());
    const auto frame = test::settledFrame(*m_window->controller());
    QVERIFY(frame);
    QTRY_VERIFY(m_window->viewport()->snapshot() == frame->snapshot);

    const QSize view = m_window->viewport()->size() * m_window->viewport()->devicePixelRatio();
    const int scales[2] = {1, 4};
    double thickness[2] = {0.0, 0.0};
    for (int k = 0; k < 2; ++k) {
        const QString path = m_files.filePath(QStringLiteral("spring-%1.png").arg(scales[k]));
        QString error;
        QVERIFY2(m_window->exporter()->exportImage({path, view * scales[k]}, &error), qPrintable(error));
        const QImage image(path);
        QCOMPARE(image.size(), view * scales[k]);
        // along a stretch of the spring around a quarter of the way, away from the particles,
        // averaged over columns, since an image may have no multisampling to blend the edges
        const ui::Camera camera = cameraFor(image.size());
        constexpr int kColumns = 24;
        for (int c = 0; c < kColumns; ++c) {
            const auto pixel = camera.project(QVector3D(-0.6f + 0.2f * c / kColumns, 3.0f, 0.0f));
            QVERIFY(pixel);
            const double seen = test::lineThickness(image, pixel->toPoint().x(), pixel->toPoint().y(), 3 * scales[k]);
            QVERIFY2(seen > 0.0, qPrintable(QStringLiteral("no line at %1, %2").arg(pixel->x()).arg(pixel->y())));
            thickness[k] += seen / kColumns;
        }
    }
    const double ratio = thickness[1] / thickness[0];
    QVERIFY2(thickness[0] >= 1.5 && ratio >= 3.0 && ratio <= 5.0,
             qPrintable(QStringLiteral("%1 px at the view's size, %2 px at 4 times it").arg(thickness[0]).arg(thickness[1])));
}

void TestExport::tooLargeASideIsSaidNotCut()
{
    // 20000 typed as the width stays 20000, and the dialog says why it cannot be used (a box
    // capped at the maximum turned it into 2000 without a word)
    QTest::keyClick(m_window, Qt::Key_F2, Qt::ShiftModifier);
    ui::ExportDialog *dialog = nullptr;
    QTRY_VERIFY((dialog = m_window->findChild<ui::ExportDialog *>()) && dialog->isVisible());
    auto *width = dialog->findChild<QSpinBox *>(u"exportWidth"_s);
    m_answer = m_files.filePath(u"big.png"_s);
    QTest::mouseClick(dialog->findChild<QPushButton *>(u"exportBrowse"_s), Qt::LeftButton);
    QPushButton *ok = dialog->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isEnabled());
    typeInto(width, u"20000"_s);
    QCOMPARE(width->value(), 20000);
    const QString said = dialog->findChild<QLabel *>(u"exportSummary"_s)->text();
    QVERIFY2(said.startsWith(u"Width must be from 1 to "_s) && said.endsWith(u"20000 px cannot be used."_s),
             qPrintable(said));
    QVERIFY(!ok->isEnabled());
    // mended, it can be exported again
    typeInto(width, u"640"_s);
    QVERIFY(ok->isEnabled());
    QVERIFY(dialog->findChild<QLabel *>(u"exportSummary"_s)->text().contains(u"640"_s));
    dialog->reject();
}

void TestExport::dialogStartsBesideTheSceneAndRemembers()
{
    // a scene with a file: the export starts in its folder, named after it; the last export is
    // remembered for that scene, and another scene starts beside its own file
    QDir(m_files.path()).mkpath(u"scenes"_s);
    const QString sceneFile = m_files.filePath(u"scenes/moving.json"_s);
    m_window->document()->replace(movingScene(), sceneFile);
    ui::ExportDialog *dialog = openDialog("actionExportImage");
    QVERIFY(dialog);
    auto *path = dialog->findChild<QLineEdit *>(u"exportPath"_s);
    QCOMPARE(QFileInfo(path->text()).absolutePath(), QFileInfo(sceneFile).absolutePath());

    // exported at 640 × 360 to a path of the user's: the next image dialog starts there
    typeInto(dialog->findChild<QSpinBox *>(u"exportWidth"_s), u"640"_s);
    typeInto(dialog->findChild<QSpinBox *>(u"exportHeight"_s), u"360"_s);
    const QString chosen = m_files.filePath(u"mine.png"_s);
    browseAndExport(dialog, chosen);
    QTRY_VERIFY(QFile::exists(chosen));
    QTRY_VERIFY(!m_window->findChild<ui::ExportDialog *>());
    dialog = openDialog("actionExportImage");
    QVERIFY(dialog);
    QCOMPARE(dialog->findChild<QLineEdit *>(u"exportPath"_s)->text(), chosen);
    QCOMPARE(dialog->findChild<QSpinBox *>(u"exportWidth"_s)->value(), 640);
    QCOMPARE(dialog->findChild<QSpinBox *>(u"exportHeight"_s)->value(), 360);
    dialog->reject();
    QTRY_VERIFY(!m_window->findChild<ui::ExportDialog *>());

    // another saved scene, in another folder: its export starts beside it again, named after it
    QDir(m_files.path()).mkpath(u"other"_s);
    const QString otherFile = m_files.filePath(u"other/second.json"_s);
    core::SceneDesc second = movingScene();
    second.name = "second";
    m_window->document()->replace(second, otherFile);
    dialog = openDialog("actionExportImage");
    QVERIFY(dialog);
    QCOMPARE(dialog->findChild<QLineEdit *>(u"exportPath"_s)->text(),
             QDir(QFileInfo(otherFile).absolutePath()).filePath(u"second.png"_s));
    dialog->reject();
}

void TestExport::sequenceShowsTheStepAtEachFrameTime()
{
    ui::ExportDialog *dialog = openDialog("actionExportSequence");
    QVERIFY(dialog);
    typeInto(dialog->findChild<QDoubleSpinBox *>(u"exportFps"_s), u"30"_s);
    typeInto(dialog->findChild<QDoubleSpinBox *>(u"exportDuration"_s), u"0.1"_s);
    typeInto(dialog->findChild<QSpinBox *>(u"exportWidth"_s), u"320"_s);
    typeInto(dialog->findChild<QSpinBox *>(u"exportHeight"_s), u"240"_s);
    QVERIFY2(dialog->findChild<QLabel *>(u"exportSummary"_s)->text().startsWith(u"3 frames"_s),
             qPrintable(dialog->findChild<QLabel *>(u"exportSummary"_s)->text()));
    dialog->findChild<QCheckBox *>(u"exportVideo"_s)->setChecked(false);
    const QString folder = m_files.filePath(u"sequence"_s);
    exportAndWait(dialog, folder);
    QVERIFY2(m_exportOk, qPrintable(m_exportMessage));
    QCOMPARE(m_dialogModes, QList<ui::MainWindow::FileDialogMode>{ui::MainWindow::FileDialogMode::Folder});

    // three frames, at steps 0, 5 and 9: the first at or after 0, 1/30 and 2/30 s for 8 ms steps
    // (4.17 and 8.33 steps; the nearest steps would be 4 and 8, early)
    QCOMPARE(ui::sequenceFramesIn(folder).size(), 3);
    const std::vector<std::uint64_t> steps{0, 5, 9};
    QCOMPARE(ui::sequenceFrameSteps(30.0, 3, kTimeStep), steps);
    const ui::Camera camera = cameraFor(QSize(320, 240));
    QImage first;
    for (int k = 0; k < 3; ++k) {
        const QImage image(ui::sequenceFramePath(folder, k));
        QCOMPARE(image.size(), QSize(320, 240));
        if (k == 0)
            first = image;

        // the particle is drawn centred where the core has it at that step, not a step off
        const QPointF at = camera.project(toVector(movingAt(steps[k]))).value();
        const double perStep = camera.project(toVector(movingAt(steps[k] + 1))).value().x() - at.x();
        QCOMPARE_GT(perStep, 4.0);  // a step moves it several pixels: a frame a step off would show
        const double middle = amberMiddle(image, at);
        const QString where = u"frame %1: the particle's middle is at x = %2, expected %3"_s.arg(k).arg(middle);
        QVERIFY2(std::abs(middle - at.x()) < perStep / 3.0, qPrintable(where.arg(at.x())));
    }

    // a pixel that moves: the particle has left where it was in the first frame
    const QPoint start = camera.project(toVector(kStart)).value().toPoint();
    QVERIFY(isFree(first.pixelColor(start)));
    QVERIFY(!isFree(QImage(ui::sequenceFramePath(folder, 2)).pixelColor(start)));

    // and the run is paused at the last frame's step and time
    const auto frame = test::settledFrame(*m_window->controller());
    QCOMPARE(frame->snapshot->step, std::uint64_t(9));
    QCOMPARE(frame->snapshot->time, 9 * kTimeStep);
    QVERIFY(!m_window->controller()->isRunning());
    QVERIFY(!m_window->exporter()->isExporting());
}

void TestExport::sequenceSaysClearlyWhenFfmpegIsNotInstalled()
{
    // no ffmpeg on PATH, whether or not this machine has one
    QTemporaryDir empty;
    const QByteArray path = qgetenv("PATH");
    qputenv("PATH", empty.path().toLocal8Bit());
    auto restore = qScopeGuard([&] { qputenv("PATH", path); });

    // the dialog says so, and offers no MP4
    ui::ExportDialog *dialog = openDialog("actionExportSequence");
    QVERIFY(dialog);
    QVERIFY(!dialog->findChild<QCheckBox *>(u"exportVideo"_s)->isEnabled());
    const QString note = dialog->findChild<QLabel *>(u"exportFfmpegNote"_s)->text();
    QVERIFY2(note.startsWith(u"ffmpeg not found"_s), qPrintable(note));
    dialog->reject();

    // asked for an MP4 anyway: the frames are written, and the end says why there is no MP4
    QSignalSpy finished(m_window->exporter(), &ui::Exporter::finished);
    const QString folder = m_files.filePath(u"no-ffmpeg"_s);
    QString error;
    QVERIFY2(m_window->exporter()->startSequenceExport({folder, 30.0, 0.1, QSize(96, 64), true}, &error), qPrintable(error));
    QVERIFY(finished.wait(60000));
    QVERIFY(!finished.first().at(0).toBool());
    const QString message = finished.first().at(1).toString();
    QVERIFY2(message.contains(u"ffmpeg not found"_s), qPrintable(message));
    QVERIFY2(message.contains(u"3 frame"_s), qPrintable(message));
    QCOMPARE(ui::sequenceFramesIn(folder).size(), 3);
    QVERIFY(!QFile::exists(QDir(folder).filePath(u"no-ffmpeg.mp4"_s)));
}

void TestExport::sequenceMakesAnMp4WhereFfmpegIsInstalled()
{
    if (ui::VideoEncoder::findFfmpeg().isEmpty())
        QSKIP("ffmpeg is not installed here; sequenceSaysClearlyWhenFfmpegIsNotInstalled covers that case");
    ui::ExportDialog *dialog = openDialog("actionExportSequence");
    QVERIFY(dialog);
    QVERIFY(dialog->findChild<QCheckBox *>(u"exportVideo"_s)->isChecked());
    typeInto(dialog->findChild<QDoubleSpinBox *>(u"exportDuration"_s), u"0.1"_s);
    typeInto(dialog->findChild<QSpinBox *>(u"exportWidth"_s), u"97"_s);  // odd: padded to even for yuv420p
    typeInto(dialog->findChild<QSpinBox *>(u"exportHeight"_s), u"64"_s);
    const QString folder = m_files.filePath(u"movie"_s);
    exportAndWait(dialog, folder);
    QVERIFY2(m_exportOk, qPrintable(m_exportMessage));
    QVERIFY(QFileInfo(QDir(folder).filePath(u"movie.mp4"_s)).size() > 0);
}

void TestExport::cancelStopsTheSequence()
{
    // a long sequence, cancelled by the progress dialog's button once frames are coming
    QSignalSpy finished(m_window->exporter(), &ui::Exporter::finished);
    const QString folder = m_files.filePath(u"cancelled"_s);
    const int frames = ui::sequenceFrameCount(30.0, 10.0);
    QVERIFY(m_window->exporter()->startSequenceExport({folder, 30.0, 10.0, QSize(64, 48), false}));
    QVERIFY(m_window->exporter()->isExporting());
    QProgressDialog *progress = m_window->findChild<QProgressDialog *>(u"exportProgress"_s);
    QVERIFY(progress);
    QTRY_VERIFY(progress->isVisible() && progress->value() >= 2);
    QPushButton *cancel = progress->findChild<QPushButton *>();
    QVERIFY(cancel);
    QTest::mouseClick(cancel, Qt::LeftButton);
    QVERIFY(finished.count() == 1 || finished.wait(10000));
    QVERIFY(!finished.first().at(0).toBool());
    const QString message = finished.first().at(1).toString();
    QVERIFY2(message.startsWith(u"Export cancelled"_s), qPrintable(message));

    // what was written stays, and is less than the whole
    const qsizetype written = ui::sequenceFramesIn(folder).size();
    QCOMPARE_GE(written, 2);
    QCOMPARE_LT(written, frames);
    QVERIFY2(message.contains(u"%1 frame"_s.arg(written)), qPrintable(message));
    QVERIFY(!m_window->exporter()->isExporting());
}

void TestExport::traceHasARowPerParticleAndExportedStep()
{
    ui::ExportDialog *dialog = openDialog("actionExportTrace");
    QVERIFY(dialog);
    typeInto(dialog->findChild<QDoubleSpinBox *>(u"exportDuration"_s), u"0.08"_s);  // 10 steps
    typeInto(dialog->findChild<QSpinBox *>(u"exportEvery"_s), u"4"_s);
    const QString path = m_files.filePath(u"trace.csv"_s);
    exportAndWait(dialog, path);
    QVERIFY2(m_exportOk, qPrintable(m_exportMessage));

    // springlab-sim's header, then both particles at steps 0, 4 and 8
    QByteArray header;
    const QList<QList<QByteArray>> rows = test::readTraceRows(path, &header);
    QCOMPARE(header, QByteArray("step,time,particle,x,y,z,vx,vy,vz"));
    QCOMPARE(rows.size(), 2 * 3);

    // the values the core has at those steps, as floats
    const core::SceneDesc scene = movingScene();
    const auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    core::Workspace work;
    for (int row = 0; row < rows.size(); ++row) {
        const QList<QByteArray> &fields = rows[row];
        QCOMPARE(fields.size(), 9);
        const std::uint64_t step = std::uint64_t(4 * (row / 2));
        while (state.step < step)
            QVERIFY(core::step(*model, state, work));
        const int particle = row % 2;
        QCOMPARE(test::parseNumber<std::uint64_t>(fields[0]), step);
        QCOMPARE(test::parseNumber<double>(fields[1]), state.time);
        QCOMPARE(fields[2].toInt(), particle);
        for (int axis = 0; axis < 3; ++axis) {
            QCOMPARE(test::parseNumber<float>(fields[3 + axis]), float(state.position(axis, particle)));
            QCOMPARE(test::parseNumber<float>(fields[6 + axis]), float(state.velocity(axis, particle)));
        }
    }
    QVERIFY2(m_exportMessage.contains(u"6 row"_s), qPrintable(m_exportMessage));
}

void TestExport::exportsNeverWriteOverTheScene()
{
    // the document's file, and other names of it: a hard link and a symbolic link
    const QByteArray bytes("the scene's own bytes\n");
    const auto write = [](const QString &path, const QByteArray &content) {
        QFile file(path);
        return file.open(QIODevice::WriteOnly) && file.write(content) == content.size();
    };
    const auto read = [](const QString &path) {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    };
    const QString scene = m_files.filePath(u"moving.json"_s);
    QVERIFY(write(scene, bytes));
    m_window->document()->replace(movingScene(), scene);
    const QString hardLink = m_files.filePath(u"alias.png"_s);
    QVERIFY(::link(QFile::encodeName(scene).constData(), QFile::encodeName(hardLink).constData()) == 0);
    const QString symbolicLink = m_files.filePath(u"link.csv"_s);
    QVERIFY(QFile::link(scene, symbolicLink));

    // Shift+F2 onto the hard link: the dialog's export is refused with a message, nothing written
    ui::ExportDialog *dialog = openDialog("actionExportImage");
    QVERIFY(dialog);
    typeInto(dialog->findChild<QSpinBox *>(u"exportWidth"_s), u"64"_s);
    typeInto(dialog->findChild<QSpinBox *>(u"exportHeight"_s), u"48"_s);
    browseAndExport(dialog, hardLink);
    QTRY_COMPARE(m_messages.size(), 1);
    QVERIFY2(m_messages.front().contains(u"is the open scene's file"_s), qPrintable(m_messages.front()));
    QCOMPARE(read(scene), bytes);

    // an image at the scene's own path, and a trace through the symbolic link
    QString error;
    QVERIFY(!m_window->exporter()->exportImage({scene, QSize(64, 48)}, &error));
    QVERIFY2(error.contains(u"is the open scene's file"_s), qPrintable(error));
    error.clear();
    QVERIFY(!m_window->exporter()->startTraceExport({symbolicLink, 0.08, 1}, &error));
    QVERIFY2(error.contains(u"is the open scene's file"_s), qPrintable(error));
    QVERIFY(!m_window->exporter()->isExporting());
    QCOMPARE(read(scene), bytes);

    // a sequence whose MP4 would be the scene (named after its folder), asked for whether or not
    // ffmpeg is installed
    QVERIFY(QDir(m_files.path()).mkdir(u"clip"_s));
    QVERIFY(::link(QFile::encodeName(scene).constData(), QFile::encodeName(m_files.filePath(u"clip/clip.mp4"_s)).constData()) == 0);
    error.clear();
    QVERIFY(!m_window->exporter()->startSequenceExport({m_files.filePath(u"clip"_s), 30.0, 0.1, QSize(64, 48), true}, &error));
    QVERIFY2(error.contains(u"open scene's file"_s), qPrintable(error));
    QVERIFY(ui::sequenceFramesIn(m_files.filePath(u"clip"_s)).isEmpty());
    QCOMPARE(read(scene), bytes);

    // and one whose folder holds the scene as one of the frames it would replace
    QVERIFY(QDir(m_files.path()).mkdir(u"frames"_s));
    const QString sceneAsFrame = m_files.filePath(u"frames/frame-00001.png"_s);
    QVERIFY(write(sceneAsFrame, bytes));
    m_window->document()->replace(movingScene(), sceneAsFrame);
    error.clear();
    QVERIFY(!m_window->exporter()->startSequenceExport({m_files.filePath(u"frames"_s), 30.0, 0.1, QSize(64, 48), false}, &error));
    QVERIFY2(error.contains(u"is among the frames"_s), qPrintable(error));
    QCOMPARE(read(sceneAsFrame), bytes);
    QVERIFY(!m_window->exporter()->isExporting());
}

void TestExport::f1ListsTheExports()
{
    const std::optional<QStringList> entries = test::helpEntries(m_window);
    QVERIFY(entries);
    const QString all = entries->join(u'\n');
    QVERIFY2(all.contains(u"Shift+F2\tFile › Export › Image"_s), qPrintable(all));
    for (const QString &entry : {u"File › Export › Image Sequence"_s, u"MP4"_s, u"File › Export › Trace CSV"_s,
                                 u"--render DIR"_s, u"xvfb-run"_s})
        QVERIFY2(all.contains(entry), qPrintable(entry));
}

QTEST_MAIN(TestExport)
#include "test_export.moc"
