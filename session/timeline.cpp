#include "timeline.h"

#include <algorithm>

namespace ui {

namespace {

std::size_t matrixBytes(const Eigen::Matrix3Xd &m)
{
    return static_cast<std::size_t>(m.size()) * sizeof(double);
}

// recycled: a state whose memory the copy may reuse (an aged tail keyframe's)
TimelineKey makeKey(const std::shared_ptr<const core::Model> &model, const std::shared_ptr<const core::SceneDesc> &scene,
                    const core::State &state, const HeldForces &held, core::State recycled = {})
{
    TimelineKey key;
    key.model = model;
    key.scene = scene;
    key.held = held;
    key.state = std::move(recycled);
    key.state = state;
    const core::State &kept = key.state;
    key.bytes = sizeof(TimelineKey) + matrixBytes(kept.position) + matrixBytes(kept.velocity) + matrixBytes(kept.applied) +
                kept.springBroken.size() + kept.breaks.size() * sizeof(core::SpringBreak);
    return key;
}

}  // namespace

// The mouse spring is a critically damped spring per unit mass, ω² (target - x) - 2ω v, so every
// particle follows the cursor in the same time whatever its mass. ω is held to a tenth of the
// sub-step's rate, well inside every explicit integrator's stability limit. Worked out before each
// step from where the particle is, by the run and by the timeline's replays alike.
void applyGrabForce(const core::Model &model, core::State &state, const HeldForces &held)
{
    if (held.grabParticle < 0 || held.grabParticle >= model.particleCount())
        return;
    const int i = held.grabParticle;
    const auto col = static_cast<Eigen::Index>(i);
    if (model.isPinned(i)) {
        state.position.col(col) = held.grabTarget;
        return;
    }
    const double h = model.timeStep / model.substeps;
    const double omega = std::min(kGrabRate, 0.1 / h);
    const Eigen::Vector3d x = state.position.col(col);
    const Eigen::Vector3d v = state.velocity.col(col);
    Eigen::Vector3d force = model.mass[col] * (omega * omega * (held.grabTarget - x) - 2.0 * omega * v);
    if (i == held.steerParticle)
        force += held.steerForce;
    core::setAppliedForce(state, i, force);
}

void restoreKey(const TimelineKey &key, core::State &state)
{
    state = key.state;
    state.breaks.reserve(state.springBroken.size());  // so that a replayed break allocates nothing
}

void Timeline::setBudget(std::size_t bytes)
{
    m_budget = bytes;
    while (!m_keys.empty() && m_used > m_budget)
        dropOldest();
}

void Timeline::clear()
{
    m_keys.clear();
    m_spare = {};
    m_breakSteps.clear();
    m_used = 0;
    m_lastStep = 0;
    m_lastTime = 0.0;
}

void Timeline::afterStep(const std::shared_ptr<const core::Model> &model,
                         const std::shared_ptr<const core::SceneDesc> &scene, const core::State &state,
                         const HeldForces &held)
{
    if (m_budget == 0)
        return;  // recording is off
    if (!empty() && state.step <= m_lastStep)
        truncateAfter(state.step - 1);  // a step taken again after a roll-back: that future is gone
    const std::optional<std::uint64_t> lasting = lastLastingStep();
    TimelineKey key = makeKey(model, scene, state, held, std::move(m_spare));
    key.tail = lasting && state.step < *lasting + kKeyInterval;
    m_spare = {};
    add(std::move(key));
    // the tail keyframes that are too old now (the newest is the one just added)
    for (std::size_t i = m_keys.size(); i-- > 0;) {
        if (m_keys[i].state.step + kTailSteps >= state.step)
            continue;
        if (m_keys[i].tail)
            eraseKey(i);
        else
            break;  // lasting keyframes before it; any tail ones between went on earlier steps
    }
}

std::optional<std::uint64_t> Timeline::lastLastingStep() const
{
    for (auto key = m_keys.rbegin(); key != m_keys.rend(); ++key)
        if (!key->tail)
            return key->state.step;
    return std::nullopt;
}

void Timeline::eraseKey(std::size_t index)
{
    if (index == 0) {
        dropOldest();
        return;
    }
    TimelineKey &key = m_keys[index];
    // a model is counted with the first keyframe of the run of keyframes that use it
    const bool first = m_keys[index - 1].model != key.model;
    const bool alone = first && (index + 1 == m_keys.size() || m_keys[index + 1].model != key.model);
    m_used -= key.bytes + (alone ? modelBytes(key.model) : 0);
    m_spare = std::move(key.state);
    m_keys.erase(m_keys.begin() + static_cast<std::ptrdiff_t>(index));
}

void Timeline::afterEdit(const std::shared_ptr<const core::Model> &model,
                         const std::shared_ptr<const core::SceneDesc> &scene, const core::State &state,
                         const HeldForces &held)
{
    if (m_budget == 0)
        return;
    if (!empty())
        truncateAfter(state.step);
    if (!empty() && m_keys.back().state.step == state.step) {
        // the edit replaces the keyframe of its step: the state there is now the edited one
        TimelineKey replaced = std::move(m_keys.back());
        m_keys.pop_back();
        m_used -= replaced.bytes + (m_keys.empty() || m_keys.back().model != replaced.model ? modelBytes(replaced.model) : 0);
    }
    add(makeKey(model, scene, state, held));
}

void Timeline::truncateAfter(std::uint64_t step)
{
    while (!m_keys.empty() && m_keys.back().state.step > step) {
        const TimelineKey &last = m_keys.back();
        const bool ownModel = m_keys.size() == 1 || m_keys[m_keys.size() - 2].model != last.model;
        m_used -= last.bytes + (ownModel ? modelBytes(last.model) : 0);
        m_keys.pop_back();
    }
    if (m_keys.empty()) {
        clear();
        return;
    }
    // breaks after the last keyframe kept are no longer in the recording
    while (!m_breakSteps.empty() && m_breakSteps.back() > m_keys.back().state.step)
        m_breakSteps.pop_back();
    if (m_lastStep > step) {
        // the steps after the last keyframe are gone too; its own step and time are the end now
        // unless step lies between it and the old end
        const TimelineKey &last = m_keys.back();
        m_lastStep = std::max(last.state.step, step);
        m_lastTime = last.state.step == m_lastStep
                         ? last.state.time
                         : last.state.time + static_cast<double>(m_lastStep - last.state.step) * last.model->timeStep;
    }
}

std::uint64_t Timeline::firstStep() const
{
    return m_keys.empty() ? 0 : m_keys.front().state.step;
}

double Timeline::firstTime() const
{
    return m_keys.empty() ? 0.0 : m_keys.front().state.time;
}

const TimelineKey *Timeline::keyAtOrBefore(std::uint64_t step) const
{
    // the keyframes are in ascending step order: the last one not after step
    const auto after = std::upper_bound(m_keys.begin(), m_keys.end(), step,
                                        [](std::uint64_t s, const TimelineKey &key) { return s < key.state.step; });
    return after == m_keys.begin() ? nullptr : &*(after - 1);
}

void Timeline::add(TimelineKey key)
{
    const bool newModel = m_keys.empty() || m_keys.back().model != key.model;
    const std::size_t bytes = key.bytes + (newModel ? modelBytes(key.model) : 0);
    // a keyframe larger than the whole budget: nothing can be kept, and the bar says why
    if (bytes > m_budget) {
        clear();
        m_tooLarge = bytes;
        return;
    }
    m_tooLarge = 0;
    // the breaks since the keyframe before: each keyframe lists every break since its state was
    // built, in the order they happened
    const std::uint64_t previous = m_keys.empty() ? 0 : m_keys.back().state.step;
    for (const core::SpringBreak &b : key.state.breaks)
        if (b.step > previous && b.step <= key.state.step && (m_breakSteps.empty() || m_breakSteps.back() < b.step))
            m_breakSteps.push_back(b.step);
    m_lastStep = key.state.step;
    m_lastTime = key.state.time;
    m_used += bytes;
    m_keys.push_back(std::move(key));
    while (m_used > m_budget)
        dropOldest();
}

void Timeline::dropOldest()
{
    // a model is counted with the first keyframe of the run of keyframes that use it
    const TimelineKey &oldest = m_keys.front();
    const bool ownModel = m_keys.size() == 1 || m_keys[1].model != oldest.model;
    m_used -= oldest.bytes + (ownModel ? modelBytes(oldest.model) : 0);
    m_keys.pop_front();
    if (m_keys.empty()) {
        clear();
        return;
    }
    const auto kept = std::lower_bound(m_breakSteps.begin(), m_breakSteps.end(), m_keys.front().state.step);
    m_breakSteps.erase(m_breakSteps.begin(), kept);
}

std::size_t Timeline::modelBytes(const std::shared_ptr<const core::Model> &model) const
{
    if (!model)
        return 0;
    // the model's arrays and the scene it was compiled from, about as large again
    const auto n = static_cast<std::size_t>(model->particleCount());
    const auto springs = static_cast<std::size_t>(model->springCount());
    const std::size_t modelArrays = n * (3 * sizeof(double) + sizeof(int) * 2) + springs * (5 * sizeof(double) + 4 * sizeof(int));
    const std::size_t sceneArrays = n * sizeof(core::ParticleDesc) + springs * sizeof(core::SpringDesc);
    return sizeof(core::Model) + modelArrays + sceneArrays;
}

}  // namespace ui
