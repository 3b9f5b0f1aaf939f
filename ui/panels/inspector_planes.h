#pragma once
// InspectorPlanes: the inspector's section for the scene's planes, shown whatever is selected. It
// lists every plane, adds a ground plane, removes the chosen one and edits the chosen one: its
// normal and offset, whether it is two-sided, its own friction (or the scene's), and its size as a
// rectangle with the rectangle's centre and width axis. A zero normal is refused; any other normal
// is made unit length when applied, as the file loader does. A size is both sides or neither, so
// typing a side on an unbounded plane makes a square of it, and typing 0 makes the plane whole
// again. Each change is one undo command (InspectorEdits), named after what it did.

#include <QGroupBox>
#include <array>
#include <vector>

class QCheckBox;
class QFormLayout;
class QListWidget;
class QPushButton;

namespace ui {

class InspectorEdits;
class InspectorSpinBox;

class InspectorPlanes : public QGroupBox {
    Q_OBJECT

public:
    explicit InspectorPlanes(InspectorEdits *edits, QWidget *parent = nullptr);
    ~InspectorPlanes() override;

    QListWidget *list() const { return m_list; }
    QPushButton *addButton() const { return m_add; }
    QPushButton *removeButton() const { return m_remove; }
    // axis 0, 1, 2: the chosen plane's normal x, y, z
    InspectorSpinBox *normalField(int axis) const { return m_normal[std::size_t(axis)]; }
    InspectorSpinBox *offsetField() const { return m_offset; }
    QCheckBox *twoSidedBox() const { return m_twoSided; }
    // checked: the plane has friction of its own, in frictionField(); else it shows the scene's
    QCheckBox *ownFrictionBox() const { return m_ownFriction; }
    InspectorSpinBox *frictionField() const { return m_friction; }
    // side 0: the width, 1: the height (m; 0 is the whole plane)
    InspectorSpinBox *sizeField(int side) const { return m_size[std::size_t(side)]; }
    // axis 0, 1, 2: the rectangle's centre and width axis, x, y, z; shown for a rectangle only
    InspectorSpinBox *centreField(int axis) const { return m_centre[std::size_t(axis)]; }
    InspectorSpinBox *axisField(int axis) const { return m_axis[std::size_t(axis)]; }

    // the chosen plane, -1 for none
    int currentPlane() const;
    void setCurrentPlane(int plane);

    // shows the scene's planes without emitting an edit; keeps the chosen plane where it can
    void refresh();

private:
    void showChosen();
    void addPlane();
    void removePlane();
    void editNormal(int axis, double value, bool step);
    void editOffset(double value, bool step);
    void setTwoSided(bool on);
    void setOwnFriction(bool own);
    void editFriction(double value, bool step);
    void editSize(int side, double value, bool step);
    void editPoint(bool axisVector, int axis, double value, bool step);
    // every field of this section
    std::vector<InspectorSpinBox *> fields() const;

    InspectorEdits *m_edits;
    QListWidget *m_list = nullptr;
    QPushButton *m_add = nullptr;
    QPushButton *m_remove = nullptr;
    QFormLayout *m_form = nullptr;
    std::array<InspectorSpinBox *, 3> m_normal{};
    InspectorSpinBox *m_offset = nullptr;
    QCheckBox *m_twoSided = nullptr;
    QCheckBox *m_ownFriction = nullptr;
    InspectorSpinBox *m_friction = nullptr;
    std::array<InspectorSpinBox *, 2> m_size{};
    std::array<InspectorSpinBox *, 3> m_centre{};
    std::array<InspectorSpinBox *, 3> m_axis{};
    QWidget *m_centreRow = nullptr;
    QWidget *m_axisRow = nullptr;
};

}  // namespace ui
