// The timeline under the editor's view, with real keys and mouse: steps taken show on its slider;
// scrubbing back to the start draws the very pixels the start drew; the step back button and
// Shift+F6 step back, F6 steps forward through the recording, and play goes on from the step
// shown; the budget box reaches the worker and the memory figure; the steps springs broke in are
// drawn as red ticks. Waits are on frames, never fixed sleeps.
#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/panels/plot_series.h"
#include "ui/panels/plots_widget.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/panels/timeline_bar.h"
#include "ui/viewport/viewport.h"

#include "core/model/generators.h"
#include "core/io/scene_file.h"

#include <QLabel>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include "editor_fixture.h"

namespace {

using test::settledFrame;

// pixels that differ between two images of the same size
int differingPixels(const QImage &a, const QImage &b)
{
    int count = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            count += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
    return count;
}

}  // namespace

class TestTimelineBar : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void scrubbingToTheStartDrawsTheStartAgain();
    void stepsBackAndForthAndPlaysOn();
    void budgetReachesTheWorker();
    void saysWhenAStepIsOverTheBudget();
    void breaksAreRedTicks();

private:
    ui::TimelineBar &bar() { return *m_window->timelineBar(); }
    void press(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QTest::keyClick(m_window, key, modifiers);
    }
    // presses the left button at x, moves to toX, lets go, along the slider's middle
    static void drag(QSlider &slider, int x, int toX)
    {
        const int y = slider.height() / 2;
        QTest::mousePress(&slider, Qt::LeftButton, {}, QPoint(x, y));
        QMouseEvent move(QEvent::MouseMove, QPointF(toX, y), slider.mapToGlobal(QPointF(toX, y)), Qt::NoButton,
                         Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&slider, &move);
        QTest::mouseRelease(&slider, Qt::LeftButton, {}, QPoint(toX, y));
    }
    // F6 count times; the frame once all are taken
    std::shared_ptr<const ui::SimulationFrame> stepBy(int count)
    {
        for (int i = 0; i < count; ++i)
            press(Qt::Key_F6);
        return settledFrame(controller());
    }
};

void TestTimelineBar::init()
{
    QVERIFY2(openEditor(), qPrintable(editorFailure()));
}

void TestTimelineBar::cleanup()
{
    closeEditor();
}

void TestTimelineBar::scrubbingToTheStartDrawsTheStartAgain()
{
    ui::Viewport &viewport = *m_window->viewport();
    const QImage start = viewport.grabFramebuffer();
    QVERIFY(!start.isNull());

    // 30 steps: the net sags, the slider follows to the run's end
    auto frame = stepBy(30);
    QVERIFY(frame);
    QCOMPARE(frame->snapshot->step, std::uint64_t(30));
    QCOMPARE(bar().slider()->maximum(), 30);
    QCOMPARE(bar().slider()->value(), 30);
    const QImage later = viewport.grabFramebuffer();
    QVERIFY2(differingPixels(start, later) > 100, "the net must have moved");

    // drag the handle to the middle of the groove with the mouse: a step in between is shown
    QSlider &slider = *bar().slider();
    drag(slider, slider.width() - 6, slider.width() / 2);
    const int middle = slider.value();
    QVERIFY2(middle > 5 && middle < 25, qPrintable(QString("the handle went to %1").arg(middle)));
    frame = settledFrame(controller());
    QCOMPARE(frame->snapshot->step, std::uint64_t(middle));
    QCOMPARE(*frame->timeline.scrubStep, std::uint64_t(middle));
    QVERIFY(!controller().isRunning());

    // on to the left end: the start, drawn to the pixel as it was
    const QStyleOptionSlider option = [&] {
        QStyleOptionSlider o;
        o.initFrom(&slider);
        o.orientation = Qt::Horizontal;
        o.minimum = slider.minimum();
        o.maximum = slider.maximum();
        o.sliderPosition = o.sliderValue = slider.value();
        return o;
    }();
    const QRect handle = slider.style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, &slider);
    drag(slider, handle.center().x(), 0);
    frame = settledFrame(controller());
    QCOMPARE(frame->snapshot->step, std::uint64_t(0));
    QCOMPARE(differingPixels(start, viewport.grabFramebuffer()), 0);
    QCOMPARE(bar().timeText(), QStringLiteral("t = 0.000 s, step 0"));
    // and the recording is all still there
    QCOMPARE(frame->timeline.lastStep, std::uint64_t(30));
}

void TestTimelineBar::stepsBackAndForthAndPlaysOn()
{
    auto frame = stepBy(20);
    QCOMPARE(frame->snapshot->step, std::uint64_t(20));

    // the button, then Shift+F6: two steps back
    QTest::mouseClick(bar().stepBackButton(), Qt::LeftButton);
    press(Qt::Key_F6, Qt::ShiftModifier);
    frame = settledFrame(controller());
    QCOMPARE(frame->snapshot->step, std::uint64_t(18));
    QCOMPARE(bar().slider()->value(), 18);

    // F6 inside the recording moves through it and keeps the rest
    press(Qt::Key_F6);
    frame = settledFrame(controller());
    QCOMPARE(frame->snapshot->step, std::uint64_t(19));
    QCOMPARE(frame->timeline.lastStep, std::uint64_t(20));

    // the plots kept the run's curves while scrubbing: one sample per step 0..20
    const ui::PlotSeries &energies = m_window->plots()->series(ui::PlotGroup::Energies);
    QCOMPARE(energies.step(energies.size() - 1), std::uint64_t(20));

    // play goes on from step 19: what was recorded after it is gone, then new steps come
    press(Qt::Key_F4);
    QTRY_VERIFY_WITH_TIMEOUT(controller().frame()->snapshot->step >= 25, 20000);
    press(Qt::Key_F4);
    frame = settledFrame(controller());
    QVERIFY(!frame->timeline.scrubStep.has_value());
    QCOMPARE(frame->timeline.lastStep, frame->snapshot->step);
    QCOMPARE(bar().slider()->value(), int(frame->snapshot->step));
    // the plots too: the history from step 0 as it was, then the new run's, in order, nothing twice
    QCOMPARE(energies.step(0), std::uint64_t(0));
    for (std::size_t i = 1; i < energies.size(); ++i)
        QVERIFY(energies.step(i) > energies.step(i - 1));
    QCOMPARE(energies.step(energies.size() - 1), frame->snapshot->step);
}

void TestTimelineBar::budgetReachesTheWorker()
{
    QSpinBox &budget = *bar().budgetBox();
    budget.setFocus();
    budget.selectAll();
    QTest::keyClicks(&budget, QStringLiteral("3"));
    QTest::keyClick(&budget, Qt::Key_Enter);
    QCOMPARE(budget.value(), 3);
    auto frame = stepBy(12);
    QCOMPARE(frame->timeline.budgetBytes, std::size_t(3) << 20);
    QVERIFY(frame->timeline.usedBytes > 0 && frame->timeline.usedBytes <= frame->timeline.budgetBytes);
    auto *memory = bar().findChild<QLabel *>(QStringLiteral("timelineMemory"));
    QVERIFY(memory);
    QVERIFY2(memory->text().endsWith(QStringLiteral(" / 3.0 MB")), qPrintable(memory->text()));

    // remembered: the next window starts with it, and so does its worker
    QVERIFY(m_window->close());
    QVERIFY2(openEditor({.show = false, .settle = false}), qPrintable(editorFailure()));
    QCOMPARE(bar().budgetBox()->value(), 3);
    frame = settledFrame(controller());
    QCOMPARE(frame->timeline.budgetBytes, std::size_t(3) << 20);
}

void TestTimelineBar::saysWhenAStepIsOverTheBudget()
{
    // what a frame of the 10⁶-particle cloth says with the default budget: nothing recorded, since
    // one keyframe needs 693 MB of the 512
    ui::TimelineInfo info;
    info.empty = true;
    info.budgetBytes = std::size_t(512) << 20;
    info.keyframeOverBudget = std::size_t(693) << 20;
    bar().showTimeline(info, 3, 0.03);
    auto *memory = bar().findChild<QLabel *>(QStringLiteral("timelineMemory"));
    QVERIFY(memory);
    QCOMPARE(memory->text(), QStringLiteral("off: a step needs 693.0 MB"));
    QVERIFY2(memory->toolTip().contains(QStringLiteral("more than the budget of 512.0 MB")), qPrintable(memory->toolTip()));
    QVERIFY(!bar().findChild<QSlider *>()->isEnabled());

    // once a keyframe is kept, the figures as usual
    info.empty = false;
    info.keyframeOverBudget = 0;
    info.usedBytes = std::size_t(700) << 20;
    info.budgetBytes = std::size_t(1024) << 20;
    bar().showTimeline(info, 3, 0.03);
    QCOMPARE(memory->text(), QStringLiteral("700.0 / 1024.0 MB"));
}

void TestTimelineBar::breaksAreRedTicks()
{
    // a small brittle cloth that tears as it falls
    core::ClothOptions options;
    options.rows = options.cols = 6;
    options.spacing = 0.1;
    options.radius = 0.04;
    options.height = 0.5;
    core::SceneDesc scene = core::makeCloth(options);
    for (core::SpringDesc &spring : scene.springs)
        spring.breakStrain = 2e-3;
    QTemporaryDir files;
    QVERIFY(files.isValid());
    const QString path = files.filePath(QStringLiteral("brittle.json"));
    QVERIFY(io::saveScene(path, scene).ok());
    QString error;
    QVERIFY2(m_window->files()->openScene(path, &error), qPrintable(error));
    QVERIFY(settledFrame(controller()));
    const QImage whole = bar().slider()->grab().toImage();

    auto frame = stepBy(60);
    QVERIFY(frame->snapshot->breakCount > 0);
    QVERIFY(!frame->timeline.breakSteps.empty());
    QCOMPARE(bar().slider()->breaks(), frame->timeline.breakSteps);
    // red where the ticks are: pixels far redder than anything the bare slider had
    const QImage torn = bar().slider()->grab().toImage();
    const auto reds = [](const QImage &image) {
        int count = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb c = image.pixel(x, y);
                count += qRed(c) > 180 && qGreen(c) < 90 && qBlue(c) < 90 ? 1 : 0;
            }
        return count;
    };
    QCOMPARE(reds(whole), 0);
    QVERIFY2(reds(torn) >= 4, qPrintable(QString("%1 red pixels").arg(reds(torn))));
}

QTEST_MAIN(TestTimelineBar)
#include "test_timeline_bar.moc"
