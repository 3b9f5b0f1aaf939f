#pragma once
// AccuracyDialog: Simulation › Accuracy. The user types the local position error per step the run
// should keep under; the main window asks the worker to run the accuracy planner
// (core/accuracy_planner.h) on its state and applies the pick as one undoable edit. The dialog
// then says what was picked and why, above the table of every integrator it was chosen from.
// Modeless, so the run goes on while it is open.

#include <QDialog>
#include <QString>

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
    QTableWidget *table() const { return m_table; }
    // what was picked and why, or why a tolerance was refused
    QString summary() const;

    // while a plan is being made the button waits for it
    void setPlanning(bool planning);
    // a plan came back: its summary, and a row per integrator
    void showPlan(const core::AccuracyPlan &plan, const QString &summary);

signals:
    // the user asked for a plan with an accepted tolerance, m per step
    void planRequested(double tolerance);

private:
    void request();

    ValueSpinBox *m_tolerance = nullptr;
    QPushButton *m_plan = nullptr;
    QLabel *m_summary = nullptr;
    QTableWidget *m_table = nullptr;
};

}  // namespace ui
