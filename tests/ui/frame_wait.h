#pragma once
// What the editor's UI tests share: waiting for the worker's frame that includes every edit made
// so far, and for a window to become active. The waits are for an outcome, with a deadline (Qt's
// QTest::qWaitFor), never a fixed sleep.

#include "ui/simulation/simulation_controller.h"
#include "session/simulation_frame.h"

#include <QtTest>
#include <memory>

namespace test {

// the newest frame once the worker has applied edit `sequence` and shows the state after it, or
// null after timeoutMs
inline std::shared_ptr<const ui::SimulationFrame> frameAfter(const ui::SimulationController &controller,
                                                             std::uint64_t sequence, int timeoutMs = 10000)
{
    std::shared_ptr<const ui::SimulationFrame> frame;
    const bool arrived = QTest::qWaitFor(
        [&] {
            frame = controller.frame();
            // (a frame whose snapshot is behind it is followed at once by one with the snapshot)
            return frame && frame->appliedMessage >= sequence && !frame->snapshotBehind;
        },
        timeoutMs);
    return arrived ? frame : nullptr;
}

// the newest frame once the worker has applied every edit made so far and shows what they asked
// for: every step taken (a Step cut short by the messages after it is owed, and taken after them)
// and the step scrubbed to reached (the replay from the keyframe before it goes on after the
// messages too), or null after timeoutMs
inline std::shared_ptr<const ui::SimulationFrame> settledFrame(ui::SimulationController &controller,
                                                               int timeoutMs = 10000)
{
    const std::uint64_t sequence = controller.sync();
    std::shared_ptr<const ui::SimulationFrame> frame;
    const bool arrived = QTest::qWaitFor(
        [&] {
            frame = controller.frame();
            return frame && frame->appliedMessage >= sequence && !frame->snapshotBehind && frame->stepsOwed == 0 &&
                   (!frame->timeline.scrubStep || *frame->timeline.scrubStep == frame->snapshot->step);
        },
        timeoutMs);
    return arrived ? frame : nullptr;
}

// shows a window and makes it the active one, which shortcuts need; with no window manager it
// has to ask for it. False if it never became active.
inline bool showActive(QWidget &window)
{
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

}  // namespace test
