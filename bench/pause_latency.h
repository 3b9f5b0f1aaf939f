#pragma once
// `springlab-bench pause --scene FILE`: how long the editor's worker takes to answer a Pause on a
// big scene, without the window: the runner (session/simulation_runner.h) plays the scene, a second
// thread raises the messages-waiting flag part way through a step, as a Pause does, and the bench
// times how long the step takes to stop and put the state back, and how long the snapshot of the
// state it stopped at takes to make (what the frame answering the Pause carries); then, paused,
// how long a Step and a scrub back to step 0 take to be answered.

#include <QString>
#include <QTextStream>

namespace bench {

struct PauseLatencyOptions {
    QString scene;  // the scene file to play
    int runs = 7;   // Pauses timed, each at another point of a step
    int timelineMegabytes = 512;  // the recording's budget (the editor's default)
    bool busy = false;    // a loop keeps one core busy all along (a busy desktop)
    bool window = false;  // in the editor's window, from the key to the picture (pause_on_screen.h)
};

int runPauseLatency(const PauseLatencyOptions &options, QTextStream &out, QTextStream &err);

}  // namespace bench
