// springlab-bench rolling end to end, through QProcess: the CSV's header, a row for every quantity
// of every scene, the core within 1% of each closed form (to the step for when it starts rolling),
// Bullet's column filled exactly when CMake built the bullet variant. The figures themselves are in
// docs/benchmarks.md.

#include "bench_run.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace Qt::Literals::StringLiterals;

namespace {

// the columns of rolling.csv
enum Column { Scene, Quantity, ClosedForm, Springlab, Bullet, SpringlabError, BulletError, ColumnCount };

using test::number;

}  // namespace

class TestBenchRolling : public QObject {
    Q_OBJECT

private slots:
    void theCoreMeetsEveryClosedForm();
};

void TestBenchRolling::theCoreMeetsEveryClosedForm()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_BENCH)).isExecutable());
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const test::ProgramRun run = test::runBench({u"rolling"_s, u"--out"_s, dir.path()});
    QVERIFY2(run.exitCode == 0, run.out.constData());
    QFile file(dir.filePath(u"rolling.csv"_s));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = file.readAll().split('\n');
    QCOMPARE(lines.takeFirst(), QByteArray("scene,quantity,closed_form,springlab,bullet,springlab_error,bullet_error"));
    int rows = 0;
    for (const QByteArray &line : lines) {
        if (line.isEmpty())
            continue;
        const QList<QByteArray> row = line.split(',');
        QCOMPARE(row.size(), int(ColumnCount));
        ++rows;
        const double expected = number(row[ClosedForm]);
        const double core = number(row[Springlab]);
        // when it starts rolling: to the step (0.01 s); anything else within 1%
        const double tolerance = row[Quantity].startsWith("rolls from") ? 0.011 : 0.01 * std::abs(expected);
        QVERIFY2(std::abs(core - expected) <= tolerance, line.constData());
        QCOMPARE(row[Bullet] != "-", bool(SPRINGLAB_BENCH_HAS_BULLET));
    }
    QCOMPARE(rows, 7);  // strike 2, roll 2, slide 2, backspin 1
}

QTEST_GUILESS_MAIN(TestBenchRolling)
#include "test_bench_rolling.moc"
