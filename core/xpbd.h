#pragma once
// Extended position-based dynamics (Macklin, Müller and Chentanez, "XPBD", 2016), as "Small Steps
// in Physics Simulation" (Macklin et al., 2019) runs it: many sub-steps of one constraint
// iteration each. xpbd.cpp has the sub-step; this is what the model needs from it.

#include "model.h"

namespace core {

// the springs of the model into colours (Model::xpbdOrder, Model::xpbdColourStart): greedily, in
// spring order, each the lowest colour no spring already coloured shares a free particle with.
// A spring with a pinned end does not move it, so the pinned end takes no colour
void colourSprings(Model &model);

}  // namespace core
