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
    // each Play and each scene measures its own frames: what a huge scene cost says nothing of
    // the next (the springs example after one of 10⁶ particles showed one frame in 30 s)
    connect(m_controller, &SimulationController::runningChanged, this, [this](bool running) {
        if (running)
            startFramePacingOver();
        m_framesLabel->setText(framesText(running, m_pacer.framesPerSecond()));
    });
    connect(m_controller, &SimulationController::sceneReplaced, this, [this] { startFramePacingOver(); });
}

void MainWindow::startFramePacingOver()
{
    m_pacer.startOver(double(m_paceClock.nsecsElapsed()) * 1e-9);
    m_frameArrival = -1.0;
    m_controller->setFrameInterval(m_pacer.interval(false));
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
        // (as fast as it goes is always behind: the core, not the clock, sets the pace)
        const bool behind = !(frame->speed > 0.0) || frame->realTimeFactor < kRealTimeTolerance * frame->speed;
        m_controller->setFrameInterval(m_pacer.interval(behind));
        m_framesLabel->setText(framesText(true, m_pacer.framesPerSecond()));
    }
    m_frameArrival = -1.0;
}

}  // namespace ui
