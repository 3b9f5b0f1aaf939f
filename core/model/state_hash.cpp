#include "core/model/state_hash.h"

#include <bit>

namespace core {

std::uint64_t stateHash(const State &state)
{
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    const auto add = [&hash](double value) {
        const auto bits = std::bit_cast<std::uint64_t>(value);
        for (int byte = 0; byte < 8; ++byte) {
            hash ^= (bits >> (8 * byte)) & 0xffU;
            hash *= 0x100000001b3ULL;
        }
    };
    for (Eigen::Index i = 0; i < state.position.size(); ++i)
        add(state.position.data()[i]);
    for (Eigen::Index i = 0; i < state.velocity.size(); ++i)
        add(state.velocity.data()[i]);
    // the spins, where the plan has them (empty otherwise: the hash of a state that cannot turn is
    // as it was)
    for (Eigen::Index i = 0; i < state.angularVelocity.size(); ++i)
        add(state.angularVelocity.data()[i]);
    for (Eigen::Index i = 0; i < state.orientation.size(); ++i)
        add(state.orientation.data()[i]);
    return hash;
}

}  // namespace core
