// springlab-bench pause end to end, through QProcess, on a cloth whose steps are slow (3000
// sub-steps) and that rests its contacts on a floor: every Pause cuts a step short, the state is
// the one the step began from, and the figures are printed for each run and as a median. The
// figures themselves are measured in docs/benchmarks.md, not asserted here.

#include "bench_run.h"

#include "core/model/generators.h"
#include "core/io/scene_file.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

class TestBenchPause : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void everyPauseCutsAStep();
    void badArguments();

private:
    QTemporaryDir m_dir;
    QString m_scene;
};

void TestBenchPause::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_BENCH)).isExecutable());
    QVERIFY(m_dir.isValid());
    core::ClothOptions options;
    options.rows = options.cols = 24;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.timeStep = 0.01;
    scene.settings.substeps = 3000;
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 0.0}};
    m_scene = m_dir.filePath(u"cloth.json"_s);
    QVERIFY(io::saveScene(m_scene, scene).ok());
}

void TestBenchPause::everyPauseCutsAStep()
{
    const test::ProgramRun run = test::runBench({u"pause"_s, u"--scene"_s, m_scene, u"--runs"_s, u"3"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QString out = QString::fromUtf8(run.out);
    QVERIFY2(out.contains(u"576 particles"_s), run.out.constData());

    // three runs, each cut short with a snapshot of the 576 particles
    static const QRegularExpression cut(
        uR"(^run \d: flag at [0-9.e-]+ s into the step, stopped and restored in [0-9.e-]+ ms, snapshot of 576 particles in [0-9.e-]+ ms$)"_s,
        QRegularExpression::MultilineOption);
    QCOMPARE(out.count(cut), 3);
    QVERIFY2(!out.contains(u"ended before the flag"_s), run.out.constData());
    QVERIFY(QRegularExpression(uR"(^stopped and restored: median [0-9.e-]+ ms, largest [0-9.e-]+ ms$)"_s,
                               QRegularExpression::MultilineOption)
                .match(out)
                .hasMatch());
    QVERIFY(QRegularExpression(uR"(^snapshot: median [0-9.e-]+ ms, largest [0-9.e-]+ ms$)"_s,
                               QRegularExpression::MultilineOption)
                .match(out)
                .hasMatch());

    // then, paused: the Step owed (its steps are slow) and the scrub back to step 0 shown
    QVERIFY2(QRegularExpression(uR"(^Step, paused: answered in [0-9.e-]+ ms, the step owed, taken after the answer$)"_s,
                                QRegularExpression::MultilineOption)
                 .match(out)
                 .hasMatch(),
             run.out.constData());
    QVERIFY2(QRegularExpression(uR"(^scrub from step [1-9]\d* to step 0: answered in [0-9.e-]+ ms, showing step 0$)"_s,
                                QRegularExpression::MultilineOption)
                 .match(out)
                 .hasMatch(),
             run.out.constData());

    // with no recording, the scrub says it has nothing to show
    const test::ProgramRun unrecorded =
        test::runBench({u"pause"_s, u"--scene"_s, m_scene, u"--runs"_s, u"1"_s, u"--timeline-mb"_s, u"0"_s});
    QVERIFY2(unrecorded.exitCode == 0, unrecorded.err.constData());
    QVERIFY2(unrecorded.out.contains("to step 0: not recorded"), unrecorded.out.constData());
}

void TestBenchPause::badArguments()
{
    const test::ProgramRun none = test::runBench({u"pause"_s});
    QCOMPARE(none.exitCode, 2);
    QVERIFY2(none.err.contains("--scene FILE is needed"), none.err.constData());
    const test::ProgramRun runs = test::runBench({u"pause"_s, u"--scene"_s, m_scene, u"--runs"_s, u"0"_s});
    QCOMPARE(runs.exitCode, 2);
    const test::ProgramRun budget = test::runBench({u"pause"_s, u"--scene"_s, m_scene, u"--timeline-mb"_s, u"-1"_s});
    QCOMPARE(budget.exitCode, 2);
    QVERIFY2(budget.err.contains("--timeline-mb"), budget.err.constData());
    const test::ProgramRun missing = test::runBench({u"pause"_s, u"--scene"_s, m_dir.filePath(u"none.json"_s)});
    QCOMPARE(missing.exitCode, 1);
    QVERIFY2(missing.err.contains("none.json"), missing.err.constData());
}

QTEST_GUILESS_MAIN(TestBenchPause)
#include "test_bench_pause.moc"
