#pragma once
// CameraActions: the View menu's camera (the Top, Front and Side views, the default view, the
// orthographic projection and following the selection) and the window's framing of new content:
// a new scene is framed once the worker shows it, and what Generate added is framed with the rest
// only if some of it is out of view, so that small edits never move the camera. Orthographic is
// kept in the settings as it changes, as the other View toggles are.

#include "ui/viewport/camera.h"

#include <QList>
#include <QObject>

#include <cstdint>
#include <vector>

class QAction;

namespace ui {

struct SimulationFrame;
class Viewport;

class CameraActions : public QObject {
    Q_OBJECT

public:
    // reads the settings and sets the viewport's projection from them
    CameraActions(Viewport *viewport, QObject *parent = nullptr);

    // Top, Front, Side, Default View, a separator, Orthographic, Follow Selection
    QList<QAction *> actions() const { return m_actions; }
    QAction *orthographicAction() const { return m_orthographic; }
    QAction *followAction() const { return m_follow; }

    // frames the whole scene in the first frame to show message `sequence` (a new scene)
    void frameAllWhenShown(std::uint64_t sequence);
    // likewise, but only if some of these particles are not in view then (new content)
    void frameWhenShownIfHidden(std::uint64_t sequence, std::vector<int> particles);
    // the window calls it with each frame, once the viewport shows it
    void frameShown(const SimulationFrame &frame);

private:
    Viewport *m_viewport;
    QList<QAction *> m_actions;
    QAction *m_orthographic = nullptr;
    QAction *m_follow = nullptr;

    // the framing awaited: after this message (0: none), all or only if these are out of view
    std::uint64_t m_frameAfter = 0;
    bool m_frameAll = false;
    std::vector<int> m_newParticles;
};

}  // namespace ui
