// springlab-bench mesh-import end to end, through QProcess (--quick): the CSV's header, a read row
// for every format of both meshes and a make and a compile row for every kind each can be, the
// triangle and particle counts those of the meshes it made (a cloth and a collider have a
// particle per vertex, a collider no springs), the streamed export's two rows (bytes written and the
// peak memory's growth), and a bad --runs refused. The timings themselves are in
// docs/benchmarks.md.

#include "bench_run.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

class TestBenchMeshImport : public QObject {
    Q_OBJECT

private slots:
    void everyFormatAndKindHasARow()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const test::ProgramRun run = test::runBench({u"mesh-import"_s, u"--quick"_s, u"--out"_s, dir.path()});
        QVERIFY2(run.exitCode == 0, run.out.constData());
        QFile file(dir.filePath(u"mesh-import.csv"_s));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QList<QByteArray> lines = file.readAll().split('\n');
        QCOMPARE(lines.takeFirst(), QByteArray("mesh,triangles,stage,what,bytes,particles,springs,median_ms,peak_growth_kb"));
        QStringList seen;
        for (const QByteArray &line : lines) {
            if (line.isEmpty())
                continue;
            const QList<QByteArray> row = line.split(',');
            QCOMPARE(row.size(), 9);
            if (row[2] == "export") {
                // the streamed export of a 20 × 20 sheet: its bytes, points and peak memory growth
                QCOMPARE(row[0], QByteArray("sheet-20"));
                QCOMPARE(row[1].toInt(), 2 * 19 * 19);
                const int frames = row[3] == "pc2 10 frames" ? 10 : row[3] == "pc2 100 frames" ? 100 : -1;
                QVERIFY2(frames > 0, line.constData());
                QCOMPARE(row[4].toLongLong(), qint64(frames) * 400 * 12);
                QCOMPARE(row[5].toInt(), 400);
                bool isNumber = false;
                QVERIFY2(row[8].toLongLong(&isNumber) >= 0 && isNumber, line.constData());
                seen << QString::fromLatin1(row[0] + ' ' + row[2] + ' ' + row[3]);
                continue;
            }
            // the quick sheet is 33 × 33 vertices, the quick sphere 40 slices by 26 rings
            const bool isSheet = row[0] == "sheet";
            QCOMPARE(row[1].toInt(), isSheet ? 2 * 32 * 32 : 2 * 40 * 25);
            QVERIFY2(test::number(row[7]) >= 0.0, line.constData());
            if (row[2] == "read") {
                QVERIFY2(row[4].toLongLong() > 0, line.constData());
            } else {
                QVERIFY2(row[2] == "make" || row[2] == "compile", line.constData());
                if (row[3] != "soft")
                    QCOMPARE(row[5].toInt(), isSheet ? 33 * 33 : 40 * 25 + 2);
                // a collider is pinned particles and triangles, no springs
                QVERIFY2(row[3] == "collider" ? row[6].toInt() == 0 : row[6].toInt() > 0, line.constData());
            }
            seen << QString::fromLatin1(row[0] + ' ' + row[2] + ' ' + row[3]);
        }
        seen.sort();
        QCOMPARE(seen, (QStringList{u"sheet compile cloth"_s, u"sheet compile collider"_s, u"sheet make cloth"_s,
                                    u"sheet make collider"_s, u"sheet read glb"_s, u"sheet read obj"_s, u"sheet read ply"_s,
                                    u"sheet read stl"_s, u"sheet-20 export pc2 10 frames"_s,
                                    u"sheet-20 export pc2 100 frames"_s, u"sphere compile cloth"_s, u"sphere compile collider"_s,
                                    u"sphere compile soft"_s, u"sphere make cloth"_s, u"sphere make collider"_s,
                                    u"sphere make soft"_s, u"sphere read glb"_s, u"sphere read obj"_s, u"sphere read ply"_s,
                                    u"sphere read stl"_s}));
    }

    void aBadRunCountIsRefused()
    {
        const test::ProgramRun run = test::runBench({u"mesh-import"_s, u"--runs"_s, u"0"_s});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("--runs must be a whole number from 1 to 1000"), run.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestBenchMeshImport)
#include "test_bench_mesh_import.moc"
