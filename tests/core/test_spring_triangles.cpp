// Spring triangles: a cloth's cells each covered once by two triangles, turned alike; no triangle
// along a line (a row and its bend spring), none in a net of squares, all four faces of a solid
// tetrahedron; and every snapshot of a model shares the model's triangles.
#include "core/model/generators.h"
#include "core/model/snapshot.h"
#include "core/springs/spring_triangles.h"
#include "scene_builder.h"

#include <Eigen/Geometry>
#include <QtTest>

#include <algorithm>
#include <map>
#include <set>

class TestSpringTriangles : public QObject {
    Q_OBJECT

private slots:
    void clothCellsAreCoveredOnce_data();
    void clothCellsAreCoveredOnce();
    void neighboursAreTurnedAlike();
    void pointsOnALineMakeNoTriangle();
    void squaresWithoutDiagonalsMakeNone();
    void flatSquareWithBothDiagonalsMakesTwo();
    void solidTetrahedronKeepsAllFourFaces();
    void snapshotsShareTheModelsTriangles();
    void anEditThatKeepsTheSpringsKeepsTheTriangles();
};

namespace {

Eigen::Vector3d normalOf(const core::SceneDesc &scene, const core::SpringTriangles &t, int i)
{
    auto p = [&](int c) { return scene.particles[std::size_t(t.corners[std::size_t(3 * i + c)])].position; };
    return (p(1) - p(0)).cross(p(2) - p(0));
}

core::SceneDesc pointsJoinedPairwise(const std::vector<Eigen::Vector3d> &points)
{
    core::SceneDesc scene = test::quietScene();
    for (const Eigen::Vector3d &p : points)
        scene.particles.push_back(test::particle(p));
    for (int a = 0; a < int(points.size()); ++a)
        for (int b = a + 1; b < int(points.size()); ++b)
            scene.springs.push_back(core::SpringDesc{a, b, 10.0, 0.0, (points[std::size_t(a)] - points[std::size_t(b)]).norm()});
    return scene;
}

}  // namespace

void TestSpringTriangles::clothCellsAreCoveredOnce_data()
{
    QTest::addColumn<int>("rows");
    QTest::addColumn<int>("cols");
    QTest::newRow("2 x 2") << 2 << 2;
    QTest::newRow("5 x 7") << 5 << 7;
    QTest::newRow("16 x 16") << 16 << 16;
}

void TestSpringTriangles::clothCellsAreCoveredOnce()
{
    // two triangles per cell, each half a cell inside it, with the cell's diagonal as a side
    QFETCH(int, rows);
    QFETCH(int, cols);
    core::ClothOptions options;
    options.rows = rows;
    options.cols = cols;
    const core::SceneDesc scene = core::makeCloth(options);
    const core::SpringTriangles t = core::findSpringTriangles(scene);
    QCOMPARE(t.count(), 2 * (rows - 1) * (cols - 1));
    QCOMPARE(t.sides.size(), t.corners.size());

    // the generator numbers the particles row by row
    std::map<std::pair<int, int>, int> perCell;
    const double cellArea = options.spacing * options.spacing;
    for (int i = 0; i < t.count(); ++i) {
        int rowLo = rows, rowHi = -1, colLo = cols, colHi = -1;
        for (int c = 0; c < 3; ++c) {
            const int p = t.corners[std::size_t(3 * i + c)];
            rowLo = std::min(rowLo, p / cols);
            rowHi = std::max(rowHi, p / cols);
            colLo = std::min(colLo, p % cols);
            colHi = std::max(colHi, p % cols);
        }
        QCOMPARE(rowHi - rowLo, 1);
        QCOMPARE(colHi - colLo, 1);
        QCOMPARE(normalOf(scene, t, i).norm() * 0.5, cellArea * 0.5);
        ++perCell[{rowLo, colLo}];

        // each side is the spring that joins its two corners
        for (int s = 0; s < 3; ++s) {
            const core::SpringDesc &spring = scene.springs[std::size_t(t.sides[std::size_t(3 * i + s)])];
            const std::set<int> ends{spring.a, spring.b};
            const std::set<int> corners{t.corners[std::size_t(3 * i + s)], t.corners[std::size_t(3 * i + (s + 1) % 3)]};
            QCOMPARE(ends, corners);
        }
    }
    QCOMPARE(int(perCell.size()), (rows - 1) * (cols - 1));
    for (const auto &[cell, count] : perCell)
        QCOMPARE(count, 2);
}

void TestSpringTriangles::neighboursAreTurnedAlike()
{
    // a flat cloth: every normal points the same way (up), so smooth normals do not cancel
    core::ClothOptions options;
    options.rows = 6;
    options.cols = 9;
    const core::SceneDesc scene = core::makeCloth(options);
    const core::SpringTriangles t = core::findSpringTriangles(scene);
    QVERIFY(t.count() > 0);
    for (int i = 0; i < t.count(); ++i)
        QVERIFY2(normalOf(scene, t, i).y() > 0.0, qPrintable(QStringLiteral("triangle %1 faces down").arg(i)));
}

void TestSpringTriangles::pointsOnALineMakeNoTriangle()
{
    const core::SceneDesc scene = pointsJoinedPairwise({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
    QCOMPARE(scene.springs.size(), std::size_t(3));
    QVERIFY(core::findSpringTriangles(scene).empty());
}

void TestSpringTriangles::squaresWithoutDiagonalsMakeNone()
{
    // the handout's net: neighbours only
    core::NetOptions options;
    const core::SceneDesc scene = core::makeNet(options);
    QVERIFY(!scene.springs.empty());
    QVERIFY(core::findSpringTriangles(scene).empty());
}

void TestSpringTriangles::flatSquareWithBothDiagonalsMakesTwo()
{
    // four triangles of a square with both diagonals, of which two cover it once
    const core::SceneDesc scene = pointsJoinedPairwise({{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}});
    const core::SpringTriangles t = core::findSpringTriangles(scene);
    QCOMPARE(t.count(), 2);
    std::set<int> used(t.corners.begin(), t.corners.end());
    QCOMPARE(int(used.size()), 4);
    QCOMPARE(normalOf(scene, t, 0).norm() + normalOf(scene, t, 1).norm(), 2.0);
}

void TestSpringTriangles::solidTetrahedronKeepsAllFourFaces()
{
    // faces 70.5° apart are not folded onto each other
    const core::SceneDesc scene =
        pointsJoinedPairwise({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}});
    QCOMPARE(core::findSpringTriangles(scene).count(), 4);
}

void TestSpringTriangles::snapshotsShareTheModelsTriangles()
{
    core::ClothOptions options;
    options.rows = 3;
    options.cols = 3;
    const core::SceneDesc scene = core::makeCloth(options);
    const auto model = core::compileModel(scene);
    QVERIFY(model->triangles);
    QCOMPARE(model->triangles->count(), 8);
    QCOMPARE(model->triangles->springEnds.size(), 2 * scene.springs.size());
    const core::State state = core::makeState(*model, scene);
    QCOMPARE(core::makeSnapshot(*model, state)->triangles, model->triangles);

    // no springs, no triangles
    core::SceneDesc lone = test::quietScene();
    lone.particles = {test::particle({0, 0, 0})};
    QVERIFY(!core::compileModel(lone)->triangles);
}

void TestSpringTriangles::anEditThatKeepsTheSpringsKeepsTheTriangles()
{
    core::ClothOptions options;
    options.rows = 4;
    options.cols = 4;
    core::SceneDesc scene = core::makeCloth(options);
    const auto model = core::compileModel(scene);

    // other stiffnesses and positions: the same triangles, not found again
    core::SceneDesc stiffer = scene;
    for (core::SpringDesc &s : stiffer.springs)
        s.stiffness *= 2.0;
    stiffer.particles[5].position.y() += 0.01;
    QCOMPARE(core::compileModel(stiffer, model.get())->triangles, model->triangles);

    // a spring fewer (the last, a bend spring): found again, the same triangles
    core::SceneDesc fewer = scene;
    fewer.springs.pop_back();
    const auto fewerModel = core::compileModel(fewer, model.get());
    QVERIFY(fewerModel->triangles != model->triangles);
    QCOMPARE(fewerModel->triangles->corners, model->triangles->corners);
}

QTEST_MAIN(TestSpringTriangles)
#include "test_spring_triangles.moc"
