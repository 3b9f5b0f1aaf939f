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
bool Scrubber::show(std::uint64_t step, core::Workspace &work)
{
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
    while (shown.state.step < step) {
        applyGrabForce(*shown.model, shown.state, key.held);
        // the run's workspace: only one of the two steps at a time
        if (!core::step(*shown.model, shown.state, work)) {
            work.blowup.reset();
            m_shown.reset();
            return false;
        }
    }
    return true;
}

ScrubbedStep Scrubber::resume()
{
    ScrubbedStep shown = std::move(*m_shown);
    m_shown.reset();
    m_timeline.truncateAfter(shown.state.step);
    ++m_resumes;
    m_resumedAt = shown.state.step;
    return shown;
}

void Scrubber::clear()
{
    m_shown.reset();
    m_timeline.clear();
}

}  // namespace ui
