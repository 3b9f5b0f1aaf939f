#pragma once
// Scrubber: the run's timeline (timeline.h) and the recorded step shown while scrubbing. A step
// is shown by replaying it exactly from the keyframe before it, with that keyframe's model and
// held forces; stepping forward goes on from the step shown rather than from the keyframe. When
// the run goes on from the step shown, the recording after it is dropped (one line of history, no
// branches). A replay may be cut short between two sub-steps by a flag raised while messages wait
// (a replay of a large scene takes as long as its steps): the last whole step replayed is shown,
// and the rest is pending, taken up again by goOn(). Qt-free; the runner owns it and lends it its
// workspace for the replays.

#include "timeline.h"

#include "core/model/model.h"
#include "core/model/scene.h"
#include "core/model/state.h"
#include "core/model/workspace.h"

#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>

namespace ui {

// a recorded step as shown: its state, the model it was stepped with and the scene that model
// came from (which may have fewer particles or springs than the scene now in the editor)
struct ScrubbedStep {
    std::shared_ptr<const core::Model> model;
    std::shared_ptr<const core::SceneDesc> scene;
    core::State state;
};

class Scrubber {
public:
    Timeline &timeline() { return m_timeline; }
    const Timeline &timeline() const { return m_timeline; }

    bool isScrubbing() const { return m_shown.has_value(); }
    // the step shown while scrubbing (nullopt at the run's end)
    std::optional<std::uint64_t> scrubStep() const;
    // the recorded step shown, null at the run's end
    const ScrubbedStep *shown() const { return m_shown ? &*m_shown : nullptr; }

    // whether the timeline has step and a keyframe to replay it from
    bool canShow(std::uint64_t step) const;
    // shows the recorded state of step, replayed in work; false if it cannot be shown, or if the
    // replay failed (a recorded step cannot fail; if it does, the run is shown instead). The
    // replay takes at most maxSteps steps, and with a raised interrupt flag it stops between
    // sub-steps: the last whole step replayed is shown and step is pending
    bool show(std::uint64_t step, core::Workspace &work, const std::atomic<bool> *interrupt = nullptr,
              int maxSteps = std::numeric_limits<int>::max());
    // the step a replay cut short is on its way to
    std::optional<std::uint64_t> pendingStep() const { return m_pending; }
    // goes on with a replay cut short, for at most maxSteps steps; true if it showed another step
    bool goOn(core::Workspace &work, const std::atomic<bool> *interrupt, int maxSteps = std::numeric_limits<int>::max());
    // hands the step shown over for the run to go on from it (only while scrubbing): what was
    // recorded after it is gone
    ScrubbedStep resume();
    // shows the run again and forgets the recording (a reset, or a replay's start)
    void clear();

    // how often the run went on from a step scrubbed to, and that step the last time
    std::uint64_t resumes() const { return m_resumes; }
    std::uint64_t resumedAt() const { return m_resumedAt; }

private:
    Timeline m_timeline;
    std::optional<ScrubbedStep> m_shown;
    std::optional<std::uint64_t> m_pending;
    core::State m_stepStart;  // where the step being replayed began, while it may be cut short
    std::uint64_t m_resumes = 0;
    std::uint64_t m_resumedAt = 0;
};

}  // namespace ui
