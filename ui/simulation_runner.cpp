#include "simulation_runner.h"

#include "core/state_hash.h"

#include "core/step.h"

#include <chrono>
#include <cstdio>
#include <random>
#include <utility>

namespace ui {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// a uniform number in [-1, 1) from the generator's bits, the same on every standard library
double symmetricUnit(std::mt19937_64 &random)
{
    const double unit = static_cast<double>(random() >> 11) * 0x1.0p-53;  // [0, 1)
    return 2.0 * unit - 1.0;
}

// the visitor that dispatches each kind of edit
template <typename... Handlers>
struct Overloaded : Handlers... {
    using Handlers::operator()...;
};
template <typename... Handlers>
Overloaded(Handlers...) -> Overloaded<Handlers...>;

}  // namespace

void SimulationRunner::apply(const Edit &edit)
{
    // what changes the run goes into the recording; requests for copies and plans do not
    if (m_recording && !std::holds_alternative<SyncEdit>(edit) && !std::holds_alternative<PlanAccuracyEdit>(edit) &&
        !std::holds_alternative<CaptureStateEdit>(edit) && !std::holds_alternative<StartRecordingEdit>(edit) &&
        !std::holds_alternative<StopRecordingEdit>(edit))
        m_recording->entries.push_back({m_stepsTaken - m_recordingFrom, edit});
    std::visit(Overloaded{
                   [this](const SetSceneEdit &e) { setScene(e); },
                   [this](const PlayEdit &) { m_running = hasScene(); },
                   [this](const PauseEdit &) { m_running = false; },
                   [this](const StepOnceEdit &) {
                       m_running = false;
                       if (hasScene()) {
                           m_lastGood = m_state;
                           if (stepOnce())
                               ++m_stepsTaken;
                           m_estimateStale = true;
                       }
                   },
                   [this](const ResetEdit &) { reset(); },
                   [this](const TiltEdit &e) { tilt(e); },
                   [this](const SteerEdit &e) { steer(e); },
                   [](const SyncEdit &) {},
                   [this](const PlanAccuracyEdit &e) { planAccuracy(e); },
                   [this](const CaptureStateEdit &e) { captureState(e); },
                   [this](const GrabEdit &e) { grab(e); },
                   [this](const StartRecordingEdit &) { startRecording(); },
                   [this](const StopRecordingEdit &e) {
                       m_finishedRecording = stopRecording();
                       m_recordingRequest = e.request;
                   },
               },
               edit);
}

void SimulationRunner::setScene(const SetSceneEdit &edit)
{
    const std::shared_ptr<const core::SceneDesc> previous = m_scene;
    const bool sameCount = previous && edit.scene->particles.size() == previous->particles.size();
    m_scene = edit.scene;
    m_model = core::compileModel(*m_scene);
    switch (edit.change) {
    case SceneChange::Parameters:
        // same particles: the state stays valid as it is
        if (sameCount)
            break;
        [[fallthrough]];
    case SceneChange::Structure:
        if (previous && m_state.position.cols() == static_cast<Eigen::Index>(previous->particles.size())) {
            carryMotion(*previous);
            break;
        }
        [[fallthrough]];
    case SceneChange::Replace:
        restart();
        break;
    }
    if (edit.change == SceneChange::Replace) {
        // another scene: nothing of the old one's steering survives, and its costs start afresh
        m_running = false;
        m_steerParticle = -1;
        m_steerForce.setZero();
        m_grabParticle = -1;
        m_stepSeconds = 0.0;
        m_estimateSeconds = 0.0;
        m_lastEstimateSeconds = 0.0;
    }
    applySteering();
    m_estimateStale = true;
    m_stabilityStale = true;
    checkPairSpeed();
}

void SimulationRunner::checkPairSpeed()
{
    const std::optional<core::PairSpeedExcess> excess = core::pairSpeedExcess(*m_model, m_state);
    m_pairSpeedWarning = excess ? core::explainPairSpeed(*excess) : std::string();
}

// A structural edit while a run is under way keeps the run: a particle the edit left as it was
// keeps its current motion, one it added or changed (moved, pinned, given a new mass) starts from
// its description. Edits keep the particles' order, so the old particle each new one continues is
// found by walking both lists in step: same index when the count is the same, else the next old
// particle with the same description (a deletion skips old ones, an addition matches none).
void SimulationRunner::carryMotion(const core::SceneDesc &previous)
{
    const auto &before = previous.particles;
    const auto &after = m_scene->particles;
    core::State rebuilt = core::makeState(*m_model, *m_scene);
    std::size_t next = 0;
    for (std::size_t i = 0; i < after.size(); ++i) {
        std::size_t from = before.size();
        if (before.size() == after.size()) {
            from = before[i] == after[i] ? i : before.size();
        } else {
            std::size_t k = next;
            while (k < before.size() && !(before[k] == after[i]))
                ++k;
            if (k < before.size()) {
                from = k;
                next = k + 1;
            }
        }
        if (from >= before.size() || after[i].pinned)
            continue;
        const auto col = static_cast<Eigen::Index>(i);
        const auto old = static_cast<Eigen::Index>(from);
        rebuilt.position.col(col) = m_state.position.col(old);
        rebuilt.velocity.col(col) = m_state.velocity.col(old);
    }
    rebuilt.time = m_state.time;
    rebuilt.step = m_state.step;
    m_state = std::move(rebuilt);
}

// the scene's initial conditions, and the energy the drift is measured from
void SimulationRunner::restart()
{
    m_state = core::makeState(*m_model, *m_scene);
    m_owed = 0.0;
    m_initialEnergies = core::energies(*m_model, m_state);
}

void SimulationRunner::reset()
{
    if (!hasScene())
        return;
    restart();
    applySteering();
    m_estimateStale = true;
    checkPairSpeed();
}

void SimulationRunner::tilt(const TiltEdit &edit)
{
    if (!hasScene())
        return;
    // every free particle gets a kick of up to `speed` per component, from one seeded generator
    std::mt19937_64 random(edit.seed);
    for (int i : m_model->freeParticles)
        for (int axis = 0; axis < 3; ++axis)
            m_state.velocity(axis, i) += edit.speed * symmetricUnit(random);
    m_estimateStale = true;
}

void SimulationRunner::steer(const SteerEdit &edit)
{
    // clear the old particle's force before moving it to another one
    if (hasScene() && m_steerParticle >= 0 && m_steerParticle < m_model->particleCount())
        core::setAppliedForce(m_state, m_steerParticle, Eigen::Vector3d::Zero());
    m_steerParticle = edit.particle;
    m_steerForce = edit.force;
    applySteering();
    m_estimateStale = true;
}

void SimulationRunner::applySteering()
{
    if (hasScene() && m_steerParticle >= 0 && m_steerParticle < m_model->particleCount())
        core::setAppliedForce(m_state, m_steerParticle, m_steerForce);
}

void SimulationRunner::grab(const GrabEdit &edit)
{
    const bool valid = hasScene() && edit.particle >= 0 && edit.particle < m_model->particleCount();
    // let go of the old particle: steering alone acts on it again
    if (m_grabParticle >= 0 && m_grabParticle < m_state.position.cols()) {
        core::setAppliedForce(m_state, m_grabParticle, Eigen::Vector3d::Zero());
        applySteering();
    }
    m_grabParticle = valid ? edit.particle : -1;
    m_grabTarget = edit.target;
    applyGrab();
}

// The mouse spring is a critically damped spring per unit mass, ω² (target - x) - 2ω v, so every
// particle follows the cursor in the same time whatever its mass. ω is held to a tenth of the
// sub-step's rate, well inside every explicit integrator's stability limit.
void SimulationRunner::applyGrab()
{
    if (!hasScene() || m_grabParticle < 0 || m_grabParticle >= m_model->particleCount())
        return;
    const int i = m_grabParticle;
    const auto col = static_cast<Eigen::Index>(i);
    if (m_model->isPinned(i)) {
        m_state.position.col(col) = m_grabTarget;
        return;
    }
    const double h = m_model->timeStep / m_model->substeps;
    const double omega = std::min(kGrabRate, 0.1 / h);
    const Eigen::Vector3d x = m_state.position.col(col);
    const Eigen::Vector3d v = m_state.velocity.col(col);
    Eigen::Vector3d force = m_model->mass[col] * (omega * omega * (m_grabTarget - x) - 2.0 * omega * v);
    if (i == m_steerParticle)
        force += m_steerForce;
    core::setAppliedForce(m_state, i, force);
}

bool SimulationRunner::stepOnce()
{
    applyGrab();
    if (core::step(*m_model, m_state))
        return true;
    // blown up: stop, keep the report, and go back to the last good state
    m_blowup = m_state.blowup;
    m_running = false;
    m_owed = 0.0;
    core::Profile profile = m_state.profile;
    m_state = m_lastGood;
    m_state.profile = profile;
    m_state.blowup.reset();
    m_estimateStale = true;
    return false;
}

SimulationRunner::Advance SimulationRunner::advance(double wallSeconds, double budgetSeconds)
{
    Advance result;
    if (!m_running || !hasScene())
        return result;

    m_owed += wallSeconds;
    m_wallSinceEstimate += wallSeconds;
    const double h = m_model->timeStep;
    if (m_owed < h)
        return result;
    m_lastGood = m_state;
    const auto start = Clock::now();
    bool blewUp = false;
    while (m_owed >= h) {
        if (!stepOnce()) {
            blewUp = true;
            m_stepsTaken -= static_cast<std::uint64_t>(result.steps);  // back at the tick's start
            break;
        }
        m_owed -= h;
        ++result.steps;
        ++m_stepsTaken;
        // out of time for this tick: give up what is still owed
        if (secondsSince(start) > budgetSeconds) {
            result.droppedSeconds = m_owed;
            m_owed = 0.0;
            break;
        }
    }
    const double seconds = secondsSince(start);
    m_stepSeconds += seconds;
    m_stepSecondsSinceEstimate += seconds;
    checkPairSpeed();

    // the periodic estimate, of the state these steps ended at: rare enough in wall time, and
    // only once the steps have paid for it many times over
    if (!blewUp && (m_estimateStale || (m_wallSinceEstimate >= kEstimateInterval &&
                                        kEstimateShare * m_stepSecondsSinceEstimate >= m_lastEstimateSeconds)))
        estimate(true);
    return result;
}

void SimulationRunner::updateEstimate()
{
    if (m_estimateStale)
        estimate(false);
}

// counted: made between steps of the run, so part of what the run costs
void SimulationRunner::estimate(bool counted)
{
    m_estimateStale = false;
    if (!hasScene())
        return;
    const auto start = Clock::now();
    m_localError = m_doubling.estimate(m_model, m_state);
    m_localErrorStep = m_state.step;
    const double seconds = secondsSince(start);
    m_lastEstimateSeconds = seconds;
    if (counted)
        m_estimateSeconds += seconds;
    m_wallSinceEstimate = 0.0;
    m_stepSecondsSinceEstimate = 0.0;
}

void SimulationRunner::planAccuracy(const PlanAccuracyEdit &edit)
{
    // the cost of a force evaluation as measured in this run, else timed now
    auto plan = std::make_shared<core::AccuracyPlan>();
    if (hasScene()) {
        double secondsPerEvaluation = core::profiledSecondsPerEvaluation(m_state);
        if (!(secondsPerEvaluation > 0.0))
            secondsPerEvaluation = core::timedSecondsPerEvaluation(*m_model, m_state);
        *plan = core::planAccuracy(*m_model, m_state, edit.tolerance, secondsPerEvaluation);
    }
    m_plan = std::move(plan);
    m_planRequest = edit.request;
}

void SimulationRunner::captureState(const CaptureStateEdit &edit)
{
    // a copy in doubles: the scene's initial conditions get exactly what the run has
    auto captured = std::make_shared<CapturedState>();
    if (hasScene()) {
        captured->position = m_state.position;
        captured->velocity = m_state.velocity;
        captured->time = m_state.time;
        captured->step = m_state.step;
        captured->scene = m_scene;
    }
    m_captured = std::move(captured);
    m_captureRequest = edit.request;
}

std::shared_ptr<const core::Snapshot> SimulationRunner::snapshot() const
{
    if (!hasScene())
        return nullptr;
    return core::makeSnapshot(*m_model, m_state);
}

std::optional<std::string> SimulationRunner::takeBlowupMessage()
{
    if (!m_blowup || !hasScene())
        return std::nullopt;
    std::optional<core::Blowup> blowup;
    blowup.swap(m_blowup);
    // the state is the last good one again: the limit there is the one the steps ran into
    return core::explainBlowup(*m_model, *blowup, core::stabilityLimit(*m_model, m_state));
}

bool SimulationRunner::updateStability()
{
    if (!m_stabilityStale || !hasScene())
        return false;
    m_stabilityStale = false;
    m_stability = core::stabilityLimit(*m_model, m_state);
    return true;
}

void SimulationRunner::startRecording()
{
    if (!hasScene())
        return;
    auto recording = std::make_shared<SessionRecording>();
    recording->scene = m_scene;
    recording->position = m_state.position;
    recording->velocity = m_state.velocity;
    recording->time = m_state.time;
    recording->step = m_state.step;
    recording->adaptiveStep = m_state.adaptiveStep;
    // forces held on from before the start
    if (m_steerParticle >= 0)
        recording->entries.push_back({0, SteerEdit{m_steerParticle, m_steerForce}});
    if (m_grabParticle >= 0)
        recording->entries.push_back({0, GrabEdit{m_grabParticle, m_grabTarget}});
    m_recording = std::move(recording);
    m_recordingFrom = m_stepsTaken;
}

std::shared_ptr<const SessionRecording> SimulationRunner::stopRecording()
{
    if (!m_recording)
        return nullptr;
    m_recording->steps = m_stepsTaken - m_recordingFrom;
    m_recording->finalHash = core::stateHash(m_state);
    return std::exchange(m_recording, nullptr);
}

bool SimulationRunner::restoreRecordedStart(const SessionRecording &recording)
{
    if (!hasScene() || recording.position.cols() != m_state.position.cols() ||
        recording.velocity.cols() != m_state.velocity.cols())
        return false;
    m_state.position = recording.position;
    m_state.velocity = recording.velocity;
    m_state.time = recording.time;
    m_state.step = recording.step;
    m_state.adaptiveStep = recording.adaptiveStep;
    m_stepsTaken = 0;
    m_estimateStale = true;
    return true;
}

bool SimulationRunner::stepForReplay()
{
    if (!hasScene())
        return false;
    m_lastGood = m_state;
    if (!stepOnce())
        return false;
    ++m_stepsTaken;
    return true;
}

}  // namespace ui
