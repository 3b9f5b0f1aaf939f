// Meshes in the editor, through the real menus and dialogs under a virtual X server: File › Import
// Mesh reads an OBJ, previews it and adds it as one undo step (a soft body drawn by its shaded
// surface, a cloth into a new scene); a file that is not a mesh is refused in the dialog with its
// reason and Import stays off; File › Export Animation writes a PC2 cache whose frames are the
// file's own vertices at the run's steps, and of the recorded run (the timeline) the very bytes a
// run on wrote, a part of it starting at its frame. Waits are on signals and frames, never fixed
// sleeps.

#include "ui/dialogs/generate_preview.h"
#include "ui/dialogs/import_mesh_dialog.h"
#include "ui/document/scene_document.h"
#include "ui/export/export_dialog.h"
#include "ui/export/exporter.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"
#include "ui/window/main_window.h"

#include "core/meshes/mesh_import.h"
#include "core/meshes/mesh_surface.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>

#include "editor_fixture.h"
#include "tests/io/mesh_files.h"
#include "tests/io/point_cache_read.h"


using namespace Qt::Literals::StringLiterals;

class TestMeshEditor : public test::EditorTest {
    Q_OBJECT

private slots:
    void init()
    {
        const auto answerHere = [this](ui::MainWindow &window) {
            window.setFileDialogFunction(
                [this](ui::MainWindow::FileDialogMode, const QString &, const QString &) { return m_answer; });
            window.setMessageBoxFunction([this](QMessageBox::Icon, const QString &, const QString &text,
                                                QMessageBox::StandardButtons, QMessageBox::StandardButton) {
                m_messages << text;
                return QMessageBox::Discard;
            });
        };
        QVERIFY2(openEditor({.setup = answerHere, .size = QSize(900, 650)}), qPrintable(editorFailure()));
    }

    void cleanup() { closeEditor(); }

    void importsASoftBodyDrawnByItsSurface()
    {
        const core::TriangleMesh sphere = test::icosphere(2, 0.3);
        const QString path = write(u"ball.obj"_s, test::objText(sphere));
        const std::size_t before = m_window->document()->scene().particles.size();
        ui::ImportMeshDialog *dialog = openImport();
        QVERIFY(dialog);
        QVERIFY(!dialog->importButton()->isEnabled());  // no file yet
        m_answer = path;
        QTest::mouseClick(dialog->findChild<QPushButton *>(u"importBrowse"_s), Qt::LeftButton);
        QCOMPARE(dialog->findChild<QLineEdit *>(u"importPath"_s)->text(), path);
        QCOMPARE(dialog->findChild<QLineEdit *>(u"importName"_s)->text(), u"ball"_s);
        dialog->findChild<QComboBox *>(u"importKind"_s)->setCurrentIndex(1);  // soft body
        typeInto(dialog->findChild<QDoubleSpinBox *>(u"importSpacing"_s), u"0.1"_s);
        QVERIFY2(dialog->problemText().isEmpty(), qPrintable(dialog->problemText()));
        QVERIFY2(dialog->countText().contains(u"a lattice of 0.1 m"_s), qPrintable(dialog->countText()));
        QVERIFY2(dialog->countText().contains(u"drawn by its 320 triangle"_s), qPrintable(dialog->countText()));
        QVERIFY(dialog->preview()->scene() && !dialog->preview()->scene()->particles.empty());
        const std::size_t made = dialog->made()->particles.size();
        QVERIFY(dialog->importButton()->isEnabled());
        QTest::mouseClick(dialog->importButton(), Qt::LeftButton);

        // one undo step: the particles and the mesh, on the scene's particles after the others
        const core::SceneDesc &scene = m_window->document()->scene();
        QCOMPARE(scene.particles.size(), before + made);
        QCOMPARE(scene.meshes.size(), std::size_t(1));
        QCOMPARE(scene.meshes[0].kind, core::MeshKind::Soft);
        QCOMPARE(scene.meshes[0].name, std::string("ball"));
        QCOMPARE(scene.meshes[0].vertexCount(), int(sphere.vertices.size()));
        QCOMPARE(m_window->document()->undoStack()->undoText(), u"Import ball"_s);

        // the worker draws it: its surface's vertices follow the particles, on the ball
        QTRY_VERIFY(m_window->viewport()->snapshot() && m_window->viewport()->snapshot()->embedded);
        const auto snapshot = m_window->viewport()->snapshot();
        QCOMPARE(snapshot->embedded->triangleCount(), int(sphere.faces.size()));
        QCOMPARE(snapshot->embeddedPositions.size(), 3 * sphere.vertices.size());

        m_window->document()->undoStack()->undo();
        QCOMPARE(m_window->document()->scene().particles.size(), before);
        QVERIFY(m_window->document()->scene().meshes.empty());
    }

    void importsAClothIntoANewScene()
    {
        const QString path = write(u"flag.obj"_s, test::objText(test::panel(5, 7, 0.1)));
        ui::ImportMeshDialog *dialog = openImport();
        QVERIFY(dialog);
        dialog->setPath(path);
        dialog->findChild<QComboBox *>(u"importInto"_s)->setCurrentIndex(1);
        dialog->findChild<QComboBox *>(u"importPin"_s)->setCurrentIndex(3);  // left
        QVERIFY2(dialog->countText().startsWith(u"35 particle"_s), qPrintable(dialog->countText()));
        QTest::mouseClick(dialog->importButton(), Qt::LeftButton);
        const core::SceneDesc &scene = m_window->document()->scene();
        QCOMPARE(scene.particles.size(), std::size_t(35));
        QCOMPARE(scene.planes.size(), std::size_t(1));  // the floor the new scene has
        QCOMPARE(scene.meshes.size(), std::size_t(1));
        QCOMPARE(std::count_if(scene.particles.begin(), scene.particles.end(), [](const core::ParticleDesc &p) { return p.pinned; }),
                 5);
        QVERIFY(scene.settings.triangleCollisions);
        QVERIFY(m_window->document()->filePath().isEmpty());
        QVERIFY(m_window->document()->undoStack()->canUndo());
    }

    void aFileThatIsNotAMeshIsRefusedInTheDialog()
    {
        const QString path = write(u"notes.obj"_s, "this is not a mesh\n");
        const core::SceneDesc before = m_window->document()->scene();
        ui::ImportMeshDialog *dialog = openImport();
        QVERIFY(dialog);
        dialog->setPath(path);
        QVERIFY2(dialog->problemText().startsWith(u"Cannot import: "_s) &&
                     dialog->problemText().endsWith(u"notes.obj: the file holds no mesh: no triangles"_s), qPrintable(dialog->problemText()));
        QVERIFY(!dialog->importButton()->isEnabled());
        QVERIFY(!dialog->made());
        // a scale of 0 is refused likewise once the file is good
        dialog->setPath(write(u"good.obj"_s, test::objText(test::panel(3, 3, 0.1))));
        QVERIFY(dialog->importButton()->isEnabled());
        typeInto(dialog->findChild<QDoubleSpinBox *>(u"importScale"_s), u"0"_s);
        QVERIFY2(!dialog->problemText().isEmpty(), qPrintable(dialog->countText()));
        QVERIFY(!dialog->importButton()->isEnabled());
        dialog->reject();
        QCOMPARE(m_window->document()->scene(), before);
    }

    void exportAnimationWritesThePointCache()
    {
        const core::TriangleMesh flag = openFlag();

        auto *trigger = m_window->findChild<QAction *>(u"actionExportAnimation"_s);
        QVERIFY(trigger);
        trigger->trigger();
        ui::ExportDialog *dialog = nullptr;
        QTRY_VERIFY((dialog = m_window->findChild<ui::ExportDialog *>()) && dialog->isVisible());
        QCOMPARE(dialog->kind(), ui::ExportKind::Animation);
        QVERIFY2(dialog->findChild<QLabel *>(u"exportSummary"_s)->text().contains(u"flag (35 vertices)"_s),
                 qPrintable(dialog->findChild<QLabel *>(u"exportSummary"_s)->text()));
        typeInto(dialog->findChild<QDoubleSpinBox *>(u"exportDuration"_s), u"0.1"_s, Qt::Key_Tab);
        typeInto(dialog->findChild<QDoubleSpinBox *>(u"exportFps"_s), u"50"_s, Qt::Key_Tab);
        const QString pc2 = m_files.filePath(u"flag.pc2"_s);
        dialog->findChild<QLineEdit *>(u"exportPath"_s)->setText(pc2);
        QSignalSpy finished(m_window->exporter(), &ui::Exporter::finished);
        QTest::mouseClick(dialog->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok), Qt::LeftButton);
        QVERIFY(finished.count() == 1 || finished.wait(60000));
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));

        // the header, then 6 frames (0 to 0.1 s at 50 frames/s) of 35 points, float32
        QFile file(pc2);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(finished.first().at(1).toString()));
        const QByteArray bytes = file.readAll();
        QCOMPARE(bytes.left(12), QByteArray("POINTCACHE2\0", 12));
        const test::PointCache cache = test::readPointCache(bytes);
        QCOMPARE(cache.version, 1);
        QCOMPARE(cache.points, 35);
        QCOMPARE(cache.samples, 6);
        QVERIFY(cache.wholeFile);
        // the first frame is the file's own vertices (cm, z up)
        for (int v = 0; v < 35; ++v)
            for (int a = 0; a < 3; ++a)
                QVERIFY(std::abs(double(cache.frames[0][std::size_t(3 * v + a)]) - flag.vertices[std::size_t(v)][a]) < 1e-4);
        QVERIFY(QFile::exists(m_files.filePath(u"flag.obj"_s)));
    }

    void exportAnimationOfTheRecordedRun()
    {
        openFlag();
        // a run on from the start, 0.1 s at 50 frames/s: steps 0 to 10, which the timeline records
        ui::MeshAnimationExport runOn;
        runOn.pc2Path = m_files.filePath(u"run-on.pc2"_s);
        runOn.fps = 50.0;
        runOn.duration = 0.1;
        QVERIFY(exportAndWait(runOn));

        // the recorded run, chosen in the dialog: the same steps replayed from the timeline, so
        // the very same bytes
        auto *trigger = m_window->findChild<QAction *>(u"actionExportAnimation"_s);
        trigger->trigger();
        ui::ExportDialog *dialog = nullptr;
        QTRY_VERIFY((dialog = m_window->findChild<ui::ExportDialog *>()) && dialog->isVisible());
        auto *source = dialog->findChild<QComboBox *>(u"exportSource"_s);
        QVERIFY(source);
        source->setCurrentIndex(1);
        auto *from = dialog->findChild<QDoubleSpinBox *>(u"exportFrom"_s);
        auto *to = dialog->findChild<QDoubleSpinBox *>(u"exportTo"_s);
        QVERIFY(from->isEnabled() && to->isEnabled());
        QVERIFY(!dialog->findChild<QDoubleSpinBox *>(u"exportDuration"_s)->isEnabled());
        QCOMPARE(from->minimum(), 0.0);
        QVERIFY(std::abs(to->maximum() - 0.1) < 1e-9);  // the timeline holds 0 to 0.1 s
        typeInto(from, u"0"_s, Qt::Key_Tab);
        typeInto(to, u"0.1"_s, Qt::Key_Tab);
        typeInto(dialog->findChild<QDoubleSpinBox *>(u"exportFps"_s), u"50"_s, Qt::Key_Tab);
        const QString recorded = m_files.filePath(u"recorded.pc2"_s);
        dialog->findChild<QLineEdit *>(u"exportPath"_s)->setText(recorded);
        dialog->findChild<QLineEdit *>(u"exportObjFolder"_s)->clear();
        dialog->findChild<QLineEdit *>(u"exportMeshPath"_s)->clear();
        QVERIFY2(dialog->findChild<QLabel *>(u"exportSummary"_s)->text().contains(u"6 frames"_s),
                 qPrintable(dialog->findChild<QLabel *>(u"exportSummary"_s)->text()));
        QSignalSpy finished(m_window->exporter(), &ui::Exporter::finished);
        QTest::mouseClick(dialog->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok), Qt::LeftButton);
        QVERIFY(finished.count() == 1 || finished.wait(60000));
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
        const QByteArray live = test::readAll(runOn.pc2Path);
        QCOMPARE(live.size(), qsizetype(32 + 6 * 35 * 12));
        QCOMPARE(test::readAll(recorded), live);

        // a part of it: 0.04 to 0.08 s is frames 2 to 4, and the cache says it starts at frame 2
        ui::MeshAnimationExport part;
        part.pc2Path = m_files.filePath(u"part.pc2"_s);
        part.fps = 50.0;
        part.fromTimeline = true;
        part.from = 0.04;
        part.to = 0.08;
        QVERIFY(exportAndWait(part));
        const test::PointCache whole = test::readPointCache(live);
        const test::PointCache cache = test::readPointCache(test::readAll(part.pc2Path));
        QCOMPARE(cache.start, 2.0f);
        QCOMPARE(cache.samples, 3);
        for (int k = 0; k < 3; ++k)
            QCOMPARE(cache.frames[std::size_t(k)], whole.frames[std::size_t(k + 2)]);
        // nothing recorded was lost: the timeline still reaches 0.1 s, and the view shows the last
        // frame's step, 8 (0.08 s)
        QVERIFY(std::abs(controller().frame()->timeline.lastTime - 0.1) < 1e-9);
        QCOMPARE(controller().frame()->snapshot->step, std::uint64_t(8));

        // beyond what was recorded: refused, with what the timeline holds
        part.to = 5.0;
        QString error;
        QVERIFY(!m_window->exporter()->startAnimationExport(part, &error));
        QVERIFY2(error.contains(u"holds the run from 0 s to 0.1 s"_s), qPrintable(error));
    }

private:
    // a flag of 35 vertices, in a file that is z-up and in centimetres, as a new scene
    core::TriangleMesh openFlag()
    {
        core::TriangleMesh flag;
        const core::SceneDesc scene = test::flagScene(5, 7, &flag);
        m_window->document()->replace(scene, QString());
        if (!test::settledFrame(controller()))
            qFatal("the flag's scene never reached the view");
        return flag;
    }

    // starts the export and waits for its end; false (with the message logged) if it failed
    bool exportAndWait(const ui::MeshAnimationExport &settings)
    {
        QSignalSpy finished(m_window->exporter(), &ui::Exporter::finished);
        QString error;
        if (!m_window->exporter()->startAnimationExport(settings, &error)) {
            qWarning("%s", qPrintable(error));
            return false;
        }
        if (finished.count() == 0 && !finished.wait(60000))
            return false;
        if (!finished.first().at(0).toBool())
            qWarning("%s", qPrintable(finished.first().at(1).toString()));
        return finished.first().at(0).toBool();
    }

    ui::ImportMeshDialog *openImport()
    {
        auto *trigger = m_window->findChild<QAction *>(u"actionImportMesh"_s);
        if (!trigger)
            return nullptr;
        trigger->trigger();
        ui::ImportMeshDialog *dialog = nullptr;
        const bool shown = QTest::qWaitFor(
            [&] { return (dialog = m_window->findChild<ui::ImportMeshDialog *>()) && dialog->isVisible(); });
        return shown ? dialog : nullptr;
    }

    // finish: Return in the import dialog (it has no default button), Tab in the export dialog,
    // where Return presses Export
    static void typeInto(QAbstractSpinBox *box, const QString &text, Qt::Key finish = Qt::Key_Return)
    {
        box->setFocus();
        box->selectAll();
        QTest::keyClicks(box, text);
        QTest::keyClick(box, finish);
    }

    QString write(const QString &name, const QByteArray &bytes)
    {
        const QString path = m_files.filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
            qFatal("cannot write %s", qPrintable(path));
        return path;
    }

    QString m_answer;
    QStringList m_messages;
};

QTEST_MAIN(TestMeshEditor)
#include "test_mesh_editor.moc"
