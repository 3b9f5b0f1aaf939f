#include "session_recording.h"

#include "simulation_runner.h"

#include "core/model/state_hash.h"

namespace ui {

ReplayResult replay(const SessionRecording &recording)
{
    ReplayResult result;
    if (!recording.scene) {
        result.error = "the recording has no scene";
        return result;
    }
    SimulationRunner runner;
    runner.apply(SetTimelineBudget{0});  // a replay is not scrubbed: no timeline to keep
    runner.apply(SetSceneEdit{recording.scene, SceneChange::Replace});
    if (!runner.restoreRecordedStart(recording)) {
        result.error = "the recorded state does not fit the recorded scene";
        return result;
    }
    // each message after the steps taken before it; a step that blows up here never stuck in the
    // recorded run (the runner went back before it), so the replay has gone astray
    const auto stepTo = [&](std::uint64_t steps) {
        while (runner.stepsTaken() < steps)
            if (!runner.stepForReplay()) {
                result.error = "the replay blew up after " + std::to_string(runner.stepsTaken()) +
                               " steps, where the recorded run did not";
                return false;
            }
        return true;
    };
    for (const SessionRecording::Entry &entry : recording.entries) {
        if (!stepTo(entry.steps))
            return result;
        runner.apply(entry.message);
    }
    if (!stepTo(recording.steps))
        return result;
    result.state = runner.state();
    result.hash = core::stateHash(result.state);
    return result;
}

}  // namespace ui
