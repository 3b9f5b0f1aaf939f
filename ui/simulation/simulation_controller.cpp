#include "simulation_controller.h"

#include "simulation_worker.h"
#include "thread_handover.h"

#include "ui/document/scene_document.h"

#include <QThread>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

namespace ui {

namespace {

// mixes the seed and the tilt's number into a well spread seed (splitmix64)
std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t count)
{
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (count + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

}  // namespace

SimulationController::SimulationController(QObject *parent)
    : QObject(parent), m_thread(new QThread(this)), m_worker(new SimulationWorker(m_messages, m_replies, m_mailbox))
{
    // the worker lives on its own thread and is deleted there when the thread finishes
    m_thread->setObjectName(QStringLiteral("simulation"));
    m_worker->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);

    // frames, replies and blow-ups come back queued, onto this (the UI) thread
    m_frameConnection = connect(m_worker, &SimulationWorker::frameReady, this, &SimulationController::takeFrame,
                                Qt::QueuedConnection);
    m_repliesConnection = connect(m_worker, &SimulationWorker::repliesReady, this,
                                  &SimulationController::takeReplies, Qt::QueuedConnection);
    m_blowUpConnection = connect(m_worker, &SimulationWorker::blewUp, this, [this](const QString &message) {
        setRunning(false);
        emit blewUp(message);
    }, Qt::QueuedConnection);
    m_thread->start();
}

SimulationController::~SimulationController()
{
    shutDown();
}

void SimulationController::shutDown()
{
    if (m_shutDown)
        return;
    m_shutDown = true;
    // Cut the worker's connections to this side here, on the UI thread, so that their slot objects
    // are freed on the thread that calls them: left for the worker's deletion on its own thread,
    // they would be freed there after a hand-over under Qt's lock that ThreadSanitizer cannot see.
    // (By their handles: a disconnect by sender would read the worker's QObject from this thread.)
    disconnect(m_frameConnection);
    disconnect(m_blowUpConnection);
    disconnect(m_repliesConnection);
    // an accuracy plan under way stops (it may have minutes to go, and does not yield to messages)
    m_worker->quitting().store(true, std::memory_order_relaxed);
    // the worker's event loop ends, its timer stops with it, and the worker is deleted on its thread
    handOverRelease(m_worker);
    // a message raises the flag that stops a long step, so that the thread can end now
    m_messages.push(Pause{});
    m_thread->quit();
    m_thread->wait();
    handOverAcquire(&m_mailbox);
    m_worker = nullptr;
    setRunning(false);
}

std::uint64_t SimulationController::post(Message message)
{
    const std::uint64_t sequence = m_messages.push(std::move(message));
    // one wake for a burst of messages; the worker applies them all at once
    if (m_worker && !m_worker->wakePending().exchange(true))
        SimulationWorker::postWake(m_worker);
    return sequence;
}

void SimulationController::follow(const SceneDocument &document)
{
    // the document's scene is an immutable shared value: sending it costs a pointer
    connect(&document, &SceneDocument::sceneChanged, this,
            [this, &document](SceneChange change) { setScene(document.sharedScene(), change); });
}

std::uint64_t SimulationController::setScene(std::shared_ptr<const core::SceneDesc> scene, SceneChange change)
{
    if (change != SceneChange::Replace)
        return post(SetSceneEdit{std::move(scene), change});
    setRunning(false);
    const std::uint64_t sequence = post(SetSceneEdit{std::move(scene), change});
    emit sceneReplaced(sequence);
    return sequence;
}

std::uint64_t SimulationController::play()
{
    setRunning(true);
    return post(Play{});
}

std::uint64_t SimulationController::pause()
{
    setRunning(false);
    return post(Pause{});
}

std::uint64_t SimulationController::scrub(std::uint64_t step)
{
    setRunning(false);
    return post(Scrub{step});
}

std::uint64_t SimulationController::stepBack()
{
    setRunning(false);
    return post(StepBack{});
}

std::uint64_t SimulationController::setTimelineBudget(std::size_t bytes)
{
    return post(SetTimelineBudget{bytes});
}

std::uint64_t SimulationController::togglePlay()
{
    return m_running ? pause() : play();
}

std::uint64_t SimulationController::stepOnce()
{
    setRunning(false);
    return post(StepOnce{});
}

std::uint64_t SimulationController::reset()
{
    return post(Reset{});
}

std::uint64_t SimulationController::tilt()
{
    return post(TiltEdit{mixSeed(m_tiltSeed, m_tiltCount++), kTiltSpeed});
}

std::uint64_t SimulationController::steer(int particle, const Eigen::Vector3d &force)
{
    return post(SteerEdit{particle, force});
}

std::uint64_t SimulationController::grab(int particle, const Eigen::Vector3d &target)
{
    return post(GrabEdit{particle, target});
}

std::uint64_t SimulationController::strike(int particle, const Eigen::Vector3d &velocityChange,
                                           const Eigen::Vector3d &spinChange)
{
    return post(StrikeEdit{particle, velocityChange, spinChange});
}

bool SimulationController::sceneTurns() const
{
    return m_frame && m_frame->model && m_frame->model->plan.spin;
}

std::uint64_t SimulationController::sync()
{
    return post(Sync{});
}

std::uint64_t SimulationController::planAccuracy(double tolerance)
{
    const std::uint64_t request = ++m_accuracyRequests;
    post(PlanAccuracy{tolerance, request});
    return request;
}

std::uint64_t SimulationController::startRecording()
{
    return post(StartRecording{});
}

std::uint64_t SimulationController::stopRecording()
{
    const std::uint64_t request = ++m_recordingRequests;
    post(StopRecording{request});
    return request;
}

std::uint64_t SimulationController::captureState()
{
    const std::uint64_t request = ++m_captureRequests;
    post(CaptureState{request});
    return request;
}

void SimulationController::setTiltSeed(std::uint64_t seed)
{
    m_tiltSeed = seed;
    m_tiltCount = 0;
}

void SimulationController::setFrameInterval(double seconds)
{
    if (m_worker)
        m_worker->frameIntervalNs().store(static_cast<std::int64_t>(std::max(0.0, seconds) * 1e9),
                                          std::memory_order_relaxed);
}

double SimulationController::frameInterval() const
{
    return m_worker ? double(m_worker->frameIntervalNs().load(std::memory_order_relaxed)) * 1e-9 : 0.0;
}

void SimulationController::setSpeed(double speed)
{
    if (m_worker)
        m_worker->speed().store(std::isfinite(speed) ? std::max(0.0, speed) : 1.0, std::memory_order_relaxed);
}

double SimulationController::speed() const
{
    return m_worker ? m_worker->speed().load(std::memory_order_relaxed) : 1.0;
}

void SimulationController::setRunning(bool running)
{
    if (m_running == running)
        return;
    m_running = running;
    emit runningChanged(running);
}

void SimulationController::setPlottedParticle(int particle)
{
    if (m_worker)
        m_worker->plottedParticle().store(particle, std::memory_order_relaxed);
}

void SimulationController::takeFrame()
{
    std::shared_ptr<const SimulationFrame> frame = m_mailbox.take();
    if (!frame)
        return;
    m_frame = std::move(frame);
    emit frameChanged();
}

void SimulationController::takeReplies()
{
    for (const Reply &reply : m_replies.drain())
        std::visit(
            [this](const auto &r) {
                using R = std::decay_t<decltype(r)>;
                if constexpr (std::is_same_v<R, AccuracyPlanReply>)
                    emit accuracyPlanned(r);
                else if constexpr (std::is_same_v<R, CapturedStateReply>)
                    emit stateCaptured(r);
                else
                    emit recordingStopped(r);
            },
            reply);
}

}  // namespace ui
