// springlab-bench contacts --quick end to end, through QProcess: the CSV's header, a row for every
// scene in every engine (Bullet's two exactly when CMake built the bullet variant,
// SPRINGLAB_BENCH_HAS_BULLET), each scene's size, figures that are finite and in range, the yes/no
// columns where they belong and empty elsewhere, a readable plot, and bad arguments refused with a
// message. The quick run is too short for any stack or pile to mean anything, and its timings far
// too short: only their shape is checked. The full run's figures are in docs/benchmarks.md.

#include "bench/contacts_plot.h"

#include "bench_run.h"

#include <QFile>
#include <QImage>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace Qt::Literals::StringLiterals;

namespace {

#if SPRINGLAB_BENCH_HAS_BULLET
const QList<QByteArray> kEngines{"springlab", "bullet", "bullet-norot"};
#else
const QList<QByteArray> kEngines{"springlab"};
#endif
const QList<QByteArray> kScenes{"column", "pyramid", "pile", "pile-4sub", "heap"};

constexpr double kRadius = 0.05;  // m, every ball's
constexpr double kG = 9.81;       // m/s²

// the columns of contacts.csv
enum Column {
    Scene, Engine, Balls, Substeps, Duration, Stands, Moved, Settled, SettleTime, KineticEnd, KineticPeak,
    KineticThreshold, Overlap, ReposeFit, ReposeCone, MsPerStep, ColumnCount
};

using Run = test::ProgramRun;

using test::runBench;

using test::number;

}  // namespace

class TestBenchContacts : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void everySceneInEveryEngine();
    void scenesHaveTheirSizes();
    void stacksSayWhetherTheyStand();
    void settlingIsConsistent();
    void figuresAreSane();
    void onlyTheHeapHasARepose();
    void outputSaysWhatDiffers();
    void plotReads();
    void badArguments_data();
    void badArguments();

private:
    QTemporaryDir m_dir;
    Run m_quick;
    QList<QList<QByteArray>> m_rows;
};

void TestBenchContacts::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_BENCH)).isExecutable());
    QVERIFY(m_dir.isValid());
    m_quick = runBench({u"contacts"_s, u"--quick"_s, u"--out"_s, m_dir.path()});
    QVERIFY2(m_quick.exitCode == 0, m_quick.out.constData());

    QFile file(m_dir.filePath(u"contacts.csv"_s));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = file.readAll().split('\n');
    QCOMPARE(lines.takeLast(), QByteArray());  // the file ends with a newline
    QCOMPARE(lines.takeFirst(), QByteArray("scene,engine,balls,substeps,duration_s,stands,moved_mm,settled,settle_s,"
                                           "kinetic_end_J,kinetic_peak_J,kinetic_threshold_J,overlap_mm,"
                                           "repose_fit_deg,repose_cone_deg,ms_per_step"));
    for (const QByteArray &line : lines) {
        m_rows.append(line.split(','));
        QVERIFY2(m_rows.last().size() == ColumnCount, line.constData());
    }
}

void TestBenchContacts::everySceneInEveryEngine()
{
    // exactly one row per scene and engine, in that order
    QCOMPARE(m_rows.size(), kScenes.size() * kEngines.size());
    qsizetype r = 0;
    for (const QByteArray &scene : kScenes)
        for (const QByteArray &engine : kEngines) {
            QCOMPARE(m_rows[r][Scene], scene);
            QCOMPARE(m_rows[r][Engine], engine);
            ++r;
        }
    QVERIFY(m_quick.out.contains(u"wrote %1 rows"_s.arg(m_rows.size()).toUtf8()));
}

void TestBenchContacts::scenesHaveTheirSizes()
{
    // the column of 30, the pyramid of 210, the pile of 1000 (at 1 and 4 sub-steps); the quick heap is 30
    const QHash<QByteArray, int> balls{{"column", 30}, {"pyramid", 210}, {"pile", 1000}, {"pile-4sub", 1000}, {"heap", 30}};
    for (const QList<QByteArray> &row : m_rows) {
        QCOMPARE(row[Balls].toInt(), balls.value(row[Scene]));
        QCOMPARE(row[Substeps].toInt(), row[Scene] == "pile-4sub" ? 4 : 1);
        const double duration = number(row[Duration]);
        QVERIFY2(duration > 0.0 && duration <= 5.0, row.join(',').constData());  // --quick: short
    }
}

void TestBenchContacts::stacksSayWhetherTheyStand()
{
    // the column and the pyramid: yes or no, and how far; the others: empty
    for (const QList<QByteArray> &row : m_rows) {
        const QByteArray line = row.join(',');
        if (row[Scene] == "column" || row[Scene] == "pyramid") {
            QVERIFY2(row[Stands] == "yes" || row[Stands] == "no", line.constData());
            const double moved = number(row[Moved]);
            QVERIFY2(std::isfinite(moved) && moved >= 0.0, line.constData());
            QCOMPARE(row[Stands] == "yes", moved < 0.01 * kRadius * 1000.0);
        } else {
            QVERIFY2(row[Stands].isEmpty() && row[Moved].isEmpty(), line.constData());
        }
    }
}

void TestBenchContacts::settlingIsConsistent()
{
    // settled exactly when the kinetic energy stayed below the threshold all through the end
    // window (a second, or half a quick run), so its peak there is at least its value at the end;
    // the settle time at least the window before the end; the threshold is 1e-3 N m g r
    const QHash<QByteArray, double> mass{{"column", 1.0}, {"pyramid", 1.0}, {"pile", 0.1}, {"pile-4sub", 0.1}, {"heap", 0.1}};
    for (const QList<QByteArray> &row : m_rows) {
        const QByteArray line = row.join(',');
        QVERIFY2(row[Settled] == "yes" || row[Settled] == "no", line.constData());
        const double energy = number(row[KineticEnd]), peak = number(row[KineticPeak]);
        const double threshold = number(row[KineticThreshold]);
        QVERIFY2(std::isfinite(energy) && energy >= 0.0 && peak >= energy, line.constData());
        const double expected = 1e-3 * row[Balls].toInt() * mass.value(row[Scene]) * kG * kRadius;
        QVERIFY2(std::abs(threshold / expected - 1.0) < 1e-4, line.constData());
        QCOMPARE(row[Settled] == "yes", peak < threshold);
        if (row[Settled] == "yes") {
            const double at = number(row[SettleTime]), duration = number(row[Duration]);
            QVERIFY2(at >= 0.0 && at <= duration - std::min(1.0, 0.5 * duration) + 1e-6, line.constData());
        } else {
            QVERIFY2(row[SettleTime].isEmpty(), line.constData());
        }
    }
}

void TestBenchContacts::figuresAreSane()
{
    // overlaps finite and less than a diameter (a ball through another or through the floor would
    // show here: the quick runs end while balls still land, so a deep impact is possible); every
    // time finite and positive
    for (const QList<QByteArray> &row : m_rows) {
        const QByteArray line = row.join(',');
        const double overlap = number(row[Overlap]);
        QVERIFY2(std::isfinite(overlap) && overlap >= 0.0 && overlap < 2.0 * kRadius * 1000.0, line.constData());
        const double ms = number(row[MsPerStep]);
        QVERIFY2(std::isfinite(ms) && ms > 0.0, line.constData());
    }
}

void TestBenchContacts::onlyTheHeapHasARepose()
{
    for (const QList<QByteArray> &row : m_rows) {
        const QByteArray line = row.join(',');
        if (row[Scene] != "heap") {
            QVERIFY2(row[ReposeFit].isEmpty() && row[ReposeCone].isEmpty(), line.constData());
            continue;
        }
        const double cone = number(row[ReposeCone]);
        QVERIFY2(cone > 0.0 && cone < 90.0, line.constData());
        if (!row[ReposeFit].isEmpty()) {
            const double fit = number(row[ReposeFit]);
            QVERIFY2(std::isfinite(fit) && fit > -90.0 && fit < 90.0, line.constData());
        }
    }
}

void TestBenchContacts::outputSaysWhatDiffers()
{
    // the machine, that the engines' balls differ in rotating, Bullet's settings or its absence,
    // the target read off the rows, and repeated runs that agree
    QVERIFY(m_quick.out.contains("machine: "));
    QVERIFY(m_quick.out.contains("do not rotate"));
    QVERIFY(m_quick.out.contains("target (issue 21"));
    QVERIFY2(m_quick.out.contains("every repetition ended on the same positions"), m_quick.out.constData());
    if (SPRINGLAB_BENCH_HAS_BULLET) {
        QVERIFY(m_quick.out.contains("bullet: Bullet "));
        QVERIFY(m_quick.out.contains("vs bullet-norot"));
    } else {
        QVERIFY(m_quick.out.contains("bullet: not built"));
    }
}

void TestBenchContacts::plotReads()
{
    const QImage plot(m_dir.filePath(u"contacts.png"_s));
    QVERIFY(!plot.isNull());
    QCOMPARE(plot.size(), bench::kContactsPlotSize);
    // not one flat colour: text, grid, bars, the table's shading
    const qsizetype colours = test::coloursIn(plot);
    QVERIFY2(colours >= 8, qPrintable(u"%1 colours"_s.arg(colours)));
}

void TestBenchContacts::badArguments_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("unknown option") << QStringList{u"contacts"_s, u"--fast"_s};
    QTest::newRow("a file name") << QStringList{u"contacts"_s, u"x.json"_s};
    QTest::newRow("--out without a folder") << QStringList{u"contacts"_s, u"--out"_s};
}

void TestBenchContacts::badArguments()
{
    QFETCH(QStringList, arguments);
    const Run run = runBench(arguments);
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.err.contains("springlab-bench: "));
    QVERIFY(run.err.contains("usage: springlab-bench"));
    QVERIFY(run.err.contains("contacts"));
}

QTEST_GUILESS_MAIN(TestBenchContacts)
#include "test_bench_contacts.moc"
