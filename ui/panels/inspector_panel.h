#pragma once
// InspectorPanel: the dock that shows and edits what is selected. Particles show mass, radius,
// pinned, position and velocity; springs show stiffness, damping, rest length and the particles
// they join; the scene's planes are listed below (InspectorPlanes). With several items selected a
// field edits all of them; where their values differ it shows "mixed" (a partly checked box for
// pinned). The particles' position and velocity are shown twice: the running simulation's current
// ones (read-only, from the latest snapshot the window receives, at its frame rate; the panel never
// reads the worker's state) and the scene's initial conditions (editable; the run starts from them).
// With exactly two particles selected (as the Measure tool leaves them), their distance shows too,
// from the lower index to the higher, now and initially, with its x, y and z parts.
// Every change is one undo command on the document (InspectorEdits); a value the parameter table
// does not allow is refused with a message and never reaches the scene. The panel follows the
// document and the selection: undo, redo or another tool's edit shows at once, without an edit.

#include <QString>
#include <QWidget>
#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

class QCheckBox;
class QGroupBox;
class QLabel;

namespace core {
struct Snapshot;
}

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

    // the running simulation's current value of the selection, read-only, by key: "position.x" ..
    // "position.z", "velocity.x" .. "velocity.z"; "mixed" where the selected particles differ
    QLabel *currentField(const QString &key) const;
    // the two selected particles' distance: "current" (the run's, live) or "initial" (the scene's)
    QLabel *distanceField(const QString &key) const;
    QGroupBox *distanceGroup() const { return m_distanceGroup; }
    // the latest snapshot of the run: the current values follow it (null: none yet)
    void showSnapshot(std::shared_ptr<const core::Snapshot> snapshot);

    // the latest refusal, empty when the latest change was accepted
    QString message() const;

signals:
    // a typed value was refused: the message names the field, the reason and the value
    void valueRefused(const QString &message);

private:
    void refresh();
    void refreshCurrent();
    // the two selected particles, lower index first, when exactly two are
    std::optional<std::pair<std::size_t, std::size_t>> selectedPair() const;
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
    std::array<QLabel *, 9> m_currentFields{};  // position x, y, z, then velocity, then spin
    std::shared_ptr<const core::Snapshot> m_snapshot;
    QGroupBox *m_distanceGroup = nullptr;
    QLabel *m_currentDistance = nullptr;
    QLabel *m_initialDistance = nullptr;
    QCheckBox *m_pinned = nullptr;
    QLabel *m_springEnds = nullptr;
    InspectorPlanes *m_planes = nullptr;
    QLabel *m_message = nullptr;
};

}  // namespace ui
