#pragma once
// What the triangle collision pass (triangle_collisions.cpp) keeps: where the particles began the
// sub-step, the candidate pairs of its broad phase (kept across sub-steps while every particle stays within
// its bound) and the impact zones of its fail-safe. Kept in the Workspace, so that a sub-step allocates
// nothing once the arrays have reached the scene's size. Nothing in it changes an answer: a pair
// the candidates miss is surely apart, so a resumed run that finds them at another sub-step moves
// every particle the same.

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

// the cells a box covers, from lo to hi on each axis
struct CellRange {
    long long lo[3], hi[3];
    long long count() const;  // (triangle_collisions.cpp) more than the grid takes: its limit + 1
};

// one kind of item's grid (triangles or edges): an open-addressing table of the occupied cells
// (kNoCell where empty), each slot's run of items in `items` from first[slot] to first[slot + 1],
// each item's cells and low cell, and the items whose boxes cover too many cells to enter
struct TriangleGrid {
    std::vector<std::uint64_t> keys;
    std::vector<int> first, fill;
    std::vector<int> items;
    std::uint64_t mask = 0;
    std::vector<CellRange> range;
    Eigen::Matrix<long long, 3, Eigen::Dynamic> lowCell;
    std::vector<int> big;
};

struct TriangleScratch {
    Eigen::Matrix3Xd start;  // m, the positions at the sub-step's start
    // the candidates below serve every sub-step while each particle stays within its bound of where it
    // was when they were found: the positions then, the bounds, the surface and the whole triangles
    // they were found for, and each candidate's distance then
    Eigen::Matrix3Xd built;
    std::vector<double> bound;  // m
    const void *builtFor = nullptr;
    std::vector<std::uint8_t> builtActive;
    std::vector<double> builtDistance;
    // m, the common shift taken away from every particle at the sub-step's start and end (the sheets'
    // mean move since the candidates were found), and the end's carried to the next sub-step's start
    Eigen::Vector3d shiftStart = Eigen::Vector3d::Zero(), shiftEnd = Eigen::Vector3d::Zero();
    Eigen::Vector3d shiftCarried = Eigen::Vector3d::Zero();
    std::vector<double> reach;  // per particle: the farthest it has been from `built` in the sub-step
    double margin = 0.0;  // m, the thickest sheet's thickness
    // the broad phase: per particle its path over the sub-step padded by its bound, and the boxes of
    // the items from those, min and max corners
    Eigen::Matrix3Xd sweptLow, sweptHigh;
    Eigen::Matrix3Xd pointLow, pointHigh, triangleLow, triangleHigh, edgeLow, edgeHigh;
    TriangleGrid triangleGrid, edgeGrid;
    double cellSize = 1.0;  // m, the grids' cells
    // found again since the grids were filled: the particles that left their bounds now, and the
    // items with one as a corner (loose: their boxes are in the small grids, not the main ones)
    std::vector<int> moved;
    std::vector<std::uint8_t> isMoved;
    std::vector<std::uint8_t> looseTriangle, looseEdge, looseTriangleActive, looseEdgeActive;
    std::vector<std::uint8_t> freshTriangle, freshEdge;  // loose since this update
    int looseCount = 0;
    TriangleGrid looseTriangleGrid, looseEdgeGrid, freshTriangleGrid;
    std::vector<TrianglePair> mergedCandidates;
    std::vector<double> mergedDistances;
    // per thread share of the search: its candidates, their distances, one item's visits
    std::vector<std::vector<TrianglePair>> shareCandidates;
    std::vector<std::vector<double>> shareDistances;
    std::vector<std::vector<int>> shareVisits;
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
    std::uint64_t updates = 0;     // sub-steps that found some particles' candidates again
};

}  // namespace core
