#include "main_window.h"

#include "field_undo_keys.h"
#include "window_size.h"

#include "ui/export/exporter.h"

#include "ui/dialogs/accuracy_dialog.h"
#include "ui/viewport/edit_tools.h"
#include "ui/panels/inspector_panel.h"
#include "ui/document/autosave.h"
#include "ui/document/document_files.h"
#include "ui/dialogs/help_dialog.h"
#include "ui/document/initial_state_command.h"
#include "ui/panels/parameters_panel.h"
#include "ui/panels/plots_widget.h"
#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "session/session_file.h"
#include "ui/simulation/playback_speed.h"
#include "session/simulation_runner.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/panels/status_text.h"
#include "camera_actions.h"
#include "dock_scroll_area.h"
#include "status_bar.h"
#include "view_layer_actions.h"
#include "ui/viewport/viewport.h"

#include "core/integrators/accuracy_planner.h"

#include <algorithm>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QComboBox>
#include <QCloseEvent>
#include <QResizeEvent>
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QSignalBlocker>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QScreen>
#include <QUndoStack>
#include <QUndoView>

namespace ui {

namespace {

// how long the status bar shows what the accuracy planner picked, ms
constexpr int kPlanMessageMs = 20000;
// how long the status bar says what an Undo or Redo did, ms
constexpr int kUndoMessageMs = 5000;

// the right-hand docks' width on a first start (the view gets the rest), px
constexpr int kDefaultDockWidth = 400;

QString defaultScreenshotDirectory()
{
    const QString pictures = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    return pictures.isEmpty() ? QDir::homePath() : pictures;
}

}  // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent), m_document(new SceneDocument(this)), m_controller(new SimulationController(this)),
      m_viewport(new Viewport(this)),
      m_screenshotDirectory(defaultScreenshotDirectory())
{
    // the 3D view in the middle; it takes the keyboard focus when clicked
    setObjectName(QStringLiteral("mainWindow"));
    m_viewport->setObjectName(QStringLiteral("viewport"));
    m_viewport->setFocusPolicy(Qt::StrongFocus);
    m_viewport->setMinimumSize(320, 240);
    setStatusBar(m_statusBar = new StatusBar(this));

    // File › Export, writing where screenshots go
    m_exporter = new Exporter(*m_document, *m_controller, *m_viewport, m_prompts,
                              [this] { return m_screenshotDirectory; }, this);
    connect(m_exporter, &Exporter::statusMessage, statusBar(), &QStatusBar::showMessage);

    // File's actions on the document's files, with the same prompts
    m_files = new DocumentFiles(*m_document, m_prompts, this);
    connect(m_files, &DocumentFiles::statusMessage, statusBar(), &QStatusBar::showMessage);
    connect(m_files, &DocumentFiles::warning, this, &MainWindow::showWarning);

    createActions();
    createTimeline();  // the view with the timeline under it, in the middle
    createMenus();
    createDocks();
    createEditing();
    createPlotsDock();
    createStatusBar();
    createFramePacing();
    // a scene file dropped anywhere on the window opens
    setAcceptDrops(true);

    // the document feeds the worker and the title; the worker feeds the views, and the view is
    // framed on a new scene once the worker shows it
    m_controller->follow(*m_document);
    connect(m_controller, &SimulationController::sceneReplaced, m_plots, &PlotsWidget::startOverAfter);
    connect(m_controller, &SimulationController::sceneReplaced, m_cameraActions, &CameraActions::frameAllWhenShown);
    connect(m_document, &SceneDocument::sceneChanged, this, &MainWindow::sceneChanged);
    connect(m_document, &SceneDocument::modifiedChanged, this, &QWidget::setWindowModified);
    connect(m_document, &SceneDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::filePathChanged, this, &MainWindow::updateFileActions);
    connect(m_controller, &SimulationController::frameChanged, this, &MainWindow::frameChanged);
    connect(m_controller, &SimulationController::accuracyPlanned, this, &MainWindow::accuracyPlanned);
    connect(m_controller, &SimulationController::stateCaptured, this, &MainWindow::stateCaptured);
    connect(m_controller, &SimulationController::recordingStopped, this, &MainWindow::recordingStopped);
    connect(m_controller, &SimulationController::runningChanged, this, &MainWindow::runningChanged);
    connect(m_controller, &SimulationController::blewUp, this, [this](const QString &message) {
        showWarning(tr("%1 Paused at the last good state.").arg(message));
    });
    connect(m_parameters, &ParametersPanel::valueRefused, this, &MainWindow::showWarning);
    // a warning about a value, a run or a file is stale once the scene has changed, been undone or
    // redone, or the run reset: it goes (a run still too fast says so again)
    connect(m_document->undoStack(), &QUndoStack::indexChanged, this, &MainWindow::clearWarning);
    connect(m_document->undoStack(), &QUndoStack::indexChanged, this, &MainWindow::sayUndoOrRedo);
    connect(m_resetAction, &QAction::triggered, this, &MainWindow::clearWarning);

    readSettings();
    QString error;
    if (!m_files->openExample(QString::fromLatin1(DocumentFiles::kDefaultExample), &error))
        showWarning(error);
}

MainWindow::~MainWindow()
{
    // the worker stops first, and nothing the children say while they are torn down may reach
    // this window's slots: by then it is only a QWidget (UBSan's vptr check once caught a signal
    // reaching a MainWindow slot of a window being destroyed while a scene was still loading)
    m_controller->shutDown();
    for (QObject *child : findChildren<QObject *>())
        child->disconnect(this);
    // the tools filter the viewport's events and read the document: they go first, before the
    // children are torn down in creation order (the document before the viewport); the
    // inspector reads the tools, so it goes before them
    delete m_inspector;
    m_inspector = nullptr;
    delete m_tools;
    m_tools = nullptr;
}

void MainWindow::createActions()
{
    QStyle *style = this->style();

    // simulation
    m_playAction = new QAction(style->standardIcon(QStyle::SP_MediaPlay), tr("&Play"), this);
    m_playAction->setObjectName(QStringLiteral("actionPlay"));
    m_playAction->setShortcut(Qt::Key_F4);
    m_playAction->setStatusTip(tr("Start or pause the simulation"));
    connect(m_playAction, &QAction::triggered, m_controller, &SimulationController::togglePlay);

    m_stepAction = new QAction(style->standardIcon(QStyle::SP_MediaSkipForward), tr("&Step"), this);
    m_stepAction->setObjectName(QStringLiteral("actionStep"));
    m_stepAction->setShortcut(Qt::Key_F6);
    m_stepAction->setStatusTip(tr("Advance one time step, then pause"));
    connect(m_stepAction, &QAction::triggered, m_controller, &SimulationController::stepOnce);

    m_resetAction = new QAction(style->standardIcon(QStyle::SP_MediaSkipBackward), tr("&Reset"), this);
    m_resetAction->setObjectName(QStringLiteral("actionReset"));
    m_resetAction->setShortcut(Qt::Key_F5);
    m_resetAction->setStatusTip(tr("Back to the scene's initial state"));
    connect(m_resetAction, &QAction::triggered, m_controller, &SimulationController::reset);

    m_captureAction = new QAction(tr("&Use Current State as Initial"), this);
    m_captureAction->setObjectName(QStringLiteral("actionUseCurrentState"));
    m_captureAction->setStatusTip(
        tr("Make the running positions and velocities the scene's initial conditions (undoable); Reset returns "
           "to them"));
    connect(m_captureAction, &QAction::triggered, this, &MainWindow::useCurrentStateAsInitial);

    m_recordAction = new QAction(tr("&Record Session"), this);
    m_recordAction->setObjectName(QStringLiteral("actionRecordSession"));
    m_recordAction->setCheckable(true);
    m_recordAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_recordAction->setStatusTip(tr("Record the run and every edit from now on; unchecking saves the recording, which "
                                    "springlab-sim --replay runs again to the same bits"));
    connect(m_recordAction, &QAction::toggled, this, &MainWindow::setRecording);

    // the handout's "tilt" (T), named for what it does: a random kick, not a tilt of the scene
    m_kickAction = new QAction(tr("&Kick Particles"), this);
    m_kickAction->setObjectName(QStringLiteral("actionKickParticles"));
    m_kickAction->setShortcut(Qt::Key_T);
    m_kickAction->setStatusTip(tr("Give every free particle a random velocity (the handout's \"tilt\")"));
    connect(m_kickAction, &QAction::triggered, m_controller, &SimulationController::tilt);

    m_collisionsAction = new QAction(tr("&Collisions"), this);
    m_collisionsAction->setObjectName(QStringLiteral("actionCollisions"));
    m_collisionsAction->setCheckable(true);
    m_collisionsAction->setShortcut(Qt::Key_A);
    m_collisionsAction->setStatusTip(tr("Switch plane and particle collisions on or off"));
    connect(m_collisionsAction, &QAction::triggered, this, &MainWindow::toggleCollisions);

    m_accuracyAction = new QAction(tr("&Accuracy..."), this);
    m_accuracyAction->setObjectName(QStringLiteral("actionAccuracy"));
    m_accuracyAction->setShortcut(Qt::Key_F7);
    m_accuracyAction->setStatusTip(
        tr("Type a local error per step; the cheapest integrator and substeps that keep under it are applied"));
    connect(m_accuracyAction, &QAction::triggered, this, &MainWindow::showAccuracy);

    createSpeedActions();

    // steering, for scenes with a steerable particle: the push (arrow keys) and the cue
    struct SteerKey {
        const char *name;
        const char *text;
        const char *tip;
        QKeySequence key;
        Steering::Change change;
    };
    const SteerKey steerKeys[] = {
        {"actionSteerLeft", QT_TR_NOOP("Steer &Left"),
         QT_TR_NOOP("Turn the push and the cue on the steerable particle 15° to the left, seen from above"),
         QKeySequence(Qt::Key_Left), {.turn = 1}},
        {"actionSteerRight", QT_TR_NOOP("Steer R&ight"),
         QT_TR_NOOP("Turn the push and the cue on the steerable particle 15° to the right, seen from above"),
         QKeySequence(Qt::Key_Right), {.turn = -1}},
        {"actionSteerStronger", QT_TR_NOOP("Push &Harder"),
         QT_TR_NOOP("Push the steerable particle harder (the pool's cue ball); an arrow at it shows the push"),
         QKeySequence(Qt::Key_Up), {.push = 1}},
        {"actionSteerWeaker", QT_TR_NOOP("Push &Softer"),
         QT_TR_NOOP("Push the steerable particle more softly, down to not at all"), QKeySequence(Qt::Key_Down),
         {.push = -1}},
        {"actionCueHarder", QT_TR_NOOP("Cue Fas&ter"),
         QT_TR_NOOP("Strike the cue ball 0.5 m/s faster (S strikes)"), QKeySequence(Qt::SHIFT | Qt::Key_Up),
         {.cue = 1}},
        {"actionCueSofter", QT_TR_NOOP("Cue Slo&wer"),
         QT_TR_NOOP("Strike the cue ball 0.5 m/s slower (S strikes)"), QKeySequence(Qt::SHIFT | Qt::Key_Down),
         {.cue = -1}},
        {"actionCueHigher", QT_TR_NOOP("Cue Hi&gher"),
         QT_TR_NOOP("Strike the cue ball a tenth of its radius higher: above the centre gives topspin, so it "
                    "follows the ball it hits"),
         QKeySequence(Qt::Key_PageUp), {.height = 1}},
        {"actionCueLower", QT_TR_NOOP("Cue Lo&wer"),
         QT_TR_NOOP("Strike the cue ball a tenth of its radius lower: below the centre gives backspin, so it "
                    "draws back from the ball it hits"),
         QKeySequence(Qt::Key_PageDown), {.height = -1}},
    };
    for (const SteerKey &key : steerKeys) {
        auto *action = new QAction(tr(key.text), this);
        action->setObjectName(QString::fromLatin1(key.name));
        action->setShortcut(key.key);
        action->setStatusTip(tr(key.tip));
        connect(action, &QAction::triggered, this, [this, change = key.change] { steer(change); });
        m_steerActions << action;
    }
    auto *strike = new QAction(tr("Stri&ke Cue Ball"), this);
    strike->setObjectName(QStringLiteral("actionStrikeCueBall"));
    strike->setShortcut(Qt::Key_S);
    strike->setStatusTip(tr("Strike the steerable particle with the cue: along the push's direction, at the cue's "
                            "speed and height"));
    connect(strike, &QAction::triggered, this, &MainWindow::strikeCue);
    m_steerActions << strike;
}

void MainWindow::resizeEvent(QResizeEvent *event)
{
    QMainWindow::resizeEvent(event);
    fitToolBars();
}

void MainWindow::fitToolBars()
{
    // only while the user leaves the toolbars at the top, not floating
    if (!m_itemsToolBar || toolBarArea(m_itemsToolBar) != Qt::TopToolBarArea || m_itemsToolBar->isFloating())
        return;
    int wanted = 0;
    for (QToolBar *bar : findChildren<QToolBar *>(Qt::FindDirectChildrenOnly))
        if (!bar->isHidden() && !bar->isFloating() && toolBarArea(bar) == Qt::TopToolBarArea)
            wanted += bar->sizeHint().width();
    const bool fits = wanted <= width();
    if (fits && toolBarBreak(m_itemsToolBar))
        removeToolBarBreak(m_itemsToolBar);
    else if (!fits && !toolBarBreak(m_itemsToolBar))
        insertToolBarBreak(m_itemsToolBar);
}

void MainWindow::createSpeedActions()
{
    auto *group = new QActionGroup(this);
    for (const PlaybackSpeed &speed : playbackSpeeds()) {
        auto *action = new QAction(speedText(speed.factor), group);
        action->setObjectName(QString::fromLatin1(speed.objectName));
        action->setCheckable(true);
        action->setChecked(speed.factor == 1.0);
        action->setData(speed.factor);
        action->setStatusTip(speed.factor > SimulationRunner::kAsFastAsItGoes
                                 ? tr("Play %1 real time; faster fills the timeline ahead").arg(speedText(speed.factor))
                                 : tr("Play as fast as the computer can, each frame shown as it comes"));
        connect(action, &QAction::triggered, this, [this, factor = speed.factor] { setSpeed(factor); });
        m_speedActions << action;
    }
    // [ and ] go one speed slower or faster, as far as the ends of the list
    const auto neighbour = [this](int by) {
        const int at = int(std::find_if(m_speedActions.begin(), m_speedActions.end(),
                                         [](const QAction *a) { return a->isChecked(); }) -
                           m_speedActions.begin());
        const int next = std::clamp(at + by, 0, int(playbackSpeeds().size()) - 1);
        setSpeed(m_speedActions[next]->data().toDouble());
    };
    auto *slower = new QAction(tr("Slower"), this);
    slower->setObjectName(QStringLiteral("actionSpeedSlower"));
    slower->setShortcut(Qt::Key_BracketLeft);
    connect(slower, &QAction::triggered, this, [neighbour] { neighbour(-1); });
    auto *faster = new QAction(tr("Faster"), this);
    faster->setObjectName(QStringLiteral("actionSpeedFaster"));
    faster->setShortcut(Qt::Key_BracketRight);
    connect(faster, &QAction::triggered, this, [neighbour] { neighbour(+1); });
    auto *separator = new QAction(this);
    separator->setSeparator(true);
    m_speedActions << separator << slower << faster;
}

void MainWindow::setSpeed(double speed)
{
    m_controller->setSpeed(speed);
    for (QAction *action : std::as_const(m_speedActions))
        if (action->isCheckable())
            action->setChecked(action->data().toDouble() == speed);
    if (m_speedBox)
        m_speedBox->setCurrentIndex(m_speedBox->findData(speed));
    m_statusBar->showMessage(speed > SimulationRunner::kAsFastAsItGoes
                                 ? tr("Playing at %1 real time").arg(speedText(speed))
                                 : tr("Playing as fast as it goes"),
                             5000);
}

void MainWindow::createMenus()
{
    createFileMenu();
    createEditMenu();

    // simulation
    QMenu *simulation = m_simulationMenu = menuBar()->addMenu(tr("&Simulation"));
    simulation->addAction(m_playAction);
    simulation->addAction(m_stepAction);
    simulation->addAction(m_stepBackAction);
    simulation->addAction(m_resetAction);
    simulation->addAction(m_captureAction);
    simulation->addAction(m_recordAction);
    simulation->addSeparator();
    simulation->addAction(m_kickAction);
    simulation->addAction(m_collisionsAction);
    simulation->addAction(m_accuracyAction);
    QMenu *speed = simulation->addMenu(tr("S&peed"));
    speed->setObjectName(QStringLiteral("menuSpeed"));
    speed->addActions(m_speedActions);
    simulation->addSeparator();
    simulation->addActions(m_steerActions);

    // view: the camera, then the docks and the toolbar (added with them)
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    QAction *frameAll = m_viewMenu->addAction(tr("&Frame All"), m_viewport, &Viewport::frameAll);
    frameAll->setObjectName(QStringLiteral("actionFrameAll"));
    frameAll->setShortcuts({QKeySequence(Qt::Key_F), QKeySequence(Qt::Key_Home)});
    frameAll->setStatusTip(tr("Point the camera at the whole scene"));
    m_cameraActions = new CameraActions(m_viewport, this);
    m_viewMenu->addActions(m_cameraActions->actions());
    m_viewMenu->addSeparator();
    m_viewMenu->addActions((new ViewLayerActions(m_viewport, this))->actions());
    m_viewMenu->addSeparator();

    // help
    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *keys = help->addAction(tr("&Keyboard and Mouse"), this, &MainWindow::showHelp);
    keys->setObjectName(QStringLiteral("actionHelp"));
    keys->setShortcut(Qt::Key_F1);
    keys->setStatusTip(tr("List every shortcut and mouse gesture"));
    help->addAction(tr("&About Springlab"), this, &MainWindow::showAbout);

    // toolbar
    QToolBar *toolbar = addToolBar(tr("Simulation"));
    toolbar->setObjectName(QStringLiteral("simulationToolBar"));
    toolbar->addAction(m_playAction);
    toolbar->addAction(m_stepAction);
    toolbar->addAction(m_resetAction);
    m_speedBox = new QComboBox(toolbar);
    m_speedBox->setObjectName(QStringLiteral("speedBox"));
    m_speedBox->setToolTip(tr("Playback speed: a multiple of real time ([ and ] change it), or as fast as it goes"));
    m_speedBox->setFocusPolicy(Qt::TabFocus);
    // short names, so that the box leaves the tools' toolbar its room: "Fastest" for as fast as it goes
    for (const QAction *action : std::as_const(m_speedActions))
        if (action->isCheckable())
            m_speedBox->addItem(action->data().toDouble() > SimulationRunner::kAsFastAsItGoes ? action->text()
                                                                                          : tr("Fastest"),
                                action->data());
    m_speedBox->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_speedBox->setCurrentIndex(m_speedBox->findData(1.0));
    connect(m_speedBox, &QComboBox::activated, this,
            [this](int index) { setSpeed(m_speedBox->itemData(index).toDouble()); });
    toolbar->addWidget(m_speedBox);
    m_viewMenu->addAction(toolbar->toggleViewAction());
}

QWidget *MainWindow::inScrollArea(QWidget *content)
{
    // a dock's content scrolls rather than forcing the window taller when it grows, and is never
    // cut at its side (dock_scroll_area.h)
    return new DockScrollArea(content);
}

void MainWindow::createDocks()
{
    // parameters, scrollable when the window is short
    m_parameters = new ParametersPanel(*m_document);
    m_parametersDock = new QDockWidget(tr("Parameters"), this);
    m_parametersDock->setObjectName(QStringLiteral("parametersDock"));
    m_parametersDock->setWidget(inScrollArea(m_parameters));
    addDockWidget(Qt::RightDockWidgetArea, m_parametersDock);
    m_viewMenu->addAction(m_parametersDock->toggleViewAction());
    createUndoHistoryDock();
}

void MainWindow::createEditMenu()
{
    // undo and redo of every scene change
    m_editMenu = menuBar()->addMenu(tr("&Edit"));
    QAction *undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("actionUndo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction *redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("actionRedo"));
    // Ctrl+Shift+Z and Ctrl+Y everywhere (Ctrl+Y is redo on Windows, and what users of it press
    // here too), and the platform's own keys as well
    QList<QKeySequence> redoKeys{QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)};
    for (const QKeySequence &key : QKeySequence::keyBindings(QKeySequence::Redo))
        if (!redoKeys.contains(key))
            redoKeys << key;
    redo->setShortcuts(redoKeys);
    m_editMenu->addAction(undo);
    m_editMenu->addAction(redo);
    // and while a field has the focus with nothing typed of its own to undo
    new FieldUndoKeys(this, undo, redo);
}

void MainWindow::createUndoHistoryDock()
{
    // every step of the undo stack; a click goes back (or forward) to it. Hidden until asked for.
    m_undoView = new QUndoView(m_document->undoStack());
    m_undoView->setObjectName(QStringLiteral("undoView"));
    m_undoView->setEmptyLabel(tr("<as opened>"));
    m_undoDock = new QDockWidget(tr("Undo History"), this);
    m_undoDock->setObjectName(QStringLiteral("undoHistoryDock"));
    m_undoDock->setWidget(m_undoView);
    addHiddenDock(m_undoDock, Qt::RightDockWidgetArea, "actionUndoHistory",
                  tr("Show or hide the list of edits that undo and redo walk through"));
}

QAction *MainWindow::addHiddenDock(QDockWidget *dock, Qt::DockWidgetArea area, const char *actionName,
                                   const QString &statusTip)
{
    // docked but hidden; View has the action that shows it
    addDockWidget(area, dock);
    dock->hide();
    QAction *toggle = dock->toggleViewAction();
    toggle->setObjectName(QString::fromLatin1(actionName));
    toggle->setStatusTip(statusTip);
    m_viewMenu->addAction(toggle);
    return toggle;
}

void MainWindow::createStatusBar()
{
    // the passing message or the latest warning on the left (StatusBar), the figures of the run
    // on the right, each as wide as its text
    m_steerLabel = m_statusBar->addFigure("statusSteer", QString(), tr("The push on the steerable particle (arrow keys), and the cue's speed (Shift+Up, "
                                                     "Shift+Down) and height (Page Up, Page Down); S strikes"));
    m_timeLabel = m_statusBar->addFigure("statusTime", timeText(100.0), tr("Simulated time"));
    m_rateLabel = m_statusBar->addFigure("statusRate", rateText(true, 1.0),
                                         tr("Simulated seconds per second of wall-clock time"));
    m_stepsLabel = m_statusBar->addFigure("statusSteps", stepsText(true, 10000.0),
                                          tr("Time steps computed per second of wall-clock time"));
    m_framesLabel = m_statusBar->addFigure("statusFrames", framesText(true, 60.0),
                                           tr("Frames the view draws per second of wall-clock time; while the run "
                                              "falls behind real time, drawing is held to a tenth of it, so that "
                                              "the steps keep the rest"));
    m_energyLabel = m_statusBar->addFigure("statusEnergy", energyText(-123.456),
                                           tr("Total energy: kinetic + gravitational + spring"));
    m_driftLabel = m_statusBar->addFigure("statusDrift", tr("ΔE = +0.1 %"),
                                          tr("Change of the total energy since the last reset or scene load, "
                                             "relative to it (in joules when it is about zero)"));
    m_errorLabel = m_statusBar->addFigure("statusError", localErrorText(1e-6), QString());
    m_steerLabel->hide();
}

void MainWindow::readSettings()
{
    QSettings settings;
    settings.beginGroup(QStringLiteral("mainWindow"));
    if (!restoreGeometry(settings.value(QStringLiteral("geometry")).toByteArray()))
        resize(defaultWindowSize(screen() ? screen()->availableGeometry().size() : QSize()));
    // the docks narrow by default: the view gets most of the window
    if (!restoreState(settings.value(QStringLiteral("state")).toByteArray()))
        resizeDocks({m_parametersDock}, {kDefaultDockWidth}, Qt::Horizontal);
    settings.endGroup();
    m_screenshotDirectory =
        settings.value(QStringLiteral("screenshots/directory"), defaultScreenshotDirectory()).toString();
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    settings.beginGroup(QStringLiteral("mainWindow"));
    settings.setValue(QStringLiteral("geometry"), saveGeometry());
    settings.setValue(QStringLiteral("state"), saveState());
    settings.endGroup();
    settings.setValue(QStringLiteral("screenshots/directory"), m_screenshotDirectory);
    writeTimelineSettings(settings);
}

QString MainWindow::saveScreenshot(QString *error)
{
    auto fail = [error](const QString &reason) {
        if (error)
            *error = reason;
        return QString();
    };
    const QImage image = m_viewport->grabFramebuffer();
    if (image.isNull())
        return fail(tr("Screenshot: the 3D view has no image yet"));
    const QDir directory(m_screenshotDirectory);
    if (!directory.mkpath(QStringLiteral(".")))
        return fail(tr("Screenshot: cannot create the folder %1").arg(QDir::toNativeSeparators(m_screenshotDirectory)));

    // springlab-<scene>-<date>.png, numbered when several land in one second
    QString scene = m_document->displayName();
    scene.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_-]+")), QStringLiteral("-"));
    const QString stem = QStringLiteral("springlab-%1-%2")
                             .arg(scene, QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    QString path = directory.filePath(stem + QStringLiteral(".png"));
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = directory.filePath(QStringLiteral("%1-%2.png").arg(stem).arg(n));
    if (!image.save(path, "PNG"))
        return fail(tr("Screenshot: cannot write %1").arg(QDir::toNativeSeparators(path)));
    statusBar()->showMessage(tr("Screenshot saved to %1").arg(QDir::toNativeSeparators(path)), 5000);
    return path;
}

void MainWindow::setScreenshotDirectory(const QString &directory)
{
    m_screenshotDirectory = directory;
}

QString MainWindow::statusTime() const
{
    return m_timeLabel->text();
}

QString MainWindow::statusRate() const
{
    return m_rateLabel->text();
}

QString MainWindow::statusSteps() const
{
    return m_stepsLabel->text();
}

QString MainWindow::statusFrames() const
{
    return m_framesLabel->text();
}

QString MainWindow::statusWarning() const
{
    return m_statusBar->warning();
}

QString MainWindow::statusError() const
{
    return m_errorLabel->text();
}

QString MainWindow::statusDrift() const
{
    return m_driftLabel->text();
}

void MainWindow::setMessageBoxFunction(MessageBoxFunction function)
{
    m_prompts.setMessageBoxFunction(std::move(function));
}

void MainWindow::setFileDialogFunction(FileDialogFunction function)
{
    m_prompts.setFileDialogFunction(std::move(function));
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    writeSettings();
    // a clean end: no recovery file is left for the next start
    m_files->autosave()->discard();
    // stop the worker before the window goes: nothing may step once the views are gone
    m_controller->shutDown();
    event->accept();
}

void MainWindow::sceneChanged(SceneChange change)
{
    // the worker has it already (SimulationController::follow)
    const core::SceneDesc &scene = m_document->scene();
    if (change != SceneChange::Parameters && change != SceneChange::InitialConditions)
        m_viewport->setPlanes(scene.planes);
    if (change == SceneChange::Replace) {
        // a new scene: fresh steering and no old warning
        m_steering = Steering{};
        m_statusBar->setWarning(QString());
        // a plan still awaited was made for the old scene: drop it
        if (m_accuracyRequest != 0 && m_accuracy)
            m_accuracy->showPlan(core::AccuracyPlan{}, tr("Another scene was opened; plan again"));
        m_accuracyRequest = 0;
        m_captureRequest = 0;
    }
    {
        const QSignalBlocker block(m_collisionsAction);
        m_collisionsAction->setChecked(scene.settings.planeCollisions || scene.settings.particleCollisions);
    }
    updateSteerActions();
    updateTitle();
}

// the accuracy plan asked for has come back: apply it
void MainWindow::accuracyPlanned(const AccuracyPlanReply &reply)
{
    if (reply.request != m_accuracyRequest || !reply.plan)
        return;
    m_accuracyRequest = 0;
    if (m_applyPlan) {
        applyPlan(*reply.plan);
        return;
    }
    // a preview: shown, and the scene left as it is
    if (m_accuracy)
        m_accuracy->showPlan(*reply.plan, planText(*reply.plan) + tr(" (preview: nothing was changed)"));
}

// so has the state asked for by Use Current State as Initial
void MainWindow::stateCaptured(const CapturedStateReply &reply)
{
    if (reply.request != m_captureRequest || !reply.captured)
        return;
    m_captureRequest = 0;
    applyCapturedState(*reply.captured);
}

// and the recording that Ctrl+R stopped (none if the run had none)
void MainWindow::recordingStopped(const RecordingReply &reply)
{
    if (reply.request != m_recordingRequest)
        return;
    m_recordingRequest = 0;
    if (reply.recording)
        saveSessionRecording(*reply.recording);
}

void MainWindow::frameChanged()
{
    const std::shared_ptr<const SimulationFrame> frame = m_controller->frame();
    if (!frame)
        return;

    if (frame->stability && frame->model)
        m_parameters->showStability(*frame->stability, *frame->model, QString::fromStdString(frame->solverSummary));
    // particles too fast for the pair contacts: said once as it starts, not over every later warning
    const bool tooFast = !frame->pairSpeedWarning.empty();
    if (tooFast && !m_pairSpeedWarned)
        showWarning(QString::fromStdString(frame->pairSpeedWarning));
    else if (!tooFast && m_pairSpeedWarned && m_statusBar->warning() == m_pairSpeedWarning)
        clearWarning();  // no longer true
    if (tooFast)
        m_pairSpeedWarning = QString::fromStdString(frame->pairSpeedWarning);
    m_pairSpeedWarned = tooFast;
    if (!frame->snapshot)
        return;
    frameArrived();
    m_viewport->setSnapshot(frame->snapshot);
    showTimeline(*frame);
    m_plots->addFrame(*frame);
    m_inspector->showSnapshot(frame->snapshot);
    m_cameraActions->frameShown(*frame);

    // the figures of the run
    const core::Snapshot &snapshot = *frame->snapshot;
    m_timeLabel->setText(timeText(snapshot.time));
    m_rateLabel->setText(rateText(frame->running, frame->realTimeFactor, frame->speed));
    m_stepsLabel->setText(stepsText(frame->running, frame->stepsPerSecond, frame->stepsOwed));
    m_framesLabel->setText(framesText(frame->running, m_pacer.framesPerSecond()));
    m_energyLabel->setText(energyText(snapshot.energies));
    m_driftLabel->setText(driftText(frame->initialEnergies, snapshot.energies.total()));
    m_errorLabel->setText(localErrorText(frame->localError));
    m_errorLabel->setToolTip(tr("Local position error of one step of the integrator (one sub-step), estimated by "
                                "step doubling at step %1; the estimates take %2 % of the computing time")
                                 .arg(frame->localErrorStep)
                                 .arg(100.0 * frame->estimateShare, 0, 'f', 2));
}

void MainWindow::runningChanged(bool running)
{
    m_playAction->setText(running ? tr("&Pause") : tr("&Play"));
    m_playAction->setIcon(style()->standardIcon(running ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void MainWindow::showWarning(const QString &message)
{
    // a new warning is seen at once, not after a passing message
    m_statusBar->clearMessage();
    m_statusBar->setWarning(message);
}

// the status bar says what Undo and Redo (or a click in the history) did: the index moved with
// the count unchanged; a new edit changes the count and says its own
void MainWindow::sayUndoOrRedo(int index)
{
    const QUndoStack *stack = m_document->undoStack();
    const int count = stack->count();
    if (count == m_undoCount && index < m_undoIndex)
        statusBar()->showMessage(m_undoIndex - index == 1
                                     ? tr("Undid “%1”").arg(stack->text(index))
                                     : tr("Undid %1 edits, back to before “%2”").arg(m_undoIndex - index).arg(stack->text(index)),
                                 kUndoMessageMs);
    else if (count == m_undoCount && index > m_undoIndex)
        statusBar()->showMessage(index - m_undoIndex == 1
                                     ? tr("Redid “%1”").arg(stack->text(index - 1))
                                     : tr("Redid %1 edits, up to “%2”").arg(index - m_undoIndex).arg(stack->text(index - 1)),
                                 kUndoMessageMs);
    m_undoIndex = index;
    m_undoCount = count;
}

void MainWindow::clearWarning()
{
    if (m_statusBar->warning() == m_pairSpeedWarning)
        m_pairSpeedWarned = false;
    m_statusBar->setWarning(QString());
}

void MainWindow::updateTitle()
{
    setWindowTitle(tr("%1[*] — Springlab").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
}

void MainWindow::updateSteerActions()
{
    const core::SceneDesc &scene = m_document->scene();
    const bool steerable = scene.steerable >= 0 && scene.steerable < static_cast<int>(scene.particles.size());
    for (QAction *action : m_steerActions)
        action->setEnabled(steerable);
    m_steerLabel->setVisible(steerable);
    if (steerable) {
        const double mass = scene.particles[static_cast<std::size_t>(scene.steerable)].mass;
        m_steerLabel->setText(
            steerText(m_steering.strength(mass), m_steering.angle, m_steering.strikeSpeed(), m_steering.cueHeight));
    }
    // and the arrow in the view, while there is a push
    const Eigen::Vector3d d = m_steering.direction();
    const QVector3D direction(float(d.x()), float(d.y()), float(d.z()));
    const float strength = float(m_steering.level) / Steering::kMaxLevel;
    m_viewport->setSteeringArrow(steerable ? SteeringArrow{scene.steerable, direction, strength} : SteeringArrow{});
}

void MainWindow::chooseScreenshotDirectory()
{
    const QString directory =
        QFileDialog::getExistingDirectory(this, tr("Folder for screenshots"), m_screenshotDirectory);
    if (!directory.isEmpty())
        m_screenshotDirectory = directory;
}

void MainWindow::showHelp()
{
    HelpDialog dialog(*menuBar(), this);
    dialog.exec();
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Springlab"),
                       tr("<p><b>Springlab %1</b></p><p>An editor for particle and mass-spring physics: "
                          "gravity, drag, damped springs and collisions, simulated live.</p>")
                           .arg(QApplication::applicationVersion()));
}

void MainWindow::toggleCollisions(bool on)
{
    core::Settings settings = m_document->scene().settings;
    settings.planeCollisions = on;
    settings.particleCollisions = on;
    m_document->undoStack()->push(new SettingsCommand(*m_document, on ? tr("Collisions on") : tr("Collisions off"),
                                                      QStringLiteral("collisions"), settings));
    statusBar()->showMessage(on ? tr("Collisions on") : tr("Collisions off"), 3000);
}

void MainWindow::showAccuracy()
{
    if (!m_accuracy) {
        m_accuracy = new AccuracyDialog(this);
        connect(m_accuracy, &AccuracyDialog::planRequested, this, &MainWindow::planAccuracy);
        connect(m_accuracy, &AccuracyDialog::adaptiveRequested, this, &MainWindow::useAdaptive);
    }
    m_accuracy->show();
    m_accuracy->raise();
    m_accuracy->activateWindow();
}

void MainWindow::planAccuracy(double tolerance, bool apply)
{
    // the worker plans from its own state; the answer comes back as a reply
    m_accuracyRequest = m_controller->planAccuracy(tolerance);
    m_applyPlan = apply;
    if (m_accuracy)
        m_accuracy->setPlanning(true);
}

void MainWindow::applyPlan(const core::AccuracyPlan &plan)
{
    // the pick, integrator and substeps together, is one step of undo
    QString summary = planText(plan);
    if (const core::PlanCandidate *pick = plan.pick()) {
        core::Settings settings = m_document->scene().settings;
        if (settings.integrator == pick->integrator && settings.substeps == pick->substeps) {
            summary += tr("; already in use");
        } else {
            settings.integrator = pick->integrator;
            settings.substeps = pick->substeps;
            const std::string_view name = core::integratorName(pick->integrator);
            m_document->undoStack()->push(new SettingsCommand(
                *m_document,
                tr("Accuracy: %1 with %2 substeps")
                    .arg(QString::fromLatin1(name.data(), qsizetype(name.size())))
                    .arg(pick->substeps),
                QString(), settings));
        }
    }
    statusBar()->showMessage(summary, kPlanMessageMs);
    if (m_accuracy)
        m_accuracy->showPlan(plan, summary);
}

void MainWindow::useAdaptive(double tolerance)
{
    // adaptive-rk45 at the tolerance typed, both as one step of undo
    core::Settings settings = m_document->scene().settings;
    QString summary = tr("adaptive-rk45 keeping each step's local error under %1 m/step").arg(scientificText(tolerance));
    if (settings.integrator == core::Integrator::AdaptiveRk45 && settings.tolerance == tolerance) {
        summary += tr("; already in use");
    } else {
        settings.integrator = core::Integrator::AdaptiveRk45;
        settings.tolerance = tolerance;
        m_document->undoStack()->push(new SettingsCommand(
            *m_document, tr("Accuracy: adaptive-rk45 at %1 m/step").arg(scientificText(tolerance)), QString(), settings));
    }
    statusBar()->showMessage(summary, kPlanMessageMs);
    if (m_accuracy)
        m_accuracy->showSummary(summary);
}

void MainWindow::setRecording(bool on)
{
    if (on) {
        m_controller->startRecording();
        statusBar()->showMessage(tr("Recording the session; Ctrl+R again to stop and save it"));
    } else {
        // the worker hands the recording over as a reply
        m_recordingRequest = m_controller->stopRecording();
    }
}

void MainWindow::saveSessionRecording(const SessionRecording &recording)
{
    const QString suggested = QDir(m_document->folder()).filePath(m_document->displayName() + QStringLiteral(".replay.json"));
    const QString path = m_prompts.chooseFile(FileDialogMode::Save, tr("Save session recording"), suggested);
    if (path.isEmpty())
        return;
    // never over the scene or a recovery file, by any name
    if (const QString refused = m_files->protectedFileAt(path); !refused.isEmpty()) {
        m_prompts.ask(QMessageBox::Warning, tr("Save session recording"),
                      tr("%1: cannot save: %2").arg(QDir::toNativeSeparators(path), refused));
        return;
    }
    if (const QString error = saveRecording(path, recording); !error.isEmpty()) {
        m_prompts.ask(QMessageBox::Warning, tr("Save session recording"), error);
        return;
    }
    statusBar()->showMessage(tr("Saved the recording of %1 steps and %2 edits to %3; springlab-sim --replay runs it")
                                 .arg(recording.steps)
                                 .arg(recording.entries.size())
                                 .arg(QDir::toNativeSeparators(path)),
                             10000);
}

void MainWindow::useCurrentStateAsInitial()
{
    // the worker copies its state out; the answer comes back as a reply
    m_captureRequest = m_controller->captureState();
}

void MainWindow::applyCapturedState(const CapturedState &captured)
{
    // a scene replaced or given other particles since the request: the state no longer fits
    const core::State &state = captured.state;
    if (!captured.scene || state.particleCount() != static_cast<int>(m_document->scene().particles.size())) {
        showWarning(tr("Use current state as initial: the scene changed meanwhile; nothing was changed"));
        return;
    }
    m_document->undoStack()->push(new InitialStateCommand(
        *m_document, tr("Use state at t = %1 s as initial").arg(state.time, 0, 'g', 4), state));
    statusBar()->showMessage(
        tr("The state at t = %1 s is now the initial state; Reset (F5) returns to it").arg(state.time, 0, 'g', 4),
        kPlanMessageMs);
}

void MainWindow::steer(const Steering::Change &change)
{
    const core::SceneDesc &scene = m_document->scene();
    if (scene.steerable < 0 || scene.steerable >= static_cast<int>(scene.particles.size()))
        return;
    const bool pushChanged = change.turn != 0 || change.push != 0;
    m_steering.apply(change);
    if (pushChanged) {
        const double mass = scene.particles[static_cast<std::size_t>(scene.steerable)].mass;
        m_controller->steer(scene.steerable, m_steering.force(mass));
    }
    updateSteerActions();
}

void MainWindow::strikeCue()
{
    const core::SceneDesc &scene = m_document->scene();
    if (scene.steerable < 0 || scene.steerable >= static_cast<int>(scene.particles.size()))
        return;
    const core::ParticleDesc &ball = scene.particles[static_cast<std::size_t>(scene.steerable)];
    if (ball.pinned) {
        m_statusBar->showMessage(tr("Particle %1 is pinned: the cue does not move it").arg(scene.steerable));
        return;
    }
    const Steering::Stroke stroke = m_steering.stroke(ball.radius);
    m_controller->strike(scene.steerable, stroke.velocityChange, stroke.spinChange);
    const bool turns = m_controller->sceneTurns();
    QString text = tr("Particle %1 struck at %2 m/s, %3").arg(scene.steerable).arg(m_steering.strikeSpeed(), 0, 'g', 3)
                       .arg(cueHeightText(m_steering.cueHeight));
    if (m_steering.cueHeight != 0)
        text += turns ? tr(": spin %1 rad/s").arg(stroke.spinChange.norm(), 0, 'g', 3)
                      : tr(": no spin, as nothing in this scene has friction");
    m_statusBar->showMessage(text);
}

}  // namespace ui
