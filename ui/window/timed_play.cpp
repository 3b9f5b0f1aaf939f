#include "timed_play.h"

#include "main_window.h"

#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include <QCoreApplication>
#include <cmath>
#include <cstdio>

namespace ui {

QString TimedPlay::reportText(const Figures &figures)
{
    const double seconds = figures.seconds > 0.0 ? figures.seconds : 1.0;
    return QStringLiteral(
               "springlab: %1 s: %2 steps (%3 steps/s), %4 frames (%5 frames/s), paused in %6 s, shown in %7 s")
        .arg(figures.seconds, 0, 'f', 3)
        .arg(figures.steps)
        .arg(double(figures.steps) / seconds, 0, 'f', 2)
        .arg(figures.frames)
        .arg(double(figures.frames) / seconds, 0, 'f', 2)
        .arg(figures.pauseSeconds, 0, 'f', 3)
        .arg(figures.shownSeconds, 0, 'f', 3);
}

TimedPlay::TimedPlay(MainWindow &window, bool play, double exitAfterSeconds, QObject *parent)
    : QObject(parent), m_window(window), m_play(play)
{
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(static_cast<int>(std::lround(exitAfterSeconds * 1000.0)));
    connect(&m_timer, &QTimer::timeout, this, &TimedPlay::stop);
    connect(window.controller(), &SimulationController::frameChanged, this, &TimedPlay::frameChanged);
    connect(window.viewport(), &Viewport::frameTimeMeasured, this, [this] {
        if (m_clock.isValid() && !m_stopping)
            ++m_figures.frames;
    });
}

void TimedPlay::start()
{
    // the frames from the Play on count, the first of them gives the step the run starts from
    SimulationController &controller = *m_window.controller();
    m_startMessage = m_play ? controller.play() : controller.sync();
    m_clock.start();
    m_timer.start();
}

void TimedPlay::frameChanged()
{
    const std::shared_ptr<const SimulationFrame> frame = m_window.controller()->frame();
    if (!frame || !frame->snapshot || !m_clock.isValid() || frame->appliedMessage < m_startMessage)
        return;
    if (!m_startKnown) {
        m_startKnown = true;
        m_startStep = frame->shownStep;
    }
    m_lastStep = frame->shownStep;
    if (m_stopWhenStepped && m_lastStep > m_startStep) {
        stop();
        return;
    }
    if (!m_stopping || frame->appliedMessage < m_pauseMessage)
        return;

    // the pause is in: the steps up to it, against the time up to when it was asked for; then the
    // frame with the picture of the step it stopped at (the same frame unless its snapshot was slow)
    const double sincePause = static_cast<double>(m_clock.nsecsElapsed()) * 1e-9 - m_figures.seconds;
    if (!m_pauseAnswered) {
        m_pauseAnswered = true;
        m_figures.steps = m_lastStep > m_startStep ? m_lastStep - m_startStep : 0;
        m_figures.pauseSeconds = sincePause;
    }
    if (frame->snapshotBehind)
        return;
    m_figures.shownSeconds = sincePause;
    const QByteArray line = reportText(m_figures).toUtf8();
    std::printf("%s\n", line.constData());
    std::fflush(stdout);
    disconnect(m_window.controller(), nullptr, this, nullptr);
    QCoreApplication::quit();
}

void TimedPlay::stop()
{
    // a playing run that has not shown a step yet (the worker has had no core to itself) plays on
    // until it has: the figures are of a run that ran
    if (m_play && !(m_startKnown && m_lastStep > m_startStep)) {
        m_stopWhenStepped = true;
        return;
    }
    m_stopWhenStepped = false;
    // time is up: the clock stops here, and the frame that answers the pause gives the steps
    m_figures.seconds = static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
    m_stopping = true;
    m_pauseMessage = m_window.controller()->pause();
}

}  // namespace ui
