#include "step_samples.h"

namespace ui {

void StepSampler::setEnabled(bool on)
{
    m_enabled = on;
    if (!on)
        m_pending.clear();
}

void StepSampler::add(const core::Model &model, const core::State &state, const core::Energies &initial)
{
    if (!m_enabled)
        return;
    StepSample sample;
    sample.sequence = m_nextSequence++;
    sample.step = state.step;
    sample.time = state.time;
    sample.energies = core::energies(model, state);
    sample.initialTotal = initial.total();
    sample.momentum = core::momentum(model, state);
    if (m_particle >= 0 && m_particle < state.particleCount()) {
        sample.particle = m_particle;
        sample.position = state.position.col(m_particle);
        sample.velocity = state.velocity.col(m_particle);
    }

    // an edit at the step last sampled: its new values, under a new number
    if (!m_pending.empty() && m_pending.back().step == sample.step && m_pending.back().time == sample.time) {
        m_pending.back() = sample;
        return;
    }
    if (m_pending.size() == kMaxPending)
        m_pending.pop_front();
    m_pending.push_back(sample);
}

void StepSampler::dropAfter(std::uint64_t step)
{
    while (!m_pending.empty() && m_pending.back().step > step)
        m_pending.pop_back();
}

void StepSampler::delivered(std::uint64_t sequence)
{
    while (!m_pending.empty() && m_pending.front().sequence <= sequence)
        m_pending.pop_front();
}

std::shared_ptr<const StepSampleBatch> StepSampler::pending() const
{
    if (m_pending.empty())
        return nullptr;
    return std::make_shared<const StepSampleBatch>(m_pending.begin(), m_pending.end());
}

}  // namespace ui
