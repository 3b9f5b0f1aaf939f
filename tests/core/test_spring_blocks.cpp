// The fused lattice sub-step (core/springs/spring_blocks.cpp) against the separate passes it replaces:
// the same bits on random runs of every shape, with and without gravity, drag, applied forces,
// pins and broken springs, on 1 and 2 threads; which models take it; its index of runs by block;
// its finite check; and its profile.

#include "core/model/generators.h"
#include "core/parallel.h"
#include "core/passes.h"
#include "core/step.h"
#include "core/threads.h"

#include "scene_builder.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdint>

class TestSpringBlocks : public QObject {
    Q_OBJECT

private slots:
    void latticeModelsUseBlocks();
    void indexListsEveryRunOfEachBlock();
    void joinsShortRunsAcrossSmallGaps();
    void runsOfOneKindAreUniform();
    void blocksEqualTheSeparatePassesToTheBit_data();
    void blocksEqualTheSeparatePassesToTheBit();
    void badValueStopsTheStep();
    void profileTimesTheFusedSubStep();
};

namespace {

struct Options {
    int particles = 600;
    bool gravity = false;
    bool drag = false;
    bool pins = false;
    bool rows = false;  // rows of runs a few particles apart, most of them joined (Model::joined)
};

// Runs of one offset after another in the list and in the numbering, as a lattice's rows are:
// lengths up to past kJoinRunsBelow and gaps up to past kJoinGap, so that some join and some do not;
// one row in three of one kind of spring (SpringRun::uniform)
void addRows(core::SceneDesc &scene, test::Lcg &next)
{
    const int n = static_cast<int>(scene.particles.size());
    for (const int offset : {1, -1, 2, 37, -37, 300}) {
        int a = std::max(0, -offset) + next(50);
        while (true) {
            const int count = 1 + next(core::kJoinRunsBelow + 100);
            if (a + count + std::max(0, offset) > n)
                break;
            const bool oneKind = next(3) == 0;
            core::SpringDesc spring{0, 0, 10.0 + next(1000), next(10) * 0.1, 0.5 + next(100) * 1e-2};
            for (int j = 0; j < count; ++j) {
                if (!oneKind)
                    spring = core::SpringDesc{0, 0, 10.0 + next(1000), next(10) * 0.1, 0.5 + next(100) * 1e-2};
                spring.a = a + j;
                spring.b = a + offset + j;
                scene.springs.push_back(spring);
            }
            a += count + 1 + next(core::kJoinGap + 3);
        }
    }
}

// Springs in runs whose ends lie 1 to kSpringBlock apart, in order and reversed, long and of one
// spring, so that runs cross blocks and thread shares on either side
core::SceneDesc randomRuns(const Options &options, std::uint32_t seed)
{
    core::SceneDesc scene = test::quietScene();
    if (options.gravity)
        scene.settings.gravity = Eigen::Vector3d(0.3, -9.81, 0.1);
    scene.settings.viscosity = options.drag ? 0.37 : 0.0;
    scene.settings.timeStep = 1e-3;
    test::Lcg next{seed};
    const int n = options.particles;
    for (int i = 0; i < n; ++i) {
        const bool pinned = options.pins && (i % 97 == 3 || (i >= 1000 && i < 1100));
        scene.particles.push_back(test::particle(Eigen::Vector3d(next(1000) * 1e-3, next(1000) * 1e-3, next(1000) * 1e-3),
                                                 pinned ? Eigen::Vector3d::Zero()
                                                        : Eigen::Vector3d(next(100) * 1e-2, next(100) * 1e-2, -0.2),
                                                 0.5 + next(100) * 1e-2, 0.01, pinned));
    }
    if (options.rows)
        addRows(scene, next);
    test::addRandomRuns(scene, {1, -1, 2, -3, 37, 1025, -1025, core::kSpringBlock, -core::kSpringBlock}, 600, next);
    return scene;
}

// the separate passes and the Euler update with Eigen columns, the way the fused step must match
void separateSubStep(const core::Model &model, core::State &state, core::Workspace &work, double h, bool symplectic)
{
    if (model.plan.gravity)
        core::startWithGravity(model, state, work);
    else
        work.force.setZero();
    core::addDrag(model, state, work);
    core::addSpringsReference(model, state, work);
    core::addApplied(model, state, work);
    for (int p : model.freeParticles) {
        const double kick = h * model.invMass[p];
        const Eigen::Vector3d old = state.velocity.col(p);
        const Eigen::Vector3d next = old + kick * work.force.col(p);
        state.position.col(p) += h * (symplectic ? next : old);
        state.velocity.col(p) = next;
    }
}

}  // namespace

void TestSpringBlocks::latticeModelsUseBlocks()
{
    core::ClothOptions cloth;
    cloth.cols = cloth.rows = 40;
    QVERIFY(core::compileModel(core::makeCloth(cloth))->springLayout.blocks);

    // ends farther apart than a block: the springs would reach past the next block
    core::SceneDesc far = test::quietScene();
    const int n = 3 * core::kSpringBlock;
    for (int i = 0; i < n; ++i)
        far.particles.push_back(test::particle(Eigen::Vector3d(i * 1e-3, 0, 0)));
    for (int i = 0; i + core::kSpringBlock + 1 < n; ++i)
        far.springs.push_back(core::SpringDesc{i, i + core::kSpringBlock + 1, 10.0, 0.1, 1.0});
    const auto farModel = core::compileModel(far);
    QCOMPARE(farModel->springLayout.pass, core::SpringPass::Runs);
    QCOMPARE(farModel->springLayout.reach, core::kSpringBlock + 1);
    QVERIFY(!farModel->springLayout.blocks);

    // one block apart exactly: still within reach
    for (core::SpringDesc &spring : far.springs)
        spring.b -= 1;
    QVERIFY(core::compileModel(far)->springLayout.blocks);

    // no springs: nothing to fuse
    far.springs.clear();
    QVERIFY(!core::compileModel(far)->springLayout.blocks);
}

void TestSpringBlocks::indexListsEveryRunOfEachBlock()
{
    Options options;
    options.particles = 20000;
    const auto model = core::compileModel(randomRuns(options, 3u));
    QVERIFY(model->springLayout.blocks);
    const int blocks = (model->particleCount() + core::kSpringBlock - 1) / core::kSpringBlock;
    QCOMPARE(int(model->springLayout.blockRunOffsets.size()), blocks + 1);
    for (int q = 0; q < blocks; ++q) {
        const int lo = q * core::kSpringBlock;
        const int hi = lo + core::kSpringBlock;
        std::vector<int> expected;
        for (int r = 0; r < int(model->springLayout.runs.size()); ++r) {
            const core::SpringRun &run = model->springLayout.runs[std::size_t(r)];
            const auto touches = [&](int end) { return end < hi && end + run.count > lo; };
            if (touches(run.a) || touches(run.b))
                expected.push_back(r);
        }
        const core::SpringLayout &layout = model->springLayout;
        const std::vector<int> listed(layout.blockRuns.begin() + layout.blockRunOffsets[std::size_t(q)],
                                      layout.blockRuns.begin() + layout.blockRunOffsets[std::size_t(q) + 1]);
        QVERIFY(!expected.empty());
        QCOMPARE(listed, expected);
    }
}

// A cloth's rows joined: one run per kind of spring, each the list's runs of that kind end to end,
// their parameters in place and padding with none in the gaps; long runs and wide gaps stay apart
void TestSpringBlocks::joinsShortRunsAcrossSmallGaps()
{
    core::ClothOptions cloth;
    cloth.rows = cloth.cols = 64;
    const auto model = core::compileModel(core::makeCloth(cloth));
    QVERIFY(model->springLayout.blocks);
    const core::SpringLayout::JoinedRuns &joined = model->springLayout.joined;
    QCOMPARE(int(joined.runs.size()), 6);  // structural, shear and bend, two directions each
    int covered = 0;
    std::size_t r = 0;
    for (const core::SpringRun &into : joined.runs) {
        QCOMPARE(into.first, covered);
        // the list's runs that make it up, in order, each at its place
        int springs = 0;
        for (; r < model->springLayout.runs.size() && model->springLayout.runs[r].a < into.a + into.count &&
               model->springLayout.runs[r].b - model->springLayout.runs[r].a == into.b - into.a;
             ++r) {
            const core::SpringRun &run = model->springLayout.runs[r];
            const int at = into.first + run.a - into.a;
            QCOMPARE(joined.restLength.segment(at, run.count), model->restLength.segment(run.first, run.count));
            QCOMPARE(joined.stiffness.segment(at, run.count), model->stiffness.segment(run.first, run.count));
            QCOMPARE(joined.damping.segment(at, run.count), model->damping.segment(run.first, run.count));
            springs += run.count;
        }
        // what is not a spring is padding: nothing at all
        const int padding = into.count - springs;
        QCOMPARE(int((joined.stiffness.segment(into.first, into.count).array() == 0.0).count()), padding);
        QCOMPARE(int((joined.damping.segment(into.first, into.count).array() == 0.0).count()), padding);
        QVERIFY(padding < into.count / 8);
        covered += into.count;
    }
    QCOMPARE(r, model->springLayout.runs.size());
    QCOMPARE(int(joined.stiffness.size()), covered);

    // springs that can break: the state's flags are the list's, so nothing is joined
    core::SceneDesc tearable = core::makeCloth(cloth);
    tearable.springs[17].breakStrain = 0.2;
    const auto breakable = core::compileModel(tearable);
    QVERIFY(breakable->plan.springBreaks);
    QVERIFY(breakable->springLayout.blocks);
    QVERIFY(breakable->springLayout.joined.runs.empty());

    // rows of kJoinRunsBelow springs or more, or kJoinGap + 1 particles apart, stay the list's runs
    for (const bool wide : {false, true}) {
        core::SceneDesc rows = test::quietScene();
        const int length = wide ? 40 : core::kJoinRunsBelow;
        const int step = length + (wide ? core::kJoinGap + 1 : 1);
        for (int i = 0; i < 8 * step; ++i)
            rows.particles.push_back(test::particle(Eigen::Vector3d(i * 1e-2, 0, 0)));
        for (int row = 0; row < 7; ++row)
            for (int j = 0; j < length; ++j)
                rows.springs.push_back(core::SpringDesc{row * step + j, row * step + j + 1, 10.0, 0.1, 1e-2});
        const auto apart = core::compileModel(rows);
        QVERIFY(apart->springLayout.blocks);
        QCOMPARE(int(apart->springLayout.runs.size()), 7);
        QVERIFY(apart->springLayout.joined.runs.empty());
        // one particle nearer or one spring shorter: they join
        for (core::SpringDesc &spring : rows.springs) {
            const int row = spring.a / step;
            if (wide) {
                spring.a -= row;
                spring.b -= row;
            }
        }
        if (!wide)
            rows.springs.erase(std::remove_if(rows.springs.begin(), rows.springs.end(),
                                              [&](const core::SpringDesc &spring) { return spring.a % step == length - 1; }),
                               rows.springs.end());
        const auto near = core::compileModel(rows);
        QCOMPARE(int(near->springLayout.runs.size()), 7);
        QCOMPARE(int(near->springLayout.joined.runs.size()), 1);
    }
}

// A generated cloth's runs each hold one kind of spring, to the bit: one rest length, stiffness and
// damping. One value an ulp off, and its run is not
void TestSpringBlocks::runsOfOneKindAreUniform()
{
    core::ClothOptions options;
    options.rows = options.cols = 200;  // rows too long to join
    core::SceneDesc cloth = core::makeCloth(options);
    const auto model = core::compileModel(cloth);
    QVERIFY(model->springLayout.joined.runs.empty());
    QCOMPARE(int(model->springLayout.runs.size()), 200 + 199 + 199 + 200 + 2);  // rows of each kind, two columns
    for (const core::SpringRun &run : model->springLayout.runs)
        QVERIFY(run.uniform);
    for (const int field : {0, 1, 2}) {
        core::SceneDesc nudged = cloth;
        core::SpringDesc &spring = nudged.springs[1000];
        double &value = field == 0 ? spring.restLength : field == 1 ? spring.stiffness : spring.damping;
        value = std::nextafter(value, 1.0);
        const auto changed = core::compileModel(nudged);
        const auto uniformRuns = std::count_if(changed->springLayout.runs.begin(), changed->springLayout.runs.end(),
                                               [](const core::SpringRun &run) { return run.uniform; });
        QCOMPARE(int(uniformRuns), int(changed->springLayout.runs.size()) - 1);
        QVERIFY(!changed->springLayout.runs[std::size_t(1000 / 199)].uniform);
    }
}

void TestSpringBlocks::blocksEqualTheSeparatePassesToTheBit_data()
{
    QTest::addColumn<int>("particles");
    QTest::addColumn<bool>("symplectic");
    QTest::addColumn<bool>("gravity");
    QTest::addColumn<bool>("drag");
    QTest::addColumn<bool>("applied");
    QTest::addColumn<bool>("pins");
    QTest::addColumn<bool>("breakable");
    QTest::addColumn<bool>("rows");
    QTest::newRow("one block, springs only") << 600 << true << false << false << false << false << false << false;
    QTest::newRow("blocks, everything") << 20000 << true << true << true << true << true << false << false;
    QTest::newRow("blocks, explicit Euler") << 20000 << false << true << true << false << true << false << false;
    QTest::newRow("blocks, some springs broken") << 20000 << true << true << false << false << true << true << false;
    QTest::newRow("blocks, no gravity, applied") << 13001 << true << false << false << true << false << false << false;
    QTest::newRow("one block, joined rows") << 3000 << true << true << false << false << false << false << true;
    QTest::newRow("blocks, joined rows, everything") << 20000 << true << true << true << true << true << false << true;
    QTest::newRow("blocks, rows, some springs broken") << 20000 << true << true << false << false << true << true << true;
}

// three sub-steps fused and separate from the same state: every position and velocity equal to the
// bit, however the particles are shared out (shares cut inside blocks, runs crossing the cuts)
void TestSpringBlocks::blocksEqualTheSeparatePassesToTheBit()
{
    QFETCH(int, particles);
    QFETCH(bool, symplectic);
    QFETCH(bool, gravity);
    QFETCH(bool, drag);
    QFETCH(bool, applied);
    QFETCH(bool, pins);
    QFETCH(bool, breakable);
    QFETCH(bool, rows);
    Options options;
    options.particles = particles;
    options.gravity = gravity;
    options.drag = drag;
    options.pins = pins;
    options.rows = rows;
    core::SceneDesc scene = randomRuns(options, 29u);
    scene.settings.integrator = symplectic ? core::Integrator::SymplecticEuler : core::Integrator::ExplicitEuler;

    const auto prepare = [&](test::Sim &sim) {
        test::coincideAndBreak(sim, breakable);
        if (applied)
            for (int p = 7; p < particles; p += 501)
                core::setAppliedForce(sim.state, p, Eigen::Vector3d(0.5, -1.5, 2.5 + p * 1e-3));
    };
    const double h = 1e-3;

    test::Sim separate = test::compile(scene);
    QVERIFY(separate.model->springLayout.blocks);
    QCOMPARE(!separate.model->springLayout.joined.runs.empty(), rows);  // the random runs alone never join
    if (rows) {  // and are never of one kind; some rows are, and some of those stay alone
        const auto uniform = [](const std::vector<core::SpringRun> &runs) {
            return std::count_if(runs.begin(), runs.end(), [](const core::SpringRun &run) { return run.uniform && run.count > 1; });
        };
        QVERIFY(uniform(separate.model->springLayout.runs) > 0);
        QVERIFY(uniform(separate.model->springLayout.joined.runs) > 0);
    }
    QCOMPARE(separate.model->plan.gravity, gravity);
    QCOMPARE(separate.model->plan.drag, drag);
    prepare(separate);
    const Eigen::Matrix3Xd start = separate.state.position;
    for (int sub = 0; sub < 3; ++sub)
        separateSubStep(*separate.model, separate.state, separate.work, h, symplectic);
    QVERIFY(separate.state.position.cwiseNotEqual(start).any());

    // 1 and 2 threads, then 3 and 5 shares run one after another in both orders: each thread's
    // neighbours move their particles before it reads them, on either side, whatever the schedule
    struct Run {
        int threads;
        int sequential;
        bool descending;
    };
    const int before = core::threadCount();
    for (const Run run : {Run{1, 0, false}, Run{2, 0, false}, Run{1, 3, false}, Run{1, 3, true}, Run{1, 5, false},
                          Run{1, 5, true}}) {
        if (run.threads > core::maxThreadCount())
            continue;
        core::setThreadCount(run.threads);
        test::Sim fused = test::compile(scene);
        prepare(fused);
        for (int sub = 0; sub < 3; ++sub) {
            // it checked what it wrote, and all was well
            QVERIFY(core::stepSpringBlocks(*fused.model, fused.state, fused.work, h,
                                           core::SharesInTurn{run.sequential, run.descending}));
        }
        const Eigen::Index positions = (fused.state.position.array() != separate.state.position.array()).count();
        const Eigen::Index velocities = (fused.state.velocity.array() != separate.state.velocity.array()).count();
        QVERIFY2(positions == 0 && velocities == 0,
                 qPrintable(QString("%1 threads, %2 shares in turn%3: %4 positions and %5 velocities differ")
                                .arg(run.threads)
                                .arg(run.sequential)
                                .arg(run.descending ? " from the last" : "")
                                .arg(positions)
                                .arg(velocities)));
    }
    core::setThreadCount(before);
}

// a free particle's velocity past the bound in the middle of a block, on the far side of a thread
// share: the step stops and names it
void TestSpringBlocks::badValueStopsTheStep()
{
    Options options;
    options.particles = 20000;
    for (int culprit : {0, 9001, 19999}) {
        test::Sim sim = test::compile(randomRuns(options, 7u));
        QVERIFY(sim.model->springLayout.blocks);
        QVERIFY(sim.step());
        sim.state.velocity(1, culprit) = 2.0 * core::kBlowupBound;
        QVERIFY(!sim.step());
        QVERIFY(sim.work.blowup.has_value());
        QCOMPARE(sim.work.blowup->particle, culprit);
        QCOMPARE(sim.work.blowup->step, std::uint64_t(2));
    }
}

// the fused path is one stage of the profile: its force passes and update are not timed apart
void TestSpringBlocks::profileTimesTheFusedSubStep()
{
    Options options;
    options.particles = 9000;
    options.gravity = true;
    core::SceneDesc scene = randomRuns(options, 5u);
    scene.settings.substeps = 4;
    test::Sim sim = test::compile(scene);
    QVERIFY(sim.model->springLayout.blocks);
    QVERIFY(sim.step());
    QVERIFY(sim.step());
    const core::Profile &profile = sim.work.profile;
    QCOMPARE(sim.model->plan.subStep, core::SubStepPath::FusedLattice);
    QCOMPARE(profile[core::Stage::FusedSubStep].calls, std::uint64_t(8));
    QVERIFY(profile[core::Stage::FusedSubStep].seconds > 0.0);
    QCOMPARE(profile[core::Stage::Check].calls, std::uint64_t(8));
    // the stages it stands for: neither called nor timed
    for (const core::Stage stage : {core::Stage::Gravity, core::Stage::Drag, core::Stage::Springs, core::Stage::Applied,
                                    core::Stage::Integrate}) {
        QCOMPARE(profile[stage].calls, std::uint64_t(0));
        QCOMPARE(profile[stage].seconds, 0.0);
    }
    QCOMPARE(sim.work.profile.forceEvaluations, std::uint64_t(8));
}

QTEST_APPLESS_MAIN(TestSpringBlocks)
#include "test_spring_blocks.moc"
