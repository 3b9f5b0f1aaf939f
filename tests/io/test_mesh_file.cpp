// Mesh files in (core/io/mesh_file.h): the file's own vertices in the file's order (an OBJ's v
// records, a PLY's split vertices), polygons split, every format assimp writes read back, the
// meshes of a scene saved and loaded bit for bit, and every bad file refused with its reason.

#include "mesh_files.h"

#include "core/io/animation_export.h"
#include "core/io/mesh_file.h"
#include "core/io/scene_file.h"
#include "core/meshes/mesh_import.h"
#include "core/model/validate.h"

#include <QTemporaryDir>
#include <QTest>

#include <algorithm>

using namespace Qt::Literals::StringLiterals;

class TestMeshFile : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    QString write(const QString &name, const QByteArray &bytes)
    {
        const QString path = m_dir.filePath(name);
        if (!test::writeAll(path, bytes))
            qFatal("cannot write %s", qPrintable(path));
        return path;
    }

    // the mesh file's message, checked to name the file and to say `words`
    void refused(const QString &name, const QByteArray &bytes, const QString &words)
    {
        const QString path = write(name, bytes);
        const io::MeshReadResult read = io::readMeshFile(path);
        QVERIFY2(!read.ok(), qPrintable(name));
        QVERIFY2(read.error.startsWith(path + u": "_s), qPrintable(read.error));
        QVERIFY2(read.error.contains(words), qPrintable(read.error));
    }

private slots:
    void objKeepsItsVertexRecordsInOrder()
    {
        // the icosphere's records shuffled: the library gives a vertex per face corner, in face
        // order; the mesh read has the file's records, in the file's order
        core::TriangleMesh ball = test::icosphere(2, 0.5);
        std::vector<int> order(ball.vertices.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            order[i] = int((i * 37) % order.size());  // 162 and 37 are coprime: a permutation
        core::TriangleMesh shuffled;
        std::vector<int> newIndex(order.size());
        for (std::size_t i = 0; i < order.size(); ++i) {
            shuffled.vertices.push_back(ball.vertices[std::size_t(order[i])]);
            newIndex[std::size_t(order[i])] = int(i);
        }
        for (const auto &f : ball.faces)
            shuffled.faces.push_back({newIndex[std::size_t(f[0])], newIndex[std::size_t(f[1])], newIndex[std::size_t(f[2])]});
        const io::MeshReadResult read = io::readMeshFile(write(u"ball.obj"_s, test::objText(shuffled)));
        QVERIFY2(read.ok(), qPrintable(read.error));
        QCOMPARE(read.mesh->vertices.size(), shuffled.vertices.size());
        for (std::size_t v = 0; v < shuffled.vertices.size(); ++v)
            QVERIFY((read.mesh->vertices[v] - shuffled.vertices[v]).norm() < 1e-6);
        QCOMPARE(read.mesh->faces, shuffled.faces);
    }

    void objNumbersTheLibraryRoundsOtherwise()
    {
        // a strip of quads 1 cm apart written with six digits, as modellers write them: the
        // library reads some of 1.00 to 1.99 a float's last bit off a correctly rounded read, and
        // those vertices still find their records
        constexpr int kColumns = 200;
        QByteArray text;
        for (int row = 0; row < 2; ++row)
            for (int c = 0; c < kColumns; ++c)
                text += "v " + QByteArray::number(c * 0.01, 'g', 6) + " 0 " + QByteArray::number(row * 0.01, 'g', 6) + '\n';
        for (int c = 0; c + 1 < kColumns; ++c)
            text += "f " + QByteArray::number(c + 1) + ' ' + QByteArray::number(c + 1 + kColumns) + ' ' +
                    QByteArray::number(c + 2 + kColumns) + ' ' + QByteArray::number(c + 2) + '\n';
        const io::MeshReadResult read = io::readMeshFile(write(u"strip.obj"_s, text));
        QVERIFY2(read.ok(), qPrintable(read.error));
        QVERIFY2(read.notes.isEmpty(), qPrintable(read.notes.join(u"; "_s)));
        QCOMPARE(read.mesh->vertices.size(), std::size_t(2 * kColumns));
        for (int row = 0; row < 2; ++row)
            for (int c = 0; c < kColumns; ++c) {
                const Eigen::Vector3d &v = read.mesh->vertices[std::size_t(row * kColumns + c)];
                QVERIFY(std::abs(v.x() - c * 0.01) < 1e-6 && std::abs(v.z() - row * 0.01) < 1e-6);
            }
        QCOMPARE(read.mesh->faces.size(), std::size_t(2 * (kColumns - 1)));
    }

    void objWithNormalsQuadsAndPolygons()
    {
        // a cube with a normal a face (its corners split in the library's arrays, not in the file):
        // 8 records, 6 quads split into 12 triangles
        const QByteArray cube = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                                "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n"
                                "f 4//1 3//1 2//1 1//1\nf 5//2 6//2 7//2 8//2\nf 1//3 2//3 6//3 5//3\n"
                                "f 3//4 4//4 8//4 7//4\nf 1//5 5//5 8//5 4//5\nf 2//6 3//6 7//6 6//6\n";
        const io::MeshReadResult read = io::readMeshFile(write(u"cube.obj"_s, cube));
        QVERIFY2(read.ok(), qPrintable(read.error));
        QCOMPARE(read.mesh->vertices.size(), std::size_t(8));
        QCOMPARE(read.mesh->vertices[6], Eigen::Vector3d(1, 1, 1));
        QCOMPARE(read.mesh->faces.size(), std::size_t(12));
        core::SceneDesc scene;
        core::MeshImportOptions options;
        options.kind = core::MeshKind::Soft;
        options.spacing = 0.5;
        const core::MeshImportResult soft = core::addMeshToScene(scene, *read.mesh, options);
        QVERIFY2(soft.ok(), soft.error.c_str());
        QVERIFY(std::abs(soft.volume - 8.0) < 1e-12);

        // a quad, a pentagon, a concave hexagon (an L) and a triangle: 2 + 3 + 4 + 1 triangles,
        // each polygon's area kept
        const QByteArray polygons = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                    "v 3 0 0\nv 4 0 0\nv 4.5 1 0\nv 3.5 2 0\nv 2.5 1 0\n"
                                    "v 6 0 0\nv 8 0 0\nv 8 1 0\nv 7 1 0\nv 7 2 0\nv 6 2 0\n"
                                    "v 10 0 0\nv 11 0 0\nv 10 1 0\n"
                                    "f 1 2 3 4\nf 5 6 7 8 9\nf 10 11 12 13 14 15\nf 16 17 18\n";
        const io::MeshReadResult flat = io::readMeshFile(write(u"polygons.obj"_s, polygons));
        QVERIFY2(flat.ok(), qPrintable(flat.error));
        QCOMPARE(flat.mesh->faces.size(), std::size_t(10));
        QCOMPARE(flat.mesh->vertices.size(), std::size_t(18));
        std::vector<Eigen::Vector3d> points = flat.mesh->vertices;
        const double area = core::surfaceArea(points, flat.mesh->faces);
        QVERIFY2(std::abs(area - (1.0 + 2.5 + 3.0 + 0.5)) < 1e-6, qPrintable(QString::number(area)));
    }

    void plyKeepsSplitVertices()
    {
        // 24 vertex elements (a cube split at its edges): 24 vertices, welded to 8 particles
        const io::MeshReadResult read = io::readMeshFile(write(u"split.ply"_s, test::plyText(test::splitCube(2.0))));
        QVERIFY2(read.ok(), qPrintable(read.error));
        QCOMPARE(read.mesh->vertices.size(), std::size_t(24));
        QCOMPARE(read.mesh->vertices, test::splitCube(2.0).vertices);
        core::SceneDesc scene;
        const core::MeshImportResult cloth = core::addMeshToScene(scene, *read.mesh, {});
        QVERIFY(cloth.ok());
        QCOMPARE(scene.particles.size(), std::size_t(8));
        QCOMPARE(scene.meshes[0].vertexCount(), 24);
    }

    void stlAndTheExportFormatsReadBack()
    {
        const core::TriangleMesh ball = test::icosphere(1, 1.0);
        const io::MeshReadResult stl = io::readMeshFile(write(u"ball.stl"_s, test::stlBinary(ball)));
        QVERIFY2(stl.ok(), qPrintable(stl.error));
        QCOMPARE(stl.mesh->faces.size(), ball.faces.size());
        core::SceneDesc scene;
        QVERIFY(core::addMeshToScene(scene, *stl.mesh, {}).ok());
        QCOMPARE(scene.particles.size(), ball.vertices.size());  // three a facet, welded

        // what the export writes as one frame, every format read back: the same triangles
        Eigen::Matrix3Xd vertices(3, Eigen::Index(ball.vertices.size()));
        for (std::size_t v = 0; v < ball.vertices.size(); ++v)
            vertices.col(Eigen::Index(v)) = ball.vertices[v];
        for (const QString &extension : {u"glb"_s, u"gltf"_s, u"ply"_s, u"stl"_s, u"obj"_s}) {
            const QString path = m_dir.filePath(u"frame."_s + extension);
            QVERIFY2(io::writeMeshFrame(path, vertices, ball.faces, "ball").isEmpty(), qPrintable(extension));
            const io::MeshReadResult back = io::readMeshFile(path);
            QVERIFY2(back.ok(), qPrintable(back.error));
            QCOMPARE(back.mesh->faces.size(), ball.faces.size());
            core::SceneDesc again;
            QVERIFY(core::addMeshToScene(again, *back.mesh, {}).ok());
            QCOMPARE(again.particles.size(), ball.vertices.size());
            QVERIFY2(std::abs(core::surfaceArea(ball.vertices, ball.faces) -
                              core::surfaceArea(back.mesh->vertices, back.mesh->faces)) < 1e-5,
                     qPrintable(extension));
        }
        QVERIFY(io::writeMeshFrame(m_dir.filePath(u"frame.nope"_s), vertices, ball.faces, "ball").contains(u"no mesh format"_s));
    }

    void badFilesAreRefused()
    {
        refused(u"empty.obj"_s, QByteArray(), u"the file is empty"_s);
        refused(u"words.obj"_s, "this is not a mesh at all\n", u"no triangles"_s);
        refused(u"words.txt"_s, "this is not a mesh at all\n", u"not a mesh file"_s);
        refused(u"lines.obj"_s, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n", u"no triangles"_s);
        refused(u"nan.obj"_s, "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n", u"not a finite number"_s);
        refused(u"nan.ply"_s, test::plyText(test::panel(2, 2, 1.0)).replace("1 0 1", "1 nan 1"), u"not a finite number"_s);
        // 10^8 faces announced in a file of a few hundred bytes: refused before any room is made
        const QByteArray header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                  "property float z\nelement face 100000000\nproperty list uchar int vertex_indices\n"
                                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
        refused(u"huge.ply"_s, header, u"announces 100000000"_s);
        QByteArray binary = header;
        binary.replace("ascii", "binary_little_endian").replace("100000000", "1000");
        binary.truncate(binary.indexOf("end_header\n") + 11);
        binary += QByteArray(3 * 12 + 13, '\0');
        refused(u"truncated.ply"_s, binary, u"truncated or damaged"_s);
        refused(u"huge.off"_s, "OFF\n3 100000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", u"100000000 faces"_s);
        refused(u"short.off"_s, "OFF\n3 1000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", u"truncated or damaged"_s);
        // a binary STL whose count is not its size
        QByteArray stl = test::stlBinary(test::icosphere(0));
        stl.chop(100);
        refused(u"cut.stl"_s, stl, u"cannot read it as a mesh"_s);
        const io::MeshReadResult missing = io::readMeshFile(m_dir.filePath(u"missing.obj"_s));
        QVERIFY(!missing.ok() && missing.error.endsWith(u"no such file"_s));
        QVERIFY(io::readMeshFile(m_dir.path()).error.endsWith(u"not a file"_s));
    }

    void meshesInSceneFilesRoundTrip()
    {
        core::SceneDesc scene;
        scene.name = "meshes";
        core::MeshImportOptions cloth;
        cloth.name = "flag \"one\"";
        cloth.source = "flag.obj";
        cloth.placement.scale = 0.5;
        cloth.placement.zUp = true;
        cloth.placement.at = Eigen::Vector3d(0.25, 1.0, -0.5);
        QVERIFY(core::addMeshToScene(scene, test::splitCube(1.0), cloth).ok());
        core::MeshImportOptions soft;
        soft.kind = core::MeshKind::Soft;
        soft.spacing = 0.3;
        QVERIFY(core::addMeshToScene(scene, test::icosphere(1, 0.7), soft).ok());
        scene.planes.push_back({});
        const QString path = m_dir.filePath(u"meshes.json"_s);
        QVERIFY(io::saveScene(path, scene).ok());
        const io::LoadResult loaded = io::loadScene(path);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QVERIFY(loaded.warnings.isEmpty());
        QCOMPARE(loaded.scene->meshes.size(), std::size_t(2));
        QVERIFY(loaded.scene->meshes[0] == scene.meshes[0]);
        QVERIFY(loaded.scene->meshes[1] == scene.meshes[1]);
        QVERIFY(*loaded.scene == scene);
    }

    void badMeshesInSceneFiles_data()
    {
        QTest::addColumn<QByteArray>("meshes");
        QTest::addColumn<QString>("message");
        QTest::newRow("not an array") << QByteArray("{}") << u"meshes: expected an array, got an object"_s;
        QTest::newRow("kind") << QByteArray(R"([{"kind": "jelly", "vertices": [0], "faces": []}])")
                              << u"meshes[0].kind: unknown mesh kind \"jelly\" (known: cloth, soft, collider)"_s;
        QTest::newRow("no kind") << QByteArray(R"([{"vertices": [0], "faces": []}])") << u"meshes[0].kind: missing"_s;
        QTest::newRow("no faces") << QByteArray(R"([{"kind": "cloth", "vertices": [0]}])") << u"meshes[0].faces: missing"_s;
        QTest::newRow("particle") << QByteArray(R"([{"kind": "cloth", "vertices": [0, 1, 7], "faces": [[0, 1, 2]]}])")
                                  << u"meshes[0].vertices[2]: particle index 7 is out of range (the scene has 3 particles)"_s;
        QTest::newRow("weights") << QByteArray(R"([{"kind": "soft", "vertices": [0, 1, [0, 0.5, 1, 0.4]], "faces": [[0, 1, 2]]}])")
                                 << u"meshes[0].vertices[2]: its weights must sum to 1"_s;
        QTest::newRow("pairs") << QByteArray(R"([{"kind": "soft", "vertices": [0, 1, [0, 0.5, 1]], "faces": [[0, 1, 2]]}])")
                               << u"meshes[0].vertices[2]: expected a particle index or an array of particle index and weight pairs"_s;
        QTest::newRow("string") << QByteArray(R"([{"kind": "soft", "vertices": [0, 1, "two"], "faces": [[0, 1, 2]]}])")
                                << u"meshes[0].vertices[2]: expected a particle index or an array"_s;
        QTest::newRow("face") << QByteArray(R"([{"kind": "cloth", "vertices": [0, 1, 2], "faces": [[0, 1, 3]]}])")
                              << u"meshes[0].faces[0][2]: vertex index 3 is out of range (the mesh has 3 vertices)"_s;
        QTest::newRow("corner twice") << QByteArray(R"([{"kind": "cloth", "vertices": [0, 1, 2], "faces": [[0, 1, 1]]}])")
                                      << u"meshes[0].faces[0]: names a vertex twice"_s;
        QTest::newRow("scale") << QByteArray(R"([{"kind": "cloth", "scale": 0, "vertices": [0, 1, 2], "faces": [[0, 1, 2]]}])")
                               << u"meshes[0].scale: must be greater than 0"_s;
    }

    void badMeshesInSceneFiles()
    {
        QFETCH(QByteArray, meshes);
        QFETCH(QString, message);
        const QByteArray json = R"({"format": "springlab-scene", "version": 1, "name": "bad",
            "particles": [{"position": [0, 0, 0], "mass": 1, "radius": 0.1},
                          {"position": [1, 0, 0], "mass": 1, "radius": 0.1},
                          {"position": [0, 1, 0], "mass": 1, "radius": 0.1}],
            "springs": [], "planes": [], "meshes": )" + meshes + "}";
        const io::LoadResult loaded = io::parseScene(json, u"bad.json"_s);
        QVERIFY(!loaded.ok());
        QVERIFY2(loaded.error.startsWith(u"bad.json: "_s + message), qPrintable(loaded.error));
    }

    void unknownMeshKeysWarn()
    {
        const QByteArray json = R"({"format": "springlab-scene", "version": 1, "name": "ok",
            "particles": [{"position": [0, 0, 0], "mass": 1, "radius": 0.1},
                          {"position": [1, 0, 0], "mass": 1, "radius": 0.1},
                          {"position": [0, 1, 0], "mass": 1, "radius": 0.1}],
            "springs": [], "planes": [],
            "meshes": [{"kind": "collider", "colour": "red", "vertices": [0, [1, 0.25, 2, 0.75], 2], "faces": [[0, 1, 2]]}]})";
        const io::LoadResult loaded = io::parseScene(json, u"ok.json"_s);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QCOMPARE(loaded.warnings, QStringList{u"ok.json: meshes[0].colour: unknown key, ignored"_s});
        const core::MeshDesc &mesh = loaded.scene->meshes[0];
        QCOMPARE(mesh.name, std::string("mesh"));
        QCOMPARE(mesh.offsets, (std::vector<int>{0, 1, 3, 4}));
        QCOMPARE(mesh.weights, (std::vector<double>{1.0, 0.25, 0.75, 1.0}));
    }
};

QTEST_GUILESS_MAIN(TestMeshFile)
#include "test_mesh_file.moc"
