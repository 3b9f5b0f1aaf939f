#pragma once
// EditTools: the editing tools of the viewport (Select, Add particle, Pin, Spring, Drag, Measure), the
// selection they work on, and the Edit actions on it (Delete, Duplicate, Copy, Paste, Select All,
// Pin). It filters the viewport's left-button and hover events, so the viewport stays a view; the
// camera keeps the buttons the tools leave alone. Every change of the scene is one SceneCommand
// on the document's undo stack (a drag is one, merged as it goes), so it reaches the running
// worker like any other edit and undoes exactly. While running, the Drag tool holds the particle
// with the worker's mouse spring instead, which changes the run, not the scene. The Spring tool
// joins the particle pressed on to the one clicked or released on next, with a rubber band line
// from the first to the cursor meanwhile. The Measure tool picks two particles the same way and
// keeps a line between them labelled with their distance, drawn from the positions the view shows,
// so it follows them while the run plays; the pair becomes the selection, for the inspector.

#include "ui/document/scene_edits.h"

#include "core/model/scene.h"

#include <QObject>
#include <QLineF>
#include <QPoint>
#include <QString>
#include <QVector3D>

#include <memory>
#include <optional>
#include <vector>

class QAction;
class QActionGroup;
class QMouseEvent;
class QWheelEvent;
class QRubberBand;

namespace ui {

class GuideLine;
class SceneDocument;
class SimulationController;
class Viewport;

enum class SceneChange;

enum class Tool { Select, AddParticle, Pin, Spring, Drag, Measure };

// what new particles and springs get
struct ItemDefaults {
    double mass = 1.0;         // kg
    double radius = 0.05;      // m
    double stiffness = 100.0;  // N/m
    double damping = 0.5;      // N·s/m
    bool snap = false;         // place new particles on the grid
    double gridStep = 0.1;     // m
};

class EditTools : public QObject {
    Q_OBJECT

public:
    // the spin one wheel notch gives the particle the Drag tool holds, turns per second
    static constexpr double kFlickTurnsPerNotch = 1.0;

    EditTools(Viewport *viewport, SceneDocument *document, SimulationController *controller, QObject *parent = nullptr);

    Tool tool() const { return m_tool; }
    void setTool(Tool tool);
    // one checkable action per tool, exclusive, with its shortcut (1 to 6)
    const std::vector<QAction *> &toolActions() const { return m_toolActions; }
    QAction *toolAction(Tool tool) const;

    // the Edit actions on the selection, with their shortcuts
    QAction *deleteAction() const { return m_delete; }
    QAction *duplicateAction() const { return m_duplicate; }
    QAction *copyAction() const { return m_copy; }
    QAction *pasteAction() const { return m_paste; }
    QAction *selectAllAction() const { return m_selectAll; }
    QAction *clearSelectionAction() const { return m_clearSelection; }
    QAction *pinAction() const { return m_pin; }
    std::vector<QAction *> editActions() const;

    const Selection &selection() const { return m_selection; }
    void setSelection(Selection selection);

    ItemDefaults &defaults() { return m_defaults; }
    const ItemDefaults &defaults() const { return m_defaults; }

    // the Spring tool's first particle, -1 while none is chosen
    int springStart() const { return m_tool == Tool::Spring ? m_bandStart : -1; }
    // the Spring or Measure tool's rubber band from it to the cursor (shown while it is chosen)
    const GuideLine *springBand() const { return m_band; }

    // the Measure tool: the first particle, -1 while none is chosen; the pair measured, from the
    // first to the second, and the vector between them as the view shows them now (the run's
    // latest snapshot, else the scene's initial positions); nullopt while no pair is measured
    int measureStart() const { return m_tool == Tool::Measure ? m_bandStart : -1; }
    struct Measurement {
        int from = -1;
        int to = -1;
        Eigen::Vector3d delta = Eigen::Vector3d::Zero();  // m, to - from
    };
    std::optional<Measurement> measurement() const;
    // the line between the pair with their distance, following them (shown while measured)
    const GuideLine *measureLine() const { return m_measureLine; }
    // the particle the Drag tool holds with the mouse spring, -1 for none
    int grabbed() const { return m_grabbed; }

    // where a click at this pixel would place a particle: on the ground plane y = 0, or with one
    // particle selected on the plane through it facing the view; snapped when snapping is on
    std::optional<Eigen::Vector3d> placementAt(const QPointF &pixel) const;

    void deleteSelection();
    void duplicateSelection();
    void copySelection();
    void paste();
    void selectAll();
    void clearSelection();
    void togglePinSelection();

signals:
    void selectionChanged();
    void toolChanged(ui::Tool tool);
    // a line for the status bar: what the tool did or waits for
    void message(const QString &text);
    // an edit was refused (adding particles past kMaxSceneParticles): why, for the warning line
    void refused(const QString &text);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void createActions();
    bool press(QMouseEvent *event);
    bool move(QMouseEvent *event);
    bool release(QMouseEvent *event);
    // the wheel while the Drag tool holds a particle (running): spins it about the line of sight,
    // kFlickTurnsPerNotch a notch, so that letting go flicks it with spin
    bool spinGrabbed(QWheelEvent *event);
    void hover(const QPointF &pixel);
    // the Spring and Measure tools: the rubber band from their first particle to the pixel (to the
    // centre of a particle there, labelled with its distance while measuring), hidden when none is
    // chosen; joining the first particle to another, or measuring from it to another
    void followBand(const QPointF &pixel);
    void setBandStart(int particle);
    void joinSpring(int particle);
    void measureTo(int particle);
    void setMeasured(int from, int to);
    // the measured pair's line on screen now, with their distance
    std::optional<QLineF> lineBetween(int a, int b) const;
    void sceneChanged(ui::SceneChange change);

    // pushes one command that replaces the scene with an edited copy
    void apply(const QString &text, const std::function<void(core::SceneDesc &)> &edit, const QString &mergeKey = {});
    // a point on the plane through `through` facing the view, under the pixel
    std::optional<Eigen::Vector3d> onViewPlane(const QPointF &pixel, const Eigen::Vector3d &through) const;
    // where particle i is drawn now (the run's position, not the scene's initial one)
    Eigen::Vector3d shownPosition(int i) const;
    // the particle or spring under the pixel, as an index into the document's scene (-1: none)
    int particleUnder(const QPointF &pixel) const;
    int springUnder(const QPointF &pixel) const;
    // false, with the reason emitted, when `added` more particles would take the scene past
    // kMaxSceneParticles; notDone names the edit: "Not duplicated"
    bool roomFor(std::size_t added, const QString &notDone);
    // how far a pasted or duplicated copy is moved so that it sits beside the original
    Eigen::Vector3d copyOffset(const Fragment &fragment) const;

    Viewport *m_viewport;
    SceneDocument *m_document;
    SimulationController *m_controller;
    Tool m_tool = Tool::Select;
    Selection m_selection;
    ItemDefaults m_defaults;
    Fragment m_clipboard;

    std::vector<QAction *> m_toolActions;
    QActionGroup *m_toolGroup = nullptr;
    QAction *m_delete = nullptr;
    QAction *m_duplicate = nullptr;
    QAction *m_copy = nullptr;
    QAction *m_paste = nullptr;
    QAction *m_selectAll = nullptr;
    QAction *m_clearSelection = nullptr;
    QAction *m_pin = nullptr;

    // gestures under way
    enum class Gesture { None, RubberBand, Move, Grab, Band };
    Gesture m_gesture = Gesture::None;
    QPointF m_pressPixel;
    bool m_addToSelection = false;
    QRubberBand *m_rubberBand = nullptr;
    GuideLine *m_band = nullptr;
    int m_bandStart = -1;
    GuideLine *m_measureLine = nullptr;
    int m_measuredFrom = -1;
    int m_measuredTo = -1;
    int m_particleCount = 0;  // the scene's, as last seen
    int m_grabbed = -1;
    double m_grabSpin = 0.0;  // turns/s the wheel gave the held particle, counter-clockwise as seen
    Eigen::Vector3d m_dragPlanePoint = Eigen::Vector3d::Zero();  // the plane the drag moves in
    Eigen::Vector3d m_dragStart = Eigen::Vector3d::Zero();       // where the cursor met it at the press
    std::vector<int> m_moving;                                    // particles a paused drag moves
    std::vector<Eigen::Vector3d> m_movingFrom;                    // where they were drawn at the press
    int m_moveSerial = 0;                                         // makes each drag its own undo step
};

}  // namespace ui
