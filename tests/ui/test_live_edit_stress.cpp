// Live editing under load: for a while (SPRINGLAB_STRESS_SECONDS, 10 s by default; 60 s in
// tools/long_tests.sh under ThreadSanitizer) a script of edits arrives through real events while
// the worker runs: slider keys, particles added, pinned, dragged, measured, turned (Transform
// Selection) and deleted by mouse, undo, a save and a scene load, over and over. Every frame the
// window takes must be one step's (each spring's drawn ends are exactly its particles' drawn
// positions, nothing from two steps), the worker must keep answering, and no event may take the
// UI longer than 5 s to handle (a hang).
// How long events take is printed (median, 99th percentile, longest): a figure to read, not a
// pass mark, since it depends on the machine.

#include "ui/dialogs/transform_dialog.h"
#include "ui/viewport/edit_tools.h"
#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include "core/model/validate.h"

#include <QAbstractSlider>
#include <QDoubleSpinBox>
#include <QtTest>

#include "editor_fixture.h"

#include <algorithm>
#include <map>
#include <vector>

namespace {

constexpr qint64 kHangMs = 5000;

// a frame is one step's: the drawn spring ends are the drawn particle positions of that snapshot
bool frameIsWhole(const ui::SimulationFrame &frame)
{
    if (!frame.snapshot || !frame.scene)
        return true;
    const core::Snapshot &s = *frame.snapshot;
    const core::SceneDesc &scene = *frame.scene;
    if (s.positions.size() != 3 * scene.particles.size() || s.springEnds.size() != 6 * scene.springs.size())
        return false;
    for (std::size_t k = 0; k < scene.springs.size(); ++k)
        for (int axis = 0; axis < 3; ++axis)
            if (s.springEnds[6 * k + std::size_t(axis)] != s.positions[3 * std::size_t(scene.springs[k].a) + std::size_t(axis)] ||
                s.springEnds[6 * k + 3 + std::size_t(axis)] != s.positions[3 * std::size_t(scene.springs[k].b) + std::size_t(axis)])
                return false;
    return true;
}

}  // namespace

class TestLiveEditStress : public test::EditorTest {
    Q_OBJECT

private slots:
    void initTestCase();
    void scriptedEditsWhileRunning();
};

void TestLiveEditStress::initTestCase()
{
    QVERIFY(foldersReady());
    setAutosave(m_files.filePath(QStringLiteral("recovery")), 0);
}

void TestLiveEditStress::scriptedEditsWhileRunning()
{
    const int seconds = qEnvironmentVariableIsSet("SPRINGLAB_STRESS_SECONDS")
                            ? qEnvironmentVariableIntValue("SPRINGLAB_STRESS_SECONDS")
                            : 10;
    // every question answered Discard where it may be, else Ok
    const auto discard = [](ui::MainWindow &editor) {
        editor.setMessageBoxFunction([](QMessageBox::Icon, const QString &, const QString &,
                                        QMessageBox::StandardButtons buttons, QMessageBox::StandardButton) {
            return buttons.testFlag(QMessageBox::Discard) ? QMessageBox::Discard : QMessageBox::Ok;
        });
    };
    QVERIFY2(openEditor({.setup = discard, .size = QSize(800, 600), .settle = false}), qPrintable(editorFailure()));
    ui::MainWindow &window = *m_window;
    ui::SimulationController &controller = *window.controller();
    ui::Viewport *viewport = window.viewport();
    ui::EditTools *tools = window.editTools();
    const QStringList examples = ui::DocumentFiles::exampleNames();

    int frames = 0;
    int torn = 0;
    QObject::connect(&controller, &ui::SimulationController::frameChanged, &window, [&] {
        ++frames;
        if (!frameIsWhole(*controller.frame()))
            ++torn;
    });

    // where particle i is drawn now, on screen
    const auto drawnAt = [&](int i) -> std::optional<QPoint> {
        const auto snapshot = viewport->snapshot();
        if (!snapshot || 3 * std::size_t(i) + 2 >= snapshot->positions.size())
            return std::nullopt;
        const float *p = snapshot->positions.data() + 3 * std::size_t(i);
        const auto pixel = viewport->camera().project(QVector3D(p[0], p[1], p[2]));
        if (!pixel || !viewport->rect().contains(pixel->toPoint()))
            return std::nullopt;
        return pixel->toPoint();
    };

    // Transform Selection, never shown: a small turn and lift of whatever is selected
    ui::TransformDialog transform(window.document(), tools, &window);
    transform.findChild<QDoubleSpinBox *>(QStringLiteral("transform-angle"))->setValue(5.0);
    transform.findChild<QDoubleSpinBox *>(QStringLiteral("transform-move-y"))->setValue(0.01);

    std::vector<qint64> handled;  // ms per event
    std::map<QString, qint64> longestOf;  // the longest of each kind of event
    QElapsedTimer total;
    total.start();
    int round = 0;
    QString error;
    while (total.elapsed() < 1000LL * seconds) {
        const QString example = examples[round % examples.size()];
        QElapsedTimer event;
        const auto timed = [&](const char *kind, auto &&what) {
            event.start();
            what();
            QCoreApplication::processEvents();
            handled.push_back(event.elapsed());
            longestOf[kind] = std::max(longestOf[kind], handled.back());
        };

        // load, and run
        timed("load", [&] { QVERIFY2(window.files()->openExample(example, &error), qPrintable(error)); });
        controller.play();
        QVERIFY(test::settledFrame(controller));
        for (int i = 0; i < 6; ++i) {
            const int particles = int(window.document()->scene().particles.size());
            // a parameter slider, by its keys
            const QList<QAbstractSlider *> sliders = window.findChildren<QAbstractSlider *>();
            if (!sliders.isEmpty())
                timed("slider", [&] { QTest::keyClick(sliders[(round + i) % sliders.size()], i % 2 ? Qt::Key_PageUp : Qt::Key_PageDown); });
            // a particle added in the middle of the view
            timed("add", [&] {
                tools->setTool(ui::Tool::AddParticle);
                QTest::mouseClick(viewport, Qt::LeftButton, {}, viewport->rect().center() + QPoint(7 * i, 5 * i));
            });
            if (particles == 0)
                continue;
            // pinned, dragged
            if (const auto at = drawnAt((round + i) % particles)) {
                timed("pin", [&] {
                    tools->setTool(ui::Tool::Pin);
                    QTest::mouseClick(viewport, Qt::LeftButton, {}, *at);
                });
                timed("drag", [&] {
                    tools->setTool(ui::Tool::Drag);
                    QTest::mousePress(viewport, Qt::LeftButton, {}, *at);
                    QTest::mouseMove(viewport, *at + QPoint(20, -15));
                    QTest::mouseRelease(viewport, Qt::LeftButton, {}, *at + QPoint(20, -15));
                });
            }
            // measured from it to the last, which selects the two, then the two turned
            const auto from = drawnAt((round + i) % particles);
            const auto to = drawnAt(particles - 1);
            if (from && to) {
                timed("measure", [&] {
                    tools->setTool(ui::Tool::Measure);
                    QTest::mouseClick(viewport, Qt::LeftButton, {}, *from);
                    QTest::mouseClick(viewport, Qt::LeftButton, {}, *to);
                });
                timed("transform", [&] { transform.apply(); });
            }
            // selected and deleted, then undone every other time
            if (const auto at = drawnAt(particles - 1)) {
                timed("delete", [&] {
                    tools->setTool(ui::Tool::Select);
                    QTest::mouseClick(viewport, Qt::LeftButton, {}, *at);
                    QTest::keyClick(&window, Qt::Key_Delete);
                });
                if (i % 2 == 0)
                    timed("undo", [&] { QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier); });
            }
        }
        timed("save", [&] { QVERIFY2(window.files()->saveTo(m_files.filePath(QStringLiteral("stress.json")), &error), qPrintable(error)); });
        ++round;
    }

    // the worker still answers, with a valid scene, and nothing was torn or hung
    const auto last = test::settledFrame(controller);
    QVERIFY2(last, "the worker stopped answering");
    QVERIFY(!core::findProblem(window.document()->scene()));
    QCOMPARE(torn, 0);
    QVERIFY(frames > 0);
    std::sort(handled.begin(), handled.end());
    const qint64 median = handled[handled.size() / 2];
    const qint64 p99 = handled[handled.size() * 99 / 100];
    const qint64 longest = handled.back();
    QStringList kinds;
    for (const auto &[kind, ms] : longestOf)
        kinds << QStringLiteral("%1 %2").arg(kind).arg(ms);
    qInfo("the longest of each kind, ms: %s", qPrintable(kinds.join(QStringLiteral(", "))));
    qInfo("%d rounds, %d events, %d frames taken; ms to handle an event: median %lld, 99th percentile %lld, "
          "longest %lld",
          round, int(handled.size()), frames, median, p99, longest);
    QVERIFY2(longest < kHangMs, qPrintable(QStringLiteral("an event took %1 ms").arg(longest)));
}

QTEST_MAIN(TestLiveEditStress)
#include "test_live_edit_stress.moc"
