#include "simulation_worker.h"

#include "thread_handover.h"

#include "core/integrators/solver_report.h"

#include <QCoreApplication>
#include <QEvent>
#include <QTimer>
#include <algorithm>
#include <atomic>

namespace ui {

namespace {

const QEvent::Type kWakeEvent = static_cast<QEvent::Type>(QEvent::registerEventType());

// the messages that leave the state shown as it was, unless they take a step (which the step
// number tells): after them the latest snapshot still holds
bool keepsTheShownState(const Message &message)
{
    return std::holds_alternative<Pause>(message) || std::holds_alternative<Play>(message) ||
           std::holds_alternative<Sync>(message) || std::holds_alternative<StepOnce>(message) ||
           std::holds_alternative<PlanAccuracy>(message) || std::holds_alternative<CaptureState>(message) ||
           std::holds_alternative<StartRecording>(message) || std::holds_alternative<StopRecording>(message) ||
           std::holds_alternative<SetTimelineBudget>(message);
}

}  // namespace

SimulationWorker::SimulationWorker(MessageQueue &messages, ReplyQueue &replies, LatestMailbox<SimulationFrame> &mailbox)
    : m_messages(messages), m_replies(replies), m_mailbox(mailbox), m_timer(new QTimer(this))
{
    // the timer is a child, so it moves to the worker thread with this object
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setInterval(kTickIntervalMs);
    connect(m_timer, &QTimer::timeout, this, &SimulationWorker::tick);
    // a long step stops for the messages that arrive while it runs
    m_runner.setInterrupt(&m_messages.waiting());
    m_runner.setPlanStop(&m_quitting);
    // the plots have every step, however seldom the window draws
    m_runner.samples().setEnabled(true);
}

SimulationWorker::~SimulationWorker()
{
    // deleted on its own thread once its event loop ended: see what the UI side did before, and
    // hand what this thread did (its last frame in the mailbox) to the UI side's wait for the end
    handOverAcquire(this);
    handOverRelease(&m_mailbox);
}

void SimulationWorker::postWake(SimulationWorker *worker)
{
    // (an event rather than a queued functor: Qt frees the event inside its own code, whereas a
    // functor's slot object would be freed in Springlab's, on the worker's thread)
    auto *event = new QEvent(kWakeEvent);
    handOverRelease(worker);
    QCoreApplication::postEvent(worker, event);
}

void SimulationWorker::customEvent(QEvent *event)
{
    handOverAcquire(this);
    if (event->type() == kWakeEvent)
        wake();
    else
        QObject::customEvent(event);
}

void SimulationWorker::wake()
{
    m_wakePending = false;
    tick();
}

void SimulationWorker::tick()
{
    const bool wasRunning = m_runner.isRunning();
    const std::uint64_t owedBefore = m_runner.stepsOwed();
    m_runner.samples().setParticle(m_plottedParticle.load(std::memory_order_relaxed));

    // messages first: they land between two steps
    MessageQueue::Batch batch = m_messages.drain();
    for (const Message &message : batch.messages) {
        m_runner.apply(message);
        m_snapshotStale = m_snapshotStale || !keepsTheShownState(message);
    }
    bool changed = !batch.messages.empty();

    // the answers to one-off requests, each once, ahead of the frame that follows them
    bool told = false;
    for (Reply &reply : m_runner.takeReplies())
        if (m_replies.push(std::move(reply)) && !told) {
            told = true;
            emit repliesReady();
        }
    m_appliedMessage = batch.lastSequence;

    // slow steps come next: the messages are answered first, not a step later (and when that
    // answer had to go with the snapshot before it, the next frame brings the new one at once,
    // ahead of the steps and the diagnostics, which may take seconds on such a scene)
    if (changed && m_runner.stepsAreSlow()) {
        publish(Frame::Answering);
        if (m_snapshotStale)
            publish();
        changed = false;
    }

    // the steps asked for that earlier messages cut short, and the replay to a step scrubbed to
    if (m_runner.takeOwedSteps() || m_runner.continueScrub()) {
        changed = true;
        m_snapshotStale = true;
    }

    // the steps the run takes by itself: shown at the pace the window asks for (frameInterval)
    bool stepped = false;

    // then the steps that the wall time elapsed since the last tick asks for
    if (m_runner.isRunning()) {
        if (!wasRunning) {
            // just started: time starts counting now, and so do the rates
            m_clock.start();
            m_window.start();
            m_rates.start();
        } else {
            const double elapsed = static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
            m_clock.start();
            const double capped = std::min(elapsed, kMaxTickSeconds);
            const double speed = m_speed.load(std::memory_order_relaxed);
            const double timeStep = m_runner.hasScene() ? m_runner.model()->timeStep : 0.0;
            const SimulationRunner::Advance advance = m_runner.advance(capped, kStepBudgetSeconds, speed);
            stepped = advance.steps > 0;
            m_snapshotStale = m_snapshotStale || stepped;
            // the rates over a window that holds a step, then a fresh window; the simulated time
            // the tick kept up with (as fast as it goes: the steps it took)
            const double credited = speed > SimulationRunner::kAsFastAsItGoes
                                        ? capped * speed - advance.droppedSeconds
                                        : static_cast<double>(advance.steps) * timeStep;
            if (m_rates.add(advance.steps, credited, static_cast<double>(m_window.nsecsElapsed()) * 1e-9))
                m_window.start();
        }
    }
    if (!m_runner.isRunning())
        m_rates.start();

    // a message or a blow-up changed what the error estimate is of: estimate again
    m_runner.updateEstimate();

    // an edit changed the model: its stability limit, for the parameters panel
    changed = m_runner.updateStability() || changed;

    // a blow-up paused the run: say what, where, why and what to do
    if (const std::optional<std::string> message = m_runner.takeBlowupMessage()) {
        changed = true;
        m_snapshotStale = true;
        emit blewUp(QString::fromStdString(*message));
    }

    // the timer runs only while the simulation does, or work cut short by messages waits
    const bool busy = m_runner.isRunning() || m_runner.hasWorkLeft();
    if (busy && !m_timer->isActive())
        m_timer->start();
    else if (!busy && m_timer->isActive())
        m_timer->stop();

    // what answers a message, or warns of particles too fast, goes at once; new steps alone once
    // the window is ready for a frame
    changed = changed || m_runner.diagnostics().pairSpeedWarning() != m_shownPairSpeedWarning;
    m_unshownSteps = m_unshownSteps || stepped;
    const bool frameDue = !m_published.isValid() ||
                          m_published.nsecsElapsed() >= m_frameIntervalNs.load(std::memory_order_relaxed);
    if (changed || m_runner.isRunning() != wasRunning || m_runner.stepsOwed() != owedBefore ||
        (m_unshownSteps && frameDue))
        publish();
}

std::shared_ptr<core::Snapshot> SimulationWorker::freeSnapshot(const core::Model &model)
{
    for (std::shared_ptr<core::Snapshot> &pooled : m_snapshotPool) {
        if (pooled.use_count() != 1)
            continue;  // the window (or a frame on its way) still reads it
        // only the pool holds it: the window's last reads of it came before it let go
        std::atomic_thread_fence(std::memory_order_acquire);
        // one of another size is another scene's: its memory goes rather than stay unused
        if (pooled->particleCount() != model.particleCount() || pooled->springCount() != model.springCount())
            pooled = std::make_shared<core::Snapshot>();
        return pooled;
    }
    auto fresh = std::make_shared<core::Snapshot>();
    if (m_snapshotPool.size() < kPooledSnapshots)
        m_snapshotPool.push_back(fresh);
    return fresh;
}

void SimulationWorker::makeSnapshot()
{
    m_snapshotModel = m_runner.shownModel();
    m_snapshotStale = false;
    if (!m_snapshotModel) {
        m_snapshot = nullptr;
        return;
    }
    std::shared_ptr<core::Snapshot> into = freeSnapshot(*m_snapshotModel);
    m_runner.fillSnapshot(*into);
    m_snapshot = std::move(into);
}

void SimulationWorker::publish(Frame kind)
{
    m_published.start();
    m_unshownSteps = false;
    auto frame = std::make_shared<SimulationFrame>();
    // the snapshot's own model and scene, the recorded ones while a past step is shown
    frame->model = m_runner.shownModel();
    frame->scene = m_runner.shownScene();
    // a new snapshot only when what it shows changed: one of 10⁶ particles and 6·10⁶ springs takes
    // a sixth of a second or more to make, which would hold up the answer to a Pause
    const core::State &shown = m_runner.shownState();
    const bool sameModel = m_snapshot && frame->model == m_snapshotModel;
    const bool sameState =
        !m_snapshotStale && sameModel && m_snapshot->step == shown.step && m_snapshot->time == shown.time;
    if (!sameState) {
        const std::int64_t elements = std::int64_t(frame->model->particleCount()) + frame->model->springCount();
        if (kind == Frame::Answering && sameModel && elements > m_slowSnapshotElements) {
            // the answer goes now with the snapshot before; the new one comes in the next frame
            m_snapshotStale = true;
            frame->snapshotBehind = true;
        } else {
            makeSnapshot();
        }
    }
    frame->snapshot = m_snapshot;
    frame->shownStep = shown.step;
    frame->appliedMessage = m_appliedMessage;
    frame->running = m_runner.isRunning();
    frame->stepsOwed = m_runner.stepsOwed();
    frame->realTimeFactor = m_rates.realTimeFactor();
    frame->speed = m_speed.load(std::memory_order_relaxed);
    frame->stepsPerSecond = m_rates.stepsPerSecond();
    const RunDiagnostics &diagnostics = m_runner.diagnostics();
    frame->localError = diagnostics.localError();
    frame->localErrorStep = diagnostics.localErrorStep();
    frame->initialEnergies = diagnostics.initialEnergies();
    frame->estimateShare = diagnostics.estimateShare();
    frame->stability = diagnostics.stability();
    frame->pairSpeedWarning = diagnostics.pairSpeedWarning();
    if (frame->model)
        frame->solverSummary = core::lastSolveSummary(frame->model->integrator, m_runner.profile());
    m_shownPairSpeedWarning = frame->pairSpeedWarning;
    const Scrubber &scrubber = m_runner.scrubber();
    const Timeline &timeline = scrubber.timeline();
    TimelineInfo &info = frame->timeline;
    info.empty = timeline.empty();
    info.firstStep = timeline.firstStep();
    info.lastStep = timeline.lastStep();
    info.firstTime = timeline.firstTime();
    info.lastTime = timeline.lastTime();
    info.scrubStep = scrubber.scrubStep();
    info.scrubPending = scrubber.pendingStep();
    info.usedBytes = timeline.usedBytes();
    info.budgetBytes = timeline.budget();
    info.keyframeOverBudget = timeline.keyframeOverBudget();
    info.breakSteps = timeline.breakSteps();
    info.locked = m_runner.isRecording();
    info.resumes = scrubber.resumes();
    info.resumedAt = scrubber.resumedAt();
    // the samples the window has not taken: an empty box means it took those of the last frame
    StepSampler &samples = m_runner.samples();
    if (m_mailbox.empty())
        samples.delivered(m_lastSampleSent);
    frame->samples = samples.pending();
    if (frame->samples)
        m_lastSampleSent = frame->samples->back().sequence;
    if (m_mailbox.publish(std::move(frame)))
        emit frameReady();
}

}  // namespace ui
