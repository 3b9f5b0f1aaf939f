#pragma once
// StepSamples: what the plots show of every step of the run, taken on the worker's thread. The
// window draws a large scene a few times a second or less, and a plot made from the frames it
// draws would skip most steps; so the runner takes a sample after each step it keeps (and after
// each edit or reset that changes the state), a few doubles that cost an energy pass, and every
// frame the worker publishes carries the samples the window has not taken yet. The mailbox keeps
// only the latest frame, so the samples stay pending until a frame that carried them is known to
// have been taken (the mailbox was found empty); a frame may therefore carry a sample again, and
// each sample's sequence number lets the window see it once. Qt-free.

#include "core/model/diagnostics.h"
#include "core/model/model.h"
#include "core/model/state.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

namespace ui {

struct StepSample {
    std::uint64_t sequence = 0;  // counts every sample taken, never reused: a sample seen again is skipped
    std::uint64_t step = 0;
    double time = 0.0;  // s
    core::Energies energies;
    double initialTotal = 0.0;  // J, the total energy at the last reset or scene load
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();  // kg·m/s
    // the particle followed (-1: none) and its motion, in doubles
    int particle = -1;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s
};

using StepSampleBatch = std::vector<StepSample>;

class StepSampler {
public:
    // the most samples kept waiting for a window that takes no frame; past it the oldest go
    static constexpr std::size_t kMaxPending = std::size_t(1) << 16;

    // off (the default): add() takes nothing, so that springlab-sim's replays pay nothing
    void setEnabled(bool on);
    bool enabled() const { return m_enabled; }
    // the particle whose position and velocity go into the samples (-1: none)
    void setParticle(int particle) { m_particle = particle; }
    int particle() const { return m_particle; }

    // a sample of the state; one at the same step and time as the last one pending replaces it
    // (an edit while paused changes the values, not the step)
    void add(const core::Model &model, const core::State &state, const core::Energies &initial);
    // forgets the pending samples after step (the run went back to it)
    void dropAfter(std::uint64_t step);
    // forgets every pending sample (the run started over)
    void clear() { m_pending.clear(); }

    // the samples up to sequence reached the window: they go
    void delivered(std::uint64_t sequence);
    // a copy of the pending samples, oldest first, for a frame; null when there is none
    std::shared_ptr<const StepSampleBatch> pending() const;
    std::size_t pendingCount() const { return m_pending.size(); }

private:
    bool m_enabled = false;
    int m_particle = -1;
    std::uint64_t m_nextSequence = 1;
    std::deque<StepSample> m_pending;
};

}  // namespace ui
