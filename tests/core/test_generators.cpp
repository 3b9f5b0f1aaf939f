// Scene generators: counts, rest lengths, pins, and that every generated scene is valid; granular
// blocks and balls never overlap and jitter the same for the same seed; a soft ball's points lie on
// its sphere; options out of range are refused with a message naming the option.
#include "core/model/generators.h"
#include "core/model/validate.h"

#include "scene_builder.h"

#include <QtTest>

#include <functional>
#include <set>
#include <numbers>

// a row of the bad-options table: checks one generator's options, changed to be wrong
using GeneratorCheck = std::function<std::optional<std::string>()>;
Q_DECLARE_METATYPE(GeneratorCheck)
// a row of the valid-scenes table: a generator's options checked, and the scene they make
using Generation = std::function<std::pair<std::optional<std::string>, core::SceneDesc>()>;
Q_DECLARE_METATYPE(Generation)

namespace {

// the closest two particles come, surface to surface (negative: they overlap); brute force, for
// small scenes
double smallestGap(const core::SceneDesc &scene)
{
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        for (std::size_t j = i + 1; j < scene.particles.size(); ++j) {
            const core::ParticleDesc &a = scene.particles[i];
            const core::ParticleDesc &b = scene.particles[j];
            gap = std::min(gap, (a.position - b.position).norm() - a.radius - b.radius);
        }
    return gap;
}

// the largest difference between a spring's rest length and the distance of its ends
double worstRestLength(const core::SceneDesc &scene)
{
    double worst = 0.0;
    for (const core::SpringDesc &s : scene.springs) {
        const double distance =
            (scene.particles[std::size_t(s.a)].position - scene.particles[std::size_t(s.b)].position).norm();
        worst = std::max(worst, std::abs(distance - s.restLength));
    }
    return worst;
}

// each particle's number of springs
std::vector<int> springsAt(const core::SceneDesc &scene)
{
    std::vector<int> count(scene.particles.size(), 0);
    for (const core::SpringDesc &s : scene.springs) {
        ++count[std::size_t(s.a)];
        ++count[std::size_t(s.b)];
    }
    return count;
}

// the check of a generator's default options after change(options)
template <class Options, class Change>
GeneratorCheck checkAfter(Change change)
{
    return [change] {
        Options options;
        change(options);
        return core::checkOptions(options);
    };
}

// a generator's default options after change(options), checked and made
template <class Options, class Change>
Generation generationAfter(core::SceneDesc (*make)(const Options &), Change change)
{
    return [make, change] {
        Options options;
        change(options);
        return std::pair(core::checkOptions(options), make(options));
    };
}

// the volume a closed surface of triangles encloses, at positions (3 × n)
double enclosedVolume(const std::vector<std::array<int, 3>> &triangles, const Eigen::Matrix3Xd &positions)
{
    double volume = 0.0;
    for (const std::array<int, 3> &t : triangles)
        volume += positions.col(t[0]).dot(positions.col(t[1]).cross(positions.col(t[2]))) / 6.0;
    return volume;
}

}  // namespace

class TestGenerators : public QObject {
    Q_OBJECT

private slots:
    void netIsTheHandoutsSpringsScene();
    void clothHasStructuralShearAndBendSprings();
    void chainHangsFromItsFirstParticle();
    void ropeParticlesTouch();
    void blockIsALatticeThatNeverOverlaps();
    void jitterIsTheSameForTheSameSeed();
    void ballIsTheLatticeInsideItsSphere();
    void softBallPointsLieOnItsSphere();
    void softBallSurfaceIsItsHullWoundOutwards();
    void softBallKeepsItsShapeWhenDropped_data();
    void softBallKeepsItsShapeWhenDropped();
    void generatedScenesAreValidAndAtRest_data();
    void generatedScenesAreValidAndAtRest();
    void badOptionsAreRefusedWithAMessage_data();
    void badOptionsAreRefusedWithAMessage();
};

void TestGenerators::netIsTheHandoutsSpringsScene()
{
    const core::SceneDesc net = core::makeNet({});
    QVERIFY(!core::findProblem(net));
    QCOMPARE(net.particles.size(), std::size_t(121));
    QCOMPARE(net.springs.size(), std::size_t(2 * 11 * 10));
    int pinned = 0;
    for (const auto &p : net.particles)
        pinned += p.pinned ? 1 : 0;
    QCOMPARE(pinned, 22);
    for (const auto &s : net.springs) {
        QVERIFY(std::abs(s.restLength - 0.4) < 1e-12);
        QCOMPARE(s.stiffness, 4000.0);
    }
}

void TestGenerators::clothHasStructuralShearAndBendSprings()
{
    core::ClothOptions options;
    options.rows = 4;
    options.cols = 5;
    const core::SceneDesc cloth = core::makeCloth(options);
    QVERIFY(!core::findProblem(cloth));
    QCOMPARE(cloth.particles.size(), std::size_t(20));
    // structural 4·4 + 3·5, shear 2·3·4, bend 4·3 + 2·5
    const std::size_t structural = 16 + 15, shear = 24, bend = 12 + 10;
    QCOMPARE(cloth.springs.size(), structural + shear + bend);
    QVERIFY(cloth.particles[0].pinned);
    QVERIFY(cloth.particles[4].pinned);
    QVERIFY(!cloth.particles[5].pinned);
    QVERIFY(std::abs(cloth.springs[structural].restLength - options.spacing * std::sqrt(2.0)) < 1e-12);
    QCOMPARE(cloth.springs[structural].stiffness, options.shearStiffness);
    QVERIFY(std::abs(cloth.springs.back().restLength - 2 * options.spacing) < 1e-12);
    QCOMPARE(cloth.springs.back().stiffness, options.bendStiffness);
}

void TestGenerators::chainHangsFromItsFirstParticle()
{
    const core::SceneDesc chain = core::makeChain({});
    QVERIFY(!core::findProblem(chain));
    QCOMPARE(chain.particles.size(), std::size_t(11));
    QCOMPARE(chain.springs.size(), std::size_t(10));
    QVERIFY(chain.particles[0].pinned);
    QVERIFY(!chain.particles[1].pinned);
}

void TestGenerators::ropeParticlesTouch()
{
    core::RopeOptions options;
    options.length = 2.0;
    options.segments = 20;
    const core::SceneDesc rope = core::makeRope(options);
    QVERIFY(!core::checkOptions(options));
    QCOMPARE(rope.particles.size(), std::size_t(21));
    QCOMPARE(rope.springs.size(), std::size_t(20));
    QVERIFY(rope.particles.front().pinned);
    QCOMPARE(rope.particles.back().position.x(), 2.0);
    // neighbours touch: a link is a diameter long, and no two particles overlap
    for (const core::SpringDesc &s : rope.springs)
        QVERIFY(std::abs(s.restLength - 2.0 * rope.particles[std::size_t(s.a)].radius) < 1e-12);
    QVERIFY(smallestGap(rope) > -1e-12);
    // stiff links on light particles need substeps: ω h stays under symplectic Euler's limit
    const double omega = std::sqrt(4.0 * options.stiffness / options.mass);
    QVERIFY(omega * rope.settings.timeStep / rope.settings.substeps <= 1.2);
    QVERIFY(rope.settings.substeps > 1);

    options.pinFirst = false;
    QVERIFY(!core::makeRope(options).particles.front().pinned);
}

void TestGenerators::blockIsALatticeThatNeverOverlaps()
{
    core::BlockOptions options;
    options.nx = 3;
    options.ny = 4;
    options.nz = 5;
    options.jitter = 0.0;
    const core::SceneDesc block = core::makeBlock(options);
    QCOMPARE(block.particles.size(), std::size_t(60));
    QVERIFY(block.springs.empty());
    // without jitter: the lattice, centred on the y axis, from y = height up
    double lowest = 1e9, highest = -1e9;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const core::ParticleDesc &p : block.particles) {
        lowest = std::min(lowest, p.position.y());
        highest = std::max(highest, p.position.y());
        sum += p.position;
        QVERIFY(!p.pinned);
    }
    QCOMPARE(lowest, options.height);
    QVERIFY(std::abs(highest - (options.height + 3 * options.spacing)) < 1e-12);
    QVERIFY(std::abs(sum.x()) < 1e-12 && std::abs(sum.z()) < 1e-12);
    QVERIFY(std::abs(smallestGap(block) - (options.spacing - 2.0 * options.radius)) < 1e-12);

    // with the largest jitter the options allow, particles come close but never overlap
    options.jitter = 0.5 * options.spacing - options.radius;
    QVERIFY(!core::checkOptions(options));
    const core::SceneDesc jittered = core::makeBlock(options);
    QVERIFY(smallestGap(jittered) >= -1e-12);
    QVERIFY(smallestGap(jittered) < smallestGap(block));
    for (std::size_t i = 0; i < block.particles.size(); ++i)
        QVERIFY((jittered.particles[i].position - block.particles[i].position).lpNorm<Eigen::Infinity>() <=
                options.jitter);
}

void TestGenerators::jitterIsTheSameForTheSameSeed()
{
    core::BlockOptions options;
    const core::SceneDesc first = core::makeBlock(options);
    QVERIFY(first == core::makeBlock(options));
    options.seed = 2;
    QVERIFY(!(first == core::makeBlock(options)));
    core::BallOptions ball;
    QVERIFY(core::makeBall(ball) == core::makeBall(ball));
}

void TestGenerators::ballIsTheLatticeInsideItsSphere()
{
    core::BallOptions options;
    options.ballRadius = 0.3;
    options.spacing = 0.1;
    options.jitter = 0.0;
    const core::SceneDesc ball = core::makeBall(options);
    // the integer points with x² + y² + z² ≤ 9
    int inside = 0;
    for (int x = -3; x <= 3; ++x)
        for (int y = -3; y <= 3; ++y)
            for (int z = -3; z <= 3; ++z)
                inside += x * x + y * y + z * z <= 9 ? 1 : 0;
    QCOMPARE(inside, 123);
    QCOMPARE(int(ball.particles.size()), inside);
    const Eigen::Vector3d centre(0.0, options.height, 0.0);
    for (const core::ParticleDesc &p : ball.particles)
        QVERIFY((p.position - centre).norm() <= options.ballRadius + 1e-12);
    QVERIFY(std::abs(smallestGap(ball) - (options.spacing - 2.0 * options.radius)) < 1e-12);

    options.jitter = 0.005;
    QVERIFY(smallestGap(core::makeBall(options)) >= 0.0);
}

void TestGenerators::softBallPointsLieOnItsSphere()
{
    core::SoftBallOptions options;
    options.points = 200;
    const core::SceneDesc ball = core::makeSoftBall(options);
    QVERIFY(!core::checkOptions(options));
    QCOMPARE(ball.particles.size(), std::size_t(201));
    const Eigen::Vector3d centre(0.0, options.height, 0.0);
    for (int i = 0; i < options.points; ++i)
        QVERIFY(std::abs((ball.particles[std::size_t(i)].position - centre).norm() - options.ballRadius) < 1e-12);
    QCOMPARE(ball.particles.back().position, centre);
    QVERIFY(smallestGap(ball) >= 0.0);

    // every surface point has surface neighbours (a closed shell) and one spring to the centre
    const std::vector<int> count = springsAt(ball);
    for (int i = 0; i < options.points; ++i)
        QVERIFY2(count[std::size_t(i)] >= 4, qPrintable(QString::number(count[std::size_t(i)])));
    QCOMPARE(count.back(), options.points);
    const double spacing = options.ballRadius * std::sqrt(4.0 * std::numbers::pi / options.points);
    int toCentre = 0;
    for (const core::SpringDesc &s : ball.springs) {
        if (s.b == options.points) {
            ++toCentre;
            QCOMPARE(s.stiffness, options.centreStiffness);
        } else {
            QVERIFY(s.restLength <= 1.5 * spacing);
            QCOMPARE(s.stiffness, options.stiffness);
        }
    }
    QCOMPARE(toCentre, options.points);

    // without the centre: the shell alone
    options.centre = false;
    const core::SceneDesc shell = core::makeSoftBall(options);
    QCOMPARE(shell.particles.size(), std::size_t(options.points));
    QCOMPARE(shell.springs.size(), ball.springs.size() - std::size_t(options.points));
}

void TestGenerators::softBallSurfaceIsItsHullWoundOutwards()
{
    // the surface drawn: the convex hull of the points, each face wound counter-clockwise seen from
    // outside (its spring triangles drew half the ball dark: fans to the centre, both windings)
    for (int points : {4, 5, 12, 120, 500, 2000}) {
        core::SoftBallOptions options;
        options.points = points;
        options.radius = std::min(0.3 * options.ballRadius * std::sqrt(4.0 * std::numbers::pi / points), 0.2 * options.ballRadius);
        QVERIFY(!core::checkOptions(options));
        const core::SceneDesc ball = core::makeSoftBall(options);
        const Eigen::Vector3d centre(0.0, options.height, 0.0);
        // a closed surface of n vertices, all on the hull: 2n - 4 triangles (Euler)
        QCOMPARE(ball.triangles.size(), std::size_t(2 * points - 4));
        std::set<std::pair<int, int>> edges;
        for (const std::array<int, 3> &t : ball.triangles) {
            for (int corner : t)
                QVERIFY(corner >= 0 && corner < points);  // never the centre
            const Eigen::Vector3d &a = ball.particles[std::size_t(t[0])].position;
            const Eigen::Vector3d &b = ball.particles[std::size_t(t[1])].position;
            const Eigen::Vector3d &c = ball.particles[std::size_t(t[2])].position;
            QVERIFY((b - a).cross(c - a).dot(a + b + c - 3.0 * centre) > 0.0);
            for (int s = 0; s < 3; ++s)
                QVERIFY2(edges.insert({t[std::size_t(s)], t[std::size_t((s + 1) % 3)]}).second, "an edge twice one way");
        }
        // each edge once each way: closed, and wound alike on both sides of every edge
        for (const auto &[a, b] : edges)
            QVERIFY(edges.count({b, a}) == 1);
        // and it encloses nearly the sphere's volume
        Eigen::Matrix3Xd positions(3, std::ptrdiff_t(points));
        for (int i = 0; i < points; ++i)
            positions.col(i) = ball.particles[std::size_t(i)].position - centre;
        const double sphere = 4.0 / 3.0 * std::numbers::pi * std::pow(options.ballRadius, 3);
        const double volume = enclosedVolume(ball.triangles, positions);
        QVERIFY2(volume > 0.0 && volume < sphere, qPrintable(QString::number(volume / sphere)));
        if (points >= 120)
            QVERIFY2(volume > 0.95 * sphere, qPrintable(QString::number(volume / sphere)));
    }
}

void TestGenerators::softBallKeepsItsShapeWhenDropped_data()
{
    QTest::addColumn<double>("drop");  // m, from the floor to the ball's lowest point
    QTest::newRow("0.6 m") << 0.6;
    QTest::newRow("2 m") << 2.0;
    QTest::newRow("4 m") << 4.0;
}

void TestGenerators::softBallKeepsItsShapeWhenDropped()
{
    // the defaults dropped onto a floor: the ball bounces and holds its shape (at surface k 200 and
    // centre k 100 it dented from 1 m, and from 2 m it crumpled into a cone and stayed one, with 15%
    // of its volume)
    QFETCH(double, drop);
    const core::SoftBallOptions options;
    core::SceneDesc scene = core::makeSoftBall(options);
    for (core::ParticleDesc &p : scene.particles)
        p.position.y() += drop + options.ballRadius + options.radius - options.height;
    scene.planes = {core::PlaneDesc{}};
    test::Sim sim = test::compile(scene);
    const int n = options.points;
    const auto surface = [&sim, n] {
        const Eigen::Matrix3Xd points = sim.state.position.leftCols(n);
        const Eigen::Vector3d mid = points.rowwise().mean();
        return std::pair<Eigen::Matrix3Xd, Eigen::Vector3d>(points.colwise() - mid, mid);
    };
    const double start = enclosedVolume(scene.triangles, surface().first);
    double least = 1.0;
    double lowest = std::numeric_limits<double>::infinity();
    double risen = 0.0;  // how far the centre rose after its lowest point
    const int steps = int(std::lround(3.0 / scene.settings.timeStep));
    for (int i = 0; i < steps; ++i) {
        QVERIFY2(sim.step(), qPrintable(QString("blew up at step %1").arg(i)));
        const auto [points, mid] = surface();
        least = std::min(least, enclosedVolume(scene.triangles, points) / start);
        lowest = std::min(lowest, mid.y());
        risen = std::max(risen, mid.y() - lowest);
    }
    const auto [points, mid] = surface();
    const double end = enclosedVolume(scene.triangles, points) / start;
    const Eigen::VectorXd distances = points.colwise().norm();
    qInfo("least volume %.3f, at the end %.3f, centre rose %.3f m after its lowest, distances %.3f..%.3f of the radius",
          least, end, risen, distances.minCoeff() / options.ballRadius, distances.maxCoeff() / options.ballRadius);
    QVERIFY2(least > 0.7, qPrintable(QString::number(least)));
    QVERIFY2(end > 0.95, qPrintable(QString::number(end)));
    QVERIFY2(distances.minCoeff() > 0.9 * options.ballRadius && distances.maxCoeff() < 1.1 * options.ballRadius,
             "it does not hold its round shape at rest");
    QVERIFY2(risen > 0.25 * drop, qPrintable(QString::number(risen)));  // it bounced
}

void TestGenerators::generatedScenesAreValidAndAtRest_data()
{
    QTest::addColumn<Generation>("generate");
    using core::BallOptions, core::BlockOptions, core::ChainOptions, core::ClothOptions, core::RopeOptions,
        core::SoftBallOptions;
    for (int size : {1, 2, 7}) {
        const auto row = [size](const char *kind, Generation generate) {
            QTest::newRow(qPrintable(QStringLiteral("%1 of size %2").arg(QLatin1String(kind)).arg(size))) << generate;
        };
        row("cloth", generationAfter<ClothOptions>(core::makeCloth, [size](auto &o) {
                o.rows = 2 + size;
                o.cols = 3 * size;
            }));
        row("chain", generationAfter<ChainOptions>(core::makeChain, [size](auto &o) { o.links = 4 * size; }));
        row("rope", generationAfter<RopeOptions>(core::makeRope, [size](auto &o) { o.segments = 5 * size; }));
        row("block", generationAfter<BlockOptions>(core::makeBlock, [size](auto &o) {
                o.nx = size;
                o.ny = 2;
                o.nz = size + 1;
                o.seed = std::uint64_t(size);
            }));
        row("ball", generationAfter<BallOptions>(core::makeBall, [size](auto &o) { o.ballRadius = 0.1 * size; }));
        row("soft ball", generationAfter<SoftBallOptions>(core::makeSoftBall, [size](auto &o) {
                o.points = 4 + 30 * (size - 1);
                o.centre = size != 2;
            }));
    }
}

void TestGenerators::generatedScenesAreValidAndAtRest()
{
    // each generator at a few sizes: valid options make a valid scene with no spring stretched and
    // no two particles overlapping
    QFETCH(Generation, generate);
    const auto [problem, scene] = generate();
    QVERIFY2(!problem, problem ? problem->c_str() : "");
    QVERIFY(!scene.particles.empty());
    const std::optional<core::SceneProblem> found = core::findProblem(scene);
    QVERIFY2(!found, found ? (found->path + ": " + found->message).c_str() : "");
    QVERIFY(worstRestLength(scene) < 1e-12);
    QVERIFY(smallestGap(scene) >= -1e-12);
}

void TestGenerators::badOptionsAreRefusedWithAMessage_data()
{
    QTest::addColumn<GeneratorCheck>("check");
    QTest::addColumn<QString>("expected");
    using core::BallOptions, core::BlockOptions, core::ChainOptions, core::ClothOptions, core::RopeOptions,
        core::SoftBallOptions;
    const auto row = [](const char *name, GeneratorCheck check, const char *expected) {
        QTest::newRow(name) << check << QString::fromUtf8(expected);
    };
    row("cloth of no rows", checkAfter<ClothOptions>([](auto &o) { o.rows = 0; }), "rows must be at least 2 (got 0)");
    row("cloth too large", checkAfter<ClothOptions>([](auto &o) { o.rows = o.cols = 1000; }),
        "makes 1000000 particles, more than the 200000 a generator may make");
    row("negative spacing", checkAfter<ClothOptions>([](auto &o) { o.spacing = -0.1; }),
        "spacing must be greater than 0 m (got -0.1 m)");
    row("overlapping cloth", checkAfter<ClothOptions>([](auto &o) { o.radius = 0.03; }),
        "radius 0.03 m is too large: at most 0.025 m");
    row("negative stiffness", checkAfter<ClothOptions>([](auto &o) { o.bendStiffness = -1.0; }),
        "bend stiffness must be at least 0 N/m (got -1 N/m)");
    row("zero mass", checkAfter<ClothOptions>([](auto &o) { o.mass = 0.0; }), "mass must be greater than 0 kg");
    row("cloth too wide", checkAfter<ClothOptions>([](auto &o) { o.spacing = 1e5; }), "a generator may span");
    row("chain of no links", checkAfter<ChainOptions>([](auto &o) { o.links = 0; }), "links must be at least 1 (got 0)");
    row("rope of NaN length", checkAfter<RopeOptions>([](auto &o) { o.length = std::nan(""); }),
        "length must be greater than 0 m");
    row("block of no layers", checkAfter<BlockOptions>([](auto &o) { o.ny = 0; }), "ny must be at least 1 (got 0)");
    row("block too large", checkAfter<BlockOptions>([](auto &o) { o.nx = o.ny = o.nz = 100; }),
        "makes 1000000 particles");
    row("jitter that overlaps", checkAfter<BlockOptions>([](auto &o) { o.jitter = 0.01; }),
        "at most 0.04 m (half the spacing less the jitter)");
    row("negative jitter", checkAfter<BallOptions>([](auto &o) { o.jitter = -1.0; }), "jitter must be at least 0 m");
    row("ball too large", checkAfter<BallOptions>([](auto &o) { o.ballRadius = 100.0; }),
        "more than the 200000 a generator may make");
    // about 212000 lattice points: counted, not estimated
    row("ball just over the cap", checkAfter<BallOptions>([](auto &o) { o.ballRadius = 3.7; }),
        "particles, more than the 200000");
    row("soft ball of 3 points", checkAfter<SoftBallOptions>([](auto &o) { o.points = 3; }),
        "points must be at least 4 (got 3)");
    row("soft ball too fine", checkAfter<SoftBallOptions>([](auto &o) { o.points = 5000; }),
        "for this many points on this ball");
    row("soft ball centre overlaps", checkAfter<SoftBallOptions>([](auto &o) {
            o.points = 4;
            o.radius = 0.13;
        }),
        "the centre would overlap the surface");
}

void TestGenerators::badOptionsAreRefusedWithAMessage()
{
    QFETCH(GeneratorCheck, check);
    QFETCH(QString, expected);
    const std::optional<std::string> problem = check();
    QVERIFY(problem.has_value());
    QVERIFY2(QString::fromStdString(*problem).contains(expected), problem->c_str());
}

QTEST_APPLESS_MAIN(TestGenerators)
#include "test_generators.moc"
