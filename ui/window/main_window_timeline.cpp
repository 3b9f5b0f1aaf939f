// MainWindow's timeline: the bar under the viewport, Simulation › Step Back, and the recording's
// memory budget, kept in the settings.
#include "main_window.h"

#include "ui/simulation/simulation_controller.h"
#include "session/simulation_frame.h"
#include "ui/panels/timeline_bar.h"
#include "ui/viewport/viewport.h"

#include <QAction>
#include <QSettings>
#include <QSpinBox>
#include <QStyle>
#include <QVBoxLayout>

namespace ui {

namespace {

const QString kBudgetKey = QStringLiteral("timeline/budgetMB");

}  // namespace

void MainWindow::createTimeline()
{
    // the view above, the timeline under it
    auto *centre = new QWidget(this);
    centre->setObjectName(QStringLiteral("centre"));
    auto *layout = new QVBoxLayout(centre);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_timelineBar = new TimelineBar(centre);
    layout->addWidget(m_viewport, 1);
    layout->addWidget(m_timelineBar);
    setCentralWidget(centre);

    m_stepBackAction = new QAction(style()->standardIcon(QStyle::SP_MediaSeekBackward), tr("Step &Back"), this);
    m_stepBackAction->setObjectName(QStringLiteral("actionStepBack"));
    m_stepBackAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F6));
    m_stepBackAction->setStatusTip(tr("One step back through the recorded run, then paused"));
    connect(m_stepBackAction, &QAction::triggered, m_controller, &SimulationController::stepBack);

    connect(m_timelineBar, &TimelineBar::scrubRequested, m_controller, &SimulationController::scrub);
    connect(m_timelineBar, &TimelineBar::stepBackRequested, m_stepBackAction, &QAction::trigger);
    connect(m_timelineBar, &TimelineBar::stepForwardRequested, m_stepAction, &QAction::trigger);
    connect(m_timelineBar, &TimelineBar::budgetChanged, m_controller, &SimulationController::setTimelineBudget);

    // the budget of the last session (writeTimelineSettings), else the default; the worker hears
    // of it before any scene
    const int megabytes = QSettings().value(kBudgetKey, m_timelineBar->budgetBox()->value()).toInt();
    m_timelineBar->budgetBox()->setValue(megabytes);
    m_controller->setTimelineBudget(m_timelineBar->budgetBytes());
}

void MainWindow::writeTimelineSettings(QSettings &settings) const
{
    settings.setValue(kBudgetKey, m_timelineBar->budgetBox()->value());
}

void MainWindow::showTimeline(const SimulationFrame &frame)
{
    m_timelineBar->showTimeline(frame.timeline, frame.snapshot->step, frame.snapshot->time);
    m_stepBackAction->setEnabled(!frame.timeline.empty && !frame.timeline.locked &&
                                 frame.snapshot->step > frame.timeline.firstStep);
}

}  // namespace ui
