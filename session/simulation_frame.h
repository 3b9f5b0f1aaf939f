#pragma once
// SimulationFrame: what the worker publishes after a tick: the snapshot of the state, the model it
// was stepped with, how fast the run keeps up with the wall clock and how accurate it is.
// Immutable once published. (One-off answers come back as replies, replies.h.)


#include "core/model/diagnostics.h"
#include "core/model/model.h"
#include "core/model/scene.h"
#include "core/model/snapshot.h"
#include "core/integrators/stability.h"

#include "step_samples.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ui {

// what the timeline holds, for its bar under the view
struct TimelineInfo {
    std::uint64_t firstStep = 0;  // the recorded steps, oldest to newest
    std::uint64_t lastStep = 0;
    double firstTime = 0.0;  // s
    double lastTime = 0.0;   // s
    bool empty = true;
    std::optional<std::uint64_t> scrubStep;  // the step shown while scrubbing
    std::optional<std::uint64_t> scrubPending;  // the step a replay of slow steps is on its way to
    std::size_t usedBytes = 0;
    std::size_t budgetBytes = 0;
    std::size_t keyframeOverBudget = 0;  // a keyframe too large for the budget, so none is kept (bytes)
    std::vector<std::uint64_t> breakSteps;  // steps in which springs broke
    bool locked = false;  // a session is being recorded: no scrubbing until it ends
    // how often the run went on from a step scrubbed to, and the step it last did
    std::uint64_t resumes = 0;
    std::uint64_t resumedAt = 0;
};

struct SimulationFrame {
    std::shared_ptr<const core::Snapshot> snapshot;
    std::shared_ptr<const core::Model> model;      // the model the snapshot was stepped with
    std::shared_ptr<const core::SceneDesc> scene;  // the scene that model was compiled from
    std::uint64_t appliedMessage = 0;  // sequence number of the newest message applied before this frame
    // the step of the state the run shows now: the snapshot's, unless the snapshot is behind it (a
    // frame answering a message on a scene whose snapshot is slow to make goes with the snapshot
    // before, and the next frame brings the snapshot of this step)
    std::uint64_t shownStep = 0;
    bool snapshotBehind = false;
    bool running = false;
    // steps asked for (Step) that later messages cut short and that are still to come: the
    // snapshot is not yet the step asked for
    std::uint64_t stepsOwed = 0;

    // measured over the last second or so of running; 0 while paused or not yet measured
    double realTimeFactor = 0.0;  // simulated seconds per wall-clock second
    // the speed the run was asked to play at (SimulationWorker::speed; 0: as fast as it goes)
    double speed = 1.0;
    double stepsPerSecond = 0.0;  // steps per wall-clock second

    // the live accuracy figures: the local position error of one sub-step by step doubling, made
    // every few steps (nullopt before the first, or when a trial blew up), and the energies at the
    // last reset or scene load, from which the snapshot's energies have drifted
    std::optional<double> localError;  // m
    std::uint64_t localErrorStep = 0;  // the step whose state it was estimated at
    core::Energies initialEnergies;
    double estimateShare = 0.0;  // computing time of the estimates over that of the steps

    // the explicit integrators' stability limit for the model (nullopt before the first scene)
    std::optional<core::StabilityLimit> stability;
    // particles faster than the pair speed limit allows (core::explainPairSpeed); empty when not
    std::string pairSpeedWarning;
    // implicit-euler's, projective's and vbd's last sub-step: its iterations and the residual they
    // left (core::solverSummary's words); empty for the other integrators and before a step
    std::string solverSummary;

    TimelineInfo timeline;

    // the plots' samples of the run's steps that no frame taken before this one carried, oldest
    // first (some may have come in an earlier frame too: their sequence numbers tell); null when none
    std::shared_ptr<const StepSampleBatch> samples;
};

}  // namespace ui
