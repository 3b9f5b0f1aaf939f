#pragma once
// AccuracyDialog: Simulation › Accuracy. The user types the local position error per step the run
// should keep under; the main window asks the worker to run the accuracy planner
// (core/integrators/accuracy_planner.h) on its state and, with Plan and Apply, applies the pick as one
// undoable edit; Preview shows the same plan and leaves the scene alone. The dialog then says
// what was picked and why, above the table of every integrator it was chosen from. adaptive-rk45
// is not planned (it chooses its own steps), so its row offers it at the tolerance typed: Use
// Adaptive RK45 sets both, as one undoable edit. Modeless, so the run goes on while it is open.

#include <QDialog>
#include <QString>
#include <optional>

class QLabel;
class QPushButton;
class QTableWidget;

namespace core {
struct AccuracyPlan;
}

namespace ui {

class ValueSpinBox;

class AccuracyDialog : public QDialog {
    Q_OBJECT

public:
    explicit AccuracyDialog(QWidget *parent = nullptr);

    ValueSpinBox *toleranceBox() const { return m_tolerance; }
    QPushButton *planButton() const { return m_plan; }
    QPushButton *previewButton() const { return m_preview; }
    QPushButton *adaptiveButton() const { return m_adaptive; }
    QTableWidget *table() const { return m_table; }
    // what was picked and why, or why a tolerance was refused
    QString summary() const;

    // while a plan is being made the button waits for it
    void setPlanning(bool planning);
    // a line above the table, which stays as it is
    void showSummary(const QString &summary);
    // a plan came back: its summary, and a row per integrator
    void showPlan(const core::AccuracyPlan &plan, const QString &summary);

signals:
    // the user asked for a plan with an accepted tolerance, m per step; apply: its pick is to
    // be applied, else only shown
    void planRequested(double tolerance, bool apply);
    // the user asked for adaptive-rk45 at an accepted tolerance, m per step
    void adaptiveRequested(double tolerance);

private:
    // the tolerance typed, or nullopt (and why, in the summary) when it is refused
    std::optional<double> acceptedTolerance();
    void addAdaptiveRow();

    ValueSpinBox *m_tolerance = nullptr;
    QPushButton *m_plan = nullptr;
    QPushButton *m_preview = nullptr;
    QPushButton *m_adaptive = nullptr;
    QLabel *m_summary = nullptr;
    QTableWidget *m_table = nullptr;
};

}  // namespace ui
