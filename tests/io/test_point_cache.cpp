// The animation export (core/io/animation_export.h): a PC2 file read back (point_cache_read.h)
// matches the run's positions to float32 precision, in the file's vertex order with its placement
// undone; the OBJ beside it and the OBJ sequence hold the same numbers; a cancelled export leaves
// nothing; each frame is on disk once written (streamed); a frame of a scene edited meanwhile is
// refused; a cloth generated beside an imported mesh is a surface of its own.

#include "mesh_files.h"
#include "point_cache_read.h"

#include "core/io/animation_export.h"
#include "core/meshes/mesh_import.h"
#include "core/meshes/mesh_surface.h"
#include "core/model/generators.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "core/step.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

namespace {

test::PointCache readPointCache(const QString &path)
{
    return test::readPointCache(test::readAll(path));
}

// an OBJ's v records
std::vector<Eigen::Vector3f> objVertices(const QString &path)
{
    std::vector<Eigen::Vector3f> vertices;
    for (const QByteArray &line : test::readAll(path).split('\n'))
        if (line.startsWith("v ")) {
            const QList<QByteArray> w = line.split(' ');
            vertices.emplace_back(w[1].toFloat(), w[2].toFloat(), w[3].toFloat());
        }
    return vertices;
}

// the flag of these tests: 6 × 8 vertices
core::SceneDesc flagScene(core::TriangleMesh *file = nullptr)
{
    return test::flagScene(6, 8, file);
}

}  // namespace

class TestPointCache : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void pc2MatchesTheRun()
    {
        core::TriangleMesh file;
        const core::SceneDesc scene = flagScene(&file);
        const double h = scene.settings.timeStep;
        const std::uint64_t steps = 50;
        io::ExportOptions options;
        options.pc2Path = m_dir.filePath(u"flag.pc2"_s);
        options.objFolder = m_dir.filePath(u"frames"_s);
        options.fps = 40.0;  // a frame every 2.5 steps: frames at steps 0, 3, 5, 8, 10, ...
        io::AnimationExport exported;
        QCOMPARE(exported.open(options, scene, h, steps), QString());
        QCOMPARE(exported.frameCount(), 21);  // 0 to 0.5 s at 40 frames/s

        // the run, with the positions the export should have written, in the file's space
        const auto model = core::compileModel(scene);
        core::State state = core::makeState(*model, scene);
        core::Workspace work;
        std::vector<Eigen::Matrix3Xd> expected;
        Eigen::Matrix3Xd vertices;
        const auto due = [&] {
            while (int(expected.size()) < exported.frameCount() &&
                   double(state.step) * h >= double(expected.size()) / options.fps - 1e-12) {
                core::meshVertexPositions(scene.meshes[0], state.position, vertices, core::MeshSpace::File);
                expected.push_back(vertices);
            }
        };
        due();
        QCOMPARE(exported.writeDue(state.step, state.position), QString());
        while (state.step < steps) {
            QVERIFY(core::step(*model, state, work));
            due();
            QCOMPARE(exported.writeDue(state.step, state.position), QString());
        }
        QCOMPARE(exported.finish(), QString());
        QCOMPARE(exported.framesWritten(), 21);
        QCOMPARE(int(expected.size()), 21);

        const test::PointCache cache = readPointCache(options.pc2Path);
        QVERIFY(cache.wholeFile);
        QCOMPARE(cache.signature, QByteArray("POINTCACHE2\0", 12));
        QCOMPARE(cache.version, 1);
        QCOMPARE(cache.points, qint32(file.vertices.size()));
        QCOMPARE(cache.start, 0.0f);
        QCOMPARE(cache.sampling, 1.0f);
        QCOMPARE(cache.samples, 21);
        for (std::size_t s = 0; s < cache.frames.size(); ++s)
            for (qint32 v = 0; v < cache.points; ++v)
                for (int a = 0; a < 3; ++a)
                    QCOMPARE(cache.frames[s][std::size_t(3 * v + a)], float(expected[s](a, v)));
        // the first frame is the file's own vertices (to float32), the pinned side stays put, the
        // rest sags (an upright flag hangs in its own plane, so only by its springs' stretch: 1.6 mm
        // at the far corner after 0.5 s; z is up in the file, in cm)
        for (std::size_t v = 0; v < file.vertices.size(); ++v)
            QVERIFY((expected[0].col(Eigen::Index(v)) - file.vertices[v]).norm() < 1e-9);
        QVERIFY2(expected.back()(2, 47) < file.vertices[47].z() - 0.05,
                 qPrintable(QStringLiteral("%1 %2 %3 from %4").arg(expected.back()(0, 47)).arg(expected.back()(1, 47)).arg(expected.back()(2, 47)).arg(file.vertices[47].z())));
        QCOMPARE(expected.back()(2, 0), expected[0](2, 0));

        // the OBJ beside it is the first frame; the sequence, frame by frame, the cache's numbers
        const std::vector<Eigen::Vector3f> first = objVertices(m_dir.filePath(u"flag.obj"_s));
        QCOMPARE(first.size(), file.vertices.size());
        for (std::size_t v = 0; v < first.size(); ++v)
            QCOMPARE(first[v], Eigen::Vector3f(cache.frames[0][3 * v], cache.frames[0][3 * v + 1], cache.frames[0][3 * v + 2]));
        const QStringList objs = QDir(options.objFolder).entryList({u"flag_*.obj"_s}, QDir::Files, QDir::Name);
        QCOMPARE(objs.size(), 21);
        QCOMPARE(objs.first(), u"flag_00000.obj"_s);
        const std::vector<Eigen::Vector3f> last = objVertices(QDir(options.objFolder).filePath(objs.last()));
        for (std::size_t v = 0; v < last.size(); ++v)
            QCOMPARE(last[v], Eigen::Vector3f(cache.frames[20][3 * v], cache.frames[20][3 * v + 1], cache.frames[20][3 * v + 2]));
    }

    void rangeAndSceneSpace()
    {
        const core::SceneDesc scene = flagScene();
        io::ExportOptions options;
        options.pc2Path = m_dir.filePath(u"range.pc2"_s);
        options.fps = 10.0;
        options.from = 0.2;
        options.to = 0.4;
        options.space = core::MeshSpace::Scene;
        io::AnimationExport exported;
        QCOMPARE(exported.open(options, scene, scene.settings.timeStep, 100), QString());
        QCOMPARE(exported.frameCount(), 3);  // 0.2, 0.3, 0.4 s
        QCOMPARE(exported.nextStep(100), std::uint64_t(20));
        core::State state = core::makeState(*core::compileModel(scene), scene);
        for (std::uint64_t step : {20, 30, 40})
            QCOMPARE(exported.writeDue(step, state.position), QString());
        QCOMPARE(exported.finish(), QString());
        const test::PointCache cache = readPointCache(options.pc2Path);
        QCOMPARE(cache.start, 2.0f);  // frame 2 at 10 frames/s
        QCOMPARE(cache.samples, 3);
        // in the scene's space: the pinned corner where the scene has it
        QCOMPARE(cache.frames[0][1], float(scene.particles[std::size_t(scene.meshes[0].particles[0])].position.y()));
    }

    void splitVerticesAreWrittenEach()
    {
        // a cloth cube of 24 file vertices on 8 particles: 24 points, those of one corner alike
        core::SceneDesc scene;
        QVERIFY(core::sceneFromMesh(scene, test::splitCube(1.0), {}).ok());
        io::ExportOptions options;
        options.pc2Path = m_dir.filePath(u"cube.pc2"_s);
        io::AnimationExport exported;
        QCOMPARE(exported.open(options, scene, 0.01, 10), QString());
        core::State state = core::makeState(*core::compileModel(scene), scene);
        QCOMPARE(exported.writeDue(0, state.position), QString());
        QCOMPARE(exported.finish(), QString());
        const test::PointCache cache = readPointCache(options.pc2Path);
        QCOMPARE(cache.points, 24);
        QCOMPARE(cache.samples, 1);  // finished early: the count is what was written
        const core::TriangleMesh cube = test::splitCube(1.0);
        for (std::size_t v = 0; v < 24; ++v)
            QCOMPARE(Eigen::Vector3f(cache.frames[0][3 * v], cache.frames[0][3 * v + 1], cache.frames[0][3 * v + 2]),
                     cube.vertices[v].cast<float>());
    }

    void refusedAndCancelled()
    {
        core::SceneDesc bare;
        bare.particles.resize(2);
        io::ExportOptions options;
        options.pc2Path = m_dir.filePath(u"none.pc2"_s);
        io::AnimationExport nothing;
        QVERIFY(nothing.open(options, bare, 0.01, 10).contains(u"no surface"_s));
        options.fps = 0.0;
        QVERIFY(io::AnimationExport().open(options, flagScene(), 0.01, 10).contains(u"frame rate"_s));
        options.fps = 30.0;
        options.from = 1.0;
        QVERIFY(io::AnimationExport().open(options, flagScene(), 0.01, 10).contains(u"after the run's end"_s));

        // a cancelled export leaves no file
        options.from = 0.0;
        options.pc2Path = m_dir.filePath(u"cancelled/flag.pc2"_s);
        options.objFolder = m_dir.filePath(u"cancelled/objs"_s);
        const core::SceneDesc scene = flagScene();
        io::AnimationExport cancelled;
        QCOMPARE(cancelled.open(options, scene, 0.01, 10), QString());
        core::State state = core::makeState(*core::compileModel(scene), scene);
        QCOMPARE(cancelled.writeDue(0, state.position), QString());
        cancelled.cancel();
        QVERIFY(QDir(m_dir.filePath(u"cancelled"_s)).entryList({u"*.pc2*"_s, u"*.obj"_s}, QDir::Files).isEmpty());
        QVERIFY(QDir(options.objFolder).entryList(QDir::Files).isEmpty());
    }

    void aGeneratedClothBesideAnImportedMeshIsExportedToo()
    {
        // a table imported as a collider, then a 6 × 5 cloth generated over it: two surfaces, the
        // table's and the cloth's 30 particles with its 40 triangles, in the particles' order
        core::SceneDesc scene;
        core::MeshImportOptions table;
        table.kind = core::MeshKind::Collider;
        table.name = "table";
        QVERIFY(core::sceneFromMesh(scene, test::splitCube(1.0), table).ok());
        scene.name = "drape";
        core::ClothOptions cloth;
        cloth.rows = 5;
        cloth.cols = 6;
        cloth.height = 2.0;
        cloth.sheetCollisions = true;  // its triangles listed
        const core::SceneDesc sheet = core::makeCloth(cloth);
        const int first = int(scene.particles.size());
        scene.particles.insert(scene.particles.end(), sheet.particles.begin(), sheet.particles.end());
        for (const std::array<int, 3> &t : sheet.triangles)
            scene.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
        const std::vector<core::MeshDesc> meshes = core::exportedMeshes(scene);
        QCOMPARE(meshes.size(), std::size_t(2));
        QCOMPARE(meshes[0].name, std::string("table"));
        QCOMPARE(meshes[1].name, std::string("drape-sheets"));
        QCOMPARE(meshes[1].vertexCount(), 30);
        QCOMPARE(meshes[1].faces.size(), std::size_t(2 * 4 * 5));
        QCOMPARE(meshes[1].particles.front(), first);
        QCOMPARE(meshes[1].faces.front(), (std::array<int, 3>{sheet.triangles.front()}));
    }

    void framesGoToDiskAsTheyCome()
    {
        // a 50 × 50 sheet, 30 kB a frame: after each frame the cache on disk holds every frame so
        // far (within QFile's 16 kB buffer), so an export of any length holds one frame in memory
        core::SceneDesc scene;
        QVERIFY(core::sceneFromMesh(scene, test::panel(50, 50, 0.02), {}).ok());
        io::ExportOptions options;
        options.pc2Path = m_dir.filePath(u"streamed.pc2"_s);
        options.fps = 100.0;
        io::AnimationExport exported;
        QCOMPARE(exported.open(options, scene, 0.01, 60), QString());
        core::State state = core::makeState(*core::compileModel(scene), scene);
        constexpr qint64 kFrameBytes = 2500 * 12;
        for (std::uint64_t step = 0; step <= 60; ++step) {
            QCOMPARE(exported.writeDue(step, state.position), QString());
            const qint64 onDisk = QFileInfo(options.pc2Path + u".part"_s).size();
            QVERIFY2(onDisk >= 32 + qint64(step + 1) * kFrameBytes - 16 * 1024,
                     qPrintable(u"frame %1: %2 bytes on disk"_s.arg(step).arg(onDisk)));
        }
        QCOMPARE(exported.finish(), QString());
        QCOMPARE(QFileInfo(options.pc2Path).size(), 32 + 61 * kFrameBytes);
    }

    void aSceneEditedMeanwhileIsRefused()
    {
        // the editor's scene lost particles during the export (a Delete while it ran): the frame
        // is refused with the reason, never read past the positions
        const core::SceneDesc scene = flagScene();
        io::ExportOptions options;
        options.pc2Path = m_dir.filePath(u"edited.pc2"_s);
        io::AnimationExport exported;
        QCOMPARE(exported.open(options, scene, 0.01, 10), QString());
        core::State state = core::makeState(*core::compileModel(scene), scene);
        QCOMPARE(exported.writeDue(0, state.position), QString());
        const Eigen::Matrix3Xd fewer = state.position.leftCols(state.position.cols() - 5);
        const QString refused = exported.writeDue(exported.nextStep(10), fewer);
        QVERIFY2(refused.contains(u"was edited during the export"_s), qPrintable(refused));
        QCOMPARE(exported.framesWritten(), 1);
        QCOMPARE(exported.finish(), QString());
        QCOMPARE(readPointCache(options.pc2Path).samples, 1);
    }
};

QTEST_GUILESS_MAIN(TestPointCache)
#include "test_point_cache.moc"
