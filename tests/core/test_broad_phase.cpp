// The broad phase of particle contacts: the grid finds exactly the brute force's pairs, in the
// same order, on ordinary and degenerate scenes, and a run with it equals a run with the brute
// force to the last bit.
#include "core/contacts/broad_phase.h"
#include "core/passes.h"
#include "core/step.h"
#include "core/threads.h"
#include "scene_builder.h"

#include <QtTest>
#include <cmath>
#include <limits>
#include <random>

class TestBroadPhase : public QObject {
    Q_OBJECT

private slots:
    void gridEqualsBruteForce_data();
    void gridEqualsBruteForce();
    void gridIsReusedAcrossScenes();
    void gridSortsAlikeOnAnyThreadCount_data();
    void gridSortsAlikeOnAnyThreadCount();
    void runEqualsBruteForceRun();
    void stepAllocatesNothingOnceWarm();
    void nonFiniteParticleNeverCollides();
    void crowdNeedsMemoryInProportion();
};

namespace {

enum class Layout {
    Uniform,      // a box at about 30 % volume fraction, radii 0.02..0.04 m
    VariedRadii,  // radii from 1 mm to 10 cm, log-uniform
    Clumps,       // a few tight clumps
    Coincident,   // every particle at one point
    Line,         // on the x axis
    Plane,        // in the plane z = 0
    OneHuge,      // one particle of 5 m among small ones
    FewHuge,      // three large ones of different sizes among small ones
    Pinned,       // half of them pinned, in a dense box
    FarApart,     // clumps at ±1e6 m
    Lattice,      // a cubic lattice spaced a hair under one diameter: every neighbour just overlapping
    NotFinite,    // some positions NaN or infinite among overlapping ones
    Extreme,      // positions near the largest double
};

struct Case {
    std::vector<Eigen::Vector3d> positions;
    std::vector<double> radii;
    std::vector<bool> pinned;
};

// a scene of `count` particles laid out as `layout`, from `seed`
Case makeCase(Layout layout, int count, unsigned seed)
{
    std::mt19937 random(seed);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
    auto inBox = [&](double side) { return Eigen::Vector3d(uniform(0, side), uniform(0, side), uniform(0, side)); };
    Case c;
    for (int i = 0; i < count; ++i) {
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        double r = 0.02;
        bool pinned = false;
        switch (layout) {
        case Layout::Uniform:
            r = uniform(0.02, 0.04);
            x = inBox(std::cbrt(count * 2.4e-4 / 0.3));
            break;
        case Layout::VariedRadii:
            r = std::exp(uniform(std::log(0.001), std::log(0.1)));
            x = inBox(1.0);
            break;
        case Layout::Clumps:
            x = Eigen::Vector3d(double(i % 4), 0.5 * double(i % 3), 0.0) + 0.05 * inBox(1.0);
            break;
        case Layout::Coincident:
            x = Eigen::Vector3d(0.3, -2.0, 7.0);
            break;
        case Layout::Line:
            x = Eigen::Vector3d(uniform(-10, 10), 0.0, 0.0);
            break;
        case Layout::Plane:
            x = Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), 0.0);
            break;
        case Layout::OneHuge:
            r = i == count / 2 ? 5.0 : 0.02;
            x = inBox(4.0);
            break;
        case Layout::FewHuge:
            r = i == 3 ? 2.0 : i == count - 1 ? 0.7 : i == count / 3 ? 0.4 : 0.01;
            x = inBox(3.0);
            break;
        case Layout::Pinned:
            pinned = i % 2 == 0;
            x = inBox(0.5);
            break;
        case Layout::FarApart:
            x = Eigen::Vector3d(i % 2 == 0 ? 1e6 : -1e6, i % 3 == 0 ? 1e6 : 0.0, -1e6) + 0.3 * inBox(1.0);
            break;
        case Layout::Lattice:
            x = 0.04 * (1.0 - 1e-12) * Eigen::Vector3d(double(i % 10), double(i / 10 % 10), double(i / 100));
            break;
        case Layout::NotFinite: {
            x = 0.3 * inBox(1.0);
            const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity()};
            if (i % 7 == 0)
                x[i % 3] = bad[i % 3];
            break;
        }
        case Layout::Extreme:
            x = inBox(0.2);
            if (i % 5 == 0)
                x[i % 3] = i % 2 == 0 ? 1.7e308 : -1.7e308;
            break;
        }
        c.positions.push_back(x);
        c.radii.push_back(r);
        c.pinned.push_back(pinned);
    }
    return c;
}

// the case compiled (positions are set after compiling, so that any value can be tried)
test::Sim compileCase(const Case &c)
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.particleCollisions = true;
    for (std::size_t i = 0; i < c.radii.size(); ++i)
        scene.particles.push_back(test::particle(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 1.0, c.radii[i], c.pinned[i]));
    test::Sim sim = test::compile(scene);
    for (std::size_t i = 0; i < c.positions.size(); ++i)
        sim.state.position.col(Eigen::Index(i)) = c.positions[i];
    return sim;
}

// "(i, j)" for a failure message
QByteArray describe(const std::vector<core::ContactPair> &pairs, std::size_t at)
{
    if (at >= pairs.size())
        return "(none)";
    return QByteArray("(") + QByteArray::number(pairs[at].i) + ", " + QByteArray::number(pairs[at].j) + ")";
}

// the grid's list equals the brute force's; the first difference otherwise
void compareWithBruteForce(const test::Sim &sim, core::ContactGrid &grid)
{
    std::vector<core::ContactPair> reference;
    core::findContactsBruteForce(*sim.model, sim.state.position, reference);
    core::findContacts(*sim.model, sim.state.position, grid);
    if (grid.crowded) {
        // a crowd: the grid keeps at most kMaxGridPartners pairs a particle, every one of them a
        // true pair, and leaves a true pair out only where one of its particles has them all
        std::vector<int> partners(std::size_t(sim.model->particleCount()), 0);
        for (const core::ContactPair &pair : grid.pairs) {
            QVERIFY(std::binary_search(reference.begin(), reference.end(), pair, [](const auto &a, const auto &b) {
                return a.i < b.i || (a.i == b.i && a.j < b.j);
            }));
            ++partners[std::size_t(pair.i)];
            ++partners[std::size_t(pair.j)];
        }
        const bool bigInvolved = !grid.big.empty();  // pairs of the big ones are never capped
        for (const int count : partners)
            QVERIFY(bigInvolved || count <= core::kMaxGridPartners);
        std::size_t k = 0;
        for (const core::ContactPair &pair : reference) {
            while (k < grid.pairs.size() && (grid.pairs[k].i < pair.i || (grid.pairs[k].i == pair.i && grid.pairs[k].j < pair.j)))
                ++k;
            const bool kept = k < grid.pairs.size() && grid.pairs[k] == pair;
            QVERIFY2(kept || partners[std::size_t(pair.i)] >= core::kMaxGridPartners ||
                         partners[std::size_t(pair.j)] >= core::kMaxGridPartners,
                     qPrintable(QString("pair %1-%2 left out with room on both sides").arg(pair.i).arg(pair.j)));
        }
        return;
    }
    std::size_t first = 0;
    while (first < reference.size() && first < grid.pairs.size() && reference[first] == grid.pairs[first])
        ++first;
    QVERIFY2(grid.pairs == reference, QByteArray("grid " + describe(grid.pairs, first) + " where brute force " +
                                                 describe(reference, first) + ", pair " + QByteArray::number(qulonglong(first)))
                                          .constData());
}

// bit-for-bit equality of two matrices (NaN equal to the same NaN)
bool sameBits(const Eigen::Matrix3Xd &a, const Eigen::Matrix3Xd &b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * std::size_t(a.size())) == 0;
}

// particles of varied sizes and masses poured into a box under gravity, some pinned in the middle
core::SceneDesc pouredBox()
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = {0, -9.81, 0};
    scene.settings.planeCollisions = true;
    scene.settings.particleCollisions = true;
    scene.settings.restitution = 0.5;
    scene.settings.timeStep = 0.005;
    scene.settings.substeps = 4;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 400; ++i) {
        const Eigen::Vector3d x(unit(random), 0.2 + 1.5 * unit(random), unit(random));
        const Eigen::Vector3d v(unit(random) - 0.5, -unit(random), unit(random) - 0.5);
        const bool pinned = i % 50 == 0;
        scene.particles.push_back(test::particle(x, pinned ? Eigen::Vector3d::Zero() : v, 0.5 + unit(random),
                                                 0.02 + 0.03 * unit(random), pinned));
    }
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 0.0}, core::PlaneDesc{{1, 0, 0}, 0.0}, core::PlaneDesc{{-1, 0, 0}, -1.0},
                    core::PlaneDesc{{0, 0, 1}, 0.0}, core::PlaneDesc{{0, 0, -1}, -1.0}};
    return scene;
}

}  // namespace

Q_DECLARE_METATYPE(Layout)

void TestBroadPhase::gridEqualsBruteForce_data()
{
    QTest::addColumn<Layout>("layout");
    QTest::addColumn<int>("count");
    QTest::addColumn<bool>("touching");  // whether the scene has overlapping pairs at all
    for (unsigned seed : {1u, 2u, 3u}) {
        const QByteArray s = " " + QByteArray::number(seed);
        QTest::newRow("uniform" + s) << Layout::Uniform << 1500 + int(seed) * 100 << true;
        QTest::newRow("varied radii" + s) << Layout::VariedRadii << 1500 << true;
    }
    QTest::newRow("clumps") << Layout::Clumps << 600 << true;
    QTest::newRow("coincident") << Layout::Coincident << 300 << true;
    QTest::newRow("line") << Layout::Line << 1000 << true;
    QTest::newRow("plane") << Layout::Plane << 1500 << true;
    QTest::newRow("one huge") << Layout::OneHuge << 1500 << true;
    QTest::newRow("few huge") << Layout::FewHuge << 1500 << true;
    QTest::newRow("pinned") << Layout::Pinned << 800 << true;
    QTest::newRow("far apart") << Layout::FarApart << 600 << true;
    QTest::newRow("lattice") << Layout::Lattice << 1000 << true;
    QTest::newRow("not finite") << Layout::NotFinite << 500 << true;
    QTest::newRow("extreme") << Layout::Extreme << 300 << true;
    QTest::newRow("none") << Layout::Uniform << 0 << false;
    QTest::newRow("one") << Layout::Coincident << 1 << false;
    QTest::newRow("two touching") << Layout::Coincident << 2 << true;
    QTest::newRow("two apart") << Layout::Line << 2 << false;
}

void TestBroadPhase::gridEqualsBruteForce()
{
    QFETCH(Layout, layout);
    QFETCH(int, count);
    QFETCH(bool, touching);
    const unsigned seed = qHash(QByteArray(QTest::currentDataTag()));
    const test::Sim sim = compileCase(makeCase(layout, count, seed));
    core::ContactGrid grid;
    compareWithBruteForce(sim, grid);
    if (touching)
        QVERIFY(!grid.pairs.empty());
    // each pair i < j once, in lexicographic order
    for (std::size_t k = 0; k < grid.pairs.size(); ++k) {
        QVERIFY(grid.pairs[k].i < grid.pairs[k].j);
        if (k > 0)
            QVERIFY(grid.pairs[k - 1].i < grid.pairs[k].i ||
                    (grid.pairs[k - 1].i == grid.pairs[k].i && grid.pairs[k - 1].j < grid.pairs[k].j));
    }
}

// Scenes large enough for the grid to be sorted in parallel shares: the same slots, buckets and
// pairs as on one thread, and the brute force's pairs
void TestBroadPhase::gridSortsAlikeOnAnyThreadCount_data()
{
    QTest::addColumn<Layout>("layout");
    QTest::addColumn<int>("count");
    QTest::newRow("uniform, dense cells") << Layout::Uniform << 20000;
    QTest::newRow("varied radii") << Layout::VariedRadii << 12000;
    QTest::newRow("far apart, hashed cells") << Layout::FarApart << 12000;
    QTest::newRow("not finite") << Layout::NotFinite << 9000;
    QTest::newRow("few huge") << Layout::FewHuge << 9000;
    QTest::newRow("pinned") << Layout::Pinned << 9000;
}

void TestBroadPhase::gridSortsAlikeOnAnyThreadCount()
{
    if (core::maxThreadCount() < 2)
        QSKIP("one processor: the grid is never sorted in shares");
    QFETCH(Layout, layout);
    QFETCH(int, count);
    const test::Sim sim = compileCase(makeCase(layout, count, qHash(QByteArray(QTest::currentDataTag()))));
    const int before = core::threadCount();
    core::ContactGrid one, two;
    core::setThreadCount(1);
    core::findContacts(*sim.model, sim.state.position, one);
    core::setThreadCount(2);
    compareWithBruteForce(sim, two);
    core::setThreadCount(before);
    QVERIFY(!one.pairs.empty());
    QCOMPARE(two.hashed, one.hashed);
    QCOMPARE(two.bucketStart, one.bucketStart);
    QCOMPARE(two.slotOf, one.slotOf);
    QCOMPARE(two.sorted.size(), one.sorted.size());
    for (std::size_t k = 0; k < one.sorted.size(); ++k) {
        QCOMPARE(two.sorted[k].particle, one.sorted[k].particle);
        QCOMPARE(two.sorted[k].cell, one.sorted[k].cell);
    }
    QVERIFY(two.pairs == one.pairs);
}

void TestBroadPhase::gridIsReusedAcrossScenes()
{
    // one scratch for scenes of different sizes and shapes, as when the editor rebuilds a scene
    // (and both ways of numbering the cells: dense over the bounding box, and hashed)
    core::ContactGrid grid;
    bool dense = false;
    bool hashed = false;
    for (Layout layout : {Layout::Uniform, Layout::Coincident, Layout::OneHuge, Layout::Uniform, Layout::Line})
        for (int count : {1200, 40, 700}) {
            compareWithBruteForce(compileCase(makeCase(layout, count, unsigned(count))), grid);
            if (QTest::currentTestFailed())
                return;
            (grid.hashed ? hashed : dense) = true;
        }
    QVERIFY(dense && hashed);
}

void TestBroadPhase::runEqualsBruteForceRun()
{
    test::Sim grid = test::compile(pouredBox());
    test::Sim brute = test::compile(pouredBox());
    brute.work.contacts.bruteForce = true;
    std::size_t contacts = 0;
    for (int i = 0; i < 150; ++i) {
        QVERIFY(grid.step());
        QVERIFY(brute.step());
        contacts += grid.work.contacts.pairs.size();
        QVERIFY2(sameBits(grid.state.position, brute.state.position), qPrintable(QString("step %1").arg(i + 1)));
        QVERIFY2(sameBits(grid.state.velocity, brute.state.velocity), qPrintable(QString("step %1").arg(i + 1)));
    }
    QVERIFY2(contacts > 4000, qPrintable(QString::number(contacts)));  // the pass had work to do
}

void TestBroadPhase::stepAllocatesNothingOnceWarm()
{
    // once the first sub-step has sized the scratch, its arrays stay where they are
    test::Sim sim = test::compile(pouredBox());
    QVERIFY(sim.step());
    const core::ContactGrid &grid = sim.work.contacts;
    const void *before[] = {grid.pairs.data(), grid.sorted.data(), grid.bucketStart.data(), grid.slotOf.data(),
                            grid.cellOf.data(), grid.radiusSample.data(), grid.found.data(), grid.pairStart.data()};
    for (int i = 0; i < 100; ++i)
        QVERIFY(sim.step());
    const void *after[] = {grid.pairs.data(), grid.sorted.data(), grid.bucketStart.data(), grid.slotOf.data(),
                           grid.cellOf.data(), grid.radiusSample.data(), grid.found.data(), grid.pairStart.data()};
    for (std::size_t k = 0; k < std::size(before); ++k)
        QVERIFY2(before[k] == after[k], qPrintable(QString("array %1 moved").arg(k)));
}

void TestBroadPhase::nonFiniteParticleNeverCollides()
{
    // a NaN particle on top of two overlapping ones: the two are resolved, the NaN stays put and
    // spreads to nobody
    core::SceneDesc scene = test::quietScene();
    scene.settings.particleCollisions = true;
    scene.particles = {test::particle({0, 0, 0}), test::particle({0.1, 0, 0}), test::particle({0.05, 0, 0})};
    test::Sim sim = test::compile(scene);
    sim.state.position(1, 2) = std::numeric_limits<double>::quiet_NaN();
    core::collideParticles(*sim.model, sim.state, sim.work);
    QCOMPARE(sim.work.contacts.pairs.size(), std::size_t(1));
    QCOMPARE(sim.state.position(0, 0), -0.05);
    QCOMPARE(sim.state.position(0, 1), 0.15);
    QVERIFY(std::isnan(sim.state.position(1, 2)));
    QVERIFY(sim.state.position.leftCols(2).allFinite() && sim.state.velocity.allFinite());
}

void TestBroadPhase::crowdNeedsMemoryInProportion()
{
    // 6000 coincident particles: 18 million overlapping pairs, of which the grid keeps at most
    // kMaxGridPartners / 2 a particle; a step with the contact solver on them ends
    core::SceneDesc scene = test::quietScene();
    scene.settings.particleCollisions = true;
    for (int i = 0; i < 6000; ++i) {
        core::ParticleDesc p;
        p.position = {0.25, 0.5, -0.125};
        p.radius = 0.01;
        scene.particles.push_back(p);
    }
    test::Sim sim = test::compile(scene);
    core::ContactGrid grid;
    core::findContacts(*sim.model, sim.state.position, grid);
    QVERIFY(grid.crowded);
    QVERIFY(!grid.pairs.empty());
    QVERIFY2(grid.pairs.size() <= std::size_t(6000 * core::kMaxGridPartners / 2), qPrintable(QString::number(grid.pairs.size())));
    QVERIFY(sim.step());
    QVERIFY(sim.work.contacts.pairs.size() <= std::size_t(6000 * core::kMaxGridPartners / 2));
}

QTEST_APPLESS_MAIN(TestBroadPhase)
#include "test_broad_phase.moc"
