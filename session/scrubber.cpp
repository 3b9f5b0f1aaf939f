#include "scrubber.h"

#include "core/step.h"

#include <utility>

namespace ui {

std::optional<std::uint64_t> Scrubber::scrubStep() const
{
    if (!m_shown)
        return std::nullopt;
    return m_shown->state.step;
}

bool Scrubber::canShow(std::uint64_t step) const
{
    return m_timeline.covers(step) && m_timeline.keyAtOrBefore(step) != nullptr;
}

// the recorded state of a step: the keyframe before it, then the steps after it taken again with
// the keyframe's model and held forces, exactly as the run took them
bool Scrubber::show(std::uint64_t step, core::Workspace &work, const std::atomic<bool> *interrupt, int maxSteps)
{
    m_pending.reset();
    if (!canShow(step))
        return false;
    const TimelineKey &key = *m_timeline.keyAtOrBefore(step);
    if (!m_shown)
        m_shown.emplace();
    ScrubbedStep &shown = *m_shown;
    // on from the step shown when it lies between the keyframe and the target (stepping forward)
    const bool onward = shown.model == key.model && shown.state.step >= key.state.step && shown.state.step <= step &&
                        shown.state.particleCount() == key.state.particleCount();
    if (!onward)
        restoreKey(key, shown.state);
    shown.model = key.model;
    shown.scene = key.scene;
    for (int replayed = 0; shown.state.step < step; ++replayed) {
        // messages wait, or enough for now: the step replayed so far is shown, the rest waits for
        // goOn()
        if (replayed >= maxSteps || (interrupt && interrupt->load(std::memory_order_relaxed))) {
            m_pending = step;
            return true;
        }
        if (interrupt)
            m_stepStart = shown.state;
        applyGrabForce(*shown.model, shown.state, key.held);
        // the run's workspace: only one of the two steps at a time
        work.interrupt = interrupt;
        const bool stepped = core::step(*shown.model, shown.state, work);
        work.interrupt = nullptr;
        if (!stepped && work.interrupted) {
            // cut short between two sub-steps: back to the step's start, the state of a whole step
            shown.state = m_stepStart;
            m_pending = step;
            return true;
        }
        if (!stepped) {
            work.blowup.reset();
            m_shown.reset();
            return false;
        }
    }
    return true;
}

bool Scrubber::goOn(core::Workspace &work, const std::atomic<bool> *interrupt, int maxSteps)
{
    if (!m_pending || !m_shown)
        return false;
    const std::uint64_t before = m_shown->state.step;
    show(*m_pending, work, interrupt, maxSteps);
    return !m_shown || m_shown->state.step != before;
}

ScrubbedStep Scrubber::resume()
{
    m_pending.reset();
    ScrubbedStep shown = std::move(*m_shown);
    m_shown.reset();
    m_timeline.truncateAfter(shown.state.step);
    ++m_resumes;
    m_resumedAt = shown.state.step;
    return shown;
}

void Scrubber::clear()
{
    m_pending.reset();
    m_shown.reset();
    m_timeline.clear();
}

}  // namespace ui
