#pragma once
// What the triangle collision pass (triangle_collisions.cpp) keeps within a sub-step: where the
// particles started it, the candidate pairs of its broad phase and the impact zones of its
// fail-safe. Rebuilt every sub-step and kept in the Workspace, so that a step allocates nothing
// once the arrays have reached the scene's size. Nothing in it carries over to the next sub-step.

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace core {

// a pair the broad phase found: particle a and triangle b, or edges a < b
struct TrianglePair {
    bool edges = false;
    int a = 0;
    int b = 0;
};

struct TriangleScratch {
    Eigen::Matrix3Xd start;  // m, the positions at the sub-step's start
    // the candidates below serve every sub-step while each particle stays within its margin of the
    // box it was found with: the positions then, the box (unpadded), the margin, the surface and
    // the whole triangles they were found for, and each candidate's distance then
    Eigen::Matrix3Xd built;
    Eigen::Matrix3Xd builtLow, builtHigh;
    std::vector<double> particleMargin;
    const void *builtFor = nullptr;
    std::vector<std::uint8_t> builtActive;
    std::vector<double> builtDistance;
    std::vector<double> reach;  // per particle: the farthest it has been from `built` in the sub-step
    double margin = 0.0;  // m, the least margin: the thickest sheet's thickness
    // the broad phase: boxes swept over the sub-step, min and max corners per item
    Eigen::Matrix3Xd pointLow, pointHigh, triangleLow, triangleHigh, edgeLow, edgeHigh;
    std::vector<std::pair<std::uint64_t, int>> triangleCells, edgeCells;  // (cell key, item), sorted
    std::vector<int> bigTriangles, bigEdges;  // boxes over too many cells for the grid
    std::vector<std::uint8_t> triangleActive, edgeActive;  // whole (no side torn)
    // per particle: its distance from a sheet's middle at contact (ClothSurface::contactRadius, or
    // its radius once every triangle it was a corner of has torn away), and whether it still is one
    std::vector<double> pointRadius;
    std::vector<std::uint8_t> inSheet;
    std::vector<std::uint8_t> finite;  // per particle: its box is finite
    std::vector<TrianglePair> candidates;
    std::vector<int> impacted;  // the candidates with an impact in the last pass
    std::vector<std::uint8_t> pending;  // per candidate: an impact found but not answered
    std::vector<int> changedAt;  // per particle: the last pass that moved it (-1: none)
    // the fail-safe's impact zones: union-find per particle, and per zone its mass and momenta
    std::vector<int> zoneOf;
    std::vector<int> zoneMembers;
    std::vector<std::uint8_t> inZone;
    std::vector<double> zoneMass;
    std::vector<std::uint8_t> zonePinned;
    Eigen::Matrix3Xd zoneMove, zoneVelocity;

    // totals over the run, for the tests and the benchmark
    std::uint64_t impacts = 0;     // impacts found by the continuous passes and answered
    std::uint64_t zoneRounds = 0;  // rounds of the fail-safe
    std::uint64_t stops = 0;       // sub-steps the fail-safe ended by stopping every particle
    std::uint64_t builds = 0;      // broad phases run at a sub-step's start
    std::uint64_t rebuilds = 0;    // broad phases run again within a sub-step
};

}  // namespace core
