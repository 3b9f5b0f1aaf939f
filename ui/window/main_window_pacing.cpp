// MainWindow's part that paces the frames of a running simulation (FramePacer): each frame's cost,
// from its arrival to the screen, sets how soon the worker sends the next one, and the frames/s
// in the status bar count what reached the screen while running.

#include "main_window.h"

#include "ui/panels/status_text.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include <QLabel>

namespace ui {

void MainWindow::createFramePacing()
{
    m_paceClock.start();
    connect(m_viewport, &Viewport::frameTimeMeasured, this, &MainWindow::frameDrawn);
    connect(m_controller, &SimulationController::runningChanged, this, [this](bool running) {
        if (running)
            m_pacer.restartRate(double(m_paceClock.nsecsElapsed()) * 1e-9);
        m_framesLabel->setText(framesText(running, m_pacer.framesPerSecond()));
    });
}

void MainWindow::frameArrived()
{
    // the first frame since the last drawn one: what is drawn next costs from here
    if (m_frameArrival < 0.0)
        m_frameArrival = double(m_paceClock.nsecsElapsed()) * 1e-9;
}

void MainWindow::frameDrawn()
{
    const double now = double(m_paceClock.nsecsElapsed()) * 1e-9;
    const std::shared_ptr<const SimulationFrame> frame = m_controller->frame();
    const bool running = frame && frame->running;
    if (m_frameArrival >= 0.0 && running) {
        // a run that does not keep up with real time gets the frames its drawing share allows
        m_pacer.drawn(now - m_frameArrival, now);
        const bool behind = frame->realTimeFactor < kRealTimeTolerance;
        m_controller->setFrameInterval(m_pacer.interval(behind));
        m_framesLabel->setText(framesText(true, m_pacer.framesPerSecond()));
    }
    m_frameArrival = -1.0;
}

}  // namespace ui
