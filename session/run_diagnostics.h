#pragma once
// RunDiagnostics: how well the run goes, worked out beside it on the runner's own model and state,
// which the runner passes in. The live error estimate: a step-doubling estimate of the local
// error, refreshed after a change and, while running, at most every kEstimateInterval of wall time
// and only once the steps since the last estimate took 1 / kEstimateShare times as long as it did
// (1 / kBigSceneEstimateShare where an estimate takes over kCheapEstimateSeconds), so that the
// estimates never cost more than that share of the run. The energies at the last
// reset, from which the drift is measured. The explicit integrators' stability limit for the model
// as edited: its power iteration runs a slice at a time (core::StabilityAnalysis), while running
// only as the steps pay for it (kStabilityShare of their computing time), while paused to its end,
// and it stops for waiting messages, so that a large scene's analysis (seconds) neither holds up
// the run nor a Pause. The pair speed warning, the explanation of a blow-up at the last good state,
// and the accuracy plan asked for. Qt-free.

#include "core/integrators/accuracy_planner.h"
#include "core/model/diagnostics.h"
#include "core/integrators/error_estimate.h"
#include "core/model/model.h"
#include "core/integrators/stability.h"
#include "core/model/state.h"
#include "core/model/workspace.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace ui {

class RunDiagnostics {
public:
    // the live error estimate: at most this often (s of wall time), and at most this share of the
    // computing time of the steps
    static constexpr double kEstimateInterval = 0.25;
    static constexpr double kEstimateShare = 0.05;
    // an estimate that takes longer than this (s) is of a big scene: it gets the smaller share,
    // so that the run keeps its speed (a 200 × 200 cloth's takes 40-90 ms)
    static constexpr double kCheapEstimateSeconds = 0.005;
    static constexpr double kBigSceneEstimateShare = 0.02;
    // the stability analysis, while running: this share of the steps' computing time, and this
    // many seconds a tick besides
    static constexpr double kStabilityShare = 0.02;
    static constexpr double kLeastStabilitySlice = 0.001;

    // a flag raised when messages wait: an estimate in progress stops and is made again later, the
    // stability analysis goes on from where it stopped
    void setInterrupt(const std::atomic<bool> *flag)
    {
        m_interrupt = flag;
        m_doubling.setInterrupt(flag);
    }
    // what changed in the run: the state (estimate again), or the model too (and analyse the
    // stability limit again)
    void stateChanged() { m_estimateStale = true; }
    // a Step taken while paused: the estimate is made again only once the Steps since the last
    // have paid for it as the running steps do (1 / kEstimateShare times its cost, kEstimateSteps),
    // by their count, not their time, so that the same Steps give the same estimates on any
    // machine. A fresh estimate at every Step made a Step cost four
    void stepped();
    static constexpr double kEstimateSteps = 3.0;  // step doubling: a step and two half steps
    // how many estimates were made since the scene was loaded
    std::uint64_t estimateCount() const { return m_estimateCount; }
    // whether the estimate waits to be made again (a change, or an estimate cut short)
    bool estimateStale() const { return m_estimateStale; }
    void modelChanged();
    // another scene: its costs start afresh
    void resetCosts();
    // the run starts again from the scene's initial conditions: the energies the drift is measured from
    void restarted(const core::Model &model, const core::State &state);
    // an edit of the running scene changed the energy from `before` to `after`: that is work the
    // user did, not drift, so the drift's baseline moves with it
    void editedBy(const core::Energies &before, const core::Energies &after);
    // wall time the run was given, while running (s)
    void addWallTime(double seconds) { m_wallSinceEstimate += seconds; }
    // a tick's steps took seconds of computing and ended at state (the last good one if they blew
    // up): the pair speed, then the periodic estimate if they did not blow up
    void afterSteps(double seconds, bool blewUp, const std::shared_ptr<const core::Model> &model,
                    const core::State &state);
    // particles faster than the pair speed limit allows, at state
    void checkPairSpeed(const core::Model &model, const core::State &state);
    // estimates the local error now if the model or the state changed since the last estimate
    void updateEstimate(const std::shared_ptr<const core::Model> &model, const core::State &state);
    // works on the stability limit: starts the analysis when the model changed since the last, then
    // runs it (while running, as far as the steps since have paid for; else to its end, unless
    // messages wait); true when a new limit is in
    bool updateStability(const std::shared_ptr<const core::Model> &model, const core::State &state, bool running);
    // whether the stability analysis waits to be started or finished
    bool stabilityPending() const { return m_stabilityStale || m_analysis != nullptr; }
    // a blow-up, kept until takeBlowupMessage() explains it at state, the last good one
    void blewUp(std::optional<core::Blowup> blowup) { m_blowup = std::move(blowup); }
    // a step that could not be taken for want of memory, said by takeBlowupMessage() like a blow-up
    void ranOutOfMemory(std::string message) { m_outOfMemory = std::move(message); }
    std::optional<std::string> takeBlowupMessage(const core::Model &model, const core::State &state);
    // after a tick's steps: a total energy kEnergyGrowth times its scale above what the run started
    // with (the initial energies, the edits' changes and the work of forces from outside), a blow-up
    // whose values are all still finite. While forcesFromOutside (a grab, the steering keys) act,
    // what the energy gains is their work, and nothing is checked.
    std::optional<core::Blowup> watchEnergy(const core::Model &model, const core::State &state, bool forcesFromOutside);
    static constexpr double kEnergyGrowth = 1000.0;
    // the integrator and substeps for a tolerance (m per sub-step) at state, with the cost of a
    // force evaluation as measured in the run (profile), else timed now; an empty plan without a
    // model; a raised `stop` ends it, stopped (core::planAccuracy)
    static std::shared_ptr<const core::AccuracyPlan> planAccuracy(const std::shared_ptr<const core::Model> &model,
                                                                  const core::State &state,
                                                                  const core::Profile &profile, double tolerance,
                                                                  const std::atomic<bool> *stop = nullptr);

    // the limit of the model as it is now (nullopt before the first scene)
    const std::optional<core::StabilityLimit> &stability() const { return m_stability; }
    // particles faster than the pair speed limit allows, as of the latest steps, edit or reset
    // (empty when within it): core::explainPairSpeed
    const std::string &pairSpeedWarning() const { return m_pairSpeedWarning; }
    // the local position error of one sub-step (m) at the state of step localErrorStep(); nullopt
    // before the first estimate or when a trial blew up
    std::optional<double> localError() const { return m_localError; }
    std::uint64_t localErrorStep() const { return m_localErrorStep; }
    // the energies at the last reset or scene load, plus what the edits since changed them by
    const core::Energies &initialEnergies() const { return m_initialEnergies; }
    // computing time (s) since the scene was loaded: of the steps while running, and of the
    // estimates made between them
    double stepSeconds() const { return m_stepSeconds; }
    double estimateSeconds() const { return m_estimateSeconds; }
    // estimateSeconds() / stepSeconds(), 0 before any step
    double estimateShare() const { return m_stepSeconds > 0.0 ? m_estimateSeconds / m_stepSeconds : 0.0; }

private:
    void estimate(bool counted, const std::shared_ptr<const core::Model> &model, const core::State &state);

    std::optional<core::Blowup> m_blowup;
    std::optional<std::string> m_outOfMemory;
    std::optional<core::StabilityLimit> m_stability;
    bool m_stabilityStale = true;  // the model changed since the limit was analysed
    // the model under analysis (kept alive for it, so declared before it), and the analysis
    std::shared_ptr<const core::Model> m_analysedModel;
    std::unique_ptr<core::StabilityAnalysis> m_analysis;
    double m_stabilityCredit = 0.0;  // s of computing the steps have paid the analysis, less what it took
    double m_sliceSeconds = 0.0;  // what its latest slice took
    const std::atomic<bool> *m_interrupt = nullptr;
    std::string m_pairSpeedWarning;

    // the live error estimate and what it has cost
    core::StepDoubling m_doubling;
    std::optional<double> m_localError;
    std::uint64_t m_localErrorStep = 0;
    bool m_estimateStale = true;              // the model or the state changed since
    double m_wallSinceEstimate = 0.0;         // s of wall time run since the last estimate
    std::uint64_t m_estimateCount = 0;
    int m_stepsSinceEstimate = 0;             // Steps taken while paused since the last estimate
    double m_stepSecondsSinceEstimate = 0.0;  // s of computing spent on steps since then
    double m_lastEstimateSeconds = 0.0;       // s the last estimate took
    double m_stepSeconds = 0.0;
    double m_estimateSeconds = 0.0;
    core::Energies m_initialEnergies;
    double m_outsideWork = 0.0;  // J the grabs and the steering added since the last reset
    double m_tickEnergy = 0.0;   // J at the end of the last tick watched
    bool m_tickEnergyKnown = false;
};

}  // namespace ui
