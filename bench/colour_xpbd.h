#pragma once
// xpbd's sub-step as the core first ran it, kept as the yardstick of `springlab-bench xpbd-substep`:
// the springs coloured greedily over the whole model, projected colour by colour with Eigen columns,
// one spring at a time, each colour a parallel loop of its own (so a barrier a colour). The physics
// is the core's (core/integrators/xpbd.cpp, one constraint pass a sub-step); only the order of the springs and
// the organisation of the loop differ, which is what the benchmark measures.

#include "core/model/model.h"
#include "core/model/state.h"
#include "core/model/workspace.h"

#include <vector>

namespace bench {

struct ColourXpbd {
    std::vector<int> order;        // the springs, colour by colour
    std::vector<int> colourStart;  // colour c: order[colourStart[c] .. colourStart[c + 1])
};

// the model's springs coloured over the whole model (core::greedyColours), in spring order within a colour
ColourXpbd colourXpbd(const core::Model &model);

// one sub-step of h
void colourXpbdSubStep(const core::Model &model, const ColourXpbd &colours, core::State &state,
                       core::Workspace &work, double h);

}  // namespace bench
