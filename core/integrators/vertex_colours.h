#pragma once
// A colouring of the particles such that no spring joins two of one colour: vbd updates a colour's
// particles at once (each reads only its neighbours, none of which moves meanwhile), so the bits
// do not depend on the thread count.

#include <cstdint>
#include <vector>

namespace core {

struct Model;

// greedy, in index order: each free particle takes the smallest colour none of its springs'
// other ends has. `order` gets the free particles colour by colour (ascending within one) and
// colour c's are order[colours[c] .. colours[c + 1]); pinned particles are left out
void colourVertices(const Model &model, std::vector<int> &order, std::vector<int> &colours);
// the same without the springs flagged in `broken` (one flag per spring, non-zero: broken)
void colourVertices(const Model &model, const std::vector<std::uint8_t> &broken, std::vector<int> &order,
                    std::vector<int> &colours);

}  // namespace core
