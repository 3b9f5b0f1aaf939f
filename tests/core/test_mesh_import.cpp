// Meshes made into bodies (core/meshes/mesh_import.h): counts, masses, welding, the lattice's
// embedding, placement and its inverse, and the meshes a body cannot be made of.

#include "../test_meshes.h"

#include "core/contacts/cloth_surface.h"
#include "core/meshes/mesh_import.h"
#include "core/meshes/mesh_surface.h"
#include "core/model/diagnostics.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "core/model/validate.h"
#include "core/step.h"

#include <QTest>

#include <set>

namespace {

core::MeshImportOptions as(core::MeshKind kind)
{
    core::MeshImportOptions options;
    options.kind = kind;
    options.name = "test";
    return options;
}

// the scene's particle positions as columns
Eigen::Matrix3Xd positionsOf(const core::SceneDesc &scene)
{
    Eigen::Matrix3Xd x(3, Eigen::Index(scene.particles.size()));
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        x.col(Eigen::Index(i)) = scene.particles[i].position;
    return x;
}

double maxDistance(const Eigen::Matrix3Xd &a, const std::vector<Eigen::Vector3d> &b)
{
    double worst = 0.0;
    for (std::size_t v = 0; v < b.size(); ++v)
        worst = std::max(worst, (a.col(Eigen::Index(v)) - b[v]).norm());
    return worst;
}

double totalMass(const core::SceneDesc &scene)
{
    double sum = 0.0;
    for (const core::ParticleDesc &p : scene.particles)
        sum += p.mass;
    return sum;
}

}  // namespace

class TestMeshImport : public QObject {
    Q_OBJECT

private slots:
    void weldingJoinsSplitVertices()
    {
        const core::TriangleMesh cube = test::splitCube(1.0);
        QCOMPARE(cube.vertices.size(), std::size_t(24));
        const core::WeldedMesh welded = core::weldVertices(cube, 1e-9);
        QCOMPARE(welded.points.size(), std::size_t(8));
        QCOMPARE(welded.faces.size(), std::size_t(12));
        const core::MeshEdges edges = core::meshEdges(welded.faces, 8);
        QCOMPARE(edges.ends.size(), std::size_t(18));
        QVERIFY(edges.closed());
        QCOMPARE(core::enclosedVolume(welded.points, welded.faces), 1.0);
        QCOMPARE(core::surfaceArea(welded.points, welded.faces), 6.0);
    }

    void clothOfAPanel()
    {
        // 5 × 4 vertices 0.1 m apart: 20 particles, 31 edges, 24 faces, 19 interior edges
        core::SceneDesc scene;
        auto options = as(core::MeshKind::Cloth);
        options.density = 0.2;
        const core::MeshImportResult result = core::addMeshToScene(scene, test::panel(5, 4, 0.1), options);
        QVERIFY2(result.ok(), result.error.c_str());
        QCOMPARE(result.particles, 20);
        QCOMPARE(int(scene.particles.size()), 20);
        QCOMPARE(int(scene.triangles.size()), 24);
        // an edge spring each, and one across each pair of faces that share an edge
        const int edges = 5 * 3 + 4 * 4 + 12;  // 5 rows of 3, 4 columns of 4, a diagonal a cell
        const int interior = edges - 2 * (3 + 4);  // all but the 14 on the rim
        QCOMPARE(int(scene.springs.size()), edges + interior);
        QCOMPARE(result.springs, edges + interior);
        // mass: the density over the area, 0.4 × 0.3 m
        QVERIFY(std::abs(totalMass(scene) - 0.2 * 0.12) < 1e-12);
        QVERIFY(std::abs(result.area - 0.12) < 1e-12);
        QVERIFY(scene.settings.triangleCollisions);
        QVERIFY(!core::findProblem(scene));
        // the mesh is the file's vertices on their particles
        QCOMPARE(scene.meshes.size(), std::size_t(1));
        QCOMPARE(scene.meshes[0].vertexCount(), 20);
        QCOMPARE(scene.meshes[0].faces.size(), std::size_t(24));
        QCOMPARE(scene.meshes[0].kind, core::MeshKind::Cloth);
        // springs rest at their lengths: the cloth starts at rest
        for (const core::SpringDesc &s : scene.springs)
            QCOMPARE(s.restLength, (scene.particles[std::size_t(s.a)].position - scene.particles[std::size_t(s.b)].position).norm());
    }

    void shearAndBendAcrossFaces()
    {
        // on a grid, the spring across a diagonal is a cell's other diagonal (shear), the one across
        // a side spans two cells (bend): the material's two stiffnesses
        core::SceneDesc scene;
        auto options = as(core::MeshKind::Cloth);
        options.material = core::ClothMaterial::Denim;
        QVERIFY(core::addMeshToScene(scene, test::panel(4, 4, 0.1), options).ok());
        const core::ClothMaterialValues &denim = core::clothMaterial(core::ClothMaterial::Denim);
        int shear = 0, bend = 0, stretch = 0;
        for (const core::SpringDesc &s : scene.springs) {
            if (s.stiffness == denim.stretch) {
                ++stretch;
                QVERIFY(s.restLength < 0.1 * std::sqrt(2.0) + 1e-12);
            } else if (s.stiffness == denim.shear) {
                ++shear;
                QVERIFY(std::abs(s.restLength - 0.1 * std::sqrt(2.0)) < 1e-12);
            } else {
                QCOMPARE(s.stiffness, denim.bend);
                ++bend;
                QVERIFY(s.restLength > 0.2);
            }
        }
        QCOMPARE(stretch, 3 * 4 * 2 + 9);
        QCOMPARE(shear, 9);
        QVERIFY(bend > 0);
    }

    void clothOfASplitCubeWeldsIt()
    {
        core::SceneDesc scene;
        const core::MeshImportResult result = core::addMeshToScene(scene, test::splitCube(1.0), as(core::MeshKind::Cloth));
        QVERIFY(result.ok());
        QCOMPARE(int(scene.particles.size()), 8);  // no duplicate particles
        QCOMPARE(result.weldedVertices, 16);
        std::set<std::array<double, 3>> places;
        for (const core::ParticleDesc &p : scene.particles)
            places.insert({p.position.x(), p.position.y(), p.position.z()});
        QCOMPARE(places.size(), std::size_t(8));
        // yet the mesh keeps the file's 24 vertices, each on the particle at its place
        const core::MeshDesc &mesh = scene.meshes[0];
        QCOMPARE(mesh.vertexCount(), 24);
        Eigen::Matrix3Xd at;
        core::meshVertexPositions(mesh, positionsOf(scene), at);
        QCOMPARE(maxDistance(at, test::splitCube(1.0).vertices), 0.0);
        QVERIFY(std::abs(totalMass(scene) - core::clothMaterial(core::ClothMaterial::Cotton).density * 6.0) < 1e-12);
    }

    void nonManifoldAndOpenMeshes()
    {
        // a fin: a cloth and a collider all the same; no soft body
        core::SceneDesc scene;
        QVERIFY(core::addMeshToScene(scene, test::fan(), as(core::MeshKind::Cloth)).ok());
        QVERIFY(core::addMeshToScene(scene, test::fan(), as(core::MeshKind::Collider)).ok());
        core::SceneDesc untouched = scene;
        const core::MeshImportResult fin = core::addMeshToScene(scene, test::fan(), as(core::MeshKind::Soft));
        QVERIFY(!fin.ok());
        QVERIFY2(fin.error.find("not closed") != std::string::npos, fin.error.c_str());
        QVERIFY(scene == untouched);
        // an open box: a soft body says why not, and what to do
        const core::MeshImportResult open = core::addMeshToScene(scene, test::openBox(), as(core::MeshKind::Soft));
        QVERIFY(!open.ok());
        QVERIFY2(open.error.find("4 edges border one face only") != std::string::npos, open.error.c_str());
        QVERIFY(open.error.find("cloth or as a collider") != std::string::npos);
        QVERIFY(scene == untouched);
        // the collider of a non-manifold mesh is a surface that collides (not a volume's lattice)
        scene.particles.push_back({Eigen::Vector3d(0, 1, 0), Eigen::Vector3d::Zero(), 1.0, 0.05});
        const auto model = core::compileModel(scene);
        QVERIFY(model->plan.triangleCollisions);
        QCOMPARE(model->surface->triangleCount(), 6);
    }

    void colliderIsPinned()
    {
        core::SceneDesc scene;
        const core::MeshImportResult result = core::addMeshToScene(scene, test::icosphere(2), as(core::MeshKind::Collider));
        QVERIFY(result.ok());
        QCOMPARE(int(scene.particles.size()), 162);
        QCOMPARE(int(scene.triangles.size()), 320);
        QVERIFY(scene.springs.empty());
        for (const core::ParticleDesc &p : scene.particles)
            QVERIFY(p.pinned);
        QVERIFY(scene.settings.triangleCollisions);
        QCOMPARE(scene.meshes[0].kind, core::MeshKind::Collider);
    }

    void softBodyFillsAClosedMesh()
    {
        core::SceneDesc scene;
        auto options = as(core::MeshKind::Soft);
        options.spacing = 0.25;
        options.density = 100.0;
        const core::TriangleMesh ball = test::icosphere(3, 1.0);
        const core::MeshImportResult result = core::addMeshToScene(scene, ball, options);
        QVERIFY2(result.ok(), result.error.c_str());
        // the mass is the density times the volume the mesh encloses (a little under 4/3 π)
        const double volume = core::enclosedVolume(ball.vertices, ball.faces);
        QVERIFY(volume > 0.97 * 4.0 / 3.0 * M_PI && volume < 4.0 / 3.0 * M_PI);
        QVERIFY(std::abs(totalMass(scene) - 100.0 * volume) < 1e-9 * totalMass(scene));
        // every particle is a lattice node: on the grid, no two at one place
        std::set<std::array<long, 3>> nodes;
        for (const core::ParticleDesc &p : scene.particles)
            nodes.insert({std::lround(p.position.x() * 1e6), std::lround(p.position.y() * 1e6), std::lround(p.position.z() * 1e6)});
        QCOMPARE(nodes.size(), scene.particles.size());
        // the inside is filled: about the ball's volume over a cell's, and no more than its box's
        QVERIFY(double(scene.particles.size()) > volume / (0.25 * 0.25 * 0.25));
        QVERIFY(double(scene.particles.size()) < 11.0 * 11.0 * 11.0);
        // springs to lattice neighbours only: along an edge, a face's or a cell's diagonal
        for (const core::SpringDesc &s : scene.springs) {
            const double l = s.restLength / 0.25;
            QVERIFY(std::abs(l - 1.0) < 1e-9 || std::abs(l - std::sqrt(2.0)) < 1e-9 || std::abs(l - std::sqrt(3.0)) < 1e-9);
        }
        // the surface rides on the lattice: at rest its vertices are where the file has them
        const core::MeshDesc &mesh = scene.meshes[0];
        QCOMPARE(mesh.vertexCount(), int(ball.vertices.size()));
        QCOMPARE(mesh.faces.size(), ball.faces.size());
        Eigen::Matrix3Xd at;
        core::meshVertexPositions(mesh, positionsOf(scene), at);
        QVERIFY(maxDistance(at, ball.vertices) < 1e-12);
        QVERIFY(!core::findProblem(scene));
        // and moves with it: the whole lattice moved moves the surface as much
        Eigen::Matrix3Xd moved = positionsOf(scene);
        moved.colwise() += Eigen::Vector3d(0.5, -2.0, 1.0);
        core::meshVertexPositions(mesh, moved, at);
        std::vector<Eigen::Vector3d> expected = ball.vertices;
        for (Eigen::Vector3d &v : expected)
            v += Eigen::Vector3d(0.5, -2.0, 1.0);
        QVERIFY(maxDistance(at, expected) < 1e-12);
    }

    void softBodyLimits()
    {
        core::SceneDesc scene;
        auto options = as(core::MeshKind::Soft);
        options.spacing = 1e-4;  // a lattice of 2 × 10^4 a side
        const core::MeshImportResult fine = core::addMeshToScene(scene, test::icosphere(1), options);
        QVERIFY(!fine.ok());
        QVERIFY2(fine.error.find("choose a larger spacing") != std::string::npos, fine.error.c_str());
        QVERIFY(scene.particles.empty());
    }

    void placementAndItsInverse()
    {
        // a z-up file, scaled by 0.01 (centimetres), its box's bottom centre put at (1, 2, 3)
        core::SceneDesc scene;
        auto options = as(core::MeshKind::Cloth);
        options.placement.scale = 0.01;
        options.placement.zUp = true;
        options.placement.at = Eigen::Vector3d(1.0, 2.0, 3.0);
        core::TriangleMesh file = test::panel(3, 3, 50.0);  // in the file's xz plane: z-up makes it stand
        QVERIFY(core::addMeshToScene(scene, file, options).ok());
        double lowest = 1e9, highest = -1e9;
        for (const core::ParticleDesc &p : scene.particles) {
            lowest = std::min(lowest, p.position.y());
            highest = std::max(highest, p.position.y());
        }
        QVERIFY(std::abs(lowest - 2.0) < 1e-12);
        QVERIFY(std::abs(highest - 3.0) < 1e-12);  // 100 units of 1 cm, stood up
        // the export's file space gives back the file's coordinates
        Eigen::Matrix3Xd back;
        core::meshVertexPositions(scene.meshes[0], positionsOf(scene), back, core::MeshSpace::File);
        QVERIFY(maxDistance(back, file.vertices) < 1e-9);
    }

    void pinnedSide()
    {
        core::SceneDesc scene;
        auto options = as(core::MeshKind::Cloth);
        options.pin = core::PinSide::Left;
        QVERIFY(core::addMeshToScene(scene, test::panel(4, 5, 0.1), options).ok());
        int pinned = 0;
        for (const core::ParticleDesc &p : scene.particles) {
            QCOMPARE(p.pinned, p.position.x() == 0.0);
            pinned += p.pinned;
        }
        QCOMPARE(pinned, 4);
    }

    void badMeshesChangeNothing()
    {
        core::SceneDesc scene;
        QVERIFY(core::addMeshToScene(scene, test::panel(3, 3, 0.1), as(core::MeshKind::Cloth)).ok());
        const core::SceneDesc before = scene;
        core::TriangleMesh nan = test::panel(3, 3, 0.1);
        nan.vertices[4].y() = std::nan("");
        core::TriangleMesh noFaces = test::panel(3, 3, 0.1);
        noFaces.faces.clear();
        core::TriangleMesh flat;
        flat.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
        flat.faces = {{0, 1, 2}};
        core::TriangleMesh outOfRange = test::panel(2, 2, 0.1);
        outOfRange.faces[0][1] = 99;
        for (const auto &[mesh, words] : {std::pair{nan, "not a finite number"}, std::pair{noFaces, "no triangles"},
                                          std::pair{flat, "no area"}, std::pair{outOfRange, "names vertex 99"}}) {
            const core::MeshImportResult result = core::addMeshToScene(scene, mesh, as(core::MeshKind::Cloth));
            QVERIFY(!result.ok());
            QVERIFY2(result.error.find(words) != std::string::npos, result.error.c_str());
            QVERIFY(scene == before);
        }
        auto scaled = as(core::MeshKind::Cloth);
        scaled.placement.scale = -1.0;
        QVERIFY(!core::addMeshToScene(scene, test::panel(2, 2, 0.1), scaled).ok());
        QVERIFY(scene == before);
    }

    void importedBodiesRunWithoutGainingEnergy()
    {
        // a soft ball dropped on a floor and a cloth draped on a collider: neither gains energy
        // from its springs (the sub-steps the import chose keep them stable)
        for (const core::MeshKind kind : {core::MeshKind::Soft, core::MeshKind::Cloth}) {
            core::SceneDesc scene;
            auto options = as(kind);
            options.spacing = 0.2;
            options.placement.at = Eigen::Vector3d(0.0, 0.5, 0.0);
            QVERIFY(core::sceneFromMesh(scene, kind == core::MeshKind::Soft ? test::icosphere(2, 0.5) : test::panel(8, 8, 0.1), options).ok());
            if (kind == core::MeshKind::Cloth) {
                auto table = as(core::MeshKind::Collider);
                table.placement.at = Eigen::Vector3d(0.0, 0.0, 0.0);
                QVERIFY(core::addMeshToScene(scene, test::splitCube(0.4), table).ok());
            }
            const auto model = core::compileModel(scene);
            core::State state = core::makeState(*model, scene);
            core::Workspace work;
            const double start = core::energies(*model, state).total();
            double most = start;
            for (int s = 0; s < 300; ++s) {
                QVERIFY(core::step(*model, state, work));
                most = std::max(most, core::energies(*model, state).total());
            }
            const double scale = std::abs(start) + 1.0;
            QVERIFY2(most <= start + 1e-3 * scale,
                     qPrintable(QStringLiteral("%1: %2 J, from %3 J").arg(int(kind)).arg(most).arg(start)));
            QVERIFY(state.position.allFinite());
            if (kind == core::MeshKind::Cloth) {
                // the cloth lies on the table (top at 0.4 m, x and z from -0.2 to 0.2 m) where it
                // is over it, and hangs down its sides
                int over = 0;
                for (int i = 0; i < 64; ++i) {
                    const Eigen::Vector3d x = state.position.col(i);
                    if (std::abs(x.x()) < 0.19 && std::abs(x.z()) < 0.19) {
                        ++over;
                        QVERIFY2(x.y() > 0.4 && x.y() < 0.43, qPrintable(QString::number(x.y())));
                    }
                }
                QCOMPARE(over, 16);
                QVERIFY2(state.position.row(1).head(64).minCoeff() < 0.35, qPrintable(QString::number(state.position.row(1).head(64).minCoeff())));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestMeshImport)
#include "test_mesh_import.moc"
