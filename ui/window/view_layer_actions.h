#pragma once
// ViewLayerActions: the View menu's toggles for what a cloth shows (Viewport's ViewLayers): its
// sheet, and the spheres and springs that the sheet already shows. Checked or not, they are kept
// in the settings as they change, so that the next session draws the same way.

#include "ui/viewport/viewport.h"

#include <QList>
#include <QObject>

class QAction;

namespace ui {

class ViewLayerActions : public QObject {
    Q_OBJECT

public:
    // reads the settings, sets the viewport's layers from them and follows the actions after
    ViewLayerActions(Viewport *viewport, QObject *parent = nullptr);

    // Surface, Spheres on Surface, Springs on Surface
    QList<QAction *> actions() const { return {m_surface, m_spheres, m_springs}; }

private:
    void apply();

    Viewport *m_viewport;
    QAction *m_surface = nullptr;
    QAction *m_spheres = nullptr;
    QAction *m_springs = nullptr;
};

}  // namespace ui
