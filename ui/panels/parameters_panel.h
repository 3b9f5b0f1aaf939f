#pragma once
// ParametersPanel: the dock that tunes the scene's parameters live. Its rows are generated from
// the parameter table (core/model/parameters.h), one ParameterRow per binding below, never written out
// widget by widget; the integrator and the contact solver are combo boxes of core::kIntegrators and
// core::kContactSolvers, and the static friction row follows the friction row until it is set (a
// check box lets it follow again). An accepted change becomes an undo command on the document,
// which the main window forwards to the worker; a refused one is reported here and goes nowhere.

#include <QString>
#include <QWidget>
#include <vector>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;

namespace core {
struct Model;
struct Settings;
struct StabilityLimit;
}

namespace ui {

class ParameterRow;
class SceneDocument;
enum class SceneChange;

class ParametersPanel : public QWidget {
    Q_OBJECT

public:
    explicit ParametersPanel(SceneDocument &document, QWidget *parent = nullptr);

    // the row of a binding key: "timeStep", "substeps", "gravity.x", "stiffness", ...
    ParameterRow *row(const QString &key) const;
    // the integrators in core::kIntegrators order, named as in scene files
    QComboBox *integratorBox() const { return m_integrator; }
    QCheckBox *planeCollisionsBox() const { return m_planeCollisions; }
    QCheckBox *particleCollisionsBox() const { return m_particleCollisions; }
    QCheckBox *triangleCollisionsBox() const { return m_triangleCollisions; }
    QCheckBox *selfCollisionBox() const { return m_selfCollision; }
    QCheckBox *autoSubstepsBox() const { return m_autoSubsteps; }
    // the contact solvers in core::kContactSolvers order: "Iterative", "Handout"
    QComboBox *contactSolverBox() const { return m_contactSolver; }
    // checked while the static friction is unset and follows the friction row
    QCheckBox *staticFollowsBox() const { return m_staticFollows; }
    // "Stable sub-step ≤ 3.1 ms; each is 10 ms, 3.2× over: ...", coloured by how near the limit
    QLabel *stabilityLabel() const { return m_stabilityNote; }

    // shows the explicit integrators' limit against the sub-step the model runs with (its
    // substeps raised by auto substeps): amber near it, red past it
    // the stability note, and the solver's last sub-step (core::lastSolveSummary) when there is one
    void showStability(const core::StabilityLimit &limit, const core::Model &model, const QString &solver = QString());

    // the latest refusal, empty when the latest change was accepted
    QString message() const;

signals:
    // a typed value was refused: the message names the parameter, the reason and the value
    void valueRefused(const QString &message);

private:
    void refresh();
    void showRefusal(const QString &message);
    void edit(std::size_t binding, double value);
    void setCollisions(bool planes, bool particles);
    // a settings change from one of the switches, undoable
    void pushSettings(const core::Settings &settings, const QString &text);
    void setIntegrator(int index);
    void setAutoSubsteps(bool on);
    void setContactSolver(int index);
    void setStaticFollows(bool follows);

    SceneDocument &m_document;
    std::vector<ParameterRow *> m_rows;  // one per binding, in the bindings' order
    QGroupBox *m_springsGroup = nullptr;
    QLabel *m_springsNote = nullptr;
    QComboBox *m_integrator = nullptr;
    QCheckBox *m_planeCollisions = nullptr;
    QCheckBox *m_spin = nullptr;
    QCheckBox *m_particleCollisions = nullptr;
    QCheckBox *m_triangleCollisions = nullptr;
    QCheckBox *m_selfCollision = nullptr;
    QCheckBox *m_autoSubsteps = nullptr;
    QComboBox *m_contactSolver = nullptr;
    QCheckBox *m_staticFollows = nullptr;
    QLabel *m_stabilityNote = nullptr;
    QLabel *m_message = nullptr;
};

}  // namespace ui
