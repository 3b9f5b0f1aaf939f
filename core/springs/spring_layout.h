#pragma once
// SpringLayout: the spring list as the vectorised kernels walk it (springs.cpp, spring_blocks.cpp),
// built once when the model is compiled. Runs of lattice-like springs, which block of particles
// each run reaches, the short runs joined, and which spring pass the model takes: the kernels read
// all of it here and decide nothing themselves.

#include <Eigen/Core>
#include <vector>

namespace core {

// particles per block of the fused lattice sub-step (spring_blocks.cpp) and of the run pass
// (springs.cpp): a block's forces and its positions and velocities with the springs' reach either
// side stay in the L2 cache (786 KB for a 1024 × 1024 cloth, whose bend springs reach 2048
// particles). A spring with its ends in two blocks is computed for each, so a larger block computes
// fewer twice: 8192 was 10-20% faster than 4096 on the 1024 × 1024 cloth and no slower on the
// smaller ones (docs/benchmarks.md)
inline constexpr int kSpringBlock = 8192;
// SpringLayout::joined: runs this short are worth joining, across gaps of at most this many particles
inline constexpr int kJoinRunsBelow = 128;
inline constexpr int kJoinGap = 8;

// A stretch of consecutive springs of the list whose two ends both step by one particle from one
// spring to the next, as a lattice's springs do when they are made row by row: a run's springs are
// (a + j, b + j), j = 0 … count - 1, springs first + j. Over a run the ends are read and the forces
// added with unit stride, with no gathers.
struct SpringRun {
    int first = 0;  // the run's first spring
    int count = 0;
    int a = 0;      // end a of its first spring
    int b = 0;      // end b of its first spring
    // every spring of the run has the first's rest length, stiffness and damping: the kernels read
    // them once, not once a spring (a cloth's run is one kind of spring)
    bool uniform = false;
};

// how addSprings() (springs.cpp) computes the forces
enum class SpringPass {
    Gathered,  // each spring's force, then each particle gathers its springs' (any spring list)
    Runs,      // run by run, block by block of particles (a list cut into long runs)
};

struct SpringLayout {
    // Runs when the runs are 8 springs long or more on average: shorter ones cost more in
    // bookkeeping than they save
    SpringPass pass = SpringPass::Gathered;
    // the runs are indexed by block (blockRuns): the Euler schemes may then step the model a block
    // of particles at a time, forces and update fused (spring_blocks.cpp). Only for the Runs pass
    // whose springs reach no further than the next block
    bool blocks = false;

    // the spring list cut into runs, in order
    std::vector<SpringRun> runs;
    // the farthest apart the two ends of a run lie in the numbering, max |b - a|: how far past a
    // block of particles its springs reach
    int reach = 0;
    // the runs with an end in each block of kSpringBlock particles, ascending: block q's are
    // blockRuns[blockRunOffsets[q] .. blockRunOffsets[q + 1]). Empty unless `blocks`
    std::vector<int> blockRunOffsets;
    std::vector<int> blockRuns;
    // The runs once more for the fused sub-step, short ones joined: runs shorter than
    // kJoinRunsBelow with the same offset b - a that follow each other in the list, each starting a
    // few particles (at most kJoinGap) past the last one's end, become one run. The particles in
    // between are ends of padding springs with no rest length, stiffness or damping, whose force is
    // exactly zero, and a force sum never is -0 (it starts at 0 + m g), so adding the padding's ±0
    // changes no bit. A 64 × 64 cloth's rows of 63 springs become a run of 4095, which the kernels
    // take in full vectors instead of a remainder and a dozen calls a row. A joined run's `first`
    // indexes the three arrays here, one value per spring of the run, padding included. The
    // broken flags are the state's, one per spring of the list, so a state with flags steps by
    // `runs`; so does a model whose springs can break, which has none. Empty where no run was
    // joined, or without `blocks`.
    struct JoinedRuns {
        std::vector<SpringRun> runs;
        Eigen::VectorXd restLength;  // m
        Eigen::VectorXd stiffness;   // N/m
        Eigen::VectorXd damping;     // N·s/m
        std::vector<int> blockRunOffsets;  // as blockRunOffsets and blockRuns, for these runs
        std::vector<int> blockRuns;
    };
    JoinedRuns joined;
};

// the plain spring list of a model: ends, parameters, and whether any spring can break
struct SpringList {
    const std::vector<int> &a;
    const std::vector<int> &b;
    const Eigen::VectorXd &restLength;  // m
    const Eigen::VectorXd &stiffness;   // N/m
    const Eigen::VectorXd &damping;     // N·s/m
    int particles = 0;
    bool breakable = false;  // a spring with a breaking strain: nothing is joined (see JoinedRuns)
};

// the list's layout, and the pass it takes
SpringLayout makeSpringLayout(const SpringList &springs);

}  // namespace core
