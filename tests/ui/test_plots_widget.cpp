// The plots dock in the real main window, under a virtual X server: F8 shows it; every step of a
// run is plotted, however few frames the window gets, and every plotted energy is the core's own
// diagnostics of a run stepped here independently, bit for bit, and "lost since reset" is the
// total at reset less the total; a particle clicked in the viewport has its position and velocity
// plotted as the core has them; a reset or another scene starts over; Export PNG and Export CSV
// write an image of the canvas and its samples (a row per step, at a regular time) through the
// window's file dialog, and a file that cannot be written is reported; after a long run each plot
// grabs at the dock's size. Waits are on frames, never sleeps. (The dock's pictures in the docs
// are taken by tools/editor_screenshot.)

#include "ui/viewport/edit_tools.h"
#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/panels/plot_canvas.h"
#include "ui/panels/plots_widget.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include "core/model/diagnostics.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "core/step.h"

#include <QComboBox>
#include <QDockWidget>
#include <QImage>
#include <QStatusBar>
#include <QToolButton>
#include <QtTest>

#include <charconv>

#include "editor_fixture.h"

namespace {

using test::settledFrame;

// the curves of the energies plot, in order
enum EnergyCurve { Kinetic, Gravitational, Spring, Total, Lost };

// a damped chain of four hanging from a pin, swinging down onto a floor that takes half the speed
core::SceneDesc chainScene()
{
    core::SceneDesc scene;
    scene.name = "chain";
    scene.settings.viscosity = 0.1;
    scene.settings.restitution = 0.5;
    for (int i = 0; i < 4; ++i) {
        core::ParticleDesc particle;
        particle.position = {0.5 * i, 0.8, 0.0};
        particle.pinned = i == 0;
        scene.particles.push_back(particle);
    }
    for (int i = 0; i < 3; ++i)
        scene.springs.push_back({i, i + 1, 200.0, 0.5, 0.5});
    scene.planes.push_back({});
    return scene;
}

QVector3D toQt(const Eigen::Vector3d &v)
{
    return {float(v.x()), float(v.y()), float(v.z())};
}

// what two doubles that should be the same bits are, for a failure's message
QByteArray bits(double actual, double expected)
{
    return QStringLiteral("%1 is not %2").arg(actual, 0, 'g', 17).arg(expected, 0, 'g', 17).toUtf8();
}

double readDouble(const QString &field)
{
    const std::string text = field.toStdString();
    double value = std::numeric_limits<double>::quiet_NaN();
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
}

}  // namespace

class TestPlotsWidget : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void f8ShowsAndHidesThePlots();
    void plottedEnergiesAreTheCoresDiagnostics();
    void everyStepIsPlottedHoweverFewTheFrames();
    void clickedParticleIsPlottedAsTheCoreHasIt();
    void resetAndAnotherSceneStartOver();
    void exportsWriteAnImageAndTheSamples();
    void theCsvOfARunHasARowPerStep();
    void anExportThatCannotBeWrittenIsReported();
    void eachPlotOfALongRunGrabsAtItsSize();

private:
    ui::PlotsWidget *plots() { return m_window->plots(); }
    QDockWidget *dock() { return m_window->findChild<QDockWidget *>(QStringLiteral("plotsDock")); }
    void press(Qt::Key key) { QTest::keyClick(m_window, key); }
    // opens a scene, shows the plots, and looks at the scene from a fixed camera
    void open(const core::SceneDesc &scene);
    // F6 `count` times, each step's frame seen by the window
    void stepTimes(int count);
    void clickButton(const char *name);
    // the lines of the CSV that Export CSV writes for the plot shown
    QStringList exportedCsv();
};

void TestPlotsWidget::init()
{
    QVERIFY2(openEditor(), qPrintable(editorFailure()));
}

void TestPlotsWidget::cleanup()
{
    closeEditor();
}

void TestPlotsWidget::open(const core::SceneDesc &scene)
{
    m_window->document()->replace(scene, QString());
    const auto frame = settledFrame(controller());
    QVERIFY(frame && frame->scene == m_window->document()->sharedScene());
    if (dock()->isHidden())
        press(Qt::Key_F8);
    QTRY_VERIFY(dock()->isVisible());
    ui::Camera &camera = m_window->viewport()->camera();
    camera.setTarget(QVector3D(0.75f, 0.5f, 0.0f));
    camera.setDistance(4.0f);
    camera.setAngles(0.0f, 0.0f);
    m_window->viewport()->update();
}

void TestPlotsWidget::stepTimes(int count)
{
    for (int i = 0; i < count; ++i) {
        press(Qt::Key_F6);
        QVERIFY(settledFrame(controller()));
    }
}

void TestPlotsWidget::clickButton(const char *name)
{
    auto *button = plots()->findChild<QToolButton *>(QString::fromLatin1(name));
    QVERIFY2(button, name);
    QTest::mouseClick(button, Qt::LeftButton);
}

void TestPlotsWidget::f8ShowsAndHidesThePlots()
{
    // hidden at first; F8 (View › Plots) toggles it
    QVERIFY(dock() && dock()->isHidden());
    press(Qt::Key_F8);
    QTRY_VERIFY(dock()->isVisible());
    QCOMPARE(m_window->dockWidgetArea(dock()), Qt::BottomDockWidgetArea);
    QVERIFY(plots()->canvas()->isVisible());
    press(Qt::Key_F8);
    QTRY_VERIFY(dock()->isHidden());
}

void TestPlotsWidget::plottedEnergiesAreTheCoresDiagnostics()
{
    // a run at display rate, then single steps
    const core::SceneDesc scene = chainScene();
    open(scene);
    press(Qt::Key_F4);
    QTRY_VERIFY_WITH_TIMEOUT(controller().frame()->snapshot->step > 60, 20000);
    press(Qt::Key_F4);
    QVERIFY(settledFrame(controller()));
    stepTimes(5);
    const auto last = settledFrame(controller());
    const ui::PlotSeries &series = plots()->series(ui::PlotGroup::Energies);
    QCOMPARE(series.step(series.size() - 1), last->snapshot->step);
    QCOMPARE(series.step(0), std::uint64_t(0));
    // every step, not one per frame drawn
    QCOMPARE(series.size(), std::size_t(last->snapshot->step + 1));

    // the same scene stepped here: every sample is the core's energies at its step, to the bit
    const auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    core::Workspace work;
    const core::Energies initial = core::energies(*model, state);
    std::size_t compared = 0;
    double lost = 0.0;
    for (std::uint64_t step = 0; step <= last->snapshot->step; ++step) {
        if (step > 0)
            QVERIFY(core::step(*model, state, work));
        const std::optional<std::size_t> at = series.indexOfStep(step);
        if (!at)
            continue;
        const core::Energies expected = core::energies(*model, state);
        const double values[] = {expected.kinetic, expected.gravitational, expected.spring, expected.total(),
                                 initial.total() - expected.total()};
        QVERIFY2(series.time(*at) == state.time, bits(series.time(*at), state.time).constData());
        for (int curve : {Kinetic, Gravitational, Spring, Total, Lost}) {
            const double plotted = series.value(std::size_t(curve), *at);
            QVERIFY2(plotted == values[curve], bits(plotted, values[curve]).constData());
        }
        lost = series.value(Lost, *at);
        ++compared;
    }
    QCOMPARE(compared, series.size());
    QVERIFY(compared >= 67);  // step 0, the 60 and more of the run, the five single steps
    // drag, damping and the floor took energy out
    QVERIFY2(lost > 0.0, qPrintable(QString::number(lost)));
    QCOMPARE(last->initialEnergies.total(), initial.total());

    // and the momentum plot is the snapshot's
    const ui::PlotSeries &momentum = plots()->series(ui::PlotGroup::Momentum);
    const double py = momentum.value(1, momentum.size() - 1);
    QVERIFY2(py == last->snapshot->momentum.y(), bits(py, last->snapshot->momentum.y()).constData());
    const double length = momentum.value(3, momentum.size() - 1);
    QVERIFY2(length == last->snapshot->momentum.norm(), bits(length, last->snapshot->momentum.norm()).constData());
}

void TestPlotsWidget::everyStepIsPlottedHoweverFewTheFrames()
{
    // a worker of its own whose window draws a frame an hour: the only frames are the answers to
    // messages (here Syncs), each bringing the samples of the steps since the last one
    ui::SimulationController worker;
    ui::PlotsWidget widget;
    int frames = 0;
    connect(&worker, &ui::SimulationController::frameChanged, &widget, [&] {
        ++frames;
        widget.addFrame(*worker.frame());
    });
    const core::SceneDesc scene = chainScene();
    const auto loaded = test::frameAfter(worker, worker.setScene(std::make_shared<const core::SceneDesc>(scene),
                                                                 ui::SceneChange::Replace));
    QVERIFY(loaded);
    worker.setFrameInterval(3600.0);
    // (counted from the Play's answer on: when the worker took the Play and the first Sync in two
    // ticks, the Play's own frame came after a count taken at once, and read as one not asked for)
    QVERIFY(test::frameAfter(worker, worker.play()));
    const int framesBefore = frames;
    std::shared_ptr<const ui::SimulationFrame> frame = settledFrame(worker);
    int syncs = 1;
    while (frame && frame->snapshot->step < 100) {
        // the worker's ticks meanwhile: it steps, and shows no frame it was not asked for
        QVERIFY(!QTest::qWaitFor([&] { return frames - framesBefore > syncs; }, 100));
        frame = settledFrame(worker);
        ++syncs;
    }
    QVERIFY(frame);
    frame = test::frameAfter(worker, worker.pause());
    QVERIFY(frame);
    const std::uint64_t last = frame->snapshot->step;
    QCOMPARE_LT(std::uint64_t(frames), last);

    // yet every step from 0 is plotted, once and in order, as the core steps it
    const ui::PlotSeries &series = widget.series(ui::PlotGroup::Energies);
    QCOMPARE(series.size(), std::size_t(last + 1));
    const auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    core::Workspace work;
    for (std::size_t i = 0; i < series.size(); ++i) {
        if (i > 0)
            QVERIFY(core::step(*model, state, work));
        QCOMPARE(series.step(i), state.step);
        const double total = core::energies(*model, state).total();
        QVERIFY2(series.value(Total, i) == total, bits(series.value(Total, i), total).constData());
    }
}

void TestPlotsWidget::clickedParticleIsPlottedAsTheCoreHasIt()
{
    open(chainScene());
    ui::PlotsWidget *widget = plots();
    widget->groupBox()->setFocus();
    QTest::keyClick(widget->groupBox(), Qt::Key_Down);
    QTest::keyClick(widget->groupBox(), Qt::Key_Down);
    QCOMPARE(widget->group(), ui::PlotGroup::Position);
    QVERIFY(widget->shownSeries().empty());
    QVERIFY(widget->canvas()->emptyText().contains(QStringLiteral("Select a particle")));

    // a click on the last particle of the chain, with the Select tool
    const std::size_t chosen = 3;
    QTRY_VERIFY(m_window->viewport()->snapshot() == controller().frame()->snapshot);
    const auto pixel =
        m_window->viewport()->camera().project(toQt(m_window->document()->scene().particles[chosen].position));
    QVERIFY(pixel);
    QTest::mouseClick(m_window->viewport(), Qt::LeftButton, {}, pixel->toPoint());
    QCOMPARE(m_window->editTools()->selection().particles, std::vector<int>{int(chosen)});
    QCOMPARE(widget->particle(), int(chosen));
    QCOMPARE(widget->canvas()->title(), QStringLiteral("Particle 3"));

    // a few steps: each sample of each plot is the core's, double for double
    m_window->activateWindow();
    stepTimes(4);
    const auto frame = settledFrame(controller());
    const ui::PlotSeries &position = widget->series(ui::PlotGroup::Position);
    const ui::PlotSeries &velocity = widget->series(ui::PlotGroup::Velocity);
    QCOMPARE(position.size(), std::size_t(4));
    QCOMPARE(position.step(position.size() - 1), frame->snapshot->step);
    const core::SceneDesc &scene = m_window->document()->scene();
    const auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    core::Workspace work;
    for (std::size_t i = 0; i < position.size(); ++i) {
        QVERIFY(core::step(*model, state, work));
        QCOMPARE(position.step(i), state.step);
        for (std::size_t axis = 0; axis < 3; ++axis) {
            const double x = position.value(axis, i);
            const double v = velocity.value(axis, i);
            const double coreX = state.position(Eigen::Index(axis), Eigen::Index(chosen));
            const double coreV = state.velocity(Eigen::Index(axis), Eigen::Index(chosen));
            QVERIFY2(x == coreX, bits(x, coreX).constData());
            QVERIFY2(v == coreV, bits(v, coreV).constData());
        }
        const double speed = state.velocity.col(Eigen::Index(chosen)).norm();
        QVERIFY2(velocity.value(3, i) == speed, bits(velocity.value(3, i), speed).constData());
    }
    QVERIFY(state.velocity(1, Eigen::Index(chosen)) < 0.0);  // falling

    // another particle starts its plots over; none leaves them empty
    m_window->editTools()->setSelection({{1}, {}});
    QCOMPARE(widget->particle(), 1);
    QVERIFY(position.empty());
    m_window->editTools()->clearSelection();
    QCOMPARE(widget->particle(), -1);
}

void TestPlotsWidget::resetAndAnotherSceneStartOver()
{
    open(chainScene());
    stepTimes(3);
    const ui::PlotSeries &energies = plots()->series(ui::PlotGroup::Energies);
    QCOMPARE(energies.size(), std::size_t(4));

    // F5: back to step 0 alone, with nothing lost
    press(Qt::Key_F5);
    QVERIFY(settledFrame(controller()));
    QCOMPARE(energies.size(), std::size_t(1));
    QCOMPARE(energies.step(0), std::uint64_t(0));
    QVERIFY2(energies.value(Lost, 0) == 0.0, bits(energies.value(Lost, 0), 0.0).constData());

    // another scene, also at step 0: only its own energies
    core::SceneDesc other = chainScene();
    other.particles[3].position.y() = 2.0;
    m_window->document()->replace(other, QString());
    const auto frame = settledFrame(controller());
    QCOMPARE(energies.size(), std::size_t(1));
    const auto model = core::compileModel(other);
    const double expected = core::energies(*model, core::makeState(*model, other)).total();
    QVERIFY2(energies.value(Total, 0) == expected, bits(energies.value(Total, 0), expected).constData());
    QCOMPARE(frame->snapshot->energies.total(), expected);
}

void TestPlotsWidget::exportsWriteAnImageAndTheSamples()
{
    open(chainScene());
    stepTimes(6);
    QStringList titles;
    QStringList suggested;
    bool allSaves = true;
    using Mode = ui::MainWindow::FileDialogMode;
    m_window->setFileDialogFunction([&](Mode mode, const QString &title, const QString &path) {
        titles << title;
        suggested << path;
        allSaves = allSaves && mode == Mode::Save;
        return m_files.filePath(QFileInfo(path).fileName());
    });

    // Export PNG: the canvas as drawn, at its size
    clickButton("buttonExportPlotPng");
    QCOMPARE(titles.size(), 1);
    QVERIFY2(suggested.back().endsWith(QStringLiteral("chain-energies.png")), qPrintable(suggested.back()));
    const QImage image(m_files.filePath(QStringLiteral("chain-energies.png")));
    QVERIFY(!image.isNull());
    ui::PlotCanvas *canvas = plots()->canvas();
    QCOMPARE(image.size(), canvas->size() * canvas->devicePixelRatio());
    // drawn on: more than the white paper
    int inked = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2)
            inked += image.pixel(x, y) != qRgb(255, 255, 255) ? 1 : 0;
    QVERIFY2(inked > 200, qPrintable(QString::number(inked)));

    // Export CSV: a header, then the samples, every number as plotted
    clickButton("buttonExportPlotCsv");
    QCOMPARE(titles.size(), 2);
    QVERIFY(allSaves);
    QFile file(m_files.filePath(QStringLiteral("chain-energies.csv")));
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    const ui::PlotSeries &series = plots()->series(ui::PlotGroup::Energies);
    QCOMPARE(lines.size(), int(series.size()) + 1);
    QCOMPARE(lines.front(),
             QStringLiteral("step,time [s],kinetic [J],gravitational [J],spring [J],total [J],lost since reset [J]"));
    const QStringList lastRow = lines.back().split(QLatin1Char(','));
    QCOMPARE(lastRow.size(), 7);
    QCOMPARE(lastRow[0].toULongLong(), series.step(series.size() - 1));
    const double total = series.value(Total, series.size() - 1);
    QVERIFY2(readDouble(lastRow[2 + Total]) == total, bits(readDouble(lastRow[2 + Total]), total).constData());
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("chain-energies.csv")));

    // the canvas's context menu offers the same two
    const QList<QAction *> menu = canvas->actions();
    QVERIFY(menu.contains(plots()->exportPngAction()) && menu.contains(plots()->exportCsvAction()));
    QCOMPARE(canvas->contextMenuPolicy(), Qt::ActionsContextMenu);

    // cancelled: nothing written, nothing said
    m_window->setFileDialogFunction([](auto, const QString &, const QString &) { return QString(); });
    QFile::remove(m_files.filePath(QStringLiteral("chain-energies.png")));
    clickButton("buttonExportPlotPng");
    QVERIFY(!QFile::exists(m_files.filePath(QStringLiteral("chain-energies.png"))));
}

QStringList TestPlotsWidget::exportedCsv()
{
    const QString path = m_files.filePath(QStringLiteral("run.csv"));
    QFile::remove(path);
    m_window->setFileDialogFunction([&](auto, const QString &, const QString &) { return path; });
    clickButton("buttonExportPlotCsv");
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    return QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

void TestPlotsWidget::theCsvOfARunHasARowPerStep()
{
    // a run played at the window's pace, then paused
    const core::SceneDesc scene = chainScene();
    open(scene);
    press(Qt::Key_F4);
    QTRY_VERIFY_WITH_TIMEOUT(controller().frame()->snapshot->step > 60, 20000);
    press(Qt::Key_F4);
    const auto last = settledFrame(controller());
    QVERIFY(last && !last->running);

    // the header, then steps 0, 1, 2, … to the last, each at its step's time
    const QStringList lines = exportedCsv();
    QCOMPARE(lines.size(), int(last->snapshot->step) + 2);
    QVERIFY(lines.front().startsWith(QStringLiteral("step,time [s],")));
    const double h = scene.settings.timeStep;
    for (int row = 0; row + 1 < lines.size(); ++row) {
        const QStringList fields = lines[row + 1].split(QLatin1Char(','));
        QCOMPARE(fields[0].toULongLong(), std::uint64_t(row));
        const double time = readDouble(fields[1]);
        QVERIFY2(std::abs(time - row * h) <= 1e-12, qPrintable(lines[row + 1]));
    }
}

void TestPlotsWidget::anExportThatCannotBeWrittenIsReported()
{
    open(chainScene());
    const QString path = m_files.filePath(QStringLiteral("missing-folder/plot.csv"));
    m_window->setFileDialogFunction([&](auto, const QString &, const QString &) { return path; });
    QString said;
    m_window->setMessageBoxFunction([&](QMessageBox::Icon, const QString &, const QString &text, auto, auto) {
        said = text;
        return QMessageBox::Ok;
    });
    clickButton("buttonExportPlotCsv");
    QVERIFY2(said.startsWith(QStringLiteral("Export CSV: cannot write ")) &&
                 said.contains(QDir::toNativeSeparators(path)),
             qPrintable(said));
    QVERIFY(!QFile::exists(path));
}

void TestPlotsWidget::eachPlotOfALongRunGrabsAtItsSize()
{
    // the springs example, 2.5 s of its energies and of the middle particle's motion
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("springs"), &error), qPrintable(error));
    QVERIFY(settledFrame(controller()));
    press(Qt::Key_F8);
    QTRY_VERIFY(dock()->isVisible());
    m_window->resize(1000, 760);
    const int middle = int(m_window->document()->scene().particles.size() / 2);
    m_window->editTools()->setSelection({{middle}, {}});
    // step by step, so that every step is a sample even where the window draws slowly
    stepTimes(250);
    for (const ui::PlotGroup group : {ui::PlotGroup::Energies, ui::PlotGroup::Velocity}) {
        plots()->setGroup(group);
        const QImage image = plots()->grab().toImage();
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), plots()->size());
    }
}

QTEST_MAIN(TestPlotsWidget)
#include "test_plots_widget.moc"
