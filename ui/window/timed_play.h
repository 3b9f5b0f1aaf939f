#pragma once
// TimedPlay: `springlab SCENE --play --exit-after SECONDS`. With play it starts the run as soon as
// the scene is open; after SECONDS it pauses, waits for the frame that answers the pause, prints
// one line with the steps taken and the frames drawn in that time, how long the Pause took to
// come back as a frame and how long until a frame brought the snapshot of the step it stopped at
// (later only where a snapshot is slow to make: SimulationWorker), and ends the application. The
// clock runs from the start (the Play) to the Pause, so the figures are the editor's as a user
// sees it, drawing included: the side-by-side benchmark (bench/editor_throughput.cpp) sets them
// beside springlab-sim's on the same scene. A playing run is paused only once it has shown a step:
// on a machine so busy that the worker took no step in SECONDS, the clock runs on until it has,
// so the line always measures a run that ran, and says how long that took.

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>
#include <cstdint>

namespace ui {

class MainWindow;

class TimedPlay : public QObject {
    Q_OBJECT

public:
    struct Figures {
        double seconds = 0.0;     // wall time from the start to the pause
        std::uint64_t steps = 0;  // steps taken in it
        std::uint64_t frames = 0; // frames the view drew in it
        double pauseSeconds = 0.0;  // from the Pause to the frame that answers it
        double shownSeconds = 0.0;  // from the Pause to the frame with the snapshot of its step
    };

    // the line printed at the end, e.g. "springlab: 10.022 s: 976 steps (97.39 steps/s), 151 frames
    // (15.07 frames/s), paused in 0.044 s, shown in 0.044 s"
    static QString reportText(const Figures &figures);

    TimedPlay(MainWindow &window, bool play, double exitAfterSeconds, QObject *parent = nullptr);

    // plays (if asked) and starts the clock; call once the scene is open
    void start();

private:
    void stop();
    void frameChanged();

    MainWindow &m_window;
    bool m_play = false;
    QTimer m_timer;
    QElapsedTimer m_clock;
    std::uint64_t m_startMessage = 0;  // the Play's number: frames from it on count
    std::uint64_t m_pauseMessage = 0;  // the Pause's, once asked: its frame ends the count
    bool m_startKnown = false;
    std::uint64_t m_startStep = 0;
    std::uint64_t m_lastStep = 0;
    Figures m_figures;
    bool m_stopping = false;
    bool m_pauseAnswered = false;
    bool m_stopWhenStepped = false;  // the time is up, but the playing run has shown no step yet
};

}  // namespace ui
