#pragma once
// The stiff cloth of `springlab-bench stiff` (stiff.cpp), kept in a header of its own so that its
// test builds exactly the same scene when it runs a row again: an n × n core::makeCloth with the
// generator's spacing (0.05 m), mass (5 g a particle) and damping (0.02 N·s/m a spring), pinned at
// the two corners of its first row, structural springs of k, shear of 0.2 k and bend of 0.03 k (the
// examples' proportions), no contacts, steps of 0.01 s.

#include "core/model/generators.h"
#include "core/model/scene.h"

#include <string>

namespace bench {

inline constexpr double kStiffTimeStep = 0.01;   // s, the step h, split into the sub-steps
inline constexpr double kStiffDuration = 1.0;    // s of draping from flat
inline constexpr double kShearShare = 0.2;       // shear stiffness / structural
inline constexpr double kBendShare = 0.03;       // bend stiffness / structural
inline constexpr double kStretchLimit = 0.01;    // the largest structural stretch allowed, (l - l0) / l0
// how far above its start the total energy may go and still count as not risen: rounding, a
// fraction of the start's magnitude
inline constexpr double kEnergyRounding = 1e-9;

// the cloth of n × n particles with structural stiffness k (N/m), to be run by `integrator` at
// `substeps` sub-steps of each 0.01 s step
inline core::SceneDesc stiffCloth(int n, double stiffness, core::Integrator integrator, int substeps)
{
    core::ClothOptions options;
    options.rows = n;
    options.cols = n;
    options.structuralStiffness = stiffness;
    options.shearStiffness = kShearShare * stiffness;
    options.bendStiffness = kBendShare * stiffness;
    options.substeps = substeps;
    core::SceneDesc scene = core::makeCloth(options);
    scene.name = "stiff-cloth-" + std::to_string(n);
    scene.settings.timeStep = kStiffTimeStep;
    scene.settings.substeps = substeps;
    scene.settings.integrator = integrator;
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    return scene;
}

// makeCloth lays the structural springs down first, along the rows and then down the columns: the
// first this many of the scene's springs
inline int structuralSpringCount(int n)
{
    return 2 * n * (n - 1);
}

}  // namespace bench
