#pragma once
// Keeping a scene's saved contact impulses (SceneDesc::contactImpulses) true to its particles and
// planes when an edit renumbers them: an impulse whose particle or plane is gone goes with it.

#include "core/model/scene.h"

#include <vector>

namespace core {

// remap[old particle] is its new index, or -1 when it was removed. (The order is of no matter here:
// makeState sorts them for the solver.)
void renumberContactImpulses(std::vector<ContactImpulse> &impulses, const std::vector<int> &remap);

// plane `removed` is gone and the planes after it move down by one
void removePlaneFromContactImpulses(std::vector<ContactImpulse> &impulses, int removed);

}  // namespace core
