#pragma once
// InspectorPanel: the dock that shows and edits what is selected. Particles show mass, radius,
// pinned, position and velocity; springs show stiffness, damping, rest length and the particles
// they join; the scene's planes are listed below (InspectorPlanes). With several items selected a
// field edits all of them; where their values differ it shows "mixed" (a partly checked box for
// pinned). Positions and velocities are the scene's initial conditions, not the running state.
// Every change is one undo command on the document (InspectorEdits); a value the parameter table
// does not allow is refused with a message and never reaches the scene. The panel follows the
// document and the selection: undo, redo or another tool's edit shows at once, without an edit.

#include <QString>
#include <QWidget>
#include <vector>

class QCheckBox;
class QGroupBox;
class QLabel;

namespace ui {

class EditTools;
class InspectorEdits;
class InspectorPlanes;
class InspectorSpinBox;
class SceneDocument;

class InspectorPanel : public QWidget {
    Q_OBJECT

public:
    InspectorPanel(SceneDocument *document, EditTools *tools, QWidget *parent = nullptr);
    ~InspectorPanel() override;

    // what is selected: "3 particles, 1 spring", or "Nothing selected"
    QLabel *titleLabel() const { return m_title; }
    // a particle field by key: "mass", "radius", "position.x" .. "position.z", "velocity.x" .. "velocity.z"
    InspectorSpinBox *particleField(const QString &key) const;
    // a spring field by key: "stiffness", "damping", "restLength", "breakStrain"
    InspectorSpinBox *springField(const QString &key) const;
    QCheckBox *pinnedBox() const { return m_pinned; }
    // which particles the selected springs join, read-only
    QLabel *springEndsLabel() const { return m_springEnds; }
    QGroupBox *particlesGroup() const { return m_particlesGroup; }
    QGroupBox *springsGroup() const { return m_springsGroup; }
    InspectorPlanes *planes() const { return m_planes; }

    // the latest refusal, empty when the latest change was accepted
    QString message() const;

signals:
    // a typed value was refused: the message names the field, the reason and the value
    void valueRefused(const QString &message);

private:
    void refresh();
    void showRefusal(const QString &message);
    void editParticles(std::size_t field, double value, bool step);
    void editSprings(std::size_t field, double value, bool step);
    void pinSelection();

    SceneDocument *m_document;
    EditTools *m_tools;
    InspectorEdits *m_edits = nullptr;
    QLabel *m_title = nullptr;
    QGroupBox *m_particlesGroup = nullptr;
    QGroupBox *m_springsGroup = nullptr;
    std::vector<InspectorSpinBox *> m_particleFields;  // in kParticleFields order
    std::vector<InspectorSpinBox *> m_springFields;    // in kSpringFields order
    QCheckBox *m_pinned = nullptr;
    QLabel *m_springEnds = nullptr;
    InspectorPlanes *m_planes = nullptr;
    QLabel *m_message = nullptr;
};

}  // namespace ui
