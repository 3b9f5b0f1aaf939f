#pragma once
// SimulationController: the UI thread's handle on the simulation. It owns the worker thread, the
// message queue and the frame mailbox. Every request (scene, play, pause, step, reset, tilt, steer)
// becomes a message that the worker applies between two steps, so none of them ever blocks the UI;
// the editor's scene comes straight from the document it follows, each change as it is made;
// frames come back through the latest-wins mailbox and a queued signal, and the answers to one-off
// requests (a plan, a captured state, a recording) through the reply queue, each announced once
// by its own signal.

#include "session/messages.h"
#include "session/latest_mailbox.h"
#include "session/replies.h"
#include "session/simulation_frame.h"

#include <QObject>
#include <QString>
#include <cstdint>
#include <memory>

class QThread;

namespace ui {

class SceneDocument;
class SimulationWorker;

class SimulationController : public QObject {
    Q_OBJECT

public:
    // m/s: the largest change a tilt makes to one velocity component
    static constexpr double kTiltSpeed = 2.0;

    explicit SimulationController(QObject *parent = nullptr);
    ~SimulationController() override;

    // from now on every change of the document's scene is sent to the worker as it is made
    // (setScene)
    void follow(const SceneDocument &document);

    // each returns the message's sequence number; frame()->appliedMessage reaches it once applied.
    // A whole new scene (SceneChange::Replace) is also announced by sceneReplaced().
    std::uint64_t setScene(std::shared_ptr<const core::SceneDesc> scene, SceneChange change);
    std::uint64_t play();
    std::uint64_t pause();
    std::uint64_t togglePlay();
    std::uint64_t stepOnce();
    std::uint64_t reset();
    std::uint64_t tilt();
    std::uint64_t steer(int particle, const Eigen::Vector3d &force);
    // the Drag tool's mouse spring pulls particle toward target; particle -1 lets go
    std::uint64_t grab(int particle, const Eigen::Vector3d &target);
    // a blow to a free particle: its velocity and spin change at once (the cue's stroke, a flick)
    std::uint64_t strike(int particle, const Eigen::Vector3d &velocityChange, const Eigen::Vector3d &spinChange);
    // whether the scene of the latest frame keeps spins (core::StepPlan::spin): a strike's spin is
    // kept only there
    bool sceneTurns() const;
    // changes nothing, but the worker publishes a frame once it has applied every earlier message
    std::uint64_t sync();
    // asks the worker to plan the integrator and substeps for a tolerance (m per sub-step) from its
    // state; returns the request's number, which accuracyPlanned() carries with the plan
    std::uint64_t planAccuracy(double tolerance);
    // asks the worker for a copy of its positions and velocities; returns the request's number,
    // which stateCaptured() carries with the captured state
    std::uint64_t captureState();
    // starts recording the session; stopRecording() ends it and returns the request's number,
    // which recordingStopped() carries with the recording
    std::uint64_t startRecording();
    std::uint64_t stopRecording();

    // the timeline: show the recorded state of a step (pauses), one step back, and the memory the
    // recording may use (bytes; 0 turns it off)
    std::uint64_t scrub(std::uint64_t step);
    std::uint64_t stepBack();
    std::uint64_t setTimelineBudget(std::size_t bytes);

    // tilts are drawn from this seed: the n-th tilt after setTiltSeed(s) is the same every time
    void setTiltSeed(std::uint64_t seed);

    // the shortest time between two frames that bring nothing but new steps (s): the pace the
    // window draws at (FramePacer); 0, the default: every tick's steps are shown
    void setFrameInterval(double seconds);
    double frameInterval() const;
    // the speed a playing run goes at (playback_speed.h): a multiple of real time, or
    // SimulationRunner::kAsFastAsItGoes; 1 until set
    void setSpeed(double speed);
    double speed() const;

    // the particle whose position and velocity the frames' plot samples carry from the worker's
    // next tick on (-1: none)
    void setPlottedParticle(int particle);

    // what the UI last asked for (a blow-up also pauses)
    bool isRunning() const { return m_running; }

    // the newest frame received on the UI thread; null before the first
    std::shared_ptr<const SimulationFrame> frame() const { return m_frame; }

    // stops the worker thread and waits for it; called by the destructor, safe to call twice
    void shutDown();
    bool isShutDown() const { return m_shutDown; }
    // whether messages wait for the worker to take them (it is busy, or about to wake)
    bool messagesWaiting() const { return m_messages.waiting().load(std::memory_order_relaxed); }
    QThread *workerThread() const { return m_thread; }

signals:
    // a whole new scene went to the worker as message `sequence`: the frames before it show the
    // old scene, those with appliedMessage >= sequence the new one
    void sceneReplaced(std::uint64_t sequence);
    // a new frame() arrived
    void frameChanged();
    void runningChanged(bool running);
    // the run blew up and paused; the message names the particle, the quantity, the step and time
    void blewUp(const QString &message);
    // the replies to planAccuracy(), captureState() and stopRecording(), each once
    void accuracyPlanned(const ui::AccuracyPlanReply &reply);
    void stateCaptured(const ui::CapturedStateReply &reply);
    void recordingStopped(const ui::RecordingReply &reply);

private:
    std::uint64_t post(Message message);
    void setRunning(bool running);
    void takeFrame();
    void takeReplies();

    MessageQueue m_messages;
    LatestMailbox<SimulationFrame> m_mailbox;
    ReplyQueue m_replies;
    std::uint64_t m_recordingRequests = 0;
    QThread *m_thread = nullptr;
    SimulationWorker *m_worker = nullptr;
    // the worker's signals to this side, cut on this thread at shutDown()
    QMetaObject::Connection m_frameConnection;
    QMetaObject::Connection m_blowUpConnection;
    QMetaObject::Connection m_repliesConnection;
    std::shared_ptr<const SimulationFrame> m_frame;
    bool m_running = false;
    bool m_shutDown = false;
    std::uint64_t m_tiltSeed = 0;
    std::uint64_t m_tiltCount = 0;
    std::uint64_t m_accuracyRequests = 0;
    std::uint64_t m_captureRequests = 0;
};

}  // namespace ui
