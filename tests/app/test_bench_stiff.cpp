// springlab-bench stiff --quick end to end, through QProcess: a well-formed CSV with a row per
// cloth, stiffness, integrator and criterion, every met row within its own criterion, and every
// chosen sub-step count the first that passes: the row is run again here, through the core alone,
// at its count and at the count tried before it, and the criterion is read off independently. The
// quick run's timings are single runs of a tiny cloth, so no figure of cost is checked beyond its
// being there; the full run's are in docs/benchmarks.md.

#include "bench/stiff_plot.h"
#include "bench/stiff_scene.h"

#include "bench_run.h"

#include "core/model/diagnostics.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "core/step.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <optional>
#include <utility>

using namespace Qt::Literals::StringLiterals;

namespace {

const QByteArray kHeader =
    "size,particles,springs,stiffness,integrator,criterion,status,substeps,substeps_below,cost_s_per_s,"
    "cost_estimated_s_per_s,cost_2threads_wall_s_per_s,runs,simulated_s,max_stretch,energy_rise_J,kinetic_end_J,"
    "kinetic_ratio,reference";
const QStringList kIntegrators{u"symplectic-euler"_s, u"implicit-euler"_s, u"xpbd"_s, u"projective"_s, u"vbd"_s};
const QStringList kStatuses{u"met"_s, u"none"_s, u"capped"_s, u"soft"_s};

enum Field {
    Size,
    Particles,
    Springs,
    Stiffness,
    Integrator,
    Criterion,
    Status,
    Substeps,
    Below,
    Cost,
    Estimate,
    TwoThreads,
    Runs,
    Simulated,
    MaxStretch,
    EnergyRise,
    KineticEnd,
    KineticRatio,
    Reference,
    kFields
};

using test::number;

// what one run of the cloth did, read off here without the benchmark's code
struct Outcome {
    double maxStretch = 0.0;  // over the structural springs, at the ends of steps
    bool energyRose = false;  // above the start by more than rounding, at the end of some step
    bool blewUp = false;
    bool stretchHeld() const { return !blewUp && maxStretch < bench::kStretchLimit; }
};

Outcome runCloth(int n, double stiffness, core::Integrator integrator, int substeps)
{
    const core::SceneDesc scene = bench::stiffCloth(n, stiffness, integrator, substeps);
    const auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    core::Workspace work;
    const double start = core::energies(*model, state).total();
    Outcome outcome;
    const int steps = static_cast<int>(std::lround(bench::kStiffDuration / bench::kStiffTimeStep));
    for (int s = 0; s < steps; ++s) {
        if (!core::step(*model, state, work)) {
            outcome.blewUp = true;
            return outcome;
        }
        // structural springs join neighbours along a row or a column, at the generator's spacing
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c)
                for (const auto &[dr, dc] : {std::pair(0, 1), std::pair(1, 0)}) {
                    if (r + dr >= n || c + dc >= n)
                        continue;
                    const double length = (state.position.col(r * n + c) - state.position.col((r + dr) * n + c + dc)).norm();
                    const double rest = core::ClothOptions{}.spacing;
                    outcome.maxStretch = std::max(outcome.maxStretch, (length - rest) / rest);
                }
        if (core::energies(*model, state).total() - start > bench::kEnergyRounding * std::abs(start))
            outcome.energyRose = true;
    }
    return outcome;
}

bool meets(const Outcome &outcome, const QByteArray &criterion)
{
    return outcome.stretchHeld() && (criterion == "stretch" || !outcome.energyRose);
}

}  // namespace

class TestBenchStiff : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void csvShape();
    void metRowsMeetTheirCriterion();
    void chosenCountIsTheFirstThatPasses();
    void plotReads();
    void summaryWritten();
    void badArguments();

private:
    QTemporaryDir m_dir;
    test::ProgramRun m_quick;
    QList<QList<QByteArray>> m_rows;
};

void TestBenchStiff::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_BENCH)).isExecutable());
    QVERIFY(m_dir.isValid());
    m_quick = test::runBench({u"stiff"_s, u"--quick"_s, u"--out"_s, m_dir.path()});
    QVERIFY2(m_quick.exitCode == 0, m_quick.out.constData());
    QFile file(m_dir.filePath(u"stiff.csv"_s));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = file.readAll().split('\n');
    QCOMPARE(lines.takeLast(), QByteArray());  // the file ends with a newline
    QCOMPARE(lines.takeFirst(), kHeader);
    for (const QByteArray &line : lines)
        m_rows.append(line.split(','));
}

void TestBenchStiff::csvShape()
{
    // the quick plan: one cloth, two stiffnesses, five integrators, two criteria
    QCOMPARE(m_rows.size(), 1 * 2 * 5 * 2);
    QHash<QString, int> perIntegrator;
    for (const QList<QByteArray> &fields : m_rows) {
        const QByteArray line = fields.join(',');
        QCOMPARE(fields.size(), int(kFields));
        QVERIFY2(kIntegrators.contains(QString::fromUtf8(fields[Integrator])), line.constData());
        perIntegrator[QString::fromUtf8(fields[Integrator])] += 1;
        QVERIFY2(fields[Criterion] == "stretch" || fields[Criterion] == "stretch+energy", line.constData());
        QVERIFY2(kStatuses.contains(QString::fromUtf8(fields[Status])), line.constData());
        const int n = fields[Size].toInt();
        QCOMPARE(fields[Particles].toInt(), n * n);
        QVERIFY2(number(fields[Stiffness]) > 0.0, line.constData());
        QVERIFY2(!fields[Reference].isEmpty(), line.constData());
        // a soft cloth is not searched; every other row names a count and the run its figures are from
        if (fields[Status] == "soft") {
            QVERIFY2(fields[Substeps].isEmpty() && fields[MaxStretch].isEmpty(), line.constData());
            continue;
        }
        QVERIFY2(fields[Substeps].toInt() >= 1, line.constData());
        QVERIFY2(number(fields[Simulated]) > 0.0, line.constData());
        QCOMPARE(fields[Estimate].isEmpty(), fields[Status] != "capped");
        QCOMPARE(fields[Cost].isEmpty(), fields[Status] != "met");
    }
    for (const QString &integrator : kIntegrators)
        QCOMPARE(perIntegrator.value(integrator), 4);
    // the quick plan's stiff cloth is searched: xpbd has rows that are not soft
    int xpbdSearched = 0;
    for (const QList<QByteArray> &fields : m_rows)
        xpbdSearched += fields[Integrator] == "xpbd" && fields[Status] != "soft" ? 1 : 0;
    QCOMPARE(xpbdSearched, 2);
}

void TestBenchStiff::metRowsMeetTheirCriterion()
{
    int met = 0;
    for (const QList<QByteArray> &fields : m_rows) {
        if (fields[Status] != "met")
            continue;
        ++met;
        const QByteArray line = fields.join(',');
        QVERIFY2(number(fields[Cost]) > 0.0 && fields[Runs].toInt() >= 1, line.constData());
        QCOMPARE(number(fields[Simulated]), bench::kStiffDuration);
        QVERIFY2(number(fields[MaxStretch]) < bench::kStretchLimit, line.constData());
        QVERIFY2(number(fields[KineticRatio]) > 0.0, line.constData());
        if (fields[Criterion] == "stretch+energy")
            QVERIFY2(number(fields[EnergyRise]) <= 1e-8, line.constData());  // J, on a cloth of about 3 J
    }
    QVERIFY2(met >= 3, qPrintable(u"%1 rows met their criterion"_s.arg(met)));
}

void TestBenchStiff::chosenCountIsTheFirstThatPasses()
{
    int checked = 0;
    for (const QList<QByteArray> &fields : m_rows) {
        if (fields[Status] != "met")
            continue;
        const QByteArray line = fields.join(',');
        const int n = fields[Size].toInt();
        const double k = number(fields[Stiffness]);
        const std::optional<core::Integrator> integrator = core::integratorFromName(fields[Integrator].toStdString());
        QVERIFY(integrator);
        const int chosen = fields[Substeps].toInt();
        const Outcome at = runCloth(n, k, *integrator, chosen);
        QVERIFY2(meets(at, fields[Criterion]), line.constData());
        QVERIFY2(std::abs(at.maxStretch - number(fields[MaxStretch])) <= 1e-5 * at.maxStretch, line.constData());
        if (fields[Below].isEmpty())
            continue;  // the first count tried
        const int below = fields[Below].toInt();
        QVERIFY2(below >= 1 && below < chosen, line.constData());
        QVERIFY2(!meets(runCloth(n, k, *integrator, below), fields[Criterion]), line.constData());
        ++checked;
    }
    QVERIFY2(checked >= 2, qPrintable(u"%1 counts checked against the one below"_s.arg(checked)));
}

void TestBenchStiff::plotReads()
{
    const QImage plot(m_dir.filePath(u"stiff.png"_s));
    QVERIFY(!plot.isNull());
    QCOMPARE(plot.size(), bench::kStiffPlotSize);
    const qsizetype colours = test::coloursIn(plot);
    QVERIFY2(colours >= 8, qPrintable(u"%1 colours"_s.arg(colours)));
}

void TestBenchStiff::summaryWritten()
{
    QFile file(m_dir.filePath(u"stiff.txt"_s));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray summary = file.readAll();
    QVERIFY(summary.contains("load average at the start"));
    QVERIFY(summary.contains("load average at the end"));
    QVERIFY(summary.contains("target 1:"));
    QVERIFY(summary.contains("target 2:"));
    QCOMPARE(summary.count("\n  8x8    "), qsizetype(m_rows.size()));  // a table line a row
    QVERIFY(summary.contains("target 4:"));
    // implicit-euler's two linear solves side by side, with the conjugate gradients' iterations
    QVERIFY(summary.contains("implicit-euler's linear solve"));
    QVERIFY(summary.contains("block-Jacobi conjugate gradients"));
    QVERIFY(m_quick.out.contains("target 1:"));
}

void TestBenchStiff::badArguments()
{
    for (const QStringList &arguments : {QStringList{u"stiff"_s, u"--fast"_s}, QStringList{u"stiff"_s, u"cloth.json"_s}}) {
        const test::ProgramRun run = test::runBench(arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("usage: springlab-bench"));
    }
}

QTEST_GUILESS_MAIN(TestBenchStiff)
#include "test_bench_stiff.moc"
