#pragma once
// A torn sheet, and the check that a run resumed from a file stored after its springs broke goes on
// to the bit: shared by the integrators' tests (test_xpbd, test_stiff_solvers).

#include "core/model/generators.h"
#include "scene_builder.h"

#include <QtTest>

#include <vector>

namespace test {

// 12 × 12, held along two edges, its springs breaking at 10% strain, and a heavy ball dropped
// through it
inline core::SceneDesc tornSheet(core::Integrator integrator, int substeps)
{
    core::ClothOptions options;
    options.rows = options.cols = 12;
    options.pinCorners = false;
    options.substeps = substeps;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.integrator = integrator;
    scene.settings.particleCollisions = true;
    for (int c = 0; c < options.cols; ++c) {
        scene.particles[std::size_t(c)].pinned = true;
        scene.particles[std::size_t((options.rows - 1) * options.cols + c)].pinned = true;
    }
    for (core::SpringDesc &spring : scene.springs)
        spring.breakStrain = 0.1;
    scene.particles.push_back(particle({0.0, options.height + 0.3, 0.0}, Eigen::Vector3d::Zero(), 4.0, 0.08));
    return scene;
}

// runs `whole` (compiled from scene) for `steps` steps; from the first break on, every `every`
// steps, stores the state as springlab-sim --output stores it (the broken springs left out) and
// resumes from the stored scene, which must end on the uninterrupted run's positions and
// velocities to the bit. The caller checks QTest::currentTestFailed()
inline void checkResumeAfterBreaks(const core::SceneDesc &scene, Sim &whole, int steps, int every)
{
    std::vector<core::State> states;
    int firstBreak = -1;
    for (int i = 0; i < steps; ++i) {
        states.push_back(whole.state);
        QVERIFY(whole.step());
        if (firstBreak < 0 && !whole.state.breaks.empty())
            firstBreak = i + 1;
    }
    QVERIFY2(firstBreak > 0 && firstBreak < steps - 10, "the sheet should tear early in the run");
    QVERIFY(whole.state.breaks.size() > 3);
    for (int split = firstBreak; split < steps; split += every) {
        core::SceneDesc stored = scene;
        core::storeState(states[std::size_t(split)], stored);
        QVERIFY(stored.springs.size() < scene.springs.size());
        Sim resumed = compile(stored);
        for (int i = split; i < steps; ++i)
            QVERIFY(resumed.step());
        QVERIFY2(resumed.state.position == whole.state.position,
                 qPrintable(QStringLiteral("resumed at step %1: positions differ").arg(split)));
        QVERIFY2(resumed.state.velocity == whole.state.velocity,
                 qPrintable(QStringLiteral("resumed at step %1: velocities differ").arg(split)));
    }
}

}  // namespace test
