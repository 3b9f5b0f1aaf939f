// The sheet of a spring mesh, without GL: the triangles drawn are those whose springs all hold,
// the particles and springs they cover, smooth normals at the current positions, and when the
// drawing must be packed again; and the hidden particles and springs left out of the packing
// unless selected or under the cursor, the highlighted springs last.

#include "ui/viewport/render_data.h"
#include "ui/viewport/surface_data.h"

#include "core/meshes/mesh_import.h"
#include "core/model/generators.h"
#include "core/model/model.h"
#include "core/model/state.h"

#include "../test_meshes.h"

#include <QtTest>

#include <algorithm>
#include <QVector3D>

namespace {

// a 3 × 3 cloth, level at y = 1: four cells, eight triangles
std::shared_ptr<core::Snapshot> clothSnapshot(core::SceneDesc *sceneOut = nullptr)
{
    core::ClothOptions options;
    options.rows = 3;
    options.cols = 3;
    const core::SceneDesc scene = core::makeCloth(options);
    if (sceneOut)
        *sceneOut = scene;
    const auto model = core::compileModel(scene);
    return std::make_shared<core::Snapshot>(*core::makeSnapshot(*model, core::makeState(*model, scene)));
}

}  // namespace

class TestSurfaceData : public QObject {
    Q_OBJECT

private slots:
    void wholeClothIsDrawnAndCoversEverything();
    void brokenSpringDropsItsTriangles();
    void normalsOfALevelClothPointUp();
    void trianglesOfAnotherSceneAreNotDrawn();
    void keyNoticesTrianglesAndBreaks();
    void hiddenParticlesHaveNoRadiusUnlessPicked();
    void hiddenSpringsAreLeftOutUnlessHighlighted();
    void softBodyIsDrawnByItsSurface();
};

void TestSurfaceData::wholeClothIsDrawnAndCoversEverything()
{
    const auto s = clothSnapshot();
    const ui::SurfaceDraw draw = ui::packSurface(*s);
    QCOMPARE(draw.triangleCount(), 8);
    QCOMPARE(draw.coveredParticles, std::vector<std::uint8_t>(9, 1));
    // every spring of a cloth, bend springs too, joins two of its corners
    QCOMPARE(draw.coveredSprings, std::vector<std::uint8_t>(std::size_t(s->springCount()), 1));
}

void TestSurfaceData::brokenSpringDropsItsTriangles()
{
    // a side of the first triangle breaks: the two triangles on it go, nothing else
    auto s = clothSnapshot();
    const int side = s->triangles->sides.front();
    s->springBroken.assign(std::size_t(s->springCount()), 0);
    s->springBroken[std::size_t(side)] = 1;
    const ui::SurfaceDraw draw = ui::packSurface(*s);
    int onSide = 0;
    for (int k : s->triangles->sides)
        onSide += k == side;
    QVERIFY(onSide == 1 || onSide == 2);
    QCOMPARE(draw.triangleCount(), 8 - onSide);

    // every spring of a corner's triangles broken: that corner is no longer covered
    s->springBroken.assign(std::size_t(s->springCount()), 0);
    for (int t = 0; t < s->triangles->count(); ++t)
        for (int c = 0; c < 3; ++c)
            if (s->triangles->corners[std::size_t(3 * t + c)] == 0)
                for (int k = 0; k < 3; ++k)
                    s->springBroken[std::size_t(s->triangles->sides[std::size_t(3 * t + k)])] = 1;
    const ui::SurfaceDraw opened = ui::packSurface(*s);
    QCOMPARE(opened.coveredParticles[0], std::uint8_t(0));
    QCOMPARE(opened.coveredParticles[4], std::uint8_t(1));
}

void TestSurfaceData::normalsOfALevelClothPointUp()
{
    auto s = clothSnapshot();
    const ui::SurfaceDraw draw = ui::packSurface(*s);
    std::vector<float> normals{7.0f};
    ui::surfaceNormals(s->positions, draw.indices, normals);
    QCOMPARE(normals.size(), std::size_t(3 * 9));
    for (int i = 0; i < 9; ++i) {
        QVERIFY(std::abs(normals[std::size_t(3 * i)]) < 1e-6f);
        QCOMPARE(normals[std::size_t(3 * i + 1)], 1.0f);
        QVERIFY(std::abs(normals[std::size_t(3 * i + 2)]) < 1e-6f);
    }

    // lift the middle: the normal of the particle beside it leans away, and stays of unit length
    s->positions[3 * 4 + 1] += 0.05f;
    ui::surfaceNormals(s->positions, draw.indices, normals);
    const float x = normals[3], y = normals[4], z = normals[5];
    QVERIFY(std::abs(std::sqrt(x * x + y * y + z * z) - 1.0f) < 1e-5f);
    QVERIFY(y < 1.0f && y > 0.5f);

    // no triangles: no normals
    ui::surfaceNormals(s->positions, {}, normals);
    QVERIFY(std::all_of(normals.begin(), normals.end(), [](float v) { return v == 0.0f; }));
}

void TestSurfaceData::trianglesOfAnotherSceneAreNotDrawn()
{
    // a snapshot with a spring fewer than its triangles know of
    auto s = clothSnapshot();
    s->springStrain.pop_back();
    s->springEnds.resize(s->springEnds.size() - 6);
    QCOMPARE(ui::packSurface(*s).triangleCount(), 0);
    QCOMPARE(ui::packSurface(core::Snapshot{}).triangleCount(), 0);
}

void TestSurfaceData::keyNoticesTrianglesAndBreaks()
{
    auto s = clothSnapshot();
    ui::SurfaceKey key;
    QVERIFY(!key.matches(*s));
    key.remember(*s);
    QVERIFY(key.matches(*s));
    auto moved = std::make_shared<core::Snapshot>(*s);
    moved->positions[0] += 1.0f;
    QVERIFY(key.matches(*moved));  // new positions need new normals, not new triangles
    auto broken = std::make_shared<core::Snapshot>(*s);
    broken->springBroken.assign(std::size_t(s->springCount()), 0);
    broken->springBroken[0] = 1;
    QVERIFY(!key.matches(*broken));
    auto other = std::make_shared<core::Snapshot>(*s);
    other->triangles = std::make_shared<core::SpringTriangles>(*s->triangles);
    QVERIFY(!key.matches(*other));
    key.clear();
    QVERIFY(!key.matches(*s));
}

void TestSurfaceData::hiddenParticlesHaveNoRadiusUnlessPicked()
{
    const auto s = clothSnapshot();
    const std::vector<std::uint8_t> hidden(9, 1);
    const ui::ParticleStyle style = ui::packParticleStyle(*s, {4}, 2, hidden);
    for (int i = 0; i < 9; ++i)
        QCOMPARE(style.radius(i), i == 4 || i == 2 ? s->radii[std::size_t(i)] : 0.0f);
    // nothing hidden: every radius
    const ui::ParticleStyle all = ui::packParticleStyle(*s, {});
    for (int i = 0; i < 9; ++i)
        QCOMPARE(all.radius(i), s->radii[std::size_t(i)]);
}

void TestSurfaceData::hiddenSpringsAreLeftOutUnlessHighlighted()
{
    const auto s = clothSnapshot();
    const int springs = s->springCount();
    std::vector<std::uint8_t> hidden(std::size_t(springs), 1);
    hidden[3] = 0;
    std::vector<float> lines;
    ui::SpringHighlight highlight;
    highlight.selected = {7};
    highlight.hover = 5;
    QCOMPARE(ui::packSpringLines(*s, lines, ui::kFullStrain, highlight, hidden), 2);
    QCOMPARE(lines.size(), std::size_t(3 * 2 * ui::kVertexFloats));

    // spring 3 in its strain's colour first, then the two highlighted ones in their colours
    auto line = [&](int i) {
        const float *v = lines.data() + 2 * i * ui::kVertexFloats;
        return std::pair{QVector3D(v[0], v[1], v[2]), ui::Rgb{v[3], v[4], v[5]}};
    };
    auto endA = [&](int k) { return QVector3D(s->springEnds[6 * k], s->springEnds[6 * k + 1], s->springEnds[6 * k + 2]); };
    QCOMPARE(line(0).first, endA(3));
    QCOMPARE(line(0).second, ui::strainColour(s->springStrain[3]));
    const bool hoverFirst = line(1).first == endA(5);
    QCOMPARE(line(hoverFirst ? 1 : 2).first, endA(5));
    QCOMPARE(line(hoverFirst ? 1 : 2).second, ui::kHoverColour);
    QCOMPARE(line(hoverFirst ? 2 : 1).first, endA(7));
    QCOMPARE(line(hoverFirst ? 2 : 1).second, ui::kSelectedColour);
}

void TestSurfaceData::softBodyIsDrawnByItsSurface()
{
    // an icosphere of radius 0.5 filled as a soft body: its 320 faces are drawn over vertices that
    // follow the particles, on the sphere, with normals pointing out; its lattice is covered
    const core::TriangleMesh sphere = test::icosphere(2, 0.5);
    core::SceneDesc scene;
    core::MeshImportOptions options;
    options.kind = core::MeshKind::Soft;
    options.spacing = 0.2;
    QVERIFY(core::addMeshToScene(scene, sphere, options).ok());
    const auto model = core::compileModel(scene);
    const auto s = core::makeSnapshot(*model, core::makeState(*model, scene));
    const ui::SurfaceDraw draw = ui::packSurface(*s);
    const int n = s->particleCount();
    QCOMPARE(draw.triangleCount(), int(sphere.faces.size()));
    QCOMPARE(draw.extraVertices, int(sphere.vertices.size()));
    QVERIFY(std::all_of(draw.indices.begin(), draw.indices.end(), [n](std::uint32_t i) { return i >= std::uint32_t(n); }));
    // the particles that carry the surface are under it (those deeper inside are hidden by it)
    for (int p : s->embedded->particles)
        QCOMPARE(draw.coveredParticles[std::size_t(p)], std::uint8_t(1));

    std::vector<float> positions, normals;
    ui::surfacePositions(*s, draw, positions);
    QCOMPARE(positions.size(), 3 * std::size_t(n + draw.extraVertices));
    ui::surfaceNormals(positions, draw.indices, normals);
    for (std::size_t v = 0; v < sphere.vertices.size(); ++v) {
        const std::size_t at = 3 * (std::size_t(n) + v);
        const QVector3D x(positions[at], positions[at + 1], positions[at + 2]);
        const QVector3D normal(normals[at], normals[at + 1], normals[at + 2]);
        QVERIFY(std::abs(x.length() - 0.5f) < 1e-5f);  // the file's vertex, carried exactly at rest
        QVERIFY(QVector3D::dotProduct(normal, x.normalized()) > 0.9f);
    }

    // the body moved: its surface with it
    core::State state = core::makeState(*model, scene);
    state.position.row(1).array() += 2.0;
    const auto moved = core::makeSnapshot(*model, state);
    QCOMPARE(moved->embeddedPositions[1], s->embeddedPositions[1] + 2.0f);
}

QTEST_APPLESS_MAIN(TestSurfaceData)
#include "test_surface_data.moc"
