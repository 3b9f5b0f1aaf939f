#pragma once
// SimulationWorker: lives on the controller's worker thread. A QTimer ticks it while running; each
// tick drains the message queue, advances the simulation by the wall time elapsed (capped),
// hands the replies to one-off requests to the reply queue and publishes a frame to the mailbox.
// Only this object, on its thread, touches the core::State. A frame that answers a message is
// published at once; one that only brings new steps waits for the pace the window draws at
// (frameIntervalNs), since building a snapshot of a large scene nobody will see costs the run; and
// a frame that shows the same state as the one before reuses its snapshot. Where a snapshot is slow
// to make (10⁶ particles: a sixth of a second and more), the frame that answers a message goes
// with the snapshot before it, marked behind, and the snapshot of the new state follows in the
// same tick: a Pause is answered when the step stops, not when its picture is ready. Every frame
// carries the plots' samples of the steps taken since the last frame the window took
// (step_samples.h).

#include "session/messages.h"
#include "session/latest_mailbox.h"
#include "session/replies.h"
#include "session/run_rates.h"
#include "session/simulation_frame.h"
#include "session/simulation_runner.h"

#include <QElapsedTimer>
#include <QObject>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

class QTimer;

namespace ui {

class SimulationWorker : public QObject {
    Q_OBJECT

public:
    // longest wall time one tick simulates: after a stall the run falls behind instead of racing
    static constexpr double kMaxTickSeconds = 0.1;
    // computing time one tick may spend on steps before it gives up what is still owed
    static constexpr double kStepBudgetSeconds = 0.05;
    // ms between ticks while running
    static constexpr int kTickIntervalMs = 16;
    // a snapshot of more particles and springs together than this is made after the frame
    // answering a message, not before: one of 278 002 (the 200 × 200 cloth) took 9.5 ms, one of
    // 6 990 002 (the 1000 × 1000 cloth) 0.17 s. By size, not by the time the last one took, so
    // that which frames go first does not depend on how busy the machine is
    static constexpr std::int64_t kSlowSnapshotElements = 1000000;

    SimulationWorker(MessageQueue &messages, ReplyQueue &replies, LatestMailbox<SimulationFrame> &mailbox);

    // Posts the event that makes the worker apply pending messages now, running or not.
    static void postWake(SimulationWorker *worker);
    ~SimulationWorker() override;

    // the UI side sets this before queueing wake(), so that a burst of messages queues one wake
    std::atomic<bool> &wakePending() { return m_wakePending; }
    // raised by the UI side as it shuts the worker down: an accuracy plan under way stops
    std::atomic<bool> &quitting() { return m_quitting; }
    // the shortest time between two frames that bring nothing but new steps (ns), set by the UI
    // side to the pace it draws at; a frame that answers a message goes at once
    std::atomic<std::int64_t> &frameIntervalNs() { return m_frameIntervalNs; }
    // the speed a playing run goes at, set by the UI side: simulated seconds per wall-clock second,
    // or SimulationRunner::kAsFastAsItGoes (playback_speed.h)
    std::atomic<double> &speed() { return m_speed; }
    // how big a snapshot may be before a frame answering a message goes without it
    // (kSlowSnapshotElements); set before the worker runs (the tests set 0 to see every answer go first)
    void setSlowSnapshotElements(std::int64_t elements) { m_slowSnapshotElements = elements; }
    // the particle whose motion the plots' samples carry (-1: none), set by the UI side; read at
    // the start of each tick
    std::atomic<int> &plottedParticle() { return m_plottedParticle; }

    // the steps the run has taken, on the worker's thread only (the tests, which drive it on theirs)
    std::uint64_t stepsTaken() const { return m_runner.stepsTaken(); }

protected:
    void customEvent(QEvent *event) override;

signals:
    // a frame waits in the mailbox, and the mailbox was empty before it
    void frameReady();
    // replies wait in the reply queue, and the queue was empty before them
    void repliesReady();
    // the run stopped because a value stopped being finite or bounded
    void blewUp(const QString &message);

private:
    void wake();
    void tick();
    // a frame of where the run is; answering: it answers messages, and goes at once even if its
    // snapshot must wait (kSlowSnapshotElements)
    enum class Frame { Regular, Answering };
    void publish(Frame kind = Frame::Regular);
    // the snapshot of the state shown
    void makeSnapshot();
    // a snapshot of the pool that only the pool holds, else a new one (pooled while there is room)
    std::shared_ptr<core::Snapshot> freeSnapshot(const core::Model &model);

    MessageQueue &m_messages;
    ReplyQueue &m_replies;
    LatestMailbox<SimulationFrame> &m_mailbox;
    SimulationRunner m_runner;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;  // wall time since the previous tick while running
    std::atomic<bool> m_wakePending = false;
    std::atomic<bool> m_quitting = false;
    std::uint64_t m_appliedMessage = 0;
    std::atomic<std::int64_t> m_frameIntervalNs = 0;
    std::atomic<double> m_speed = 1.0;
    std::atomic<int> m_plottedParticle = -1;
    std::uint64_t m_lastSampleSent = 0;  // the sequence number of the newest sample a frame carried
    QElapsedTimer m_published;   // since the latest frame
    bool m_unshownSteps = false;  // steps taken since the latest frame
    std::string m_shownPairSpeedWarning;  // the latest frame's
    // the latest snapshot, for the frames that show the same state again (a Pause, a Sync), the
    // model it was made with, and whether the state changed since
    std::shared_ptr<const core::Snapshot> m_snapshot;
    std::shared_ptr<const core::Model> m_snapshotModel;
    // the snapshots made lately; one the window no longer holds is filled again rather than a new
    // one made, for its memory (a Step Back at 10⁶ particles waited 0.8 s for a fresh snapshot)
    static constexpr std::size_t kPooledSnapshots = 3;
    std::vector<std::shared_ptr<core::Snapshot>> m_snapshotPool;
    bool m_snapshotStale = true;
    std::int64_t m_slowSnapshotElements = kSlowSnapshotElements;

    // the rates, over the window m_window times
    QElapsedTimer m_window;
    RunRates m_rates;
};

}  // namespace ui
