// The pace of the frames of a playing run: a run that keeps up gets up to 60 frames/s; one that
// falls behind gets frames spaced so that drawing takes a tenth of the wall time, by the cost
// measured as they are drawn, but never more than a second apart; the cost starts over with each
// scene and Play; the frame rate never reads 0 once a frame was drawn.

#include "ui/simulation/frame_pacer.h"

#include <QtTest>

class TestFramePacer : public QObject {
    Q_OBJECT

private slots:
    void keepingUpGetsTheMostFrames();
    void behindGetsItsShare();
    void costFollowsTheLatestFrames();
    void slowFramesNeverReadZero();
    void aFrameEverySecondAtMost();
    void startsOverWithNothingMeasured();
};

void TestFramePacer::keepingUpGetsTheMostFrames()
{
    ui::FramePacer pacer;
    QCOMPARE(pacer.interval(false), 1.0 / ui::FramePacer::kMostFramesPerSecond);
    QCOMPARE(pacer.interval(true), 1.0 / ui::FramePacer::kMostFramesPerSecond);  // nothing measured
    pacer.drawn(0.5, 0.5);
    QCOMPARE(pacer.interval(false), 1.0 / ui::FramePacer::kMostFramesPerSecond);
}

void TestFramePacer::behindGetsItsShare()
{
    // frames of 80 ms: one every 0.8 s while behind; cheap ones still at most 60 a second
    ui::FramePacer pacer;
    pacer.drawn(0.08, 1.0);
    QCOMPARE(pacer.frameCost(), 0.08);
    QCOMPARE(pacer.interval(true), 0.08 / ui::FramePacer::kDrawShare);
    QCOMPARE(ui::FramePacer::kDrawShare, 0.1);

    ui::FramePacer cheap;
    cheap.drawn(0.0005, 1.0);
    QCOMPARE(cheap.interval(true), 1.0 / ui::FramePacer::kMostFramesPerSecond);
}

void TestFramePacer::costFollowsTheLatestFrames()
{
    // a first costly frame (shaders compiled, buffers made) weighs less with every cheaper one
    ui::FramePacer pacer;
    pacer.drawn(1.0, 1.0);
    double previous = pacer.frameCost();
    for (int i = 0; i < 20; ++i) {
        pacer.drawn(0.05, 2.0 + i);
        QVERIFY(pacer.frameCost() < previous);
        previous = pacer.frameCost();
    }
    QVERIFY(std::abs(pacer.frameCost() - 0.05) < 0.01);
}

void TestFramePacer::slowFramesNeverReadZero()
{
    // a frame every 4 s: 0.25 frames/s, not 0; a run that starts again is not measured yet
    ui::FramePacer pacer;
    pacer.restartRate(0.0);
    QCOMPARE(pacer.framesPerSecond(), 0.0);
    pacer.drawn(0.4, 4.0);
    QCOMPARE(pacer.framesPerSecond(), 0.25);
    pacer.drawn(0.4, 8.0);
    QCOMPARE(pacer.framesPerSecond(), 0.25);

    // 30 frames a second over a window of a second
    pacer.restartRate(10.0);
    for (int i = 1; i <= 30; ++i)
        pacer.drawn(0.01, 10.0 + i / 30.0);
    QVERIFY(std::abs(pacer.framesPerSecond() - 30.0) < 1e-9);
    pacer.restartRate(20.0);
    QCOMPARE(pacer.framesPerSecond(), 0.0);
}

void TestFramePacer::aFrameEverySecondAtMost()
{
    // frames of 3 s (10⁶ particles on a software renderer) would be 30 s apart by the share alone
    ui::FramePacer pacer;
    pacer.drawn(3.0, 3.0);
    QCOMPARE(pacer.interval(true), ui::FramePacer::kMostSecondsBetweenFrames);
    QCOMPARE(ui::FramePacer::kMostSecondsBetweenFrames, 1.0);
}

void TestFramePacer::startsOverWithNothingMeasured()
{
    // the cost of the last scene's frames is forgotten: the next run starts at the most frames
    ui::FramePacer pacer;
    for (int i = 0; i < 5; ++i)
        pacer.drawn(2.0, 2.0 * (i + 1));
    QVERIFY(pacer.frameCost() > 1.0);
    pacer.startOver(20.0);
    QCOMPARE(pacer.frameCost(), 0.0);
    QCOMPARE(pacer.framesPerSecond(), 0.0);
    QCOMPARE(pacer.interval(true), 1.0 / ui::FramePacer::kMostFramesPerSecond);
    // and the first frame measured is taken as it is, not averaged with the forgotten ones
    pacer.drawn(0.05, 20.5);
    QCOMPARE(pacer.frameCost(), 0.05);
}

QTEST_APPLESS_MAIN(TestFramePacer)
#include "test_frame_pacer.moc"
