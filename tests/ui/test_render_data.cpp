// Packing a snapshot for drawing, without GL: colours by strain and by pin and selection, the
// sizes of the packed arrays, when the style must be uploaded again, and the decoration geometry
// (a bounded plane drawn as exactly its rectangle, wherever the scene is; the ground grid on the
// floors alone, in their planes).

#include "ui/viewport/render_data.h"

#include "pool_planes.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <map>
#include <set>

namespace {

// three particles (the middle one pinned) and two springs, one compressed and one stretched
core::Snapshot threeParticles()
{
    core::Snapshot s;
    s.positions = {0.0f, 1.0f, 0.0f, 1.0f, 1.0f, 0.0f, 3.0f, 2.0f, -1.0f};
    s.radii = {0.1f, 0.2f, 0.3f};
    s.pinned = {0, 1, 0};
    s.springEnds = {0.0f, 1.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f, 1.0f, 0.0f, 3.0f, 2.0f, -1.0f};
    s.springStrain = {-0.05f, 0.5f};
    return s;
}

bool near(const ui::Rgb &a, const ui::Rgb &b, float tolerance = 1e-6f)
{
    return std::abs(a[0] - b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance &&
           std::abs(a[2] - b[2]) <= tolerance;
}

// a rectangle, and the box around its corners worked out by hand (boxKnown false when it is
// tilted: then only the general checks apply)
struct RectangleCase {
    QVector3D normal;
    double offset = 0.0;
    QPointF size;
    QVector3D centre;
    QVector3D axis;
    QVector3D low;
    QVector3D high;
    bool boxKnown = false;
};

}  // namespace

Q_DECLARE_METATYPE(RectangleCase)

class TestRenderData : public QObject {
    Q_OBJECT

private slots:
    void strainColours_data();
    void strainColours();
    void strainColourGrowsWithStrain();
    void styleColoursByPinAndSelection();
    void styleIgnoresSelectionOutOfRange();
    void onlyTheParticlesDrawnAreGathered();
    void styleKeyNoticesWhatChangesTheStyle();
    void springLines();
    void brokenSpringsAreNotDrawn();
    void springLinesOfAnEmptySnapshot();
    void boundsHoldEverySphere();
    void niceSteps_data();
    void niceSteps();
    void gridLiesOnItsPlaneAroundTheScene();
    void floorGridsLieOnFloorsOnly_data();
    void floorGridsLieOnFloorsOnly();
    void floorGridOnARectangleStaysWithinIt();
    void planeQuadsLieOnTheirPlanes();
    void planeQuadsMeetAtTheWalls();
    void aViewTakesInTheFloorWallsCloseIn();
    void rectanglesAreDrawnAsThemselves_data();
    void rectanglesAreDrawnAsThemselves();
    void icosphereIsAClosedOutwardUnitSphere_data();
    void icosphereIsAClosedOutwardUnitSphere();
};

void TestRenderData::strainColours_data()
{
    QTest::addColumn<float>("strain");
    QTest::addColumn<ui::Rgb>("expected");
    QTest::newRow("rest") << 0.0f << ui::kRestColour;
    QTest::newRow("fully compressed") << -ui::kFullStrain << ui::kCompressedColour;
    QTest::newRow("beyond compressed") << -0.9f << ui::kCompressedColour;
    QTest::newRow("fully stretched") << ui::kFullStrain << ui::kStretchedColour;
    QTest::newRow("beyond stretched") << 4.0f << ui::kStretchedColour;
    QTest::newRow("not a number") << std::numeric_limits<float>::quiet_NaN() << ui::kRestColour;
    QTest::newRow("infinite") << std::numeric_limits<float>::infinity() << ui::kRestColour;
}

void TestRenderData::strainColours()
{
    QFETCH(float, strain);
    QFETCH(ui::Rgb, expected);
    QVERIFY(near(ui::strainColour(strain), expected));
}

void TestRenderData::strainColourGrowsWithStrain()
{
    // compressed springs get bluer, stretched ones redder, the more so the larger the strain
    float lastBlueExcess = 0.0f;
    float lastRedExcess = 0.0f;
    for (int k = 1; k <= 10; ++k) {
        const float strain = ui::kFullStrain * float(k) / 10.0f;
        const ui::Rgb compressed = ui::strainColour(-strain);
        const ui::Rgb stretched = ui::strainColour(strain);
        QCOMPARE_GT(compressed[2] - compressed[0], lastBlueExcess);
        QCOMPARE_GT(stretched[0] - stretched[2], lastRedExcess);
        lastBlueExcess = compressed[2] - compressed[0];
        lastRedExcess = stretched[0] - stretched[2];
    }

    // a smaller full scale saturates sooner
    QVERIFY(near(ui::strainColour(0.01f, 0.01f), ui::kStretchedColour));
}

void TestRenderData::styleColoursByPinAndSelection()
{
    const core::Snapshot s = threeParticles();

    // no selection: free, pinned, free
    const ui::ParticleStyle plain = ui::packParticleStyle(s, {});
    QCOMPARE(plain.count(), 3);
    QCOMPARE(plain.values.size(), std::size_t(3 * ui::kStyleFloats));
    QVERIFY(near(plain.colour(0), ui::kFreeColour));
    QVERIFY(near(plain.colour(1), ui::kPinnedColour));
    QVERIFY(near(plain.colour(2), ui::kFreeColour));
    QCOMPARE(plain.radius(2), 0.3f);
    QVERIFY(!plain.pinned(0) && plain.pinned(1) && !plain.pinned(2));
    QVERIFY(!plain.selected(0) && !plain.selected(1) && !plain.selected(2));

    // the palette tells them apart
    QVERIFY(!near(ui::kFreeColour, ui::kPinnedColour, 0.1f));
    QVERIFY(!near(ui::kFreeColour, ui::kSelectedColour, 0.1f));
    QVERIFY(!near(ui::kPinnedColour, ui::kSelectedColour, 0.1f));

    // selecting the pinned one and the last: the selection colour, the pin mark kept
    const ui::ParticleStyle selected = ui::packParticleStyle(s, {2, 1});
    QVERIFY(near(selected.colour(0), ui::kFreeColour));
    QVERIFY(near(selected.colour(1), ui::kSelectedColour));
    QVERIFY(near(selected.colour(2), ui::kSelectedColour));
    QVERIFY(selected.pinned(1) && selected.selected(1));
    QVERIFY(!selected.pinned(2) && selected.selected(2));
}

void TestRenderData::styleIgnoresSelectionOutOfRange()
{
    const core::Snapshot s = threeParticles();
    const ui::ParticleStyle style = ui::packParticleStyle(s, {-1, 3, 1000});
    QCOMPARE(style.count(), 3);
    for (int i = 0; i < 3; ++i)
        QVERIFY(!style.selected(i));
    QCOMPARE(ui::packParticleStyle(core::Snapshot{}, {0}).count(), 0);
}

void TestRenderData::onlyTheParticlesDrawnAreGathered()
{
    // four particles, a sheet hides 1 and 2, 2 is selected: 0, 2 and 3 drawn
    core::Snapshot s;
    s.positions = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};
    s.radii = {0.1f, 0.2f, 0.3f, 0.4f};
    s.pinned = {0, 0, 0, 0};
    const ui::ParticleStyle style = ui::packParticleStyle(s, {2}, -1, {0, 1, 1, 0});
    const ui::DrawnParticles drawn = ui::drawnParticles(style);
    QVERIFY(!drawn.all);
    QCOMPARE(drawn.rows, (std::vector<std::uint32_t>{0, 2, 3}));
    std::vector<float> gathered;
    ui::gatherRows(s.positions.data(), 3, drawn.rows, gathered);
    QCOMPARE(gathered, (std::vector<float>{0, 0, 0, 2, 2, 2, 3, 3, 3}));
    ui::gatherRows(style.values.data(), ui::kStyleFloats, drawn.rows, gathered);
    QCOMPARE(gathered.size(), std::size_t(3 * ui::kStyleFloats));
    QCOMPARE(gathered[ui::kStyleFloats], 0.3f);  // particle 2's radius, now second

    // nothing hidden: all, and no list to gather by; everything hidden: an empty list
    const ui::DrawnParticles every = ui::drawnParticles(ui::packParticleStyle(s, {}));
    QVERIFY(every.all);
    QVERIFY(every.rows.empty());
    const ui::DrawnParticles none = ui::drawnParticles(ui::packParticleStyle(s, {}, -1, {1, 1, 1, 1}));
    QVERIFY(!none.all);
    QVERIFY(none.rows.empty());
}

void TestRenderData::styleKeyNoticesWhatChangesTheStyle()
{
    const core::Snapshot s = threeParticles();
    ui::StyleKey key;
    QVERIFY(!key.matches(s));
    key.remember(s);
    QVERIFY(key.matches(s));

    // moving particles or straining springs needs no new style
    core::Snapshot moved = s;
    moved.positions[0] += 1.0f;
    moved.springStrain[0] = 0.3f;
    moved.step = 7;
    QVERIFY(key.matches(moved));

    // a radius, a pin or the count does
    core::Snapshot grown = s;
    grown.radii[1] = 0.25f;
    QVERIFY(!key.matches(grown));
    core::Snapshot unpinned = s;
    unpinned.pinned[1] = 0;
    QVERIFY(!key.matches(unpinned));
    core::Snapshot more = s;
    more.positions.insert(more.positions.end(), {5.0f, 5.0f, 5.0f});
    more.radii.push_back(0.1f);
    more.pinned.push_back(0);
    QVERIFY(!key.matches(more));

    key.clear();
    QVERIFY(!key.matches(s));
}

void TestRenderData::springLines()
{
    const core::Snapshot s = threeParticles();
    std::vector<float> lines{1.0f, 2.0f};  // whatever was there is replaced
    ui::packSpringLines(s, lines);
    QCOMPARE(lines.size(), std::size_t(2 * 2 * ui::kVertexFloats));

    // each spring's two ends, in the spring's colour, opaque
    for (int spring = 0; spring < 2; ++spring) {
        const ui::Rgb expected = ui::strainColour(s.springStrain[spring]);
        for (int end = 0; end < 2; ++end) {
            const float *v = lines.data() + (2 * spring + end) * ui::kVertexFloats;
            for (int k = 0; k < 3; ++k)
                QCOMPARE(v[k], s.springEnds[6 * spring + 3 * end + k]);
            QVERIFY(near({v[3], v[4], v[5]}, expected));
            QCOMPARE(v[6], 1.0f);
        }
    }

    // the compressed one is bluish, the stretched one fully red
    QCOMPARE_GT(lines[5], lines[3]);
    QVERIFY(near({lines[2 * ui::kVertexFloats + 3], lines[2 * ui::kVertexFloats + 4], lines[2 * ui::kVertexFloats + 5]},
                 ui::kStretchedColour));
}

void TestRenderData::brokenSpringsAreNotDrawn()
{
    core::Snapshot s = threeParticles();
    s.springBroken = {1, 0};
    std::vector<float> lines;
    ui::packSpringLines(s, lines);
    // only the second spring's two ends
    QCOMPARE(lines.size(), std::size_t(2 * ui::kVertexFloats));
    for (int end = 0; end < 2; ++end)
        for (int k = 0; k < 3; ++k)
            QCOMPARE(lines[std::size_t(end * ui::kVertexFloats + k)], s.springEnds[6 + 3 * end + k]);
}

void TestRenderData::springLinesOfAnEmptySnapshot()
{
    std::vector<float> lines(10, 1.0f);
    ui::packSpringLines(core::Snapshot{}, lines);
    QVERIFY(lines.empty());
}

void TestRenderData::boundsHoldEverySphere()
{
    const core::Snapshot s = threeParticles();
    const ui::Sphere bounds = ui::particleBounds(s);
    for (int i = 0; i < 3; ++i) {
        const QVector3D p(s.positions[3 * i], s.positions[3 * i + 1], s.positions[3 * i + 2]);
        QCOMPARE_LE((p - bounds.centre).length() + s.radii[i], bounds.radius * (1.0f + 1e-6f));
    }

    // not much larger than it has to be: within the box's half diagonal plus the largest radius
    const float halfDiagonal = QVector3D(3.0f, 1.0f, 1.0f).length() / 2.0f;
    QCOMPARE_LE(bounds.radius, halfDiagonal + 0.3f + 1e-5f);
    QCOMPARE(ui::particleBounds(core::Snapshot{}).radius, 0.0f);

    // a particle that blew up is left out
    core::Snapshot blown = s;
    blown.positions[3] = std::numeric_limits<float>::quiet_NaN();
    blown.positions[7] = std::numeric_limits<float>::infinity();
    const ui::Sphere rest = ui::particleBounds(blown);
    QVERIFY(std::isfinite(rest.centre.x()) && std::isfinite(rest.centre.y()) && std::isfinite(rest.radius));
    QCOMPARE_LT((rest.centre - QVector3D(0.0f, 1.0f, 0.0f)).length(), 1e-6f);
    QCOMPARE(rest.radius, 0.1f);
}

void TestRenderData::niceSteps_data()
{
    QTest::addColumn<float>("length");
    QTest::addColumn<float>("step");
    QTest::newRow("1") << 1.0f << 1.0f;
    QTest::newRow("1.9") << 1.9f << 1.0f;
    QTest::newRow("3") << 3.0f << 2.0f;
    QTest::newRow("7") << 7.0f << 5.0f;
    QTest::newRow("0.03") << 0.03f << 0.02f;
    QTest::newRow("250") << 250.0f << 200.0f;
    QTest::newRow("zero") << 0.0f << 1.0f;
}

void TestRenderData::niceSteps()
{
    QFETCH(float, length);
    QFETCH(float, step);
    QCOMPARE_LT(std::abs(ui::niceStep(length) - step), 1e-5f * step);
}

void TestRenderData::gridLiesOnItsPlaneAroundTheScene()
{
    const ui::Sphere scene{QVector3D(3.0f, 2.0f, -1.0f), 2.0f};
    const std::vector<float> grid = ui::packGrid(scene, -0.5f);
    QCOMPARE(grid.size() % (2 * ui::kVertexFloats), std::size_t(0));
    QCOMPARE_GT(grid.size(), std::size_t(0));

    // every vertex on the plane y = -0.5, and the grid reaches past the scene on every side
    float minX = 1e9f, maxX = -1e9f, minZ = 1e9f, maxZ = -1e9f;
    for (std::size_t v = 0; v < grid.size(); v += ui::kVertexFloats) {
        QCOMPARE(grid[v + 1], -0.5f);
        minX = std::min(minX, grid[v]);
        maxX = std::max(maxX, grid[v]);
        minZ = std::min(minZ, grid[v + 2]);
        maxZ = std::max(maxZ, grid[v + 2]);
    }
    QCOMPARE_LT(minX, scene.centre.x() - scene.radius);
    QCOMPARE_GT(maxX, scene.centre.x() + scene.radius);
    QCOMPARE_LT(minZ, scene.centre.z() - scene.radius);
    QCOMPARE_GT(maxZ, scene.centre.z() + scene.radius);
}

namespace {

core::PlaneDesc planeOf(const Eigen::Vector3d &normal, double offset)
{
    core::PlaneDesc plane;
    plane.normal = normal.normalized();
    plane.offset = offset;
    return plane;
}

}  // namespace

void TestRenderData::floorGridsLieOnFloorsOnly_data()
{
    // the planes, and which of them carry a grid
    QTest::addColumn<std::vector<core::PlaneDesc>>("planes");
    QTest::addColumn<std::vector<int>>("floors");
    const Eigen::Vector3d tilted5(std::sin(5.0 * std::numbers::pi / 180.0), std::cos(5.0 * std::numbers::pi / 180.0), 0.0);
    const Eigen::Vector3d tilted20(std::sin(20.0 * std::numbers::pi / 180.0), std::cos(20.0 * std::numbers::pi / 180.0), 0.0);
    QTest::newRow("no planes") << std::vector<core::PlaneDesc>{} << std::vector<int>{};
    QTest::newRow("a wall") << std::vector{planeOf({1, 0, 0}, -2.0)} << std::vector<int>{};
    QTest::newRow("a ceiling") << std::vector{planeOf({0, -1, 0}, -3.0)} << std::vector<int>{};
    QTest::newRow("a slope of 20°") << std::vector{planeOf(tilted20, 0.0)} << std::vector<int>{};
    QTest::newRow("a floor below") << std::vector{planeOf({0, 1, 0}, -0.5)} << std::vector<int>{0};
    QTest::newRow("a floor tilted 5°") << std::vector{planeOf(tilted5, 0.2)} << std::vector<int>{0};
    QTest::newRow("a wall and two floors")
        << std::vector{planeOf({0, 0, 1}, -4.0), planeOf({0, 1, 0}, -1.0), planeOf({0, 1, 0}, 2.5)}
        << std::vector<int>{1, 2};
}

void TestRenderData::floorGridsLieOnFloorsOnly()
{
    QFETCH(std::vector<core::PlaneDesc>, planes);
    QFETCH(std::vector<int>, floors);
    const ui::Sphere scene{QVector3D(3.0f, 2.0f, -1.0f), 2.0f};
    const std::vector<float> grid = ui::packFloorGrids(planes, scene);
    QCOMPARE(grid.size() % (2 * ui::kVertexFloats), std::size_t(0));
    if (floors.empty()) {
        QCOMPARE(grid.size(), std::size_t(0));
        return;
    }

    // every vertex a hair above one of the floors, within its plane, and every floor gets lines
    // reaching past the scene on every side, seen from above
    std::map<int, int> vertices;
    std::map<int, std::array<float, 4>> reach;  // min x, max x, min z, max z
    for (std::size_t v = 0; v < grid.size(); v += ui::kVertexFloats) {
        const Eigen::Vector3d p(grid[v], grid[v + 1], grid[v + 2]);
        int on = -1;
        for (const int f : floors) {
            const double above = planes[std::size_t(f)].normal.dot(p) - planes[std::size_t(f)].offset;
            if (above > 0.0 && above < 1e-3)
                on = f;
        }
        QVERIFY2(on >= 0, qPrintable(QStringLiteral("(%1, %2, %3) on no floor").arg(p.x()).arg(p.y()).arg(p.z())));
        ++vertices[on];
        auto [found, made] = reach.try_emplace(on, std::array<float, 4>{1e9f, -1e9f, 1e9f, -1e9f});
        std::array<float, 4> &r = found->second;
        r = {std::min(r[0], float(p.x())), std::max(r[1], float(p.x())), std::min(r[2], float(p.z())),
             std::max(r[3], float(p.z()))};
    }
    QCOMPARE(vertices.size(), floors.size());
    for (const auto &[f, r] : reach) {
        QCOMPARE_LT(r[0], scene.centre.x() - scene.radius);
        QCOMPARE_GT(r[1], scene.centre.x() + scene.radius);
        QCOMPARE_LT(r[2], scene.centre.z() - scene.radius);
        QCOMPARE_GT(r[3], scene.centre.z() + scene.radius);
    }
}

void TestRenderData::floorGridOnARectangleStaysWithinIt()
{
    // a table top 3 m × 1 m at y = 0.8, its width along x + z: the grid's lines run across it
    // within its edges, as many as fit, and none leaves its plane
    core::PlaneDesc table = planeOf({0, 1, 0}, 0.8);
    table.size = {3.0, 1.0};
    table.centre = {1.0, 0.8, -2.0};
    table.axis = {1.0, 0.0, 1.0};
    const ui::Sphere scene{QVector3D(1.0f, 1.0f, -2.0f), 1.5f};
    const std::vector<float> grid = ui::packFloorGrids({table}, scene);
    QCOMPARE_GT(grid.size(), std::size_t(0));
    const QVector3D centre(1.0f, 0.8f, -2.0f);
    const QVector3D along = QVector3D(1.0f, 0.0f, 1.0f).normalized();
    const QVector3D across = QVector3D::crossProduct(QVector3D(0.0f, 1.0f, 0.0f), along);
    float maxAlong = 0.0f, maxAcross = 0.0f;
    for (std::size_t v = 0; v < grid.size(); v += ui::kVertexFloats) {
        const QVector3D p(grid[v], grid[v + 1], grid[v + 2]);
        QCOMPARE_GT(p.y(), 0.8f);
        QCOMPARE_LT(p.y(), 0.801f);
        const float a = std::abs(QVector3D::dotProduct(p - centre, along));
        const float b = std::abs(QVector3D::dotProduct(p - centre, across));
        QCOMPARE_LT(a, 1.5f + 1e-4f);
        QCOMPARE_LT(b, 0.5f + 1e-4f);
        maxAlong = std::max(maxAlong, a);
        maxAcross = std::max(maxAcross, b);
    }
    // out to its edges
    QCOMPARE_GT(maxAlong, 1.5f - 1e-4f);
    QCOMPARE_GT(maxAcross, 0.5f - 1e-4f);
}

void TestRenderData::planeQuadsLieOnTheirPlanes()
{
    const ui::Sphere scene{QVector3D(1.0f, 4.0f, 2.0f), 3.0f};
    std::vector<core::PlaneDesc> planes(3);
    planes[0].normal = {0.0, 1.0, 0.0};
    planes[0].offset = -1.0;
    planes[1].normal = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
    planes[1].offset = 0.5;
    planes[2].normal = {0.0, 0.0, -1.0};
    planes[2].offset = 4.0;
    // (two-sided, and the third with the scene behind it: no plane here walls the scene in, so
    // none cuts another's square, which planeQuadsMeetAtTheWalls covers)
    planes[0].twoSided = planes[1].twoSided = true;
    const std::vector<float> quads = ui::packPlaneQuads(planes, scene);
    QCOMPARE(quads.size(), std::size_t(3 * 6 * ui::kVertexFloats));

    for (int p = 0; p < 3; ++p) {
        const QVector3D n(float(planes[p].normal.x()), float(planes[p].normal.y()), float(planes[p].normal.z()));
        QVector3D sum;
        for (int v = 0; v < 6; ++v) {
            const float *f = quads.data() + (6 * p + v) * ui::kVertexFloats;
            const QVector3D corner(f[0], f[1], f[2]);
            QCOMPARE_LT(std::abs(QVector3D::dotProduct(n, corner) - float(planes[p].offset)), 1e-4f);
            QCOMPARE(f[6], ui::kPlaneAlpha);
            sum += corner;
        }

        // centred where the scene's centre drops onto the plane, and wider than the scene
        const QVector3D foot = scene.centre - (QVector3D::dotProduct(n, scene.centre) - float(planes[p].offset)) * n;
        const QVector3D first(quads[(6 * p) * ui::kVertexFloats], quads[(6 * p) * ui::kVertexFloats + 1],
                              quads[(6 * p) * ui::kVertexFloats + 2]);
        QCOMPARE_LT((sum / 6.0f - foot).length(), 1e-3f + (first - foot).length());
        QCOMPARE_GT((first - foot).length(), scene.radius);
    }
}

void TestRenderData::aViewTakesInTheFloorWallsCloseIn()
{
    // the pool: a floor and four walls 5 m from the middle around two balls
    const std::vector<core::PlaneDesc> planes = test::poolPlanes();
    const ui::Sphere balls{QVector3D(1.0f, 0.3f, -0.5f), 1.5f};
    const ui::Sphere pool = ui::withEnclosedFloors(planes, balls);
    // the floor's four corners and the balls inside, and not much more: the table's half-diagonal
    // is 7.07 m
    for (const QVector3D corner : {QVector3D(5, 0, 5), QVector3D(-5, 0, 5), QVector3D(5, 0, -5), QVector3D(-5, 0, -5)})
        QCOMPARE_LE((corner - pool.centre).length(), pool.radius + 1e-3f);
    QCOMPARE_LE((balls.centre - pool.centre).length() + balls.radius, pool.radius + 1e-3f);
    QCOMPARE_LT(pool.radius, 8.0f);

    // a wall missing, a floor alone, walls without a floor, a table top: the scene's bounds as they are
    auto same = [&](const std::vector<core::PlaneDesc> &some) {
        const ui::Sphere framed = ui::withEnclosedFloors(some, balls);
        return framed.centre == balls.centre && framed.radius == balls.radius;
    };
    QVERIFY(same({planes[0], planes[1], planes[2], planes[3]}));
    QVERIFY(same({planes[0]}));
    QVERIFY(same({planes[1], planes[2], planes[3], planes[4]}));
    QVERIFY(same({}));
    std::vector<core::PlaneDesc> table = planes;
    table[0].size = {4.0, 4.0};
    table[0].axis = {1.0, 0.0, 0.0};
    QVERIFY(table[0].bounded());
    QVERIFY(same(table));
}

void TestRenderData::planeQuadsMeetAtTheWalls()
{
    // the pool: a floor and four walls 5 m from the middle, two balls 2 m out. The floor reaches
    // the walls and stops there; each wall stands on the floor and ends at its neighbours
    const std::vector<core::PlaneDesc> planes = test::poolPlanes();
    const ui::Sphere scene{QVector3D(0.0f, 0.5f, 0.25f), 2.6f};
    const std::vector<float> quads = ui::packPlaneQuads(planes, scene);
    QCOMPARE(quads.size() % (3 * ui::kVertexFloats), std::size_t(0));
    const std::size_t count = quads.size() / ui::kVertexFloats;
    QVERIFY(count >= 5 * 6);

    // every corner on its plane and inside the pool; the floor's out to the walls on every side
    float floorX = 0.0f, floorZ = 0.0f, wallBottom = 1e9f;
    for (std::size_t v = 0; v < count; ++v) {
        const float *f = quads.data() + v * ui::kVertexFloats;
        QCOMPARE_LE(std::abs(f[0]), 5.0f + 1e-4f);
        QCOMPARE_LE(std::abs(f[2]), 5.0f + 1e-4f);
        QCOMPARE_GE(f[1], -1e-4f);
        if (std::abs(f[1]) < 1e-4f) {
            floorX = std::max(floorX, std::abs(f[0]));
            floorZ = std::max(floorZ, std::abs(f[2]));
        }
        if (std::abs(std::abs(f[0]) - 5.0f) < 1e-4f)
            wallBottom = std::min(wallBottom, f[1]);
    }
    QCOMPARE_GT(floorX, 5.0f - 1e-4f);  // before: the floor ended at 3.9 m, short of the walls
    QCOMPARE_GT(floorZ, 5.0f - 1e-4f);
    QCOMPARE_LT(wallBottom, 1e-4f);  // and the walls stood 3.4 m below the floor

    // its grid ends at the walls too (it ran on to 6.3 m), and still reaches them
    const std::vector<float> grid = ui::packFloorGrids(planes, scene);
    QVERIFY(!grid.empty());
    float gridX = 0.0f;
    for (std::size_t v = 0; v < grid.size() / ui::kVertexFloats; ++v) {
        const float *f = grid.data() + v * ui::kVertexFloats;
        QCOMPARE_LE(std::abs(f[0]), 5.0f + 1e-4f);
        QCOMPARE_LE(std::abs(f[2]), 5.0f + 1e-4f);
        gridX = std::max(gridX, std::abs(f[0]));
    }
    QCOMPARE_GT(gridX, 5.0f - 1e-3f);
}

void TestRenderData::rectanglesAreDrawnAsThemselves_data()
{
    QTest::addColumn<RectangleCase>("rectangle");

    // a table top at y = 1, 2 m along x and 1 m along z, centred over (3, ·, 0)
    QTest::newRow("table, width along x")
        << RectangleCase{{0, 1, 0}, 1.0, {2, 1}, {3, 5, 0}, {1, 0, 0}, {2, 1, -0.5}, {4, 1, 0.5}, true};
    // the default axis of a floor is n × x = -z: the width runs along z
    QTest::newRow("table, default axis")
        << RectangleCase{{0, 1, 0}, 1.0, {2, 1}, {0, 0, 0}, {0, 0, 0}, {-0.5, 1, -1}, {0.5, 1, 1}, true};
    // an axis along the normal says nothing either
    QTest::newRow("axis along the normal")
        << RectangleCase{{0, 2, 0}, 1.0, {2, 1}, {0, 0, 0}, {0, -3, 0}, {-0.5, 1, -1}, {0.5, 1, 1}, true};
    // a wall x = -2, 4 wide along z and 3 high, its centre dropped onto it from outside
    QTest::newRow("wall")
        << RectangleCase{{1, 0, 0}, -2.0, {4, 3}, {7, 1.5, 0}, {0.5, 0, 2}, {-2, 0, -2}, {-2, 3, 2}, true};
    QTest::newRow("tilted") << RectangleCase{{0, 0.8f, -0.6f}, 0.25, {1.5, 0.5}, {1, 2, 3}, {1, 1, 1}, {}, {}, false};
}

void TestRenderData::rectanglesAreDrawnAsThemselves()
{
    QFETCH(RectangleCase, rectangle);
    const QVector3D normal = rectangle.normal.normalized();
    const float offset = float(rectangle.offset);
    core::PlaneDesc plane;
    plane.normal = Eigen::Vector3d(rectangle.normal.x(), rectangle.normal.y(), rectangle.normal.z()).normalized();
    plane.offset = rectangle.offset;
    plane.size = {rectangle.size.x(), rectangle.size.y()};
    plane.centre = {rectangle.centre.x(), rectangle.centre.y(), rectangle.centre.z()};
    plane.axis = {rectangle.axis.x(), rectangle.axis.y(), rectangle.axis.z()};

    // the same quad wherever the scene is and however large it is
    const std::vector<float> quads = ui::packPlaneQuads({plane}, ui::Sphere{QVector3D(0, 0, 0), 1.0f});
    const std::vector<float> far = ui::packPlaneQuads({plane}, ui::Sphere{QVector3D(100, -50, 20), 300.0f});
    QCOMPARE(quads.size(), std::size_t(6 * ui::kVertexFloats));
    QVERIFY(quads == far);

    // two triangles a b c, a c d over the four corners, all on the plane
    std::vector<QVector3D> corners;
    for (int v = 0; v < 6; ++v) {
        const float *f = quads.data() + v * ui::kVertexFloats;
        corners.emplace_back(f[0], f[1], f[2]);
        QCOMPARE(f[6], ui::kPlaneAlpha);
        QCOMPARE_LT(std::abs(QVector3D::dotProduct(normal, corners.back()) - offset), 1e-5f);
    }
    QCOMPARE(corners[3], corners[0]);
    QCOMPARE(corners[4], corners[2]);
    const QVector3D a = corners[0], b = corners[1], c = corners[2], d = corners[5];

    // sides of the given size, at right angles
    QCOMPARE_LT(std::abs((b - a).length() - float(rectangle.size.x())), 1e-5f);
    QCOMPARE_LT(std::abs((c - b).length() - float(rectangle.size.y())), 1e-5f);
    QCOMPARE_LT(std::abs(QVector3D::dotProduct(b - a, c - b)), 1e-5f);
    QCOMPARE_LT(((a + c) * 0.5f - (b + d) * 0.5f).length(), 1e-5f);

    // centred where the given centre drops onto the plane, the width along the axis as projected
    const QVector3D foot = rectangle.centre - (QVector3D::dotProduct(normal, rectangle.centre) - offset) * normal;
    QCOMPARE_LT(((a + c) * 0.5f - foot).length(), 1e-5f);
    const QVector3D along = rectangle.axis - QVector3D::dotProduct(rectangle.axis, normal) * normal;
    if (along.length() > 1e-6f)
        QCOMPARE_LT(std::abs(std::abs(QVector3D::dotProduct((b - a).normalized(), along.normalized())) - 1.0f), 1e-5f);

    // and, where worked out by hand, exactly there
    if (rectangle.boxKnown) {
        QVector3D lo = a, hi = a;
        for (const QVector3D &p : {b, c, d}) {
            lo = QVector3D(std::min(lo.x(), p.x()), std::min(lo.y(), p.y()), std::min(lo.z(), p.z()));
            hi = QVector3D(std::max(hi.x(), p.x()), std::max(hi.y(), p.y()), std::max(hi.z(), p.z()));
        }
        QCOMPARE_LT((lo - rectangle.low).length(), 1e-5f);
        QCOMPARE_LT((hi - rectangle.high).length(), 1e-5f);
    }
}

void TestRenderData::icosphereIsAClosedOutwardUnitSphere_data()
{
    QTest::addColumn<int>("subdivisions");
    QTest::newRow("icosahedron") << 0;
    QTest::newRow("once") << 1;
    QTest::newRow("twice") << 2;
}

void TestRenderData::icosphereIsAClosedOutwardUnitSphere()
{
    QFETCH(int, subdivisions);
    const ui::SphereMesh mesh = ui::icosphere(subdivisions);
    const std::size_t triangles = 20u << (2 * subdivisions);
    QCOMPARE(mesh.indices.size(), 3 * triangles);

    // every vertex on the unit sphere
    const std::size_t vertices = mesh.vertices.size() / 3;
    for (std::size_t v = 0; v < vertices; ++v) {
        const QVector3D p(mesh.vertices[3 * v], mesh.vertices[3 * v + 1], mesh.vertices[3 * v + 2]);
        QCOMPARE_LT(std::abs(p.length() - 1.0f), 1e-5f);
    }

    // counter-clockwise from outside, and closed: each edge shared by exactly two triangles, in
    // opposite directions, so V - E + F = 2
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directedEdges;
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t *i = mesh.indices.data() + 3 * t;
        auto point = [&](std::uint32_t k) {
            return QVector3D(mesh.vertices[3 * k], mesh.vertices[3 * k + 1], mesh.vertices[3 * k + 2]);
        };
        const QVector3D a = point(i[0]), b = point(i[1]), c = point(i[2]);
        QCOMPARE_GT(QVector3D::dotProduct(QVector3D::crossProduct(b - a, c - a), a + b + c), 0.0f);
        for (int e = 0; e < 3; ++e)
            ++directedEdges[{i[e], i[(e + 1) % 3]}];
    }
    for (const auto &[edge, count] : directedEdges) {
        QCOMPARE(count, 1);
        QVERIFY(directedEdges.count({edge.second, edge.first}) == 1);
    }
    const std::size_t edges = directedEdges.size() / 2;
    QCOMPARE(int(vertices) - int(edges) + int(triangles), 2);
}

QTEST_APPLESS_MAIN(TestRenderData)
#include "test_render_data.moc"
