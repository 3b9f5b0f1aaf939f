// springlab-bench throughput --quick end to end, through QProcess: the CSV's header, a row for every
// variant on the cloth, finite positive figures whose ratio column is ms_per_step over the bound,
// Bullet's rows exactly when CMake built the bullet variant (SPRINGLAB_BENCH_HAS_BULLET), a
// readable plot, the physics check passed, and bad arguments refused with a message. The quick
// run's timings are far too short to mean anything; only their shape is checked. The full run's
// figures are in docs/benchmarks.md.

#include "bench/throughput_plot.h"

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

#if SPRINGLAB_BENCH_HAS_BULLET
const QList<QByteArray> kClothVariants{"springlab", "plain", "naive", "bullet"};
#else
const QList<QByteArray> kClothVariants{"springlab", "plain", "naive"};
#endif

using Run = test::ProgramRun;

using test::runBench;

using test::number;

}  // namespace

class TestBenchThroughput : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void csvShape();
    void figuresAreSane();
    void everyVariantOnTheCloth();
    void bulletVariant();
    void physicsAgrees();
    void plotReads();
    void badArguments_data();
    void badArguments();

private:
    QTemporaryDir m_dir;
    Run m_quick;
    QList<QList<QByteArray>> m_rows;
};

void TestBenchThroughput::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_BENCH)).isExecutable());
    QVERIFY(m_dir.isValid());
    m_quick = runBench({u"throughput"_s, u"--quick"_s, u"--out"_s, m_dir.path()});
    QVERIFY2(m_quick.exitCode == 0, m_quick.out.constData());

    QFile file(m_dir.filePath(u"throughput.csv"_s));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = file.readAll().split('\n');
    QCOMPARE(lines.takeLast(), QByteArray());  // the file ends with a newline
    QCOMPARE(lines.takeFirst(),
             QByteArray("scene,particles,springs,threads,variant,ms_per_step,bandwidth_bound_ms,ratio_to_bound"));
    for (const QByteArray &line : lines)
        m_rows.append(line.split(','));
}

void TestBenchThroughput::csvShape()
{
    QVERIFY(!m_rows.isEmpty());
    for (const QList<QByteArray> &fields : m_rows) {
        QCOMPARE(fields.size(), 8);
        QVERIFY2(fields[0].startsWith("cloth-") || fields[0].startsWith("box-"), fields.join(',').constData());
        QVERIFY2(fields[3] == "1" || fields[3] == "2", fields.join(',').constData());
    }
    QVERIFY(m_quick.out.contains(u"wrote %1 rows"_s.arg(m_rows.size()).toUtf8()));
}

void TestBenchThroughput::figuresAreSane()
{
    // every figure finite and positive (a box has no springs: 0 there), and the ratio is the
    // time over the bound
    for (const QList<QByteArray> &fields : m_rows) {
        const QByteArray line = fields.join(',');
        const double particles = number(fields[1]), springs = number(fields[2]);
        const double ms = number(fields[5]), bound = number(fields[6]), ratio = number(fields[7]);
        QVERIFY2(std::isfinite(particles) && particles > 0.0, line.constData());
        QVERIFY2(std::isfinite(springs) && (springs > 0.0 || fields[0].startsWith("box-")), line.constData());
        for (double value : {ms, bound, ratio})
            QVERIFY2(std::isfinite(value) && value > 0.0, line.constData());
        QVERIFY2(std::abs(ratio - ms / bound) <= 1e-4 * ratio, line.constData());
        // the scene's name carries its size: cloth-N has N² particles, box-n has n
        const int size = fields[0].mid(fields[0].indexOf('-') + 1).toInt();
        QCOMPARE(particles, fields[0].startsWith("cloth-") ? double(size) * size : double(size));
    }
}

void TestBenchThroughput::everyVariantOnTheCloth()
{
    QHash<QByteArray, QSet<QByteArray>> variants;  // per cloth scene
    for (const QList<QByteArray> &fields : m_rows)
        if (fields[0].startsWith("cloth-"))
            variants[fields[0]].insert(fields[4]);
    QVERIFY(!variants.isEmpty());
    for (auto it = variants.cbegin(); it != variants.cend(); ++it)
        for (const QByteArray &variant : kClothVariants)
            QVERIFY2(it.value().contains(variant), (it.key() + " lacks " + variant).constData());
}

void TestBenchThroughput::bulletVariant()
{
    // built: one row per cloth, on 1 thread (Bullet's soft-body solver has no threads), a time
    // that is a time, the check and the ratio printed; not built: no row, and the run says so
    QList<QList<QByteArray>> bullet;
    for (const QList<QByteArray> &fields : m_rows)
        if (fields[4] == "bullet")
            bullet.append(fields);
    if (!SPRINGLAB_BENCH_HAS_BULLET) {
        QVERIFY2(bullet.isEmpty(), bullet.value(0).join(',').constData());
        QVERIFY(m_quick.out.contains("bullet: not built"));
        return;
    }
    QVERIFY2(!m_quick.out.contains("not built"), m_quick.out.constData());
    QVERIFY(m_quick.out.contains("bullet: Bullet "));
    QCOMPARE(bullet.size(), 1);  // --quick: cloth-64 only
    const QList<QByteArray> &row = bullet.first();
    QCOMPARE(row[0], QByteArray("cloth-64"));
    QCOMPARE(row[3], QByteArray("1"));
    const double ms = number(row[5]);
    QVERIFY2(std::isfinite(ms) && ms > 0.0, row.join(',').constData());
    const QList<QByteArray> lines = m_quick.out.split('\n');
    const auto lineAfter = [&](const QByteArray &start) {
        for (qsizetype i = 0; i + 1 < lines.size(); ++i)
            if (lines[i].trimmed().startsWith(start))
                return lines[i + 1];
        return QByteArray();
    };
    // the check line names Bullet's difference; the summary gives its ratio to the core on cloth-64
    QVERIFY2(m_quick.out.contains(QByteArray("m, bullet ")), m_quick.out.constData());
    const QByteArray ratio = lineAfter("bullet / springlab, how many times faster the core is");
    QVERIFY2(ratio.trimmed().startsWith("cloth-64") && ratio.contains("1 thread ") && ratio.contains("x "),
             m_quick.out.constData());
}

void TestBenchThroughput::physicsAgrees()
{
    // the references were checked against the core before they were timed
    QVERIFY(m_quick.out.contains("largest position difference from springlab"));
    QVERIFY2(!m_quick.out.contains("DISAGREE"), m_quick.out.constData());
    QVERIFY(m_quick.out.contains("memory bandwidth"));
    QVERIFY(m_quick.out.contains("machine: "));
}

void TestBenchThroughput::plotReads()
{
    const QImage plot(m_dir.filePath(u"throughput.png"_s));
    QVERIFY(!plot.isNull());
    QCOMPARE(plot.size(), bench::kThroughputPlotSize);
    // not one flat colour: text, grid, and the variants' colours
    const qsizetype colours = test::coloursIn(plot);
    QVERIFY2(colours >= 8, qPrintable(u"%1 colours"_s.arg(colours)));
}

void TestBenchThroughput::badArguments_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("unknown option") << QStringList{u"throughput"_s, u"--fast"_s};
    QTest::newRow("a file name") << QStringList{u"throughput"_s, u"x.json"_s};
    QTest::newRow("--out without a folder") << QStringList{u"throughput"_s, u"--out"_s};
}

void TestBenchThroughput::badArguments()
{
    QFETCH(QStringList, arguments);
    const Run run = runBench(arguments);
    QCOMPARE(run.exitCode, 2);
    QVERIFY(run.err.contains("springlab-bench: "));
    QVERIFY(run.err.contains("usage: springlab-bench"));
    QVERIFY(run.err.contains("throughput"));
}

QTEST_GUILESS_MAIN(TestBenchThroughput)
#include "test_bench_throughput.moc"
