#pragma once
// The scratch of the particle-pair broad phase (broad_phase.cpp): a uniform grid, rebuilt every
// sub-step, and the list of pairs it finds. It lives in the Workspace so that a step allocates nothing
// once the arrays have reached the scene's size.

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <vector>

namespace core {

// two particles i < j that overlap
struct ContactPair {
    int i = 0;
    int j = 0;

    bool operator==(const ContactPair &) const = default;
};

// one particle as the grid stores it: a copy of what the narrow test reads, so that scanning a
// bucket reads consecutive memory
struct GridSlot {
    double x = 0.0, y = 0.0, z = 0.0;  // m
    double radius = 0.0;               // m
    std::uint64_t cell = 0;            // packed integer cell coordinates
    int particle = 0;
    bool pinned = false;
};

// the most pairs the grid keeps for one particle. Equal spheres touch at most 12 others; only a
// crowd of overlapping particles reaches this, and every pair of n coincident particles would take
// memory quadratic in n (20 000 of them needed 3 GB, 50 000 aborted the program)
constexpr int kMaxGridPartners = 64;

// the particles of one thread's share that go in the grid: how many, their extent and largest radius
struct GridExtent {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
    double largest = 0.0;
    int count = 0;
};

struct ContactGrid {
    // the overlapping pairs of the last pass, in lexicographic (i, j) order
    std::vector<ContactPair> pairs;

    // find the pairs by brute force instead (the reference the tests compare with)
    bool bruteForce = false;
    // how the last pass laid out its cells: hashed, or dense over the bounding box
    bool hashed = false;

    // per particle: its slot in `sorted`, or below 0 when it is not in the grid (not finite, too big)
    std::vector<int> slotOf;
    // the particles of the grid sorted by bucket: bucket b holds sorted[bucketStart[b], bucketStart[b + 1])
    std::vector<GridSlot> sorted;
    std::vector<int> bucketStart;
    std::vector<std::uint64_t> cellOf;    // per particle, while sorting
    std::vector<int> big;                 // particles too big for the cells, checked against all
    std::vector<double> radiusSample;     // radii sampled to pick the cell size
    std::vector<ContactPair> found;       // the pairs in the order the grid finds them
    std::vector<std::vector<ContactPair>> foundShares;  // the pairs each thread's share of the grid found
    std::vector<GridExtent> shareExtents;          // per thread's share, while sorting
    std::vector<std::vector<int>> bigShares;       // per thread's share, its big particles
    std::vector<std::vector<int>> shareStarts;     // per thread's share, per bucket: its count, then where it starts
    std::vector<int> rangeStarts;                  // per range of buckets: its total, then where it starts
    std::vector<std::uint16_t> partners;  // per particle, the grid pairs found for it so far
    // whether a particle reached kMaxGridPartners pairs in the last pass, so that pairs of it
    // may have been left out (a crowd of overlapping particles)
    bool crowded = false;
    std::vector<int> pairStart;           // per particle i: where its pairs start, while sorting
};

}  // namespace core
