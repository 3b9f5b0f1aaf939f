#include "export_run.h"

#include "ui/simulation/simulation_controller.h"

#include "core/model/snapshot.h"

namespace ui {

ExportRun::ExportRun(SimulationController &controller, std::vector<std::uint64_t> steps, FrameFunction onFrame,
                     QObject *parent, Source source)
    : QObject(parent), m_controller(controller), m_steps(std::move(steps)), m_onFrame(std::move(onFrame)),
      m_source(source)
{
}

void ExportRun::start()
{
    if (m_active)
        return;
    m_active = true;
    m_started = false;
    m_next = 0;
    if (m_steps.empty()) {
        finish(Outcome::Done);
        return;
    }

    // frames arrive on this thread; a blow-up ends the export with the run's own explanation
    connect(&m_controller, &SimulationController::frameChanged, this, &ExportRun::frameChanged);
    connect(&m_controller, &SimulationController::blewUp, this,
            [this](const QString &message) { finish(Outcome::Failed, message); });
    if (m_source == Source::Timeline) {
        // the steps are the run's own: the first is shown by scrubbing to it (which pauses)
        m_startStep = 0;
        m_started = true;
        m_awaited = m_controller.scrub(m_steps.front());
        return;
    }
    m_awaited = m_controller.pause();
}

void ExportRun::cancel()
{
    if (m_active)
        finish(Outcome::Cancelled);
}

void ExportRun::frameChanged()
{
    const auto frame = m_controller.frame();
    if (!m_active || !frame || frame->appliedMessage < m_awaited || frame->stepsOwed > 0)
        return;
    if (!frame->snapshot) {
        finish(Outcome::Failed, tr("there is no scene to export"));
        return;
    }
    const core::Snapshot &snapshot = *frame->snapshot;
    if (!m_started) {
        m_startStep = snapshot.step;
        m_started = true;
    }

    // the frame must be the step asked for: anything else (a reset, another scene) ends the export
    const std::uint64_t expected = m_startStep + m_steps[static_cast<std::size_t>(m_next)];
    if (snapshot.step != expected) {
        // slow steps are replayed from their keyframe a tick at a time, each shown on the way
        if (m_source == Source::Timeline && frame->timeline.scrubPending == expected && snapshot.step < expected)
            return;
        if (m_source == Source::Timeline) {
            finish(Outcome::Failed, tr("the timeline shows step %1 instead of step %2: the step is no longer recorded "
                                       "(the timeline's memory budget let it go), or the run went on meanwhile")
                                        .arg(snapshot.step)
                                        .arg(expected));
            return;
        }
        finish(Outcome::Failed, tr("the run is at step %1 instead of step %2: it was reset or changed meanwhile")
                                    .arg(snapshot.step)
                                    .arg(expected));
        return;
    }
    if (const QString error = m_onFrame(frame->snapshot, m_next); !error.isEmpty()) {
        finish(Outcome::Failed, error);
        return;
    }
    ++m_next;
    emit progressed(m_next, frameCount());
    if (!m_active)
        return;  // cancelled from a slot of progressed
    if (m_next == frameCount())
        finish(Outcome::Done);
    else
        advance();
}

void ExportRun::advance()
{
    // as many single steps as the next export step is away, or, for the same step again, a sync
    const std::uint64_t from = m_steps[static_cast<std::size_t>(m_next - 1)];
    const std::uint64_t to = m_steps[static_cast<std::size_t>(m_next)];
    if (m_source == Source::Timeline) {
        m_awaited = to == from ? m_controller.sync() : m_controller.scrub(to);
        return;
    }
    if (to <= from) {
        m_awaited = m_controller.sync();
        return;
    }
    for (std::uint64_t step = from; step < to; ++step)
        m_awaited = m_controller.stepOnce();
}

void ExportRun::finish(Outcome outcome, const QString &message)
{
    if (!m_active)
        return;
    m_active = false;
    disconnect(&m_controller, nullptr, this, nullptr);
    emit finished(outcome, message);
}

}  // namespace ui
