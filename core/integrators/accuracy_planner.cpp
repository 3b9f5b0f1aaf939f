#include "core/integrators/accuracy_planner.h"

#include "core/integrators/error_estimate.h"
#include "core/model/parameters.h"
#include "core/passes.h"
#include "core/integrators/stability.h"
#include "core/step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace core {

namespace {

constexpr int kExtrapolations = 6;           // measure-and-solve rounds before the bisection
constexpr int kMaxProbes = 48;               // step-doubling measurements per integrator, at most
constexpr std::uint64_t kEnoughEvaluations = 32;  // a profile with fewer says too little
constexpr int kTimedEvaluations = 16;

const double kInfinity = std::numeric_limits<double>::infinity();

int maxSubsteps()
{
    return static_cast<int>(parameterInfo(Parameter::Substeps).maximum);
}

// the count of equal sub-steps of timeStep no longer than step; one more than the cap when the cap
// is not enough
int countFor(double timeStep, double step)
{
    const int cap = maxSubsteps();
    const double count = std::ceil(timeStep / step);
    if (!(step > 0.0) || !(count <= static_cast<double>(cap)))
        return cap + 1;
    return std::max(1, static_cast<int>(count));
}

std::string format(double value)
{
    std::ostringstream out;
    out.precision(2);
    out << value;
    return out.str();
}

// step-doubling measurements of one integrator at several substep counts, each made once
class Probe {
public:
    Probe(const Model &model, Integrator integrator, const State &state, double omega, const std::atomic<bool> *stop)
        : m_base(model), m_state(state), m_omega(omega), m_stop(stop)
    {
        setIntegrator(m_base, integrator);
        m_doubling.setInterrupt(stop);
    }

    // whether the plan was asked to stop (a trial it cut short measured nothing)
    bool stopped() const { return m_stop && m_stop->load(std::memory_order_relaxed); }

    // the error measure of one sub-step at this count; nullopt when a trial blew up
    std::optional<double> errorAt(int substeps)
    {
        if (const auto found = m_errors.find(substeps); found != m_errors.end())
            return found->second;
        auto model = std::make_shared<Model>(m_base);
        model->substeps = substeps;
        std::optional<double> measure;
        if (const std::optional<LocalError> error = m_doubling.estimateLocalError(model, m_state)) {
            measure = error->position;
            if (m_omega > 0.0)
                measure = std::max(*measure, error->velocity / m_omega);
        }
        if (stopped())
            return std::nullopt;  // not a measurement: kept out of the table
        m_errors.emplace(substeps, measure);
        return measure;
    }

    bool meets(int substeps, double tolerance)
    {
        const std::optional<double> error = errorAt(substeps);
        return error && *error <= tolerance;
    }

    bool measured(int substeps) const { return m_errors.count(substeps) > 0; }
    int count() const { return static_cast<int>(m_errors.size()); }
    const std::map<int, std::optional<double>> &errors() const { return m_errors; }

    // force evaluations of one sub-step at this count, counted on a trial
    double evaluationsAt(int substeps) const
    {
        Model one = m_base;
        one.timeStep = m_base.timeStep / substeps;
        one.substeps = 1;
        State trial = m_state;
        Workspace work;
        if (m_base.integrator != Integrator::ImplicitEuler && !isVariational(m_base.integrator)) {
            step(one, trial, work);
            return static_cast<double>(work.profile.forceEvaluations);
        }
        // the solvers' work is a factorisation, back-substitutions or sweeps, not evaluations:
        // their sub-step timed against a force evaluation, the faster of three of each (the first
        // sub-step, which factors, counted as the later ones are)
        step(one, trial, work);
        using Clock = std::chrono::steady_clock;
        double stepSeconds = kInfinity, evaluationSeconds = kInfinity;
        for (int r = 0; r < 3; ++r) {
            State again = m_state;
            const Clock::time_point start = Clock::now();
            step(one, again, work);
            stepSeconds = std::min(stepSeconds, std::chrono::duration<double>(Clock::now() - start).count());
            const Clock::time_point before = Clock::now();
            computeForces(one, again, work);
            evaluationSeconds = std::min(evaluationSeconds, std::chrono::duration<double>(Clock::now() - before).count());
        }
        return evaluationSeconds > 0.0 ? std::max(1.0, stepSeconds / evaluationSeconds) : 1.0;
    }

private:
    Model m_base;
    const State &m_state;
    double m_omega;
    const std::atomic<bool> *m_stop;
    StepDoubling m_doubling;
    std::map<int, std::optional<double>> m_errors;
};

PlanCandidate planOne(const Model &model, const State &state, Integrator integrator, double tolerance,
                      double secondsPerEvaluation, const StabilityLimit &limit, const std::atomic<bool> *stop)
{
    PlanCandidate row;
    row.integrator = integrator;
    row.order = integratorOrder(integrator);
    const int cap = maxSubsteps();
    const double timeStep = model.timeStep;
    const int exponent = row.order + 1;

    // stability: the fewest substeps an explicit scheme may take
    const double limitStep = limit.maxSubStep(integrator);
    row.stableStep = std::isinf(limitStep) ? kInfinity : kStabilityMargin * limitStep;
    if (!(row.stableStep > 0.0)) {
        row.substeps = cap;
        row.reason = "unstable at any sub-step on these undamped springs";
        return row;
    }
    const int fewest = std::isinf(row.stableStep) ? 1 : countFor(timeStep, row.stableStep);
    if (fewest > cap) {
        row.substeps = cap;
        row.reason = "its stability limit needs more than " + std::to_string(cap) + " substeps";
        return row;
    }

    Probe probe(model, integrator, state, limit.omegaMax, stop);
    const auto giveUp = [&] {
        row.reason = "planning stopped";
        return row;
    };

    // measure, solve error = C h^(p+1) for the count, measure there, until the count settles
    int substeps = std::clamp(model.substeps, fewest, cap);
    for (int round = 0; round < kExtrapolations; ++round) {
        const std::optional<double> error = probe.errorAt(substeps);
        if (probe.stopped())
            return giveUp();
        int next = 0;
        if (!error) {
            next = std::min(2 * substeps, cap);  // blew up: smaller sub-steps
        } else if (*error <= 0.0) {
            next = fewest;  // exact at this step: only stability asks for more
        } else {
            const double h = timeStep / substeps;
            const double constant = *error / std::pow(h, exponent);
            next = std::clamp(countFor(timeStep, std::pow(tolerance / constant, 1.0 / exponent)), fewest, cap);
        }
        if (next == substeps || probe.measured(next))
            break;
        substeps = next;
    }

    // a count that meets the tolerance: the smallest measured, else doubling up to the cap
    auto smallestMeeting = [&]() -> std::optional<int> {
        for (const auto &[count, error] : probe.errors())
            if (error && *error <= tolerance)
                return count;
        return std::nullopt;
    };
    std::optional<int> high = smallestMeeting();
    while (!high && probe.count() < kMaxProbes && !probe.stopped()) {
        const int largest = probe.errors().rbegin()->first;
        if (largest >= cap)
            break;
        const int next = std::min(2 * largest, cap);
        if (probe.meets(next, tolerance))
            high = next;
    }
    if (probe.stopped())
        return giveUp();
    if (!high) {
        row.substeps = cap;
        const std::optional<double> error = probe.errorAt(cap);
        row.localError = error.value_or(kInfinity);
        row.reason = "needs more than " + std::to_string(cap) + " substeps (" + format(row.localError) +
                     " m at " + std::to_string(cap) + ")";
        return row;
    }

    // bisection between the largest failing count below it and it: the smallest count that meets
    int low = fewest - 1;  // counts below the stability bound are out, as if they failed
    for (const auto &[count, error] : probe.errors())
        if (count < *high && count > low && !(error && *error <= tolerance))
            low = count;
    if (*high - low > 1) {
        // the solve usually lands next to it: try the count just below first
        if (probe.meets(*high - 1, tolerance))
            high = *high - 1;
        else
            low = *high - 1;
    }
    while (*high - low > 1 && probe.count() < kMaxProbes && !probe.stopped()) {
        const int middle = low + (*high - low) / 2;
        if (probe.meets(middle, tolerance))
            high = middle;
        else
            low = middle;
    }
    if (probe.stopped())
        return giveUp();

    // the figures at that count
    row.substeps = *high;
    row.localError = *probe.errorAt(row.substeps);
    const double h = timeStep / row.substeps;
    row.errorConstant = row.localError / std::pow(h, exponent);
    row.accuracyStep = row.errorConstant > 0.0 ? std::pow(tolerance / row.errorConstant, 1.0 / exponent) : kInfinity;
    row.stabilityLimited = fewest > 1 && row.substeps == fewest && countFor(timeStep, row.accuracyStep) < fewest;
    row.evaluationsPerSubstep = probe.evaluationsAt(row.substeps);
    row.secondsPerSimulatedSecond = row.substeps * row.evaluationsPerSubstep * secondsPerEvaluation / timeStep;
    row.feasible = true;
    return row;
}

}  // namespace

AccuracyPlan planAccuracy(const Model &model, const State &state, double tolerance, double secondsPerEvaluation,
                          const std::atomic<bool> *stop)
{
    AccuracyPlan plan;
    plan.tolerance = tolerance;
    plan.timeStep = model.timeStep;
    plan.secondsPerEvaluation = secondsPerEvaluation;
    if (!(tolerance > 0.0) || !(model.timeStep > 0.0))
        return plan;

    // one row per fixed-step integrator, from the same state and the same stability analysis
    const StabilityLimit limit = stabilityLimit(model, state);
    const auto raised = [stop] { return stop && stop->load(std::memory_order_relaxed); };
    for (Integrator integrator : kIntegrators) {
        if (integrator == Integrator::AdaptiveRk45 || raised())
            continue;
        plan.candidates.push_back(planOne(model, state, integrator, tolerance, secondsPerEvaluation, limit, stop));
    }
    if (raised()) {
        plan.stopped = true;
        plan.candidates.clear();  // rows cut short are not to be read
        return plan;
    }

    // the cheapest feasible row; a tie goes to the one listed first
    for (std::size_t i = 0; i < plan.candidates.size(); ++i) {
        const PlanCandidate &row = plan.candidates[i];
        if (row.feasible && (plan.chosen < 0 || row.secondsPerSimulatedSecond <
                                                    plan.candidates[static_cast<std::size_t>(plan.chosen)]
                                                        .secondsPerSimulatedSecond))
            plan.chosen = static_cast<int>(i);
    }
    return plan;
}

double profiledSecondsPerEvaluation(const Profile &profile)
{
    if (profile.forceEvaluations < kEnoughEvaluations)
        return 0.0;
    // the fused sub-step evaluates the forces once, and its update is a small share of its time
    const double seconds = profile[Stage::Gravity].seconds + profile[Stage::Drag].seconds +
                           profile[Stage::Springs].seconds + profile[Stage::Applied].seconds +
                           profile[Stage::FusedSubStep].seconds;
    return seconds / static_cast<double>(profile.forceEvaluations);
}

double timedSecondsPerEvaluation(const Model &model, const State &state)
{
    State copy = state;
    Workspace work;
    computeForces(model, copy, work);  // warm the caches first
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < kTimedEvaluations; ++i)
        computeForces(model, copy, work);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return seconds / kTimedEvaluations;
}

}  // namespace core
