#pragma once
// Timeline: the run recorded as it goes, so that the editor can scrub back through it. It keeps
// keyframes: the whole dynamic state every kKeyInterval steps and at every edit, each with the
// model and the mouse spring that held from it to the next one. The step is deterministic, so any
// step between two keyframes is replayed exactly from the one before it; nothing else is stored.
// The keyframes stay within a memory budget: when a new one would pass it, the oldest go, so the
// timeline holds the most recent stretch of the run that fits. Qt-free; the runner's Scrubber
// (scrubber.h) owns it.

#include "core/model/model.h"
#include "core/model/scene.h"
#include "core/model/state.h"

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace ui {

// the forces from outside that a replay must apply as the run did: the mouse spring is worked
// out again at every step from where the particle is (the steering force is in State::applied)
struct HeldForces {
    int grabParticle = -1;
    Eigen::Vector3d grabTarget = Eigen::Vector3d::Zero();  // m
    int steerParticle = -1;
    Eigen::Vector3d steerForce = Eigen::Vector3d::Zero();  // N

    bool operator==(const HeldForces &) const = default;
};

// rad/s: how fast the mouse spring pulls a particle to the cursor (a time constant of 50 ms)
constexpr double kGrabRate = 20.0;

// the mouse spring's force on the particle held, worked out from where it is, before each step of
// the run and of the replays alike (a pinned particle is carried to the target instead)
void applyGrabForce(const core::Model &model, core::State &state, const HeldForces &held);

struct TimelineKey {
    std::shared_ptr<const core::Model> model;
    std::shared_ptr<const core::SceneDesc> scene;  // what the model was compiled from
    HeldForces held;
    core::State state;
    std::size_t bytes = 0;  // what it holds, model excluded (counted once per model)
    bool tail = false;      // one of the latest steps' own, dropped once kTailSteps old
};

class Timeline {
public:
    // keyframes at most this many steps apart: a scrub replays fewer steps than this
    static constexpr int kKeyInterval = 10;
    // the latest steps each keep a keyframe of their own until they are this many steps old, so
    // that stepping back from where a run paused replays nothing: the key's answer is one frame
    // (a step back through keyframes 10 apart replayed up to 9 steps, 0.8 s at 4·10⁴ particles)
    static constexpr int kTailSteps = kKeyInterval;
    static constexpr std::size_t kDefaultBudget = std::size_t(512) << 20;  // bytes

    // 0 turns recording off
    void setBudget(std::size_t bytes);
    std::size_t budget() const { return m_budget; }
    // bytes held now: the keyframes and the models only they keep alive
    std::size_t usedBytes() const { return m_used; }

    void clear();
    bool empty() const { return m_keys.empty(); }

    // records the state after a step: a keyframe when the last lasting one is kKeyInterval steps
    // back (or there is none), else a tail keyframe; tail keyframes over kTailSteps old go
    void afterStep(const std::shared_ptr<const core::Model> &model, const std::shared_ptr<const core::SceneDesc> &scene,
                   const core::State &state, const HeldForces &held);
    // records the state after an edit changed the run: always a keyframe, in place of one at the
    // same step; every keyframe after the state's step goes (the edit ends that future)
    void afterEdit(const std::shared_ptr<const core::Model> &model, const std::shared_ptr<const core::SceneDesc> &scene,
                   const core::State &state, const HeldForces &held);
    // drops every keyframe after step (a run rolled back to it)
    void truncateAfter(std::uint64_t step);

    // the recorded steps: from the oldest keyframe to the newest step recorded
    std::uint64_t firstStep() const;
    std::uint64_t lastStep() const { return m_lastStep; }
    double firstTime() const;
    double lastTime() const { return m_lastTime; }
    bool covers(std::uint64_t step) const { return !empty() && step >= firstStep() && step <= m_lastStep; }
    // the keyframe a replay to step starts from: the newest at or before it (null if none)
    const TimelineKey *keyAtOrBefore(std::uint64_t step) const;

    // the bytes of the latest keyframe that could not be kept because it alone is over the budget
    // (its model and state: 693 MB for 10⁶ particles and 6·10⁶ springs); 0 once one was kept
    std::size_t keyframeOverBudget() const { return m_tooLarge; }

    // the steps springs broke in, within the recording, ascending and each once
    const std::vector<std::uint64_t> &breakSteps() const { return m_breakSteps; }

private:
    void add(TimelineKey key);
    void dropOldest();
    // removes the keyframe at index (not the oldest: dropOldest), its model's bytes with it if
    // no other keyframe uses that model; its state's memory is kept for the next tail keyframe
    void eraseKey(std::size_t index);
    // the step of the newest keyframe that is not a tail one (nullopt if none)
    std::optional<std::uint64_t> lastLastingStep() const;
    std::size_t modelBytes(const std::shared_ptr<const core::Model> &model) const;

    std::deque<TimelineKey> m_keys;
    std::size_t m_budget = kDefaultBudget;
    std::size_t m_used = 0;
    std::size_t m_tooLarge = 0;
    std::uint64_t m_lastStep = 0;
    double m_lastTime = 0.0;
    std::vector<std::uint64_t> m_breakSteps;  // kept up to date as keyframes come and go
    core::State m_spare;  // an aged tail keyframe's state, its memory reused by the next
};

// the key's state put into state (assignment reuses its memory)
void restoreKey(const TimelineKey &key, core::State &state);

}  // namespace ui
