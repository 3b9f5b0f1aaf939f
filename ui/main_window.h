#pragma once
// MainWindow: the editor. It ties the scene document (the UI thread's SceneDesc and its undo
// stack) to the simulation controller (the worker thread) and to the views: the 3D viewport, the
// parameters dock and the status bar. A document change becomes a scene edit for the worker; a
// frame from the worker goes to the viewport and the status bar.

#include "steering.h"

#include <QMainWindow>
#include <QString>
#include <QStringList>
#include <cstdint>

class QAction;
class QLabel;
class QMenu;
class QDockWidget;

namespace core {
struct AccuracyPlan;
}

namespace ui {

class AccuracyDialog;
class ParametersPanel;
class SceneDocument;
class SimulationController;
class Viewport;
enum class SceneChange;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    // the example opened when no scene is given
    static constexpr const char *kDefaultExample = "springs";

    // opens on the default example
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    // opens a scene file; on failure the current scene stays and error says why
    bool openScene(const QString &path, QString *error = nullptr);
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

    SceneDocument *document() const { return m_document; }
    SimulationController *controller() const { return m_controller; }
    Viewport *viewport() const { return m_viewport; }
    ParametersPanel *parametersPanel() const { return m_parameters; }
    // Simulation › Accuracy's dialog; null until first opened
    AccuracyDialog *accuracyDialog() const { return m_accuracy; }
    const Steering &steering() const { return m_steering; }

    // the status bar's fields, for the tests
    QString statusTime() const;
    QString statusRate() const;
    QString statusWarning() const;
    QString statusError() const;
    QString statusDrift() const;

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void createActions();
    void createMenus();
    void createDocks();
    void createStatusBar();
    void readSettings();
    void writeSettings() const;

    void sceneChanged(SceneChange change);
    void frameChanged();
    void runningChanged(bool running);
    void showWarning(const QString &message);
    void updateTitle();
    void updateSteerActions();

    bool maybeSave();
    void openFromDialog();
    void chooseScreenshotDirectory();
    void showHelp();
    void showAbout();
    void toggleCollisions(bool on);
    void showAccuracy();
    void planAccuracy(double tolerance);
    void applyPlan(const core::AccuracyPlan &plan);
    void steer(int turn, int change);

    SceneDocument *m_document = nullptr;
    SimulationController *m_controller = nullptr;
    Viewport *m_viewport = nullptr;
    ParametersPanel *m_parameters = nullptr;
    QDockWidget *m_parametersDock = nullptr;
    AccuracyDialog *m_accuracy = nullptr;
    std::uint64_t m_accuracyRequest = 0;  // the plan awaited from the worker; 0: none
    QString m_screenshotDirectory;
    Steering m_steering;
    std::uint64_t m_frameAllAfter = 0;  // frame the view once the worker has applied this edit

    // actions that change with the state
    QAction *m_playAction = nullptr;
    QAction *m_stepAction = nullptr;
    QAction *m_resetAction = nullptr;
    QAction *m_tiltAction = nullptr;
    QAction *m_collisionsAction = nullptr;
    QAction *m_accuracyAction = nullptr;
    QList<QAction *> m_steerActions;
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
