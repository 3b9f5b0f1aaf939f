// springlab-sim --render end to end, under a virtual X server: the frames of a run at a frame rate
// and size, the particles drawn where Frame All's camera puts them and moving between frames; the
// trace's rows still every K steps when frames fall between them; frames of an earlier, longer
// render removed; and, with no display at all, exit code 2 and the advice to use xvfb-run.

#include "program_run.h"
#include "tests/io/trace_read.h"

#include "core/io/scene_file.h"
#include "ui/export/image_sequence.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

namespace {

test::ProgramRun sim(const QStringList &arguments,
                     const QProcessEnvironment &environment = test::offscreenEnvironment())
{
    return test::runProgram(QStringLiteral(SPRINGLAB_SIM), arguments, 120000, environment);
}

// pixels that are not the background (the particles, springs, grid and axes)
int drawnPixels(const QImage &image)
{
    const QRgb background = image.pixel(0, 0);
    int drawn = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            drawn += image.pixel(x, y) != background ? 1 : 0;
    return drawn;
}

}  // namespace

class TestSimRender : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void writesTheFramesOfTheRun();
    void traceRowsStayEveryKSteps();
    void replacesTheFramesOfAnEarlierRender();
    void refusesSizesAndFrameRatesItCannotDraw();
    void withoutADisplaySaysToUseXvfbRun();

private:
    QString scene() const { return m_dir.filePath(u"scene.json"_s); }
    QTemporaryDir m_dir;
};

void TestSimRender::initTestCase()
{
    // the particles example: two particles thrown and falling, 0.5 ms steps
    QVERIFY(m_dir.isValid());
    QVERIFY(QFile::copy(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/particles.json"), scene()));
    QVERIFY(!qEnvironmentVariableIsEmpty("DISPLAY"));  // run_ui_test.sh gives it one
}

void TestSimRender::writesTheFramesOfTheRun()
{
    // 0.2 s at 20 frames/s: 4 frames, at steps 0, 100, 200 and 300
    const QString folder = m_dir.filePath(u"frames"_s);
    const test::ProgramRun run = sim(
        {scene(), u"--duration"_s, u"0.2"_s, u"--render"_s, folder, u"--fps"_s, u"20"_s, u"--size"_s, u"321x203"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.out.contains("frames     " + folder.toUtf8() + ", 4 of 4 at 20 frames/s, 321x203 px"),
             run.out.constData());
    QCOMPARE(ui::sequenceFramesIn(folder).size(), 4);

    // each of the requested size, with something drawn (the two particles and the axes: 680 pixels
    // at the first frame; the scene has no floor, so no grid), and the particles moving between them
    QImage previous;
    for (int k = 0; k < 4; ++k) {
        const QImage frame(ui::sequenceFramePath(folder, k));
        QCOMPARE(frame.size(), QSize(321, 203));
        QCOMPARE_GT(drawnPixels(frame), 300);
        if (k > 0)
            QVERIFY2(frame != previous, qPrintable(u"frame %1 is the same as the one before"_s.arg(k)));
        previous = frame;
    }
}

void TestSimRender::traceRowsStayEveryKSteps()
{
    // frames at steps 0, 67 and 134 (30 frames/s of 0.5 ms steps) fall between rows every 50
    const QString folder = m_dir.filePath(u"traced"_s);
    const QString trace = m_dir.filePath(u"trace.csv"_s);
    const test::ProgramRun run = sim({scene(), u"--steps"_s, u"200"_s, u"--trace"_s, trace, u"--every"_s, u"50"_s,
                                      u"--render"_s, folder, u"--size"_s, u"64x48"_s, u"--quiet"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QCOMPARE(ui::sequenceFramesIn(folder).size(), 3);
    QByteArray header;
    QList<int> steps;
    for (const QList<QByteArray> &row : test::readTraceRows(trace, &header))
        if (row[2] == "0")
            steps << row[0].toInt();
    QCOMPARE(steps, (QList<int>{0, 50, 100, 150, 200}));
}

void TestSimRender::replacesTheFramesOfAnEarlierRender()
{
    // 6 frames, then 2 into the same folder: only the 2 are left, and the summary says so
    const QString folder = m_dir.filePath(u"again"_s);
    QCOMPARE(sim({scene(), u"--duration"_s, u"0.2"_s, u"--render"_s, folder, u"--size"_s, u"32x32"_s}).exitCode, 0);
    QCOMPARE(ui::sequenceFramesIn(folder).size(), 6);
    const test::ProgramRun run =
        sim({scene(), u"--duration"_s, u"0.05"_s, u"--render"_s, folder, u"--size"_s, u"32x32"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QCOMPARE(ui::sequenceFramesIn(folder).size(), 2);
    QVERIFY2(run.out.contains("replacing 6 of an earlier render"), run.out.constData());
}

void TestSimRender::refusesSizesAndFrameRatesItCannotDraw()
{
    const QString folder = m_dir.filePath(u"refused"_s);
    for (const QStringList &bad : {QStringList{u"--size"_s, u"0x10"_s}, QStringList{u"--size"_s, u"wide"_s},
                                   QStringList{u"--size"_s, u"20000x10"_s}, QStringList{u"--fps"_s, u"0"_s}}) {
        const test::ProgramRun run = sim(QStringList{scene(), u"--render"_s, folder} + bad);
        QVERIFY2(run.exitCode == 2, qPrintable(bad.join(u' ')));
        QVERIFY2(run.err.contains(bad.first().toUtf8() + ": "), run.err.constData());
    }
    QVERIFY(ui::sequenceFramesIn(folder).isEmpty());
}

void TestSimRender::withoutADisplaySaysToUseXvfbRun()
{
    // no display, on the platform that needs one: a message and exit code 2, no crash
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove(u"DISPLAY"_s);
    environment.remove(u"WAYLAND_DISPLAY"_s);
    environment.insert(u"QT_QPA_PLATFORM"_s, u"xcb"_s);
    const QString folder = m_dir.filePath(u"headless"_s);
    const test::ProgramRun run = sim({scene(), u"--render"_s, folder}, environment);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("needs an X display"), run.err.constData());
    QVERIFY2(run.err.contains("xvfb-run -a"), run.err.constData());
    QVERIFY(!QFile::exists(folder));

    // the other modes still run there
    const test::ProgramRun plain = sim({scene(), u"--steps"_s, u"10"_s, u"--quiet"_s}, environment);
    QVERIFY2(plain.exitCode == 0, plain.err.constData());

    // a DISPLAY where no X server answers: the same, where Qt's xcb platform would abort (134)
    environment.insert(u"DISPLAY"_s, u":9876"_s);
    const test::ProgramRun unreachable = sim({scene(), u"--render"_s, folder}, environment);
    QCOMPARE(unreachable.exitCode, 2);
    QVERIFY2(unreachable.err.contains("no X server answers at DISPLAY=:9876"), unreachable.err.constData());
    QVERIFY(!QFile::exists(folder));
}

QTEST_GUILESS_MAIN(TestSimRender)
#include "test_sim_render.moc"
