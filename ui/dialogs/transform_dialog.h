#pragma once
// TransformDialog: Edit › Transform Selection…. Moves, turns and scales the selected particles (and
// the ends of selected springs) by typed amounts: a move in metres, a turn in degrees about x, y,
// z or a typed axis, and a factor, uniform or per axis, the turn and the factor about the
// selection's centroid (ui::SelectionTransform, scene_edits.h, does the maths). It changes the
// scene's initial conditions, pinned particles too, and their velocities turn with them; a
// running scene takes the change as it takes any edit. Each Apply is one undo step named after
// what it did. A value that cannot be used (not a number, a factor of 0, an axis of zero length)
// is named under the fields and Apply is off; a result outside the scene file's ranges is named
// when applied, and nothing changes. The dialog is not modal, so that the selection can change
// while it is open: it follows it, and says where the centroid is.

#include "ui/document/scene_edits.h"

#include <QDialog>
#include <QString>
#include <array>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;

namespace ui {

class EditTools;
class SceneDocument;
class ValueSpinBox;

class TransformDialog : public QDialog {
    Q_OBJECT

public:
    TransformDialog(SceneDocument *document, EditTools *tools, QWidget *parent = nullptr);

    // the rotation axis box's choices, in its order
    enum class Axis { X, Y, Z, Typed };

    // what the fields say, or nullopt while one cannot be used (problemText() says why)
    std::optional<SelectionTransform> transform() const;
    // why the fields cannot be applied, or why the last Apply was refused; empty when neither
    QString problemText() const;
    // where the turn and the factor are about: "About the centroid of 4 particles: (1.25, 0.5, -0.25) m"
    QString pivotText() const;

    QPushButton *applyButton() const { return m_apply; }
    QPushButton *okButton() const { return m_ok; }
    QComboBox *axisBox() const { return m_axisBox; }
    QCheckBox *uniformBox() const { return m_uniform; }
    QCheckBox *restLengthsBox() const { return m_restLengths; }

    // applies the fields to the selection as one undo step; false, with the reason in
    // problemText(), when the fields or the result cannot be used (nothing changes then). True
    // with no step when the fields change nothing.
    bool apply();

signals:
    // a change was applied: its undo text, for the status bar
    void applied(const QString &text);

private:
    // the fields' problem, checked again as any value or the selection changes
    void check();
    void refreshPivot();
    void axisChosen();
    void uniformToggled(bool uniform);

    SceneDocument *m_document;
    EditTools *m_tools;
    std::array<ValueSpinBox *, 3> m_move{};
    ValueSpinBox *m_angle = nullptr;
    QComboBox *m_axisBox = nullptr;
    std::array<ValueSpinBox *, 3> m_axis{};
    std::array<ValueSpinBox *, 3> m_scale{};
    QCheckBox *m_uniform = nullptr;
    QCheckBox *m_restLengths = nullptr;
    QLabel *m_pivot = nullptr;
    QLabel *m_problem = nullptr;
    QPushButton *m_apply = nullptr;
    QPushButton *m_ok = nullptr;
};

// the undo step's text: "Transform 4 particles: move by (1, 0, 0) m, rotate 90° about y, scale
// ×2 with rest lengths"
QString transformText(std::size_t particles, const SelectionTransform &transform);

}  // namespace ui
