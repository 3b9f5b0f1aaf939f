#pragma once
// The scenes of the throughput benchmark and the bytes a sub-step of each must move at the least
// (the accounting is spelled out in throughput_scenes.cpp and docs/benchmarks.md).

#include "core/model/scene.h"

namespace bench {

// an n × n cloth (core::makeCloth: structural, shear and bend springs, about 6 per particle, the
// two corners of its first row pinned) under gravity, no contacts, symplectic Euler, one sub-step
// of 0.5 ms per step (inside the stability limit: ω h ≤ 1.2, see core/model/generators.h)
core::SceneDesc throughputCloth(int n);

// `particles` particles, no springs, in a closed box of six planes at a volume fraction of 30%,
// on a jittered lattice with seeded random speeds, under gravity; particle and plane contacts on
core::SceneDesc throughputBox(int particles);

inline constexpr double kClothTimeStep = 5e-4;       // s
inline constexpr double kBoxVolumeFraction = 0.3;
inline constexpr double kBoxRadius = 0.05;           // m
inline constexpr double kBoxTimeStep = 2e-3;         // s

// bytes one sub-step of a cloth must move at the least: per particle, read x, v, m and 1/m, read
// and write the force, write x and v (20 doubles, 160 B); per spring, read both ends' indices
// (2 × 4 B), the rest length, the stiffness and the damping (3 × 8 B): 32 B
double clothBytesPerSubstep(long long particles, long long springs);

// bytes one sub-step of the box must move at the least: per particle, read and write x and v,
// read m, 1/m and the radius (15 doubles, 120 B). A loose lower bound: the contacts cost compute
// (and the broad phase memory) that no bandwidth figure captures
double boxBytesPerSubstep(long long particles);

}  // namespace bench
