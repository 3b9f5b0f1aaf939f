#include "run_diagnostics.h"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <utility>

namespace ui {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

void RunDiagnostics::modelChanged()
{
    m_estimateStale = true;
    m_stabilityStale = true;
}

void RunDiagnostics::resetCosts()
{
    m_stepSeconds = 0.0;
    m_estimateSeconds = 0.0;
    m_lastEstimateSeconds = 0.0;
}

void RunDiagnostics::restarted(const core::Model &model, const core::State &state)
{
    m_initialEnergies = core::energies(model, state);
    m_outsideWork = 0.0;
    m_tickEnergyKnown = false;
}

void RunDiagnostics::editedBy(const core::Energies &before, const core::Energies &after)
{
    m_initialEnergies.kinetic += after.kinetic - before.kinetic;
    m_initialEnergies.gravitational += after.gravitational - before.gravitational;
    m_initialEnergies.spring += after.spring - before.spring;
    m_tickEnergyKnown = false;
}

std::optional<core::Blowup> RunDiagnostics::watchEnergy(const core::Model &model, const core::State &state,
                                                        bool forcesFromOutside)
{
    const double now = core::energies(model, state).total();
    const bool known = std::exchange(m_tickEnergyKnown, true);
    const double last = std::exchange(m_tickEnergy, now);
    if (forcesFromOutside) {
        if (known)
            m_outsideWork += now - last;
        return std::nullopt;
    }
    // the scale: every energy the run started with, whatever its sign, and at the least the work
    // of lifting its mass a metre against gravity and of moving it at 1 m/s (a scene at rest at
    // the origin starts at 0 J)
    const core::Energies &start = m_initialEnergies;
    const double mass = model.mass.sum();
    const double scale = std::abs(start.kinetic) + std::abs(start.gravitational) + std::abs(start.spring) +
                         mass * model.gravity.norm() * 1.0 + 0.5 * mass * 1.0 * 1.0;
    const double from = start.total() + m_outsideWork;
    if (!(now - from > kEnergyGrowth * scale))
        return std::nullopt;
    core::Blowup blowup;
    blowup.quantity = core::Blowup::Quantity::Energy;
    blowup.value = now;
    blowup.from = from;
    blowup.step = state.step;
    blowup.time = state.time;
    // where: the fastest particle
    if (state.velocity.cols() > 0) {
        Eigen::Index fastest = 0;
        blowup.speed = std::sqrt(state.velocity.colwise().squaredNorm().maxCoeff(&fastest));
        blowup.particle = int(fastest);
        for (int axis = 0; axis < 3; ++axis)
            blowup.where[axis] = state.position(axis, fastest);
    }
    return blowup;
}

void RunDiagnostics::afterSteps(double seconds, bool blewUp, const std::shared_ptr<const core::Model> &model,
                                const core::State &state)
{
    m_stepSeconds += seconds;
    m_stepSecondsSinceEstimate += seconds;
    if (m_analysis)
        m_stabilityCredit += kStabilityShare * seconds;
    checkPairSpeed(*model, state);

    // the periodic estimate, of the state these steps ended at: rare enough in wall time, and
    // only once the steps have paid for it many times over
    const double share = m_lastEstimateSeconds > kCheapEstimateSeconds ? kBigSceneEstimateShare : kEstimateShare;
    if (!blewUp && (m_estimateStale || (m_wallSinceEstimate >= kEstimateInterval &&
                                        share * m_stepSecondsSinceEstimate >= m_lastEstimateSeconds)))
        estimate(true, model, state);
}

void RunDiagnostics::stepped()
{
    if (++m_stepsSinceEstimate * kEstimateShare >= kEstimateSteps)
        m_estimateStale = true;
}

void RunDiagnostics::checkPairSpeed(const core::Model &model, const core::State &state)
{
    const std::optional<core::PairSpeedExcess> excess = core::pairSpeedExcess(model, state);
    m_pairSpeedWarning = excess ? core::explainPairSpeed(*excess) : std::string();
}

void RunDiagnostics::updateEstimate(const std::shared_ptr<const core::Model> &model, const core::State &state)
{
    if (m_estimateStale)
        estimate(false, model, state);
}

// counted: made between steps of the run, so part of what the run costs
void RunDiagnostics::estimate(bool counted, const std::shared_ptr<const core::Model> &model, const core::State &state)
{
    m_estimateStale = false;
    if (!model)
        return;
    const auto start = Clock::now();
    const std::optional<double> error = m_doubling.estimate(model, state);
    if (m_doubling.interrupted()) {
        // messages wait: they go first, and the estimate is made again after them
        m_estimateStale = true;
        return;
    }
    m_localError = error;
    m_localErrorStep = state.step;
    ++m_estimateCount;
    m_stepsSinceEstimate = 0;
    const double seconds = secondsSince(start);
    m_lastEstimateSeconds = seconds;
    if (counted)
        m_estimateSeconds += seconds;
    m_wallSinceEstimate = 0.0;
    m_stepSecondsSinceEstimate = 0.0;
}

bool RunDiagnostics::updateStability(const std::shared_ptr<const core::Model> &model, const core::State &state,
                                     bool running)
{
    // an edit: the analysis starts over, at the state as it is now
    if (m_stabilityStale) {
        m_stabilityStale = false;
        m_analysis.reset();
        m_analysedModel = model;
        if (!model)
            return false;
        m_analysis = std::make_unique<core::StabilityAnalysis>(*model, state);
        m_stabilityCredit = 0.0;
        m_sliceSeconds = 0.0;
    }
    if (!m_analysis)
        return false;

    // while running, what the steps have paid for, and the least slice (so that a small scene's
    // analysis ends within a tick or two), a slice only where the last one fits in what is left;
    // paused, to the end. Either way it stops as soon as messages wait, to go on next time: a
    // slice is a share of one product's springs (one product of 6·10⁶ springs takes a quarter
    // of a second)
    const double budget = m_stabilityCredit + kLeastStabilitySlice;
    const auto start = Clock::now();
    while (!(m_interrupt && m_interrupt->load(std::memory_order_relaxed))) {
        if (running && secondsSince(start) + m_sliceSeconds > budget)
            break;
        const auto iteration = Clock::now();
        const bool done = m_analysis->runSlice();
        m_sliceSeconds = secondsSince(iteration);
        if (done)
            break;
    }
    m_stabilityCredit = running ? std::max(0.0, m_stabilityCredit - secondsSince(start)) : 0.0;
    if (!m_analysis->done())
        return false;
    m_stability = m_analysis->limit();
    m_analysis.reset();
    m_analysedModel.reset();
    return true;
}

std::optional<std::string> RunDiagnostics::takeBlowupMessage(const core::Model &model, const core::State &state)
{
    if (m_outOfMemory)
        return std::exchange(m_outOfMemory, std::nullopt);
    if (!m_blowup)
        return std::nullopt;
    std::optional<core::Blowup> blowup;
    blowup.swap(m_blowup);
    // the state is the last good one again: the limit there is the one the steps ran into
    return core::explainBlowup(model, *blowup, core::stabilityLimit(model, state));
}

std::shared_ptr<const core::AccuracyPlan> RunDiagnostics::planAccuracy(const std::shared_ptr<const core::Model> &model,
                                                                       const core::State &state,
                                                                       const core::Profile &profile, double tolerance,
                                                                       const std::atomic<bool> *stop)
{
    auto plan = std::make_shared<core::AccuracyPlan>();
    if (model) {
        double secondsPerEvaluation = core::profiledSecondsPerEvaluation(profile);
        if (!(secondsPerEvaluation > 0.0))
            secondsPerEvaluation = core::timedSecondsPerEvaluation(*model, state);
        *plan = core::planAccuracy(*model, state, tolerance, secondsPerEvaluation, stop);
    }
    return plan;
}

}  // namespace ui
