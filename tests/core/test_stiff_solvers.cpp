// The stiff solvers (core/integrators/projective.cpp, vbd.cpp, implicit_euler.cpp): each solves the
// same backward Euler step. What a user relies on: a hanging mass stretches by m g / k whatever the
// stiffness and step (the statics are exact); the two iterative solvers converge to one answer and
// more iterations bring them closer; without springs they are the inertial step exactly; pins hold;
// the bits do not depend on the thread count; a resumed run goes on to the bit, torn springs
// included; a live stiffness edit is taken at once; the implicit solve is exact to rounding and its
// conjugate-gradient variant agrees with it; the residual is reported.

#include "core/integrators/solver_report.h"
#include "core/integrators/stability.h"
#include "core/model/diagnostics.h"
#include "core/model/generators.h"
#include "core/passes.h"
#include "core/threads.h"
#include "scene_builder.h"
#include "torn_sheet.h"

#include <QtTest>

#include <cmath>

class TestStiffSolvers : public QObject {
    Q_OBJECT
private slots:
    void hangingMassStretchesByItsWeight_data();
    void hangingMassStretchesByItsWeight();
    void iterativeSolversConvergeToOneStep();
    void moreIterationsLeaveLessResidual_data();
    void moreIterationsLeaveLessResidual();
    void withoutSpringsItIsTheInertialStep_data();
    void withoutSpringsItIsTheInertialStep();
    void sameBitsOnAnyThreadCount_data();
    void sameBitsOnAnyThreadCount();
    void resumedAfterABreakGoesOnToTheBit_data();
    void resumedAfterABreakGoesOnToTheBit();
    void aStiffnessEditIsTakenAtOnce();
    void aMovedSpringIsFactoredAgain();
    void nothingFreeIsNothingToSolve_data();
    void nothingFreeIsNothingToSolve();
    void directAndConjugateGradientsAgree();
    void cappedConjugateGradientsGiveWayToTheFactorisation();
    void stiffChainFallsAtG_data();
    void stiffChainFallsAtG();
    void stiffChainOnTheFloorGainsNoEnergy_data();
    void stiffChainOnTheFloorGainsNoEnergy();
    void unconvergedRunIsWarned();
    void noStabilityLimitAndNamesInFiles();
};

namespace {

// one particle of 1 kg hanging from a pinned one by a damped spring of rest length 1 m
core::SceneDesc hangingMass(core::Integrator integrator, double stiffness)
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
    scene.settings.integrator = integrator;
    scene.settings.solverIterations = 20;
    scene.particles = {test::particle({0.0, 0.0, 0.0}, Eigen::Vector3d::Zero(), 1.0, 0.05, true),
                       test::particle({0.0, -1.0, 0.0})};
    core::addSpring(scene, 0, 1, stiffness, 2.0 * std::sqrt(stiffness));  // critically damped
    scene.springs[0].restLength = 1.0;
    return scene;
}

core::SceneDesc cloth(int size, double stiffness, core::Integrator integrator, int substeps)
{
    core::ClothOptions options;
    options.rows = size;
    options.cols = size;
    options.structuralStiffness = stiffness;
    options.shearStiffness = 0.2 * stiffness;
    options.bendStiffness = 0.03 * stiffness;
    options.substeps = substeps;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.integrator = integrator;
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    return scene;
}

void addSolvers()
{
    QTest::addColumn<core::Integrator>("integrator");
    QTest::newRow("projective") << core::Integrator::Projective;
    QTest::newRow("vbd") << core::Integrator::Vbd;
}

}  // namespace

void TestStiffSolvers::hangingMassStretchesByItsWeight_data()
{
    QTest::addColumn<core::Integrator>("integrator");
    QTest::addColumn<double>("stiffness");
    for (double k : {1e2, 1e5, 1e8}) {
        QTest::addRow("projective k=%g", k) << core::Integrator::Projective << k;
        QTest::addRow("vbd k=%g", k) << core::Integrator::Vbd << k;
        QTest::addRow("implicit-euler k=%g", k) << core::Integrator::ImplicitEuler << k;
    }
}

void TestStiffSolvers::hangingMassStretchesByItsWeight()
{
    // backward Euler's fixed point is the equilibrium: after the damped spring settles the mass hangs
    // m g / k below its rest length, at one sub-step of 0.01 s whatever k (symplectic Euler would
    // need sub-steps under 2/ω = 2e-4 s at 1e8 N/m)
    QFETCH(core::Integrator, integrator);
    QFETCH(double, stiffness);
    test::Sim sim = test::compile(hangingMass(integrator, stiffness));
    for (int i = 0; i < 3000; ++i)
        QVERIFY(sim.step());
    const double stretch = -sim.state.position(1, 1) - 1.0;
    const double expected = 9.81 / stiffness;
    QVERIFY2(std::abs(stretch - expected) <= 1e-6 * expected + 1e-12,
             qPrintable(QStringLiteral("stretch %1 m, m g / k = %2 m").arg(stretch).arg(expected)));
    QVERIFY(sim.state.position.col(0).isZero());  // the pin holds
}

void TestStiffSolvers::iterativeSolversConvergeToOneStep()
{
    // five steps of a 12 × 12 cloth at 1e3 N/m: projective and vbd minimise the same energy, so as
    // their iterations grow they land on the same positions
    double last = std::numeric_limits<double>::infinity();
    for (int iterations : {5, 50, 200}) {
        Eigen::Matrix3Xd ends[2];
        int r = 0;
        for (core::Integrator integrator : {core::Integrator::Projective, core::Integrator::Vbd}) {
            core::SceneDesc scene = cloth(12, 1e3, integrator, 1);
            scene.settings.solverIterations = iterations;
            test::Sim sim = test::compile(scene);
            for (int i = 0; i < 5; ++i)
                QVERIFY(sim.step());
            ends[r++] = sim.state.position;
        }
        const double difference = (ends[0] - ends[1]).cwiseAbs().maxCoeff();
        qInfo("%d iterations: projective and vbd differ by %.3g m after 5 steps", iterations, difference);
        QVERIFY2(difference < 0.5 * last, qPrintable(QString::number(difference)));
        last = difference;
    }
    QVERIFY2(last < 5e-5, qPrintable(QString::number(last)));  // of a 12 mm drop
}

void TestStiffSolvers::moreIterationsLeaveLessResidual_data()
{
    addSolvers();
}

void TestStiffSolvers::moreIterationsLeaveLessResidual()
{
    QFETCH(core::Integrator, integrator);
    double last = std::numeric_limits<double>::infinity();
    for (int iterations : {2, 8, 32}) {
        core::SceneDesc scene = cloth(16, 1e5, integrator, 1);
        scene.settings.solverIterations = iterations;
        test::Sim sim = test::compile(scene);
        QVERIFY(sim.step());
        const double residual = sim.work.profile.solverResidual;
        qInfo("%d iterations: residual %.3g", iterations, residual);
        QCOMPARE(sim.work.profile.solverIterations, iterations);
        QVERIFY2(residual < last, qPrintable(QString::number(residual)));
        last = residual;
    }
    QVERIFY(last < 0.5);
}

void TestStiffSolvers::withoutSpringsItIsTheInertialStep_data()
{
    addSolvers();
}

void TestStiffSolvers::withoutSpringsItIsTheInertialStep()
{
    // a thrown particle under gravity: v += h g, x += h v, as symplectic Euler steps it
    QFETCH(core::Integrator, integrator);
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
    scene.particles = {test::particle({0.0, 1.0, 0.0}, {2.0, 3.0, 0.0})};
    scene.settings.integrator = core::Integrator::SymplecticEuler;
    test::Sim reference = test::compile(scene);
    scene.settings.integrator = integrator;
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 50; ++i) {
        QVERIFY(reference.step());
        QVERIFY(sim.step());
    }
    QVERIFY((sim.state.position - reference.state.position).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY((sim.state.velocity - reference.state.velocity).cwiseAbs().maxCoeff() < 1e-9);
}

void TestStiffSolvers::sameBitsOnAnyThreadCount_data()
{
    addSolvers();
}

void TestStiffSolvers::sameBitsOnAnyThreadCount()
{
    // 160 × 160: vbd's colours hold over core::kParallelMinimum particles each, and projective's
    // springs are split between the threads
    QFETCH(core::Integrator, integrator);
    core::SceneDesc scene = cloth(160, 1e6, integrator, 1);
    scene.settings.solverIterations = 3;
    Eigen::Matrix3Xd ends[2];
    for (int threads : {1, 2}) {
        core::setThreadCount(threads);
        test::Sim sim = test::compile(scene);
        for (int i = 0; i < 2; ++i)
            QVERIFY(sim.step());
        ends[threads - 1] = sim.state.position;
    }
    core::setThreadCount(0);
    QVERIFY(ends[0] == ends[1]);
}

void TestStiffSolvers::resumedAfterABreakGoesOnToTheBit_data()
{
    addSolvers();
}

void TestStiffSolvers::resumedAfterABreakGoesOnToTheBit()
{
    // the torn sheet: a run stored at a step after the first break and resumed from the stored
    // scene goes on as the uninterrupted run does, to the bit (projective factors again after each
    // break; vbd colours again without the broken springs)
    QFETCH(core::Integrator, integrator);
    const core::SceneDesc scene = test::tornSheet(integrator, 4);
    test::Sim whole = test::compile(scene);
    test::checkResumeAfterBreaks(scene, whole, 90, 11);
    if (QTest::currentTestFailed())
        return;
    if (integrator == core::Integrator::Projective)
        QVERIFY(whole.work.profile.factorisations > 1);
}

void TestStiffSolvers::aStiffnessEditIsTakenAtOnce()
{
    // projective keeps its factorisation while nothing changes, and makes a new one in the step
    // after a stiffness edit (a new model, the same workspace, as the editor's worker steps it)
    core::SceneDesc scene = hangingMass(core::Integrator::Projective, 1e3);
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 10; ++i)
        QVERIFY(sim.step());
    QCOMPARE(sim.work.profile.factorisations, std::uint64_t(1));
    scene.springs[0].stiffness = 1e6;
    sim.model = core::compileModel(scene);
    for (int i = 0; i < 2000; ++i)
        QVERIFY(sim.step());
    QCOMPARE(sim.work.profile.factorisations, std::uint64_t(2));
    const double stretch = -sim.state.position(1, 1) - 1.0;
    QVERIFY2(std::abs(stretch - 9.81e-6) < 1e-11, qPrintable(QString::number(stretch)));
}

void TestStiffSolvers::aMovedSpringIsFactoredAgain()
{
    // an edit that moves a spring's end and keeps its stiffness changes the matrix all the same:
    // the particle hangs from its new anchor, not the old one
    core::SceneDesc scene = hangingMass(core::Integrator::Projective, 1e3);
    scene.particles.push_back(test::particle({1.0, 0.0, 0.0}, Eigen::Vector3d::Zero(), 1.0, 0.05, true));
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 10; ++i)
        QVERIFY(sim.step());
    scene.springs[0].a = 2;  // from the anchor at x = 1 m
    sim.model = core::compileModel(scene);
    for (int i = 0; i < 300; ++i)
        QVERIFY(sim.step());
    QCOMPARE(sim.work.profile.factorisations, std::uint64_t(2));
    // it swings on a spring of 1 m from the new anchor (√2 m away when the spring moved)
    const double fromAnchor = (sim.state.position.col(1) - sim.state.position.col(2)).norm();
    QVERIFY2(fromAnchor > 0.99 && fromAnchor < 1.05, qPrintable(QString::number(fromAnchor)));
}

void TestStiffSolvers::nothingFreeIsNothingToSolve_data()
{
    QTest::addColumn<core::Integrator>("integrator");
    QTest::newRow("projective") << core::Integrator::Projective;
    QTest::newRow("vbd") << core::Integrator::Vbd;
    QTest::newRow("implicit-euler direct") << core::Integrator::ImplicitEuler;
}

void TestStiffSolvers::nothingFreeIsNothingToSolve()
{
    // every particle pinned (an edit can leave a scene so): the step has nothing to solve, and
    // neither crashes nor moves anything (the sparse factorisations refuse an empty matrix)
    QFETCH(core::Integrator, integrator);
    core::SceneDesc scene = hangingMass(integrator, 1e3);
    scene.particles[1].pinned = true;
    test::Sim sim = test::compile(scene);
    sim.work.implicitSolve = core::Workspace::ImplicitSolve::Direct;
    const core::State before = sim.state;
    for (int i = 0; i < 3; ++i)
        QVERIFY(sim.step());
    QVERIFY(sim.state.position == before.position);
    QVERIFY(sim.state.velocity == before.velocity);
}

void TestStiffSolvers::directAndConjugateGradientsAgree()
{
    // implicit Euler's direct solve is exact to rounding; its block-Jacobi conjugate gradients stop
    // at a relative residual of 1e-10 and so agree with it to about that
    core::SceneDesc scene = cloth(16, 1e6, core::Integrator::ImplicitEuler, 1);
    test::Sim direct = test::compile(scene);
    direct.work.implicitSolve = core::Workspace::ImplicitSolve::Direct;
    test::Sim iterative = test::compile(scene);
    iterative.work.implicitSolve = core::Workspace::ImplicitSolve::ConjugateGradients;
    for (int i = 0; i < 5; ++i) {
        QVERIFY(direct.step());
        QVERIFY(iterative.step());
    }
    QVERIFY(direct.work.profile.solverResidual < 1e-12);
    QCOMPARE(direct.work.profile.solverIterations, 0);
    QVERIFY(iterative.work.profile.solverIterations > 0);
    QVERIFY(iterative.work.profile.solverResidual <= 1e-10);
    QCOMPARE(iterative.work.profile.solverCapHits, std::uint64_t(0));
    const double difference = (direct.state.position - iterative.state.position).cwiseAbs().maxCoeff();
    QVERIFY2(difference < 1e-9, qPrintable(QString::number(difference)));
}

void TestStiffSolvers::cappedConjugateGradientsGiveWayToTheFactorisation()
{
    // the stiff-chain example's chain (1000 links of 1 cm, 1 g, 1e8 N/m) at one sub-step of 10 ms:
    // conjugate gradients alone stop at their cap (where the chain once fell at a quarter of g);
    // by default the capped sub-step is solved directly, and the model's later ones too
    core::ChainOptions options;
    options.links = 1000;
    options.linkLength = 0.01;
    options.mass = 0.001;
    options.radius = 0.005;
    options.stiffness = 1e8;
    options.damping = 1.0;
    options.height = 1.5;
    core::SceneDesc scene = core::makeChain(options);
    scene.settings.integrator = core::Integrator::ImplicitEuler;
    scene.settings.particleCollisions = false;
    test::Sim alone = test::compile(scene);
    alone.work.implicitSolve = core::Workspace::ImplicitSolve::ConjugateGradients;
    test::Sim automatic = test::compile(scene);
    for (int i = 0; i < 3; ++i) {
        QVERIFY(alone.step());
        QVERIFY(automatic.step());
    }
    QVERIFY(alone.work.profile.solverCapHits > 0);
    QVERIFY(!core::solverWarning(core::Integrator::ImplicitEuler, alone.work.profile).empty());
    QCOMPARE(automatic.work.profile.solverCapHits, std::uint64_t(0));
    // from rest the first sub-step converges; once one has stopped at the cap, each is factored
    QVERIFY(automatic.work.profile.factorisations >= 1);
    QVERIFY(automatic.work.profile.solverIterations == 0);  // the last sub-step was factored
    QVERIFY(automatic.work.profile.worstSolverResidual < 1e-10);
    QVERIFY(core::solverWarning(core::Integrator::ImplicitEuler, automatic.work.profile).empty());
}

void TestStiffSolvers::stiffChainFallsAtG_data()
{
    QTest::addColumn<core::Integrator>("integrator");
    QTest::newRow("implicit-euler") << core::Integrator::ImplicitEuler;
    QTest::newRow("projective") << core::Integrator::Projective;
    QTest::newRow("vbd") << core::Integrator::Vbd;
}

void TestStiffSolvers::stiffChainFallsAtG()
{
    // a free chain of 20 particles joined by springs of 1e7 N/m, dropped: stiff springs carry no
    // load in free fall, so it falls g t²/2 (4.9 cm in 0.1 s) as one body; backward Euler's first
    // step is exact here, so the drop is within a step's h g t of the closed form
    QFETCH(core::Integrator, integrator);
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
    scene.settings.integrator = integrator;
    scene.settings.timeStep = 0.01;
    for (int i = 0; i < 20; ++i)
        scene.particles.push_back(test::particle({0.05 * i, 0.0, 0.0}, Eigen::Vector3d::Zero(), 0.01, 0.01));
    for (int i = 0; i + 1 < 20; ++i)
        core::addSpring(scene, i, i + 1, 1e7, 1.0);
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 10; ++i)
        QVERIFY(sim.step());
    const double drop = -sim.state.position.row(1).mean();
    const double closedForm = 0.5 * 9.81 * 0.1 * 0.1;
    QVERIFY2(std::abs(drop - closedForm) <= 9.81 * 0.01 * 0.1,
             qPrintable(QStringLiteral("dropped %1 m, g t²/2 = %2 m").arg(drop).arg(closedForm)));
}

void TestStiffSolvers::stiffChainOnTheFloorGainsNoEnergy_data()
{
    QTest::addColumn<core::Integrator>("integrator");
    QTest::addColumn<double>("stiffness");
    for (double k : {1e5, 1e8}) {
        QTest::addRow("projective k=%g", k) << core::Integrator::Projective << k;
        QTest::addRow("vbd k=%g", k) << core::Integrator::Vbd << k;
        QTest::addRow("xpbd k=%g", k) << core::Integrator::Xpbd << k;
        QTest::addRow("implicit-euler k=%g", k) << core::Integrator::ImplicitEuler << k;
    }
}

void TestStiffSolvers::stiffChainOnTheFloorGainsNoEnergy()
{
    // the stiff-chain example's links (1 cm, 1 g), 400 of them, released horizontally from a
    // pinned end 1 m over the floor, 10 sub-steps (xpbd 100) of 10 iterations: nothing adds
    // energy, so the motion's energy (kinetic and gravitational: the spring energy of a stiff
    // chain the solver has not converged is nominal, as xpbd's is) never rises above the start's
    // total as the chain strikes the floor. With vbd's sweeps over-relaxed as projective's are, it
    // rose tenfold or blew up
    QFETCH(core::Integrator, integrator);
    QFETCH(double, stiffness);
    core::ChainOptions options;
    options.links = 400;
    options.linkLength = 0.01;
    options.mass = 0.001;
    options.radius = 0.005;
    options.stiffness = stiffness;
    options.damping = 1.0;
    options.height = 1.0;
    core::SceneDesc scene = core::makeChain(options);
    scene.settings.integrator = integrator;
    scene.settings.substeps = integrator == core::Integrator::Xpbd ? 100 : 10;
    scene.settings.particleCollisions = false;
    scene.planes = {core::floorPlane()};
    test::Sim sim = test::compile(scene);
    const double start = core::energies(*sim.model, sim.state).total();
    double highest = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < 80; ++i) {
        QVERIFY(sim.step());
        const core::Energies e = core::energies(*sim.model, sim.state);
        highest = std::max(highest, e.kinetic + e.gravitational);
    }
    // it reached the floor; vbd's unconverged chain at 1e8 N/m swings down as a stiffer rod would,
    // and has not in 0.8 s
    const bool open = stiffness > 1e7 && core::isVariational(integrator);
    QVERIFY(sim.state.position.row(1).minCoeff() < 0.1 || (open && integrator == core::Integrator::Vbd));
    if (open)
        QEXPECT_FAIL("", "open: at 1e8 N/m the unconverged solves release stretch on the impact (5.8-7.5 J from 3.9)",
                     Continue);
    QVERIFY2(highest <= start + 1e-9 * std::abs(start),
             qPrintable(QStringLiteral("kinetic and gravitational energy rose from %1 J to %2 J").arg(start).arg(highest)));
}

void TestStiffSolvers::unconvergedRunIsWarned()
{
    // vbd with 3 sweeps a sub-step on a stiff cloth at 10 sub-steps: by the fifth step a sub-step
    // leaves over 90% of its gradient (a sweep carries a pull one particle on), and the report says so
    core::SceneDesc scene = cloth(32, 1e6, core::Integrator::Vbd, 10);
    scene.settings.solverIterations = 3;
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 5; ++i)
        QVERIFY(sim.step());
    QVERIFY(sim.work.profile.worstSolverResidual > core::kUnconvergedResidual);
    const std::string warning = core::solverWarning(sim.model->integrator, sim.work.profile);
    QVERIFY2(warning.find("solverIterations") != std::string::npos, warning.c_str());
    QVERIFY(!core::solverSummary(sim.model->integrator, sim.work.profile).empty());
    // the hanging mass converges: no warning
    test::Sim settled = test::compile(hangingMass(core::Integrator::Vbd, 1e3));
    for (int i = 0; i < 10; ++i)
        QVERIFY(settled.step());
    QVERIFY(core::solverWarning(settled.model->integrator, settled.work.profile).empty());
}

void TestStiffSolvers::noStabilityLimitAndNamesInFiles()
{
    for (core::Integrator integrator : {core::Integrator::Projective, core::Integrator::Vbd}) {
        test::Sim sim = test::compile(hangingMass(integrator, 1e8));
        const core::StabilityLimit limit = core::stabilityLimit(*sim.model, sim.state);
        QVERIFY(std::isinf(limit.maxSubStep(integrator)));
        QCOMPARE(core::integratorFromName(core::integratorName(integrator)), std::optional(integrator));
        QCOMPARE(core::integratorOrder(integrator), 1);
        QVERIFY(core::isVariational(integrator));
    }
    QCOMPARE(core::integratorName(core::Integrator::Projective), std::string_view("projective"));
    QCOMPARE(core::integratorName(core::Integrator::Vbd), std::string_view("vbd"));
}

QTEST_GUILESS_MAIN(TestStiffSolvers)
#include "test_stiff_solvers.moc"
