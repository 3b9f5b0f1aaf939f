#pragma once
// MainWindow: the editor. It ties the scene document (the UI thread's SceneDesc and its undo
// stack) to the simulation controller (the worker thread) and to the views: the 3D viewport, the
// parameters dock, the plots dock and the status bar. A document change becomes a scene edit for
// the worker; a frame from the worker goes to the viewport, the plots and the status bar. What
// touches files (New, Open, Save, Revert, recent files, drops, autosave and recovery) is in
// main_window_files.cpp, and File › Export (an image of any size, an image sequence and MP4 of the
// run, a trace) in main_window_export.cpp.

#include "ui/dialogs/prompts.h"
#include "ui/simulation/steering.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <functional>
#include <optional>

class QAction;
class QActionGroup;
class QLabel;
class QMenu;
class QDockWidget;
class QMimeData;
class QToolBar;
class QSettings;
class QUndoView;

namespace core {
struct AccuracyPlan;
struct SceneDesc;
}

namespace ui {

class AccuracyDialog;
class EditTools;
class GenerateDialog;
class Exporter;
class InspectorPanel;
class Autosave;
class ParametersPanel;
class PlotsWidget;
class RecentFiles;
struct AccuracyPlanReply;
struct CapturedState;
struct CapturedStateReply;
struct RecordingReply;
struct SessionRecording;
class SceneDocument;
class SimulationController;
struct SimulationFrame;
class TimelineBar;
class Viewport;
enum class SceneChange;
enum class PlotExport;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    // the example opened when no scene is given
    static constexpr const char *kDefaultExample = "springs";

    // opens on the default example
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    // every question and message the window shows goes through its Prompts, so that tests can
    // answer them without a modal dialog (ui/dialogs/prompts.h)
    using MessageBoxFunction = Prompts::MessageBoxFunction;
    using FileDialogMode = Prompts::FileDialogMode;
    using FileDialogFunction = Prompts::FileDialogFunction;
    void setMessageBoxFunction(MessageBoxFunction function);
    void setFileDialogFunction(FileDialogFunction function);

    // File › New: an empty scene (newScene()) once unsaved changes are dealt with; false if cancelled
    bool newDocument();
    // what File › New opens: no particles, the default settings, a ground plane y = 0
    static core::SceneDesc newScene();

    // opens a scene file; on failure the current scene stays and error says why
    bool openScene(const QString &path, QString *error = nullptr);
    // opens a scene file as File › Open, a recent file or a drop does: asks about unsaved changes
    // first and shows a failure in a message; false if cancelled or failed
    bool openFile(const QString &path);
    // File › Revert: reloads the document's file, after a confirmation if there are changes
    bool revert();
    // the start of the editor: offers to recover a crashed session's work, then opens path (the
    // command line's scene) unless work was recovered; a file that fails is reported in a message
    // (and error), and the default example stays open
    bool start(const QString &path = QString(), QString *error = nullptr);
    // offers the newest recovery file of a crashed session; true if one was recovered
    bool offerRecovery();
    // opens a built-in example by name ("springs"), read from ":/scenes/<name>.json"
    bool openExample(const QString &name, QString *error = nullptr);
    // the examples built in, in the handout's order
    static QStringList exampleNames();

    // saves to the document's file, or asks for one; false if not saved
    bool save();
    bool saveAs();
    bool saveTo(const QString &path, QString *error = nullptr);

    // F2: writes the viewport's image as a PNG into the screenshot folder; returns its path, or
    // an empty string and the reason
    QString saveScreenshot(QString *error = nullptr);
    QString screenshotDirectory() const { return m_screenshotDirectory; }
    void setScreenshotDirectory(const QString &directory);

    // File › Export (ui/export/exporter.h)
    Exporter *exporter() const { return m_exporter; }

    RecentFiles *recentFiles() const { return m_recentFiles; }
    Autosave *autosave() const { return m_autosave; }
    QUndoView *undoView() const { return m_undoView; }

    // Simulation › Use Current State as Initial: asks the worker for its positions and
    // velocities; they become the scene's initial conditions, as one undo step, once they arrive
    void useCurrentStateAsInitial();
    // Simulation > Record Session: on starts recording, off saves the recording (a file dialog)
    void setRecording(bool on);

    SceneDocument *document() const { return m_document; }
    // the editing tools and their selection (main_window_editing.cpp)
    EditTools *editTools() const { return m_tools; }
    InspectorPanel *inspector() const { return m_inspector; }
    SimulationController *controller() const { return m_controller; }
    Viewport *viewport() const { return m_viewport; }
    // the strip under the view that scrubs through the recorded run
    TimelineBar *timelineBar() const { return m_timelineBar; }
    ParametersPanel *parametersPanel() const { return m_parameters; }
    // View › Plots' dock content (main_window_plots.cpp)
    PlotsWidget *plots() const { return m_plots; }
    // Simulation › Accuracy's dialog; null until first opened
    AccuracyDialog *accuracyDialog() const { return m_accuracy; }
    const Steering &steering() const { return m_steering; }
    // Edit › Generate's dialog; null until first opened (main_window_editing.cpp)
    GenerateDialog *generateDialog() const { return m_generate; }

    // the status bar's fields, for the tests
    QString statusTime() const;
    QString statusRate() const;
    QString statusWarning() const;
    QString statusError() const;
    QString statusDrift() const;

protected:
    void closeEvent(QCloseEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dragMoveEvent(QDragMoveEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    void createActions();
    void createMenus();
    void createFileMenu();
    void createEditMenu();
    static QWidget *inScrollArea(QWidget *content);
    void createDocks();
    void createEditing();
    void createUndoHistoryDock();
    // adds a dock hidden until asked for, and its toggle (named actionName) to the View menu
    QAction *addHiddenDock(QDockWidget *dock, Qt::DockWidgetArea area, const char *actionName,
                           const QString &statusTip);
    void createPlotsDock();
    void createAutosave();
    void createStatusBar();
    // the timeline (main_window_timeline.cpp)
    void createTimeline();
    void showTimeline(const SimulationFrame &frame);
    void writeTimelineSettings(QSettings &settings) const;
    void readSettings();
    void writeSettings() const;

    void sceneChanged(SceneChange change);
    void frameChanged();
    // the replies to this window's requests; a reply to an older request than the one awaited,
    // or to one dropped since, is ignored
    void accuracyPlanned(const AccuracyPlanReply &reply);
    void stateCaptured(const CapturedStateReply &reply);
    void recordingStopped(const RecordingReply &reply);
    void runningChanged(bool running);
    void showWarning(const QString &message);
    void updateTitle();
    void updateSteerActions();

    // files (main_window_files.cpp)
    bool maybeSave();
    void openFromDialog();
    QMessageBox::StandardButton ask(QMessageBox::Icon icon, const QString &title, const QString &text,
                                    QMessageBox::StandardButtons buttons = QMessageBox::Ok,
                                    QMessageBox::StandardButton defaultButton = QMessageBox::NoButton);
    // filter: the file dialog's, by default the scene files
    QString chooseFile(FileDialogMode mode, const QString &title, const QString &suggestedPath,
                       const QString &filter = QString());
    void openRecent(const QString &path);
    void updateRecentMenu();
    void updateFileActions();
    void setAutosaveInterval(int seconds);
    static QString droppedScenePath(const QMimeData *mime);
    void applyCapturedState(const CapturedState &captured);
    void saveSessionRecording(const SessionRecording &recording);
    void exportPlot(PlotExport format);

    void chooseScreenshotDirectory();
    void showHelp();
    void showAbout();
    void toggleCollisions(bool on);
    void showAccuracy();
    void planAccuracy(double tolerance);
    void applyPlan(const core::AccuracyPlan &plan);
    void steer(int turn, int change);
    void showGenerate();
    void addGenerated();

    SceneDocument *m_document = nullptr;
    SimulationController *m_controller = nullptr;
    RecentFiles *m_recentFiles = nullptr;
    Autosave *m_autosave = nullptr;
    Prompts m_prompts{this};
    std::uint64_t m_captureRequest = 0;    // the captured state awaited from the worker; 0: none
    std::uint64_t m_recordingRequest = 0;  // the recording awaited from the worker; 0: none
    bool m_pairSpeedWarned = false;      // the latest frame's particles were past the pair speed limit
    Viewport *m_viewport = nullptr;
    EditTools *m_tools = nullptr;
    QToolBar *m_toolBar = nullptr;
    InspectorPanel *m_inspector = nullptr;
    ParametersPanel *m_parameters = nullptr;
    QDockWidget *m_parametersDock = nullptr;
    QDockWidget *m_undoDock = nullptr;
    QUndoView *m_undoView = nullptr;
    PlotsWidget *m_plots = nullptr;
    QDockWidget *m_plotsDock = nullptr;
    AccuracyDialog *m_accuracy = nullptr;
    GenerateDialog *m_generate = nullptr;
    std::uint64_t m_accuracyRequest = 0;  // the plan awaited from the worker; 0: none
    QString m_screenshotDirectory;
    Exporter *m_exporter = nullptr;
    Steering m_steering;
    std::uint64_t m_frameAllAfter = 0;  // frame the view once the worker has applied this edit

    // actions that change with the state
    QAction *m_playAction = nullptr;
    QAction *m_stepAction = nullptr;
    QAction *m_stepBackAction = nullptr;
    TimelineBar *m_timelineBar = nullptr;
    QAction *m_resetAction = nullptr;
    QAction *m_tiltAction = nullptr;
    QAction *m_collisionsAction = nullptr;
    QAction *m_accuracyAction = nullptr;
    QAction *m_captureAction = nullptr;
    QAction *m_recordAction = nullptr;
    QList<QAction *> m_steerActions;
    QAction *m_revertAction = nullptr;
    QMenu *m_recentMenu = nullptr;
    QList<QAction *> m_recentActions;  // File › Open Recent's entries, most recent first
    QAction *m_clearRecentAction = nullptr;
    QActionGroup *m_autosaveGroup = nullptr;
    QMenu *m_fileMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_simulationMenu = nullptr;
    QMenu *m_viewMenu = nullptr;

    // status bar fields
    QLabel *m_warningLabel = nullptr;
    QLabel *m_steerLabel = nullptr;
    QLabel *m_timeLabel = nullptr;
    QLabel *m_rateLabel = nullptr;
    QLabel *m_stepsLabel = nullptr;
    QLabel *m_energyLabel = nullptr;
    QLabel *m_errorLabel = nullptr;
    QLabel *m_driftLabel = nullptr;
};

}  // namespace ui
