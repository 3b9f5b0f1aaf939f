// Image sequences: how many frames a duration takes, and which step each frame shows (the first
// at or after its time, also when the time step does not divide 1 / fps or is longer than a
// frame); the frames' names; removing the frames of an earlier sequence and nothing else.

#include "ui/export/image_sequence.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <vector>

using Steps = std::vector<std::uint64_t>;
Q_DECLARE_METATYPE(Steps)

class TestImageSequence : public QObject {
    Q_OBJECT

private slots:
    void frameCountCoversTheDuration_data();
    void frameCountCoversTheDuration();
    void eachFrameShowsTheFirstStepAtOrAfterItsTime_data();
    void eachFrameShowsTheFirstStepAtOrAfterItsTime();
    void framesAreNamedForFfmpeg();
    void onlyFramesAreRemoved();
};

void TestImageSequence::frameCountCoversTheDuration_data()
{
    QTest::addColumn<double>("fps");
    QTest::addColumn<double>("duration");
    QTest::addColumn<int>("frames");
    QTest::newRow("0.1 s at 30") << 30.0 << 0.1 << 3;  // 0.1 × 30 is 3.0000000000000004
    QTest::newRow("1 s at 24") << 24.0 << 1.0 << 24;
    QTest::newRow("0.1 s at 25") << 25.0 << 0.1 << 3;  // 2.5 frames: the third covers the rest
    QTest::newRow("no time") << 30.0 << 0.0 << 1;
}

void TestImageSequence::frameCountCoversTheDuration()
{
    QFETCH(double, fps);
    QFETCH(double, duration);
    QFETCH(int, frames);
    QCOMPARE(ui::sequenceFrameCount(fps, duration), frames);
}

void TestImageSequence::eachFrameShowsTheFirstStepAtOrAfterItsTime_data()
{
    QTest::addColumn<double>("fps");
    QTest::addColumn<double>("timeStep");
    QTest::addColumn<Steps>("steps");
    // 1/30 s is 3.33 steps of 10 ms: steps 4 (40 ms) and 7 (70 ms), never early
    QTest::newRow("30 fps, 10 ms") << 30.0 << 0.01 << Steps{0, 4, 7, 10, 14};
    // a step that divides the frame: exactly on it, rounding error or not
    QTest::newRow("30 fps, 1/120 s") << 30.0 << 1.0 / 120.0 << Steps{0, 4, 8, 12, 16};
    QTest::newRow("25 fps, 0.5 ms") << 25.0 << 0.0005 << Steps{0, 80, 160, 240, 320};
    // a step longer than a frame: frames repeat a step
    QTest::newRow("30 fps, 0.1 s") << 30.0 << 0.1 << Steps{0, 1, 1, 1, 2};
}

void TestImageSequence::eachFrameShowsTheFirstStepAtOrAfterItsTime()
{
    QFETCH(double, fps);
    QFETCH(double, timeStep);
    QFETCH(Steps, steps);
    const Steps found = ui::sequenceFrameSteps(fps, int(steps.size()), timeStep);
    QCOMPARE(found, steps);

    // the truth it encodes: at or after the frame's time, by less than one step
    for (std::size_t k = 0; k < found.size(); ++k) {
        const double frameTime = double(k) / fps;
        const double stepTime = double(found[k]) * timeStep;
        QVERIFY(stepTime >= frameTime - 1e-12);
        QVERIFY(stepTime < frameTime + timeStep - 1e-12);
    }
}

void TestImageSequence::framesAreNamedForFfmpeg()
{
    QCOMPARE(ui::sequenceFramePath(QStringLiteral("/tmp/run"), 0), QStringLiteral("/tmp/run/frame-00000.png"));
    QCOMPARE(ui::sequenceFramePath(QStringLiteral("/tmp/run"), 42), QStringLiteral("/tmp/run/frame-00042.png"));
    QCOMPARE(QString::asprintf(ui::kSequenceFramePattern, 7), QStringLiteral("frame-00007.png"));
}

void TestImageSequence::onlyFramesAreRemoved()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QStringList names = {QStringLiteral("frame-00000.png"), QStringLiteral("frame-00001.png"),
                               QStringLiteral("frame-123456.png"), QStringLiteral("frame-1.png"),
                               QStringLiteral("frame-00002.png.txt"), QStringLiteral("notes.png")};
    for (const QString &name : names) {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::WriteOnly));
    }
    QCOMPARE(ui::sequenceFramesIn(dir.path()).size(), 3);
    QCOMPARE(ui::removeSequenceFrames(dir.path()), QString());
    QVERIFY(ui::sequenceFramesIn(dir.path()).isEmpty());
    for (const char *kept : {"frame-1.png", "frame-00002.png.txt", "notes.png"})
        QVERIFY2(QFile::exists(dir.filePath(QString::fromLatin1(kept))), kept);
}

QTEST_GUILESS_MAIN(TestImageSequence)
#include "test_image_sequence.moc"
