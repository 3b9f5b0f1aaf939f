#pragma once
// InspectorPlanes: the inspector's section for the scene's planes, shown whatever is selected. It
// lists every plane (normal and offset), adds a ground plane, removes the chosen one and edits the
// chosen one's normal and offset. A zero normal is refused; any other normal is made unit length
// when applied, as the file loader does. Each change is one undo command (InspectorEdits).

#include <QGroupBox>
#include <array>

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

    InspectorEdits *m_edits;
    QListWidget *m_list = nullptr;
    QPushButton *m_add = nullptr;
    QPushButton *m_remove = nullptr;
    std::array<InspectorSpinBox *, 3> m_normal{};
    InspectorSpinBox *m_offset = nullptr;
};

}  // namespace ui
