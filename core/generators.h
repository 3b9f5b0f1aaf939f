#pragma once
// Scene generators: functions that build a SceneDesc, shared by the examples, the editor's
// Generate menu, the tests and the benchmarks.

#include "scene.h"

namespace core {

// a rows × cols net of particles in the horizontal plane y = height, neighbours joined by springs
// of rest length `spacing`; the first and last rows pinned (the handout's springs scene)
struct NetOptions {
    int rows = 11;
    int cols = 11;
    double spacing = 0.4;     // m
    double height = 0.0;      // m
    double mass = 10.0;       // kg
    double radius = 0.1;      // m
    double stiffness = 4e3;   // N/m
    double damping = 0.0;     // N·s/m
    bool pinEdges = true;     // pin the rows i = 0 and i = rows - 1
};
SceneDesc makeNet(const NetOptions &options);

// a cloth: an n × m sheet in the horizontal plane y = height with structural (neighbour), shear
// (diagonal) and bend (second neighbour) springs, pinned at the two corners of its first row
struct ClothOptions {
    int rows = 32;
    int cols = 32;
    double spacing = 0.05;                // m
    double height = 1.0;                  // m
    double mass = 0.005;                  // kg per particle
    double radius = 0.02;                 // m
    double structuralStiffness = 3000.0;  // N/m
    double shearStiffness = 600.0;        // N/m
    double bendStiffness = 100.0;         // N/m
    double damping = 0.02;                // N·s/m, every spring
    bool pinCorners = true;
    // sub-steps per step of the default 0.01 s: keeps ω h under symplectic Euler's limit of 2
    // (Gershgorin: ω² ≤ 2 Σk / m ≈ 5.9e6 s⁻², so h = 5e-4 s gives ω h ≤ 1.2)
    int substeps = 20;
};
SceneDesc makeCloth(const ClothOptions &options);

// a chain of `links` springs hanging from a pinned first particle, laid out along +x at height y
struct ChainOptions {
    int links = 10;
    double linkLength = 0.1;  // m
    double height = 1.0;      // m
    double mass = 0.1;        // kg per particle
    double radius = 0.02;     // m
    double stiffness = 1e3;   // N/m
    double damping = 0.1;     // N·s/m
};
SceneDesc makeChain(const ChainOptions &options);

// joins particles a and b with a spring whose rest length is their current distance
void addSpring(SceneDesc &scene, int a, int b, double stiffness, double damping);

}  // namespace core
