#pragma once
// The scenes of `springlab-bench contacts` (contacts.h), one function each: balls of r = 5 cm on a
// floor, in the forms the contact targets name. Each is a plain SceneDesc that both engines
// build from (the core, and Bullet's rigid spheres in bullet_spheres.h), with what the benchmark
// measures on it and, for the heap, the rate at which its balls are poured in.

#include "core/model/scene.h"

#include <string>

namespace bench {

inline constexpr double kBallRadius = 0.05;         // m, every ball's
inline constexpr double kContactTimeStep = 0.01;    // s, h
inline constexpr double kContactRestitution = 0.5;  // e, every contact
inline constexpr double kContactFriction = 0.5;     // μ, static and kinetic, every contact

// what a scene is judged by (contacts.cpp)
enum class ContactCheck {
    Column,   // stands: the top ball ends within 1% of r of where it started
    Pyramid,  // stands: no ball ends more than 1% of r from where it started
    Pile,     // settles: kinetic energy below 1e-3 N m g r, and the deepest overlap left
    Heap,     // settles, and the slope of the heap it leaves: the angle of repose
};

struct ContactScene {
    std::string name;  // "column", "pyramid", "pile", "pile-4sub", "heap": the CSV's scene
    core::SceneDesc scene;  // every ball, in the order they enter
    double duration = 0.0;  // s simulated
    ContactCheck check = ContactCheck::Pile;
    // s between one ball entering and the next (the heap's pour: ball k enters at k × interval);
    // 0: every ball is there from the start
    double releaseInterval = 0.0;
};

// 30 balls of 1 kg stacked on the floor, touching, at rest
ContactScene contactColumn(double duration);
// 210 balls of 1 kg in the plane z = 0, a triangle of 20 rows on the floor (20 at the bottom), at rest
ContactScene contactPyramid(double duration);
// `balls` of 0.1 kg on a jittered lattice (8 × 8 a layer, 12 cm apart), dropped into a box 1 m wide
// (a floor and 4 walls, open at the top), at `substeps` sub-steps a step
ContactScene contactPile(int balls, int substeps, double duration);
// `balls` of 0.1 kg poured onto an open floor (no walls) from a point 2 m up, one every 0.05 s at
// 2 m/s downwards, each a millimetre or less off the axis so that none lands exactly on another
ContactScene contactHeap(int balls, double duration);

}  // namespace bench
