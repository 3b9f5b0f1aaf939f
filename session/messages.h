#pragma once
// Messages: everything the UI asks of the running simulation, applied by the worker between two
// steps. Edits change the scene or the run (SetSceneEdit, TiltEdit, SteerEdit, GrabEdit,
// StrikeEdit; their names say so); the rest control the run (play, pause, step, reset), move through the timeline
// (scrub, step back) or ask for a one-off answer, which comes back once as a reply (replies.h).
// The UI thread pushes, the worker drains at the start of each tick, so the worker's State is
// never read or written from the UI thread (MuJoCo's `simulate` applies its pending actions the
// same way). Qt-free, so the unit tests can drive it directly.

#include "core/model/scene.h"

#include <Eigen/Core>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <variant>
#include <vector>

namespace ui {

// how a new SceneDesc differs from the one the worker has
enum class SceneChange {
    Replace,     // another scene (opened, example, new): start from its initial conditions
    Structure,   // particles, springs or planes changed: rebuild, keep the motion if the count matches
    Parameters,  // settings or per-spring values only: recompile the model, keep the state
    // the initial conditions became a state of this run (core::storeState: positions, velocities,
    // and the springs it broke left out), or went back: the run goes on as it is
    InitialConditions,
};

// the edits: they change the scene or the run
struct SetSceneEdit {
    std::shared_ptr<const core::SceneDesc> scene;
    SceneChange change = SceneChange::Replace;
};
struct TiltEdit {
    std::uint64_t seed = 0;  // the same seed gives the same kick
    double speed = 0.0;      // m/s, the largest change of one velocity component
};
struct SteerEdit {
    int particle = -1;                                // -1: none
    Eigen::Vector3d force = Eigen::Vector3d::Zero();  // N, constant until the next SteerEdit
};
// the mouse spring of the Drag tool: pulls a free particle toward target until released
// (particle -1); a pinned particle, having infinite mass, is carried to target instead
struct GrabEdit {
    int particle = -1;
    Eigen::Vector3d target = Eigen::Vector3d::Zero();  // m
};

// a blow to one particle: its velocity and its spin change at once, as a cue's stroke changes both
// (a pinned particle keeps still but takes the spin; the spin is kept where the scene can turn,
// core::StepPlan::spin, and has no effect elsewhere)
struct StrikeEdit {
    int particle = -1;
    Eigen::Vector3d velocityChange = Eigen::Vector3d::Zero();  // m/s
    Eigen::Vector3d spinChange = Eigen::Vector3d::Zero();      // rad/s
};

// run control
struct Play {};
struct Pause {};
struct StepOnce {};  // one step, then paused
struct Reset {};     // back to the scene's initial conditions
struct Sync {};      // changes nothing; its frame shows that every earlier message was applied

// plan the integrator and substeps for a tolerance from the current state (core/integrators/accuracy_planner.h);
// the plan comes back as an AccuracyPlanReply, tagged with the request's number
struct PlanAccuracy {
    double tolerance = 1e-6;    // m, local position error per sub-step
    std::uint64_t request = 0;  // the controller's number for this request
};
// copy the current positions and velocities out (captured_state.h) for "Use current state as
// initial"; they come back as a CapturedStateReply, tagged with the request's number
struct CaptureState {
    std::uint64_t request = 0;  // the controller's number for this request
};

// session recording (session_recording.h): start, and stop handing the recording back as a
// RecordingReply, tagged with the request's number
struct StartRecording {};
struct StopRecording {
    std::uint64_t request = 0;
};

// the timeline (timeline.h): show the recorded state of a step (pausing the run), one step back,
// and the memory the recording may use
struct Scrub {
    std::uint64_t step = 0;
};
struct StepBack {};
struct SetTimelineBudget {
    std::size_t bytes = 0;
};

using Message = std::variant<SetSceneEdit, TiltEdit, SteerEdit, GrabEdit, StrikeEdit, Play, Pause, StepOnce, Reset, Sync,
                             PlanAccuracy, CaptureState, StartRecording, StopRecording, Scrub, StepBack,
                             SetTimelineBudget>;

// a thread-safe first-in first-out queue of messages, numbered in the order they were pushed
class MessageQueue {
public:
    struct Batch {
        std::vector<Message> messages;   // oldest first
        std::uint64_t lastSequence = 0;  // the number of the newest message ever drained
    };

    // returns the message's sequence number: 1 for the first, then 2, 3, ...
    std::uint64_t push(Message message);

    // takes every pending message
    Batch drain();

    bool empty() const;

    // raised while messages wait to be drained: a long step polls it between sub-steps
    // (core::Workspace::interrupt) and stops, so that they need not wait for its end
    const std::atomic<bool> &waiting() const { return m_waiting; }

private:
    std::atomic<bool> m_waiting{false};
    mutable std::mutex m_mutex;
    std::vector<Message> m_pending;
    std::uint64_t m_pushed = 0;
};

}  // namespace ui
