#pragma once
// SimulationRunner: the worker's Qt-free half. It owns the compiled Model and the State, applies
// messages between steps, and turns wall time into whole steps of the model's time step. It has no
// thread and no timer of its own: SimulationWorker calls it from its tick, and the unit tests call
// it directly, one message or one advance at a time.
//
// It also keeps the live accuracy figures: a step-doubling estimate of the local error, refreshed
// after an edit and, while running, at most every kEstimateInterval of wall time and only once the
// steps since the last estimate took 1 / kEstimateShare times as long as it did, so that the
// estimates never cost more than that share of the run; and the energies at the last reset, from
// which the drift is measured. The accuracy planner runs here too, on the runner's own state, and
// so does the stability analysis: the explicit integrators' limit for the model as edited, and the
// explanation of a blow-up at the last good state.
//
// The run is recorded on a timeline (timeline.h) as it goes. Scrubbing shows a recorded step,
// replayed exactly from the keyframe before it, and pauses the run there; stepping back and forth
// moves through the recording. Play, or any edit that changes the run, resumes from the step shown
// with the scene as it is now in the editor, and the recorded future after that step is discarded
// (one line of history, no branches).

#include "captured_state.h"
#include "messages.h"
#include "replies.h"
#include "session_recording.h"
#include "timeline.h"

#include "core/accuracy_planner.h"
#include "core/diagnostics.h"
#include "core/error_estimate.h"
#include "core/model.h"
#include "core/snapshot.h"
#include "core/stability.h"
#include "core/state.h"
#include "core/workspace.h"

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace ui {

class SimulationRunner {
public:
    // the live error estimate: at most this often (s of wall time), and at most this share of the
    // computing time of the steps
    static constexpr double kEstimateInterval = 0.25;
    // rad/s: how fast the mouse spring pulls a particle to the cursor (a time constant of 50 ms)
    static constexpr double kGrabRate = 20.0;
    static constexpr double kEstimateShare = 0.05;

    struct Advance {
        int steps = 0;                // steps taken
        double droppedSeconds = 0.0;  // s of wall time left unsimulated (the run fell behind)
    };

    // applies one message between two steps
    void apply(const Message &message);

    // recording (session_recording.h): from startRecording() on, every edit that changes the run
    // is kept with the steps taken before it; stopRecording() ends it and hands it over (null when
    // none was started or there is no scene)
    void startRecording();
    std::shared_ptr<const SessionRecording> stopRecording();
    bool isRecording() const { return m_recording != nullptr; }
    // steps that stuck since the first scene: a tick that blows up goes back to its start, and
    // its steps are taken back from the count too
    std::uint64_t stepsTaken() const { return m_stepsTaken; }
    // for replays: the recording's starting state in place of the scene's initial one (false if
    // it does not fit the scene), and one step as a run takes it (false if it blew up)
    bool restoreRecordedStart(const SessionRecording &recording);
    bool stepForReplay();

    // advances simulated time by wallSeconds (already capped by the caller) in whole steps; the
    // remainder is owed to the next call. Stops early when the steps have taken budgetSeconds of
    // computing, dropping what is still owed, so a slow scene runs slower than real time instead
    // of piling up a backlog. Does nothing while paused.
    Advance advance(double wallSeconds, double budgetSeconds);

    bool hasScene() const { return m_model != nullptr; }
    bool isRunning() const { return m_running; }
    const core::State &state() const { return m_state; }
    std::shared_ptr<const core::Model> model() const { return m_model; }
    std::shared_ptr<const core::SceneDesc> scene() const { return m_scene; }

    // the current state, packed for drawing: the step scrubbed to while scrubbing, else the run's
    std::shared_ptr<const core::Snapshot> snapshot() const;

    // the timeline: what it holds, and the step shown while scrubbing (nullopt at the run's end)
    const Timeline &timeline() const { return m_timeline; }
    bool isScrubbing() const { return m_scrub.has_value(); }
    // how often the run went on from a step scrubbed to, and that step the last time
    std::uint64_t resumes() const { return m_resumes; }
    std::uint64_t resumedAt() const { return m_resumedAt; }
    std::optional<std::uint64_t> scrubStep() const;
    // the state shown: the scrubbed step's while scrubbing, else the run's
    const core::State &shownState() const { return m_scrub ? m_scrub->state : m_state; }
    // and the model it was stepped with and the scene that model came from: while scrubbing, the
    // recorded step's, which may have fewer particles or springs than the scene now in the editor
    std::shared_ptr<const core::Model> shownModel() const { return m_scrub ? m_scrub->model : m_model; }
    std::shared_ptr<const core::SceneDesc> shownScene() const { return m_scrub ? m_scrub->scene : m_scene; }

    // what stopped the run by blowing up, once, explained at the last good state (what failed,
    // where, why and the fix: core::explainBlowup); the caller reports it
    std::optional<std::string> takeBlowupMessage();

    // analyses the stability limit again if an edit changed the model since; true if it did
    bool updateStability();
    // the limit of the model as it is now (nullopt before the first scene)
    const std::optional<core::StabilityLimit> &stability() const { return m_stability; }
    // particles faster than the pair speed limit allows, as of the latest steps, edit or reset
    // (empty when within it): core::explainPairSpeed
    const std::string &pairSpeedWarning() const { return m_pairSpeedWarning; }

    // estimates the local error now if an edit or a blow-up changed the model or the state since
    // the last estimate; the worker calls it once a tick, after the edits and the steps
    void updateEstimate();

    // the local position error of one sub-step (m) at the state of step localErrorStep(); nullopt
    // before the first estimate or when a trial blew up
    std::optional<double> localError() const { return m_localError; }
    std::uint64_t localErrorStep() const { return m_localErrorStep; }
    // the energies at the last reset or scene load
    const core::Energies &initialEnergies() const { return m_initialEnergies; }
    // computing time (s) since the scene was loaded: of the steps while running, and of the
    // estimates made between them
    double stepSeconds() const { return m_stepSeconds; }
    double estimateSeconds() const { return m_estimateSeconds; }
    // estimateSeconds() / stepSeconds(), 0 before any step
    double estimateShare() const { return m_stepSeconds > 0.0 ? m_estimateSeconds / m_stepSeconds : 0.0; }

    // the replies to the messages applied since the last call (PlanAccuracy, CaptureState,
    // StopRecording), oldest first, each handed over once
    std::vector<Reply> takeReplies() { return std::exchange(m_replies, {}); }

private:
    void setScene(const SetSceneEdit &edit);
    void restart();
    void carryMotion(const core::SceneDesc &previous);
    void carryBrokenSprings(const core::SceneDesc &previous);
    void reset();
    void tilt(const TiltEdit &edit);
    void steer(const SteerEdit &edit);
    void applySteering();
    void grab(const GrabEdit &edit);
    void applyGrab();
    bool stepOnce();
    void checkPairSpeed();
    void estimate(bool counted);
    void planAccuracy(const PlanAccuracy &request);
    void captureState(const CaptureState &request);

    // the timeline
    struct ScrubbedStep {
        std::shared_ptr<const core::Model> model;
        std::shared_ptr<const core::SceneDesc> scene;
        core::State state;
    };
    bool changesTheRun(const Message &message) const;
    HeldForces heldForces() const;
    void keyframe();
    bool scrubTo(std::uint64_t step);
    void stepBack();
    void resumeFromScrub();

    std::shared_ptr<const core::SceneDesc> m_scene;
    std::shared_ptr<const core::Model> m_model;
    core::State m_state;
    core::Workspace m_work;  // the steps' scratch and profile, for the run and the scrubs alike
    Timeline m_timeline;
    std::optional<ScrubbedStep> m_scrub;  // while a recorded step is shown
    std::uint64_t m_resumes = 0;
    std::uint64_t m_resumedAt = 0;
    core::State m_lastGood;  // the state before the latest steps, restored if they blow up
    bool m_running = false;
    double m_owed = 0.0;  // s of simulated time not yet covered by a whole step
    std::optional<core::Blowup> m_blowup;
    std::optional<core::StabilityLimit> m_stability;
    bool m_stabilityStale = true;  // the model changed since the limit was analysed
    std::string m_pairSpeedWarning;

    // the live error estimate and what it has cost
    core::StepDoubling m_doubling;
    std::optional<double> m_localError;
    std::uint64_t m_localErrorStep = 0;
    bool m_estimateStale = true;              // an edit changed the model or the state since
    double m_wallSinceEstimate = 0.0;         // s of wall time run since the last estimate
    double m_stepSecondsSinceEstimate = 0.0;  // s of computing spent on steps since then
    double m_lastEstimateSeconds = 0.0;       // s the last estimate took
    double m_stepSeconds = 0.0;
    double m_estimateSeconds = 0.0;
    core::Energies m_initialEnergies;

    std::vector<Reply> m_replies;  // not yet taken

    // the mouse spring: the particle held (-1: none) and where the cursor holds it
    int m_grabParticle = -1;
    Eigen::Vector3d m_grabTarget = Eigen::Vector3d::Zero();

    std::uint64_t m_stepsTaken = 0;
    std::shared_ptr<SessionRecording> m_recording;  // while recording
    std::uint64_t m_recordingFrom = 0;              // m_stepsTaken when it started

    // the steering force, kept across resets and parameter changes
    int m_steerParticle = -1;
    Eigen::Vector3d m_steerForce = Eigen::Vector3d::Zero();  // N
};

}  // namespace ui
