#pragma once
// SessionRecording: a run as the worker lived it, to replay bit for bit: the scene and the state
// when recording started, then every message that changes the run (the edits, play, pause, step
// and reset), each stamped with the number of steps taken before it, and the steps taken in all. Replaying it on a fresh SimulationRunner
// (replay()) applies the same messages after the same steps, so it ends with the same bits; the
// recording keeps the hash of the state it ended with to prove it. Qt-free.

#include "messages.h"

#include "core/model/scene.h"
#include "core/model/state.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ui {

struct SessionRecording {
    // the scene the runner had at the start (its initial conditions stay the scene's own, so that
    // a reset during the replay goes where the recorded one went)
    std::shared_ptr<const core::SceneDesc> scene;
    // the state at the start, springs broken before it included
    core::State start;

    struct Entry {
        std::uint64_t steps = 0;  // steps taken since the start before this message
        Message message;
    };
    std::vector<Entry> entries;
    std::uint64_t steps = 0;      // steps taken from the start to the end
    std::uint64_t finalHash = 0;  // core::stateHash of the state at the end
};

struct ReplayResult {
    std::uint64_t hash = 0;  // core::stateHash at the end
    core::State state;       // the state at the end
    std::string error;       // empty when the replay ran to the end
};

// replays a recording on a fresh runner
ReplayResult replay(const SessionRecording &recording);

}  // namespace ui
