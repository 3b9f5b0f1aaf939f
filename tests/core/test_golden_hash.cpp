// Determinism: a chaotic run (a net dropped onto a pile of balls on a floor: springs, particle and
// plane contacts) hashed bit for bit after 1000 steps and compared with a fixed value.
//
// Changing kGoldenHash on purpose means updating it on purpose, in the same change that moves it,
// saying why. What may legitimately move it: a change to the physics or its order of operations
// (forces, integrators, collision response, the order pairs are found or resolved in), to the
// generators or the defaults this scene uses, or to this scene. What must not: thread count,
// build type, compiler flags, the machine, or running it again; the design keeps -ffast-math and
// FMA contraction out so that none of those can.

#include "core/model/generators.h"
#include "core/model/state_hash.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>

#include <bit>
#include <cmath>
#include <cstdint>

using namespace Qt::Literals::StringLiterals;

namespace {

// the expected hash of kSteps steps of goldenScene(); see the note at the top before changing it.
// kGoldenHash is the course handout's contact passes (settings.contactSolver "handout"), which
// the iterative solver left alone to the bit; kGoldenIterativeHash the iterative solver, first
// fixed when it became the default, last moved when the position solve began to leave two
// particles' overlaps of under 0.1% of their radii in place (contact_solve.cpp, kOverlapSlop);
// before that when a pair whose paths began at different times
// came to be searched along its relative path from the later start, and a touch that 64
// advancements do not reach was looked for up to the least gap even where the pair is apart at
// the sub-step's end (contact_impacts.cpp, pairImpact and firstTouch); before that when the balls
// began to turn (its friction now acts at their surfaces and rolls them: contact_spin.h); before
// that when a particle's new path began to be checked
// against the fast particles and (in a small scene) the strays, which are in no one's candidates
// (contact_impacts.cpp, impactsOf); before that when a bounce in the resting solve took its
// restitution after its compression (Poisson's rule), a resting contact stopped holding a parting
// pair to its speed, and a touch that 64 advancements do not reach was found by bisection
// (contact_solve.cpp, contact_impacts.cpp); before that when an impact stopped ending a particle's
// impacts for the sub-step: every path an impact changes is searched again from its time, touching pairs
// closing fast pass the impulse on at once, and a touch at the sub-step's very end is found
// (contact_impacts.cpp); before that when the velocity solve's changes began to move the
// sub-step's end as well (contact_solve.cpp, driftWeight), so that resting particles stop sinking
// and piles stop creeping; before that when an Euler scheme's rebound from a collider began
// to keep the quantity its flight keeps (contact_impacts.cpp, eulerRebound); before that when the
// iterations took each contact's effective mass once and the impacts advanced along the pair's
// relative path, and when they began warm started from the last sub-step's impulses.
// Last moved when the grid generators (makeNet, makeCloth) gave every spring of one kind the
// grid's rest length, spacing · √(dr² + dc²), instead of the distance of its ends' coordinates,
// which differs in the last bits from spring to spring: the net's rest lengths moved by an ulp or so.
// Before that, when the spring direction became one division and three multiplications
// (d · (1/l)) instead of three divisions (d / l).
constexpr std::uint64_t kGoldenHash = 0xf59ab1b21c2967dbULL;
constexpr std::uint64_t kGoldenIterativeHash = 0xecec67c5bbc0e146ULL;
constexpr int kSteps = 1000;

// a 10 × 10 net, free at every edge, falling onto a 5 × 4 × 5 pile of balls under its middle on the
// floor y = 0
core::SceneDesc goldenScene(core::ContactSolver solver = core::ContactSolver::Handout)
{
    core::NetOptions net;
    net.rows = 10;
    net.cols = 10;
    net.spacing = 0.12;   // m
    net.height = 1.0;     // m
    net.mass = 0.05;      // kg
    net.radius = 0.05;    // m
    net.stiffness = 200;  // N/m
    net.damping = 0.05;   // N·s/m
    net.pinEdges = false;
    core::SceneDesc scene = core::makeNet(net);
    scene.name = "golden";
    scene.settings.timeStep = 0.002;  // s
    scene.settings.restitution = 0.8;
    scene.settings.contactSolver = solver;
    scene.settings.friction = solver == core::ContactSolver::Iterative ? 0.3 : 0.0;
    scene.settings.planeCollisions = true;
    scene.settings.particleCollisions = true;
    scene.planes = {core::PlaneDesc{Eigen::Vector3d(0.0, 1.0, 0.0), 0.0}};

    // the pile, each ball offset by a few millimetres in a fixed pattern so that nothing is symmetric
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 5; ++k) {
                const int n = (i * 4 + j) * 5 + k;
                const Eigen::Vector3d jitter(0.001 * (n % 7), 0.0005 * (n % 3), 0.001 * (n % 5));
                const Eigen::Vector3d at(-0.22 + 0.11 * i, 0.06 + 0.11 * j, -0.22 + 0.11 * k);
                scene.particles.push_back(test::particle(at + jitter, Eigen::Vector3d::Zero(), 0.1, 0.05));
            }
    return scene;
}

using core::stateHash;

// the hash after kSteps steps, or 0 when the run blew up
std::uint64_t runAndHash(const core::SceneDesc &scene)
{
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < kSteps; ++i)
        if (!sim.step())
            return 0;
    return stateHash(sim.state);
}

QString hex(std::uint64_t value)
{
    return QStringLiteral("0x%1").arg(value, 16, 16, QLatin1Char('0'));
}

}  // namespace

class TestGoldenHash : public QObject {
    Q_OBJECT

private slots:
    void matchesGolden_data();
    void matchesGolden();
    void sameRunSameHash();
    void oneUlpChangesHash();
};

void TestGoldenHash::matchesGolden_data()
{
    QTest::addColumn<int>("solver");
    QTest::addColumn<quint64>("golden");
    QTest::newRow("handout contacts") << int(core::ContactSolver::Handout) << quint64(kGoldenHash);
    QTest::newRow("iterative contacts, friction") << int(core::ContactSolver::Iterative)
                                                  << quint64(kGoldenIterativeHash);
}

void TestGoldenHash::matchesGolden()
{
    QFETCH(int, solver);
    QFETCH(quint64, golden);
    const std::uint64_t hash = runAndHash(goldenScene(static_cast<core::ContactSolver>(solver)));
    QVERIFY2(hash != 0, "the golden run blew up");
    QVERIFY2(hash == golden, qPrintable(u"got "_s + hex(hash) + u", expected "_s + hex(golden)));
}

void TestGoldenHash::sameRunSameHash()
{
    const core::SceneDesc scene = goldenScene();
    const std::uint64_t first = runAndHash(scene);
    QVERIFY(first != 0);
    QCOMPARE(runAndHash(scene), first);
}

void TestGoldenHash::oneUlpChangesHash()
{
    // one ulp on one ball's x: the hash sees it, so the golden comparison can fail
    const core::SceneDesc scene = goldenScene();
    core::SceneDesc nudged = scene;
    double &x = nudged.particles.back().position.x();
    x = std::nextafter(x, 1.0);
    QVERIFY(nudged.particles.back().position.x() != scene.particles.back().position.x());
    const std::uint64_t hash = runAndHash(nudged);
    QVERIFY(hash != 0);
    QVERIFY2(hash != runAndHash(scene), qPrintable(hex(hash)));
}

QTEST_GUILESS_MAIN(TestGoldenHash)
#include "test_golden_hash.moc"
