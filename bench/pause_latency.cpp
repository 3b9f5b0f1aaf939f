// Each run raises the flag at (r + 0.5) / runs of a step's measured length after the step began, so
// the runs sample every point of a step; the median and the largest of each figure are printed,
// with the load average, since other work on the machine slows every figure.
#include "pause_latency.h"

#include "bench_common.h"

#include "core/io/scene_file.h"
#include "session/simulation_runner.h"

#include <QElapsedTimer>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>
#include <thread>

namespace bench {

namespace {

double secondsOf(const QElapsedTimer &timer)
{
    return static_cast<double>(timer.nsecsElapsed()) * 1e-9;
}

}  // namespace

int runPauseLatency(const PauseLatencyOptions &options, QTextStream &out, QTextStream &err)
{
    const io::LoadResult loaded = io::loadScene(options.scene);
    if (!loaded.ok()) {
        err << "springlab-bench: " << loaded.error << '\n';
        return 1;
    }
    auto scene = std::make_shared<const core::SceneDesc>(*loaded.scene);
    std::atomic<bool> waiting{false};
    ui::SimulationRunner runner;
    runner.setInterrupt(&waiting);
    // a recording budget that holds a keyframe of this scene, so that the scrub below has one to
    // go back to (the editor's default of 512 MB holds none at 10⁶ particles, and says so)
    runner.apply(ui::SetTimelineBudget{std::size_t(options.timelineMegabytes) << 20});
    runner.apply(ui::SetSceneEdit{scene, ui::SceneChange::Replace});
    runner.apply(ui::Play{});
    const double h = runner.model()->timeStep;
    out << "pause latency: " << options.scene << ", " << runner.model()->particleCount() << " particles, "
        << runner.model()->springCount() << " springs, " << runner.model()->substeps << " sub-steps a step"
        << (options.busy ? "; a loop keeps one core busy" : "") << "\n";
    std::optional<BusyCore> busy;
    if (options.busy)
        busy.emplace();

    // one whole step first: its length spaces the flags, and it makes the next one interruptible
    QElapsedTimer clock;
    clock.start();
    runner.advance(h, 1e9);
    const double stepSeconds = secondsOf(clock);
    out << "one step: " << stepSeconds << " s; load average " << loadAverage() << "\n";

    std::vector<double> stops, snapshots;
    for (int r = 0; r < options.runs; ++r) {
        const double delay = stepSeconds * (r + 0.5) / options.runs;
        QElapsedTimer raised;
        std::thread pauser([&] {
            std::this_thread::sleep_for(std::chrono::duration<double>(delay));
            raised.start();
            waiting.store(true, std::memory_order_relaxed);
        });
        // owes two steps, so that a flag late in the first still finds a step to cut
        const ui::SimulationRunner::Advance advance = runner.advance(2.0 * h, 1e9);
        const double stop = raised.isValid() ? secondsOf(raised) : 0.0;
        pauser.join();
        if (!advance.interrupted) {
            out << "run " << r << ": the step ended before the flag (" << advance.steps << " steps)\n";
            waiting.store(false, std::memory_order_relaxed);
            continue;
        }
        clock.start();
        const std::shared_ptr<const core::Snapshot> snapshot = runner.snapshot();
        const double made = secondsOf(clock);
        waiting.store(false, std::memory_order_relaxed);
        stops.push_back(stop);
        snapshots.push_back(made);
        out << "run " << r << ": flag at " << delay << " s into the step, stopped and restored in " << stop * 1e3
            << " ms, snapshot of " << snapshot->particleCount() << " particles in " << made * 1e3 << " ms\n";
    }
    if (stops.empty()) {
        err << "springlab-bench: no step was cut short\n";
        return 1;
    }
    out << "stopped and restored: median " << median(stops) * 1e3 << " ms, largest "
        << *std::max_element(stops.begin(), stops.end()) * 1e3 << " ms\n";
    out << "snapshot: median " << median(snapshots) * 1e3 << " ms, largest "
        << *std::max_element(snapshots.begin(), snapshots.end()) * 1e3 << " ms\n";

    // then, paused, how long a Step and a scrub back to the first step take to be answered: what
    // the worker does before the frame answering them goes (that frame carries the snapshot before,
    // at this size, and the next one the picture, whose making the snapshot figure above gives)
    runner.apply(ui::Pause{});
    clock.start();
    runner.apply(ui::StepOnce{});
    const double stepAnswer = secondsOf(clock);
    out << "Step, paused: answered in " << stepAnswer * 1e3 << " ms, "
        << (runner.stepsOwed() > 0 ? "the step owed, taken after the answer" : "the step taken before the answer")
        << "\n";
    runner.apply(ui::Pause{});  // the Step not wanted after all: dropped, as a Pause drops it
    const std::uint64_t last = runner.state().step;
    const ui::Timeline &timeline = runner.scrubber().timeline();
    out << "recording: " << (timeline.usedBytes() >> 20) << " MB of a budget of " << (timeline.budget() >> 20)
        << " MB, steps " << timeline.firstStep() << " to " << timeline.lastStep() << "\n";
    clock.start();
    runner.apply(ui::Scrub{0});
    const double scrubAnswer = secondsOf(clock);
    if (runner.scrubber().scrubStep() == std::optional<std::uint64_t>(0))
        out << "scrub from step " << last << " to step 0: answered in " << scrubAnswer * 1e3
            << " ms, showing step 0\n";
    else
        out << "scrub from step " << last << " to step 0: not recorded (a larger --timeline-mb keeps it)\n";
    out << "load average after: " << loadAverage() << "\n";
    return 0;
}

}  // namespace bench
