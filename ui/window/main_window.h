#pragma once
// MainWindow: the editor. It ties the scene document (the UI thread's SceneDesc and its undo
// stack) to the simulation controller (the worker thread) and to the views: the 3D viewport, the
// parameters dock, the plots dock and the status bar. The document feeds the worker, and a frame
// from the worker goes to the viewport, the plots and the status bar. The window holds the menus
// and the wiring; what touches the document's files (New, Open, Save, Revert, recent files,
// autosave and recovery) is DocumentFiles's, and File › Export is the Exporter's.

#include "ui/dialogs/prompts.h"
#include "ui/simulation/frame_pacer.h"
#include "ui/simulation/steering.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QString>
#include <cstdint>

class QAction;
class QComboBox;
class QLabel;
class QMenu;
class QDockWidget;
class QToolBar;
class QSettings;
class QUndoView;

namespace core {
struct AccuracyPlan;
struct SceneDesc;
}

namespace ui {

class StatusBar;

class AccuracyDialog;
class CameraActions;
class DocumentFiles;
class EditTools;
class GenerateDialog;
class ImportMeshDialog;
class TransformDialog;
class Exporter;
class InspectorPanel;
class ParametersPanel;
class PlotsWidget;
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

    // File's actions on the document's files, the recent files and autosave
    DocumentFiles *files() const { return m_files; }

    // F2: writes the viewport's image as a PNG into the screenshot folder; returns its path, or
    // an empty string and the reason
    QString saveScreenshot(QString *error = nullptr);
    QString screenshotDirectory() const { return m_screenshotDirectory; }
    void setScreenshotDirectory(const QString &directory);

    // File › Export (ui/export/exporter.h)
    Exporter *exporter() const { return m_exporter; }

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
    // File › Import Mesh's dialog; null until first opened (main_window_import.cpp)
    ImportMeshDialog *importMeshDialog() const { return m_importMesh; }
    // Edit › Transform Selection's dialog; null until first opened (main_window_editing.cpp)
    TransformDialog *transformDialog() const { return m_transform; }

    // the status bar's fields, for the tests
    QString statusTime() const;
    QString statusRate() const;
    QString statusSteps() const;
    QString statusFrames() const;
    QString statusWarning() const;
    QString statusError() const;
    QString statusDrift() const;

protected:
    void closeEvent(QCloseEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dragMoveEvent(QDragMoveEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    void createActions();
    void createSpeedActions();
    // the New Items toolbar on the row above's end where it fits, else on a row of its own
    void fitToolBars();
    // plays at speed (playback_speed.h): the worker, the menu and the toolbar's box
    void setSpeed(double speed);
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
    void createStatusBar();
    // the pace of the frames while running, and the frames/s shown (main_window_pacing.cpp)
    void createFramePacing();
    void frameArrived();
    void frameDrawn();
    void startFramePacingOver();
    void sayUndoOrRedo(int index);
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
    void clearWarning();
    void updateTitle();
    void updateSteerActions();

    // the File menu and drops (main_window_files.cpp)
    void updateFileActions();

    void applyCapturedState(const CapturedState &captured);
    void saveSessionRecording(const SessionRecording &recording);
    void exportPlot(PlotExport format);

    void chooseScreenshotDirectory();
    void showHelp();
    void showAbout();
    void toggleCollisions(bool on);
    void showAccuracy();
    void planAccuracy(double tolerance, bool apply);
    void applyPlan(const core::AccuracyPlan &plan);
    void useAdaptive(double tolerance);
    void steer(const Steering::Change &change);
    // the cue strikes the steerable particle (S): along the push's direction, at the cue's speed and height
    void strikeCue();
    void showGenerate();
    void addGenerated();
    void showImportMesh();
    void addImportedMesh();
    void showTransform();

    SceneDocument *m_document = nullptr;
    SimulationController *m_controller = nullptr;
    Prompts m_prompts{this};
    DocumentFiles *m_files = nullptr;
    std::uint64_t m_captureRequest = 0;    // the captured state awaited from the worker; 0: none
    std::uint64_t m_recordingRequest = 0;  // the recording awaited from the worker; 0: none
    bool m_pairSpeedWarned = false;      // the latest frame's particles were past the pair speed limit
    int m_undoIndex = 0;                 // the undo stack's index and count as last seen, to tell an
    int m_undoCount = 0;                 // undo or redo (same count) from a new edit (count changed)
    QString m_pairSpeedWarning;          // what was said about it
    Viewport *m_viewport = nullptr;
    EditTools *m_tools = nullptr;
    QToolBar *m_toolBar = nullptr;
    QToolBar *m_itemsToolBar = nullptr;
    InspectorPanel *m_inspector = nullptr;
    ParametersPanel *m_parameters = nullptr;
    QDockWidget *m_parametersDock = nullptr;
    QDockWidget *m_undoDock = nullptr;
    QUndoView *m_undoView = nullptr;
    PlotsWidget *m_plots = nullptr;
    QDockWidget *m_plotsDock = nullptr;
    AccuracyDialog *m_accuracy = nullptr;
    GenerateDialog *m_generate = nullptr;
    ImportMeshDialog *m_importMesh = nullptr;
    TransformDialog *m_transform = nullptr;
    std::uint64_t m_accuracyRequest = 0;  // the plan awaited from the worker; 0: none
    bool m_applyPlan = true;               // whether that plan's pick is applied or only shown
    QString m_screenshotDirectory;
    Exporter *m_exporter = nullptr;
    Steering m_steering;
    CameraActions *m_cameraActions = nullptr;  // View's camera, and framing what is new

    // actions that change with the state
    QAction *m_playAction = nullptr;
    QAction *m_stepAction = nullptr;
    QAction *m_stepBackAction = nullptr;
    TimelineBar *m_timelineBar = nullptr;
    QAction *m_resetAction = nullptr;
    QAction *m_kickAction = nullptr;
    QAction *m_collisionsAction = nullptr;
    QAction *m_accuracyAction = nullptr;
    QAction *m_captureAction = nullptr;
    QAction *m_recordAction = nullptr;
    QList<QAction *> m_steerActions;
    // the playback speeds (playback_speed.h): checkable, one checked, in the Simulation menu's
    // Speed submenu and the toolbar's speed box, which follow each other
    QList<QAction *> m_speedActions;
    QComboBox *m_speedBox = nullptr;
    QAction *m_revertAction = nullptr;
    QMenu *m_fileMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_simulationMenu = nullptr;
    QMenu *m_viewMenu = nullptr;

    // status bar fields
    StatusBar *m_statusBar = nullptr;
    QLabel *m_steerLabel = nullptr;
    QLabel *m_timeLabel = nullptr;
    QLabel *m_rateLabel = nullptr;
    QLabel *m_stepsLabel = nullptr;
    QLabel *m_framesLabel = nullptr;
    QLabel *m_energyLabel = nullptr;
    QLabel *m_errorLabel = nullptr;
    QLabel *m_driftLabel = nullptr;

    // frames while running: their cost sets how often the worker sends one (FramePacer)
    FramePacer m_pacer;
    QElapsedTimer m_paceClock;
    double m_frameArrival = -1.0;  // s on m_paceClock: when the frame not yet drawn arrived; -1: none
};

}  // namespace ui
