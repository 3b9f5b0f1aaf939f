// springlab-bench cloth-contacts --quick end to end, through QProcess: the CSV's header, a row for
// every scene in every engine (Bullet's exactly when CMake built the bullet variant), the core's
// sheet with its triangle collisions never crossing itself at any step, the share of the step they
// take in range and only on that row, and bad arguments refused with a message. The quick run's
// timings are far too short to mean anything: only their shape is checked. The full run's figures
// are in docs/benchmarks.md.

#include "bench_run.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace Qt::Literals::StringLiterals;

namespace {

#if SPRINGLAB_BENCH_HAS_BULLET
const QList<QByteArray> kEngines{"springlab", "springlab-beads", "bullet"};
#else
const QList<QByteArray> kEngines{"springlab", "springlab-beads"};
#endif
const QList<QByteArray> kScenes{"crumple", "drape"};

// the columns of cloth-contacts.csv
enum Column { Scene, Size, Engine, Steps, MsPerStep, RealTime, CollisionShare, MostCrossings, EndCrossings, Status, ColumnCount };

using test::number;

}  // namespace

class TestBenchClothContacts : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void everySceneInEveryEngine();
    void theCoreNeverCrosses();
    void figuresAreSane();
    void badArguments_data();
    void badArguments();

private:
    QTemporaryDir m_dir;
    test::ProgramRun m_quick;
    QList<QList<QByteArray>> m_rows;
};

void TestBenchClothContacts::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_BENCH)).isExecutable());
    QVERIFY(m_dir.isValid());
    m_quick = test::runBench({u"cloth-contacts"_s, u"--quick"_s, u"--out"_s, m_dir.path()});
    QVERIFY2(m_quick.exitCode == 0, m_quick.out.constData());
    QFile file(m_dir.filePath(u"cloth-contacts.csv"_s));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = file.readAll().split('\n');
    QCOMPARE(lines.takeFirst(), QByteArray("scene,size,engine,steps,ms_per_step,realtime_factor,collision_share,"
                                           "most_crossings,end_crossings,status"));
    for (const QByteArray &line : lines)
        if (!line.isEmpty()) {
            m_rows.append(line.split(','));
            QCOMPARE(m_rows.last().size(), int(ColumnCount));
        }
}

void TestBenchClothContacts::everySceneInEveryEngine()
{
    QCOMPARE(m_rows.size(), kScenes.size() * kEngines.size());
    for (const QByteArray &scene : kScenes)
        for (const QByteArray &engine : kEngines) {
            int found = 0;
            for (const QList<QByteArray> &row : m_rows)
                if (row[Scene] == scene && row[Engine] == engine) {
                    ++found;
                    QCOMPARE(row[Size], QByteArray("16"));
                    QCOMPARE(row[Steps], QByteArray("10"));  // 0.1 s of 0.01 s steps
                }
            QVERIFY2(found == 1, scene + " " + engine);
        }
}

void TestBenchClothContacts::theCoreNeverCrosses()
{
    for (const QList<QByteArray> &row : m_rows)
        if (row[Engine] == "springlab") {
            QCOMPARE(row[Status], QByteArray("ok"));
            QCOMPARE(row[MostCrossings], QByteArray("0"));
            QCOMPARE(row[EndCrossings], QByteArray("0"));
        }
}

void TestBenchClothContacts::figuresAreSane()
{
    for (const QList<QByteArray> &row : m_rows) {
        const double ms = number(row[MsPerStep]);
        QVERIFY2(std::isfinite(ms) && ms > 0.0, row.join(','));
        const double realTime = number(row[RealTime]);
        // 0.01 s a step over the wall time, both rounded to three decimals
        QVERIFY2(std::abs(realTime - 10.0 / ms) <= (10.0 / ms) * (6e-4 / ms + 1e-3) + 2e-3, row.join(','));
        QVERIFY(number(row[MostCrossings]) >= number(row[EndCrossings]) || row[Status] != "ok");
        // the collisions' share: a fraction, on the core's row with them alone
        if (row[Engine] == "springlab") {
            const double share = number(row[CollisionShare]);
            QVERIFY2(share > 0.0 && share < 1.0, row.join(','));
        } else {
            QVERIFY2(row[CollisionShare].isEmpty(), row.join(','));
        }
    }
    QVERIFY(m_quick.out.contains("crossings (most, end)"));
}

void TestBenchClothContacts::badArguments_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QByteArray>("message");
    QTest::newRow("size 1") << QStringList{u"--size"_s, u"1"_s} << QByteArray("--size");
    QTest::newRow("size text") << QStringList{u"--size"_s, u"many"_s} << QByteArray("--size");
    QTest::newRow("seconds 0") << QStringList{u"--seconds"_s, u"0"_s} << QByteArray("--seconds");
    QTest::newRow("seconds nan") << QStringList{u"--seconds"_s, u"nan"_s} << QByteArray("--seconds");
    QTest::newRow("a file") << QStringList{u"scene.json"_s} << QByteArray("takes no file names");
}

void TestBenchClothContacts::badArguments()
{
    QFETCH(QStringList, arguments);
    QFETCH(QByteArray, message);
    const test::ProgramRun run = test::runBench(QStringList{u"cloth-contacts"_s} + arguments);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(message), run.err.constData());
}

QTEST_GUILESS_MAIN(TestBenchClothContacts)
#include "test_bench_cloth_contacts.moc"
