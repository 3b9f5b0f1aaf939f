#pragma once
// The order in which xpbd (xpbd.cpp) projects its springs, fixed when the model is compiled so that
// the bits of a run never depend on the thread count.
//
// The particles are cut into blocks of kXpbdBlock consecutive indices. A spring whose free ends lie
// in one block belongs to that block; one whose free ends lie in two neighbouring blocks to the seam
// between them; any other to the far springs. A sub-step's pass is then three or four phases:
//   1. every block's own springs, each block on one thread, all blocks at once (they share no free
//      particle);
//   2. the seams after even blocks (0|1, 2|3, ...), at once: no two touch the same block;
//   3. the seams after odd blocks (1|2, 3|4, ...);
//   4. the far springs, on one thread.
// So a pass waits for the other threads three or four times, whatever the springs' colours, where
// solving the whole model colour by colour waits once a colour (a cloth has twelve). Within a block,
// a seam or the far springs, the springs are coloured greedily (no two of a colour move the same
// particle) and each colour is a batch the kernel runs as one vectorised loop.
//
// The springs' data are stored in this order, structure-of-arrays, so that a batch reads them
// contiguously. A spring with one end pinned has its free end as end a; one with both ends pinned,
// or with no stiffness, has nothing to project and is left out.

#include <cstdint>
#include <vector>

namespace core {

struct Model;

// particles a block: large enough that a lattice's springs rarely leave it (a 128-wide cloth's bend
// springs reach 256), small enough that a 128 × 128 cloth has eight blocks to share out
inline constexpr int kXpbdBlock = 2048;

struct XpbdLayout {
    // per slot, in projection order
    std::vector<int> spring;  // the model's index
    std::vector<int> a;       // end a, always free
    std::vector<int> b;       // end b, free or pinned (see batchMovesB)
    std::vector<double> wa, wb;  // 1/kg, the ends' inverse masses
    std::vector<double> restLength;  // m
    std::vector<double> stiffness;   // N/m
    std::vector<double> damping;     // N·s/m
    // batch i: slots [batchStart[i], batchStart[i + 1]), no two of which move the same particle
    std::vector<int> batchStart;
    std::vector<std::uint8_t> batchMovesB;  // whether its b ends are free (else all pinned)
    // task t: batches [taskStart[t], taskStart[t + 1]), run in order on one thread
    std::vector<int> taskStart;
    // phase p: tasks [phaseStart[p], phaseStart[p + 1]), which move disjoint particles: run at once
    std::vector<int> phaseStart;
    // this layout's own number, never given to another: what a workspace's constants for it
    // (XpbdConstants) are keyed on
    std::uint64_t id = 0;

    int slotCount() const { return static_cast<int>(spring.size()); }
    int batchCount() const { return static_cast<int>(batchStart.size()) - 1; }
    int taskCount() const { return static_cast<int>(taskStart.size()) - 1; }
    int phaseCount() const { return static_cast<int>(phaseStart.size()) - 1; }
};

// Per slot, what the projection takes from the sub-step h alone, computed when h or the layout
// changes rather than in every sub-step: α̃ = 1 / (k h²), γ = c / (k h), and 1 / ((1 + γ)(wa + wb) + α̃)
struct XpbdConstants {
    std::uint64_t layout = 0;  // XpbdLayout::id they were computed for (0: none)
    double h = 0.0;            // s
    std::vector<double> compliance;
    std::vector<double> gamma;
    std::vector<double> inverseDenominator;
};

// the model's springs laid out for xpbd (empty lists when it has nothing to project)
XpbdLayout xpbdLayout(const Model &model);

// what laying out takes besides the layout: kept in a workspace, so that laying out again (after
// a spring broke) allocates nothing once it has been done
struct XpbdLayoutScratch {
    std::vector<std::vector<int>> own, seam;  // per block: its springs, and the seam after it
    std::vector<int> far;
    std::vector<int> ends, colour, batch, start, sorted, fill;
    std::vector<std::uint64_t> used;
};

// lays the model's springs out into `layout`, without those `broken` flags (one flag per spring,
// or null): exactly as the same model with those springs left out of its list would be laid out.
// Reuses the memory of `layout` and `scratch`
void layOutXpbd(const Model &model, const std::vector<std::uint8_t> *broken, XpbdLayout &layout,
                XpbdLayoutScratch &scratch);

// The springs of `springs` (indices into the model, in this order) coloured greedily: each takes the
// lowest colour no spring before it already has at one of its free ends. Returns each one's colour.
// A pinned end takes no colour, since no spring moves it.
std::vector<int> greedyColours(const Model &model, const std::vector<int> &springs);

}  // namespace core
