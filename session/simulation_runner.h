#pragma once
// SimulationRunner: the worker's Qt-free half, in charge of the run. It owns the compiled Model
// and the State, applies messages between steps (messages.h), and turns wall time into whole steps
// of the model's time step; a tick that blows up goes back to its last good state. It holds the
// steering force and the mouse spring, records sessions (session_recording.h) and answers one-off
// requests with replies (replies.h). An edit of the scene keeps the run going as far as it can
// (carry_across_edit.h). It has no thread and no timer of its own: SimulationWorker calls it from
// its tick, and the unit tests call it directly, one message or one advance at a time.
//
// Three helpers do the rest, on the runner's model, state and workspace. The Scrubber (scrubber.h)
// keeps the timeline the run is recorded on as it goes, and shows a recorded step, pausing the run
// there. Play, or any edit that changes the run, resumes from the step shown with the scene as it
// is now in the editor, and the recorded future after that step is discarded (one line of
// history, no branches). RunDiagnostics (run_diagnostics.h) keeps the live error estimate, the
// energies the drift is measured from, the stability limit, the pair speed warning, the
// explanation of a blow-up, and makes the accuracy plans. The StepSampler (step_samples.h) takes
// the plots' figures after every step the run keeps.
//
// A long step yields to the messages. Given a flag raised while messages wait (setInterrupt), a
// step stops between two sub-steps when it is raised and is not taken: the state goes back to
// where the step began, so every step is whole and its bits do not depend on when it was cut.
// While running, the steps owed are simply taken in a later tick. A step asked for by StepOnce
// becomes owed (stepsOwed), and is taken after the messages that cut it short unless one of
// them stops it (Pause, Play, Reset, another scene, a scrub). Where a step begins is copied only
// when it is slow, so that fast scenes pay nothing for this.

#include "messages.h"
#include "replies.h"
#include "run_diagnostics.h"
#include "scrubber.h"
#include "session_recording.h"
#include "step_samples.h"

#include "core/model/model.h"
#include "core/model/snapshot.h"
#include "core/model/state.h"
#include "core/model/workspace.h"
#include "core/thread_chooser.h"

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ui {

class SimulationRunner {
public:
    struct Advance {
        int steps = 0;                // steps taken
        double droppedSeconds = 0.0;  // s of wall time left unsimulated (the run fell behind)
        bool interrupted = false;     // a step stopped for waiting messages
    };

    // steps slower than this (s) are worth a copy of where the next one begins, so that it can be
    // cut short: the copy then costs a small share of the step
    static constexpr double kInterruptibleStepSeconds = 0.01;

    // the flag that stops a long step for waiting messages (MessageQueue::waiting); null: never
    void setInterrupt(const std::atomic<bool> *flag);
    // the flag that stops an accuracy plan (which can take minutes, and does not yield to
    // messages): raised when the editor closes, so that it need not wait for the plan
    void setPlanStop(const std::atomic<bool> *flag) { m_planStop = flag; }
    // steps asked for by StepOnce and not taken yet: cut short, or slow (with an interrupt flag
    // set, a slow step is owed at once, so that the Step is answered before it is taken)
    std::uint64_t stepsOwed() const { return m_stepsOwed; }
    // takes the owed steps, each of which may be cut short again; true if one was taken
    bool takeOwedSteps();
    // whether the latest step took kInterruptibleStepSeconds or more (or was cut short)
    bool stepsAreSlow() const { return m_lastStepSeconds >= kInterruptibleStepSeconds; }
    // whether there is work to come back to without a message: owed steps, a replay to a step
    // scrubbed to cut short, a missing estimate, a stability analysis not finished
    bool hasWorkLeft() const
    {
        return m_stepsOwed > 0 || m_scrubber.pendingStep().has_value() || m_diagnostics.estimateStale() ||
               m_diagnostics.stabilityPending();
    }
    // goes on with the replay to a step scrubbed to that messages cut short, or that slow steps
    // take a step a tick (so that each is shown); true if it showed another step
    bool continueScrub();

    // applies one message between two steps
    void apply(const Message &message);

    // recording (session_recording.h): from startRecording() on, every message that changes the
    // run is kept with the steps taken before it; stopRecording() ends it and hands it over (null
    // when none was started or there is no scene)
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

    // advances simulated time by wallSeconds (already capped by the caller) times speed, in whole
    // steps; the remainder is owed to the next call. Stops early when the steps have taken
    // budgetSeconds of computing, dropping what is still owed, so a slow scene runs slower than
    // asked instead of piling up a backlog. speed kAsFastAsItGoes (0) takes steps until the
    // budget is spent, whatever the wall time, and owes nothing. Does nothing while paused.
    static constexpr double kAsFastAsItGoes = 0.0;
    Advance advance(double wallSeconds, double budgetSeconds, double speed = 1.0);

    bool hasScene() const { return m_model != nullptr; }
    bool isRunning() const { return m_running; }
    const core::State &state() const { return m_state; }
    std::shared_ptr<const core::Model> model() const { return m_model; }
    std::shared_ptr<const core::SceneDesc> scene() const { return m_scene; }

    // the timeline and the step shown while scrubbing
    const Scrubber &scrubber() const { return m_scrubber; }
    // the state shown: the scrubbed step's while scrubbing, else the run's
    const core::State &shownState() const;
    // and the model it was stepped with and the scene that model came from: while scrubbing, the
    // recorded step's, which may have fewer particles or springs than the scene now in the editor
    std::shared_ptr<const core::Model> shownModel() const;
    std::shared_ptr<const core::SceneDesc> shownScene() const;
    // the state shown, packed for drawing
    std::shared_ptr<const core::Snapshot> snapshot() const;
    // the same into a snapshot nobody reads any more, its memory reused (core::fillSnapshot)
    void fillSnapshot(core::Snapshot &into) const;

    // the plots' samples of every step the run keeps (off until the editor turns them on)
    StepSampler &samples() { return m_samples; }
    const StepSampler &samples() const { return m_samples; }

    // the live accuracy figures, the stability limit and the pair speed warning
    const RunDiagnostics &diagnostics() const { return m_diagnostics; }
    const core::Profile &profile() const { return m_work.profile; }
    // estimates the local error now if a message or a blow-up changed the model or the state since
    // the last estimate; the worker calls it once a tick, after the messages and the steps
    void updateEstimate() { m_diagnostics.updateEstimate(m_model, m_state); }
    // works on the stability limit after an edit changed the model (RunDiagnostics: while running,
    // a slice the steps paid for; paused, to its end unless messages wait); true when a new one is in
    bool updateStability() { return m_diagnostics.updateStability(m_model, m_state, m_running); }
    // what stopped the run by blowing up, once, explained at the last good state (what failed,
    // where, why and the fix: core::explainBlowup); the caller reports it
    std::optional<std::string> takeBlowupMessage();

    // the replies to the messages applied since the last call (PlanAccuracy, CaptureState,
    // StopRecording), oldest first, each handed over once
    std::vector<Reply> takeReplies() { return std::exchange(m_replies, {}); }

private:
    void setScene(const SetSceneEdit &edit);
    void restart();
    void reset();
    void stepOnceMessage();
    void tilt(const TiltEdit &edit);
    void steer(const SteerEdit &edit);
    void strike(const StrikeEdit &edit);
    void applySteering();
    void grab(const GrabEdit &edit);
    void applyGrab();
    bool stepOnce();
    // a step that failed: the run stops and goes back to m_lastGood; false, for stepOnce
    bool stopAtLastGood();
    // one step, timed (m_lastStepSeconds), that the interrupt flag may cut short when start is given
    // (m_state == *start; null: it runs to its end); true if taken (false: blown up, or cut short
    // with m_state back at *start and m_work.interrupted set)
    bool interruptibleStep(const core::State *start);
    void captureState(const CaptureState &request);

    // the timeline
    HeldForces heldForces() const;
    void keyframe();
    // a sample of the run's state for the plots
    void sample();
    bool scrubTo(std::uint64_t step);
    void stepBack();
    void resumeFromScrub();

    std::shared_ptr<const core::SceneDesc> m_scene;
    std::shared_ptr<const core::Model> m_model;
    core::State m_state;
    core::Workspace m_work;  // the steps' scratch and profile, for the run and the scrubs alike
    // the threads the steps run on, chosen from their times (a busy core must not hold them up)
    core::ThreadChooser m_threads;
    Scrubber m_scrubber;
    RunDiagnostics m_diagnostics;
    StepSampler m_samples;
    core::State m_lastGood;  // the state before the latest steps, restored if they blow up
    const std::atomic<bool> *m_interrupt = nullptr;
    const std::atomic<bool> *m_planStop = nullptr;
    core::State m_stepStart;      // where the step in progress began, when it is slow (see above)
    std::uint64_t m_stepsOwed = 0;  // StepOnce steps still to take (cut short or slow)
    double m_lastStepSeconds = 0.0;  // computing time of the latest step, s (a cut one: so far)
    bool m_running = false;
    double m_owed = 0.0;  // s of simulated time not yet covered by a whole step
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
