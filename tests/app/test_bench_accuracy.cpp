// springlab-bench end to end, through QProcess: `accuracy --quick` writes a well-formed CSV and a
// readable plot per reference problem, and `write-references` gives back exactly the scenes
// shipped in resources/scenes/reference/. The figures of a quick run are not checked: it is a
// smoke test, and its timings are single runs.

#include "tests/test_files.h"
#include "bench/work_precision_plot.h"
#include "core/io/scene_file.h"

#include <QDir>
#include "bench_run.h"

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace Qt::Literals::StringLiterals;

namespace {

using test::readAll;

const QStringList kProblems{u"oscillator"_s, u"bounce"_s, u"head-on"_s, u"chain"_s, u"cloth"_s};
const QStringList kIntegrators{u"symplectic-euler"_s, u"explicit-euler"_s, u"velocity-verlet"_s,
                               u"rk4"_s,              u"implicit-euler"_s, u"adaptive-rk45"_s, u"xpbd"_s,
                               u"projective"_s,       u"vbd"_s};

using Run = test::ProgramRun;

using test::runBench;

// a positive, finite number
bool positive(const QByteArray &text)
{
    bool ok = false;
    const double value = text.toDouble(&ok);
    return ok && std::isfinite(value) && value > 0.0;
}

}  // namespace

class TestBenchAccuracy : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void csvShape_data();
    void csvShape();
    void plotReads_data();
    void plotReads();
    void summaryPrinted();
    void referenceScenesMatch();
    void badArguments_data();
    void badArguments();

private:
    QTemporaryDir m_dir;
    Run m_quick;
};

void TestBenchAccuracy::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_BENCH)).isExecutable());
    QVERIFY(m_dir.isValid());
    m_quick = runBench({u"accuracy"_s, u"--quick"_s, u"--out"_s, m_dir.filePath(u"out"_s)});
    QVERIFY2(m_quick.exitCode == 0, m_quick.out.constData());
}

void TestBenchAccuracy::csvShape_data()
{
    QTest::addColumn<QString>("problem");
    for (const QString &problem : kProblems)
        QTest::newRow(qPrintable(problem)) << problem;
}

void TestBenchAccuracy::csvShape()
{
    QFETCH(QString, problem);
    QList<QByteArray> lines = readAll(m_dir.filePath(u"out/accuracy-%1.csv"_s.arg(problem))).split('\n');
    QVERIFY(lines.size() > 1);
    QCOMPARE(lines.takeLast(), QByteArray());  // the file ends with a newline
    QCOMPARE(lines.takeFirst(), QByteArray("problem,integrator,time_step,substeps,tolerance,error,seconds_per_simulated_second"));

    // every row well formed: a blow-up has an infinite error and no cost, any other run a
    // positive error and cost; only adaptive-rk45 has a tolerance
    QHash<QString, int> rows;
    for (const QByteArray &line : lines) {
        const QList<QByteArray> fields = line.split(',');
        QCOMPARE(fields.size(), 7);
        QCOMPARE(QString::fromUtf8(fields[0]), problem);
        const QString integrator = QString::fromUtf8(fields[1]);
        QVERIFY2(kIntegrators.contains(integrator), line.constData());
        rows[integrator] += 1;
        QVERIFY2(positive(fields[2]), line.constData());
        QVERIFY2(fields[3].toInt() >= 1, line.constData());
        QCOMPARE(fields[4].isEmpty(), integrator != u"adaptive-rk45"_s);
        if (fields[5] == "inf") {
            QVERIFY2(fields[6].isEmpty(), line.constData());
        } else {
            QVERIFY2(positive(fields[5]), line.constData());
            QVERIFY2(positive(fields[6]), line.constData());
        }
    }
    for (const QString &integrator : kIntegrators)
        QVERIFY2(rows.value(integrator) >= 1, qPrintable(integrator));
}

void TestBenchAccuracy::plotReads_data()
{
    csvShape_data();
}

void TestBenchAccuracy::plotReads()
{
    QFETCH(QString, problem);
    const QImage plot(m_dir.filePath(u"out/accuracy-%1.png"_s.arg(problem)));
    QVERIFY(!plot.isNull());
    QCOMPARE(plot.size(), bench::kPlotSize);

    // not one flat colour: text, grid, and the integrators' colours
    const qsizetype colours = test::coloursIn(plot);
    QVERIFY2(colours >= 8, qPrintable(u"%1 colours"_s.arg(colours)));
}

void TestBenchAccuracy::summaryPrinted()
{
    // one table per problem, each with a row per integrator and the cheapest at each error
    const QString out = QString::fromUtf8(m_quick.out);
    QCOMPARE(out.count(u"cost to reach an error"_s), kProblems.size());
    for (const QString &target : {u"1e-2"_s, u"1e-4"_s, u"1e-6"_s})
        QCOMPARE(out.count(u"cheapest at %1 m:"_s.arg(target)), kProblems.size());
    for (const QString &integrator : kIntegrators)
        QVERIFY(out.count(u"\n  %1 "_s.arg(integrator)) >= 2 * kProblems.size());
}

void TestBenchAccuracy::referenceScenesMatch()
{
    // the shipped scenes are the benchmark's problems, byte for byte, and load cleanly
    const QString written = m_dir.filePath(u"reference"_s);
    const Run run = runBench({u"write-references"_s, written});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QDir shipped(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/reference"));
    for (const QString &problem : kProblems) {
        const QString name = problem + u".json"_s;
        const QByteArray expected = readAll(shipped.filePath(name));
        QVERIFY2(!expected.isEmpty(), qPrintable(shipped.filePath(name)));
        QCOMPARE(readAll(QDir(written).filePath(name)), expected);
        const io::LoadResult loaded = io::loadScene(shipped.filePath(name));
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QVERIFY2(loaded.warnings.isEmpty(), qPrintable(loaded.warnings.join(u'\n')));
    }
    QCOMPARE(shipped.entryList({u"*.json"_s}, QDir::Files).size(), kProblems.size());
}

void TestBenchAccuracy::badArguments_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("no benchmark") << QStringList();
    QTest::newRow("unknown benchmark") << QStringList{u"speed"_s};
    QTest::newRow("unknown option") << QStringList{u"accuracy"_s, u"--fast"_s};
    QTest::newRow("stray argument") << QStringList{u"accuracy"_s, u"scene.json"_s};
    QTest::newRow("no folder") << QStringList{u"write-references"_s};
}

void TestBenchAccuracy::badArguments()
{
    QFETCH(QStringList, arguments);
    const Run run = runBench(arguments);
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.err.contains("usage: springlab-bench"));
}

QTEST_GUILESS_MAIN(TestBenchAccuracy)
#include "test_bench_accuracy.moc"
