#pragma once
// `springlab-bench pause --window`: what a user waits for after pressing Pause, Step and Step Back
// in the editor, from the key to the changed pixels. The editor's own window (ui::MainWindow) plays
// the scene; a second thread presses each key at a moment of its choosing, so the key waits in the
// window's queue as a real one does when the window is busy drawing; the time ends when the view
// has put on screen the frame that answers it (QOpenGLWidget::frameSwapped with the answer's
// snapshot drawn). With --busy a loop keeps one core busy all along. Needs a display (xvfb-run).

#include "pause_latency.h"

#include <QTextStream>

namespace bench {

int runPauseOnScreen(const PauseLatencyOptions &options, QTextStream &out, QTextStream &err);

}  // namespace bench
