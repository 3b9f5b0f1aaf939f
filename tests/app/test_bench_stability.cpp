// springlab-bench stability --quick end to end, through QProcess: a well-formed CSV with a row per
// measured cell, ratios of measured to theoretical limit in a sane range, a readable plot, and
// implicit Euler stable at 100 times the explicit limit. A quick run's trials are short and its
// bisection coarse, so the ratios are checked loosely; the full run's figures are in
// docs/benchmarks.md.

#include "bench/stability_plot.h"

#include "bench_run.h"

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace Qt::Literals::StringLiterals;

namespace {

const QStringList kIntegrators{u"symplectic-euler"_s, u"explicit-euler"_s, u"velocity-verlet"_s, u"rk4"_s};

using Run = test::ProgramRun;

using test::runBench;

using test::number;

}  // namespace

class TestBenchStability : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void csvShape();
    void ratiosAreSane();
    void plotReads();
    void implicitStaysStable();
    void badArguments();

private:
    QTemporaryDir m_dir;
    Run m_quick;
    QList<QList<QByteArray>> m_rows;
};

void TestBenchStability::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_BENCH)).isExecutable());
    QVERIFY(m_dir.isValid());
    m_quick = runBench({u"stability"_s, u"--quick"_s, u"--out"_s, m_dir.path()});
    QVERIFY2(m_quick.exitCode == 0, m_quick.out.constData());
}

void TestBenchStability::csvShape()
{
    QFile file(m_dir.filePath(u"stability.csv"_s));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = file.readAll().split('\n');
    QCOMPARE(lines.takeLast(), QByteArray());  // the file ends with a newline
    QCOMPARE(lines.takeFirst(), QByteArray("integrator,stiffness,mass,particles,theory_time_step,measured_time_step,ratio"));

    // the quick grid: 3 stiffnesses × 2 masses × 2 chains per integrator, less the cells whose
    // limit is past the largest time step (at most the softest, heaviest corner per chain)
    QHash<QString, int> rows;
    for (const QByteArray &line : lines) {
        const QList<QByteArray> fields = line.split(',');
        QCOMPARE(fields.size(), 7);
        QVERIFY2(kIntegrators.contains(QString::fromUtf8(fields[0])), line.constData());
        rows[QString::fromUtf8(fields[0])] += 1;
        QVERIFY2(fields[3] == "2" || fields[3] == "10", line.constData());
        m_rows.append(fields);
    }
    for (const QString &integrator : kIntegrators)
        QVERIFY2(rows.value(integrator) >= 8 && rows.value(integrator) <= 12, qPrintable(integrator));
    QVERIFY(m_quick.out.contains(u"wrote %1 rows"_s.arg(lines.size()).toUtf8()));
}

void TestBenchStability::ratiosAreSane()
{
    // measured over theory within a factor 2 either way, and the ratio column agrees with the two
    // steps; symplectic Euler, the one the editor relies on, within [0.9, 1.1]
    QVERIFY(!m_rows.isEmpty());
    for (const QList<QByteArray> &fields : m_rows) {
        const double theory = number(fields[4]), measured = number(fields[5]), ratio = number(fields[6]);
        QVERIFY2(theory > 0.0 && measured > 0.0 && theory <= 1.0, fields.join(',').constData());
        QVERIFY2(std::abs(ratio - measured / theory) < 1e-3, fields.join(',').constData());
        QVERIFY2(ratio > 0.5 && ratio < 2.0, fields.join(',').constData());
        if (fields[0] == "symplectic-euler")
            QVERIFY2(ratio > 0.9 && ratio < 1.1, fields.join(',').constData());
    }
}

void TestBenchStability::plotReads()
{
    const QImage plot(m_dir.filePath(u"stability.png"_s));
    QVERIFY(!plot.isNull());
    QCOMPARE(plot.size(), bench::kStabilityPlotSize);
    // not one flat colour: text, grid, and the integrators' colours
    const qsizetype colours = test::coloursIn(plot);
    QVERIFY2(colours >= 8, qPrintable(u"%1 colours"_s.arg(colours)));
}

void TestBenchStability::implicitStaysStable()
{
    // "stable in N of N cells", with N > 0
    const QString out = QString::fromUtf8(m_quick.out);
    const QRegularExpressionMatch match = QRegularExpression(u"stable in (\\d+) of (\\d+) cells"_s).match(out);
    QVERIFY2(match.hasMatch(), qPrintable(out));
    QVERIFY(match.captured(2).toInt() > 0);
    QCOMPARE(match.captured(1), match.captured(2));
}

void TestBenchStability::badArguments()
{
    for (const QStringList &arguments : {QStringList{u"stability"_s, u"--fast"_s}, QStringList{u"stability"_s, u"x.json"_s}}) {
        const Run run = runBench(arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("usage: springlab-bench"));
    }
}

QTEST_GUILESS_MAIN(TestBenchStability)
#include "test_bench_stability.moc"
