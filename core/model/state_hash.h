#pragma once
// A fingerprint of a run's state: equal hashes mean (short of a 64-bit collision) the same bits in
// every position and velocity. Determinism tests and replays compare runs by it.

#include "core/model/state.h"

#include <cstdint>

namespace core {

// FNV-1a, 64 bits, over the bytes of every position and then every velocity component, least
// significant byte first
std::uint64_t stateHash(const State &state);

}  // namespace core
