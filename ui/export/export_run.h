#pragma once
// ExportRun: steps the editor's simulation through a list of steps, counted from where it is when
// the export starts, and hands over the snapshot at each, for File › Export's image sequence and
// trace. It never touches the worker's state: it pauses the run, posts as many single steps as the
// next export step is away (the worker applies a burst of them in one tick) and waits for the frame
// that follows the last. The first export step is usually 0: the state the run was paused at.
// With Source::Timeline the steps are the run's own (counted since it was opened or reset) and
// each is shown by scrubbing the timeline to it, replayed from its keyframe: the recorded run,
// exactly, and nothing recorded is lost (Export Animation's "the recorded run").

#include <QObject>
#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace core {
struct Snapshot;
}

namespace ui {

class SimulationController;

class ExportRun : public QObject {
    Q_OBJECT

public:
    enum class Outcome { Done, Cancelled, Failed };
    // where the frames come from: a run on from the paused state, or the timeline's recording
    enum class Source { RunOn, Timeline };

    // called with the snapshot at each export step, in order, and its index; returns empty to go
    // on, or the message that stops the export
    using FrameFunction = std::function<QString(const std::shared_ptr<const core::Snapshot> &snapshot, int index)>;

    // steps: non-decreasing, counted from the step the run is paused at (Source::Timeline: the
    // run's own step numbers, each one the timeline holds)
    ExportRun(SimulationController &controller, std::vector<std::uint64_t> steps, FrameFunction onFrame,
              QObject *parent = nullptr, Source source = Source::RunOn);

    void start();
    // stops after the frame being handled, if any; finished(Cancelled) follows at once
    void cancel();

    bool isActive() const { return m_active; }
    int framesDone() const { return m_next; }
    int frameCount() const { return static_cast<int>(m_steps.size()); }

signals:
    void progressed(int done, int total);
    // once, at the end; message says why for Failed
    void finished(ui::ExportRun::Outcome outcome, const QString &message);

private:
    void frameChanged();
    void advance();
    void finish(Outcome outcome, const QString &message = QString());

    SimulationController &m_controller;
    std::vector<std::uint64_t> m_steps;
    FrameFunction m_onFrame;
    Source m_source = Source::RunOn;
    std::uint64_t m_awaited = 0;    // the edit whose frame is the next to hand over
    std::uint64_t m_startStep = 0;  // the run's step when it was paused
    bool m_started = false;         // the paused frame has come
    bool m_active = false;
    int m_next = 0;  // the index of the next export step
};

}  // namespace ui
