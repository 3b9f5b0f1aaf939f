// springlab-sim --import MESH --as cloth|soft|collider --output SCENE.json, and a run's
// --export-pc2, --export-obj and --export-mesh, end to end: the files made, read back, and every
// bad file or argument refused with its reason and nothing written.

#include "sim_run.h"

#include "../io/mesh_files.h"
#include "../io/point_cache_read.h"

#include "core/io/scene_file.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>


using namespace Qt::Literals::StringLiterals;

class TestSimMesh : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    QString path(const QString &name) const { return m_dir.filePath(name); }

private slots:
    void initTestCase()
    {
        QVERIFY(test::writeAll(path(u"ball.obj"_s), test::objText(test::icosphere(2, 0.2))));
        QVERIFY(test::writeAll(path(u"panel.obj"_s), test::objText(test::panel(6, 6, 0.1))));
        QVERIFY(test::writeAll(path(u"table.ply"_s), test::plyText(test::splitCube(0.5))));
        QVERIFY(test::writeAll(path(u"open.ply"_s), test::plyText(test::openBox())));
    }

    void importEachKind()
    {
        const test::ProgramRun cloth = test::sim({u"--import"_s, path(u"panel.obj"_s), u"--as"_s, u"cloth"_s, u"--material"_s,
                                                  u"silk"_s, u"--pin"_s, u"left"_s, u"--at"_s, u"0,1,0"_s, u"--output"_s,
                                                  path(u"cloth.json"_s)});
        QVERIFY2(cloth.exitCode == 0, cloth.err.constData());
        QVERIFY(cloth.out.contains("36 particles"));
        const io::LoadResult loaded = io::loadScene(path(u"cloth.json"_s));
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QCOMPARE(loaded.scene->particles.size(), std::size_t(36));
        QCOMPARE(loaded.scene->meshes.size(), std::size_t(1));
        QCOMPARE(loaded.scene->meshes[0].name, std::string("panel"));
        QCOMPARE(loaded.scene->meshes[0].source, path(u"panel.obj"_s).toStdString());
        QCOMPARE(loaded.scene->planes.size(), std::size_t(1));  // a floor under it
        double mass = 0.0;
        int pinned = 0;
        for (const core::ParticleDesc &p : loaded.scene->particles) {
            mass += p.mass;
            pinned += p.pinned;
        }
        QVERIFY(std::abs(mass - 0.06 * 0.25) < 1e-12);  // silk, 0.5 m × 0.5 m
        QCOMPARE(pinned, 6);

        // a soft ball dropped into the scene with a table
        const test::ProgramRun table = test::sim({u"--import"_s, path(u"table.ply"_s), u"--as"_s, u"collider"_s, u"--output"_s,
                                                  path(u"table.json"_s)});
        QVERIFY2(table.exitCode == 0, table.err.constData());
        const test::ProgramRun soft = test::sim({u"--import"_s, path(u"ball.obj"_s), u"--as"_s, u"soft"_s, u"--spacing"_s,
                                                 u"0.08"_s, u"--at"_s, u"0,0.6,0"_s, u"--into"_s, path(u"table.json"_s),
                                                 u"--output"_s, path(u"ball-on-table.json"_s)});
        QVERIFY2(soft.exitCode == 0, soft.err.constData());
        const io::LoadResult both = io::loadScene(path(u"ball-on-table.json"_s));
        QVERIFY2(both.ok(), qPrintable(both.error));
        QCOMPARE(both.scene->meshes.size(), std::size_t(2));
        QCOMPARE(both.scene->meshes[0].kind, core::MeshKind::Collider);
        QCOMPARE(both.scene->meshes[1].kind, core::MeshKind::Soft);
        QCOMPARE(both.scene->meshes[1].vertexCount(), 162);
    }

    void importRefusals_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        const QString out = path(u"refused.json"_s);
        QTest::newRow("no kind") << QStringList{u"--import"_s, path(u"ball.obj"_s), u"--output"_s, out} << u"--import needs --as"_s;
        QTest::newRow("bad kind") << QStringList{u"--import"_s, path(u"ball.obj"_s), u"--as"_s, u"jelly"_s, u"--output"_s, out}
                                  << u"--as: expected cloth, soft or collider, got \"jelly\""_s;
        QTest::newRow("no output") << QStringList{u"--import"_s, path(u"ball.obj"_s), u"--as"_s, u"cloth"_s}
                                   << u"--import needs --output"_s;
        QTest::newRow("open soft") << QStringList{u"--import"_s, path(u"open.ply"_s), u"--as"_s, u"soft"_s, u"--output"_s, out}
                                   << u"the mesh is not closed"_s;
        QTest::newRow("bad scale") << QStringList{u"--import"_s, path(u"ball.obj"_s), u"--as"_s, u"cloth"_s, u"--scale"_s, u"-2"_s,
                                                  u"--output"_s, out}
                                   << u"--scale: must be greater than 0"_s;
        QTest::newRow("bad up") << QStringList{u"--import"_s, path(u"ball.obj"_s), u"--as"_s, u"cloth"_s, u"--up"_s, u"x"_s,
                                               u"--output"_s, out}
                                << u"--up: expected y or z"_s;
        QTest::newRow("bad material") << QStringList{u"--import"_s, path(u"ball.obj"_s), u"--as"_s, u"cloth"_s, u"--material"_s,
                                                     u"wool"_s, u"--output"_s, out}
                                      << u"--material: expected one of cotton, silk, denim, rubber-sheet"_s;
        QTest::newRow("run option") << QStringList{u"--import"_s, path(u"ball.obj"_s), u"--as"_s, u"cloth"_s, u"--duration"_s,
                                                   u"1"_s, u"--output"_s, out}
                                    << u"--duration cannot go with it"_s;
        QTest::newRow("output is input") << QStringList{u"--import"_s, path(u"ball.obj"_s), u"--as"_s, u"cloth"_s, u"--output"_s,
                                                        path(u"ball.obj"_s)}
                                         << u"names a file the import reads"_s;
        QTest::newRow("not a mesh") << QStringList{u"--import"_s, path(u"cloth.json"_s), u"--as"_s, u"cloth"_s, u"--output"_s, out}
                                    << u"cloth.json: "_s;
        QTest::newRow("import-only option") << QStringList{path(u"cloth.json"_s), u"--spacing"_s, u"0.1"_s}
                                            << u"--spacing only makes sense with --import"_s;
    }

    void importRefusals()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const test::ProgramRun run = test::sim(arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(QString::fromUtf8(run.err).contains(message), run.err.constData());
        QVERIFY(!QFile::exists(path(u"refused.json"_s)));
    }

    void hugeAnnouncedFaceCountIsRefused()
    {
        QVERIFY(test::writeAll(path(u"huge.ply"_s),
                               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                               "element face 100000000\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                               "3 0 1 2\n"));
        const test::ProgramRun run = test::sim({u"--import"_s, path(u"huge.ply"_s), u"--as"_s, u"cloth"_s, u"--output"_s,
                                                path(u"huge.json"_s)});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("announces 100000000"), run.err.constData());
        QVERIFY(!QFile::exists(path(u"huge.json"_s)));
    }

    void exportsOfARun()
    {
        const QString scene = path(u"cloth.json"_s);
        QVERIFY(QFile::exists(scene));
        const test::ProgramRun run = test::sim({scene, u"--duration"_s, u"0.5"_s, u"--export-pc2"_s, path(u"out/panel.pc2"_s),
                                                u"--export-obj"_s, path(u"out/frames"_s), u"--export-mesh"_s,
                                                path(u"out/last.ply"_s), u"--fps"_s, u"24"_s});
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QVERIFY2(run.out.contains("13 of 13 frames at 24 frames/s"), run.out.constData());
        // the point cache's header: 36 points, 13 samples of one frame each, from frame 0
        const QByteArray pc2 = test::readAll(path(u"out/panel.pc2"_s));
        QVERIFY(pc2.startsWith(QByteArray("POINTCACHE2\0", 12)));
        const test::PointCache cache = test::readPointCache(pc2);
        QCOMPARE(cache.points, 36);
        QCOMPARE(cache.samples, 13);
        QCOMPARE(cache.start, 0.0f);
        QCOMPARE(cache.sampling, 1.0f);
        QVERIFY(cache.wholeFile);
        QCOMPARE(pc2.size(), 32 + 13 * 36 * 12);
        QVERIFY(QFile::exists(path(u"out/panel.obj"_s)));
        QCOMPARE(QDir(path(u"out/frames"_s)).entryList({u"panel_*.obj"_s}, QDir::Files).size(), 13);
        QVERIFY(test::readAll(path(u"out/last.ply"_s)).startsWith("ply"));

        // refusals: an unknown format, options without an export, a scene with no surface
        const test::ProgramRun format = test::sim({scene, u"--export-mesh"_s, path(u"out/last.xyz"_s)});
        QCOMPARE(format.exitCode, 2);
        QVERIFY2(format.err.contains("no mesh format has the extension \".xyz\""), format.err.constData());
        const test::ProgramRun lone = test::sim({scene, u"--export-from"_s, u"1"_s});
        QCOMPARE(lone.exitCode, 2);
        QVERIFY(lone.err.contains("--export-from only makes sense with"));
        core::SceneDesc bare;
        bare.name = "bare";
        bare.particles.resize(1);
        QVERIFY(io::saveScene(path(u"bare.json"_s), bare).ok());
        const test::ProgramRun nothing = test::sim({path(u"bare.json"_s), u"--export-pc2"_s, path(u"bare.pc2"_s)});
        QCOMPARE(nothing.exitCode, 2);
        QVERIFY2(nothing.err.contains("no surface"), nothing.err.constData());
        QVERIFY(!QFile::exists(path(u"bare.pc2"_s)));
    }
};

QTEST_GUILESS_MAIN(TestSimMesh)
#include "test_sim_mesh.moc"
