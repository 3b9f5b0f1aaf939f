#include "view_layer_actions.h"

#include <QAction>
#include <QSettings>

namespace ui {

namespace {

const QString kSurfaceKey = QStringLiteral("view/surface");
const QString kSpheresKey = QStringLiteral("view/surfaceSpheres");
const QString kSpringsKey = QStringLiteral("view/surfaceSprings");

}  // namespace

ViewLayerActions::ViewLayerActions(Viewport *viewport, QObject *parent) : QObject(parent), m_viewport(viewport)
{
    // the defaults are ViewLayers' own: the sheet alone (a 200 × 200 cloth's spheres and 2-pixel
    // springs, a few pixels apart in the view, would cover it)
    const ViewLayers defaults;
    const QSettings settings;
    auto make = [this, &settings](const char *name, const QString &text, const QString &key, bool byDefault,
                                  const QString &tip) {
        auto *action = new QAction(text, this);
        action->setObjectName(QString::fromLatin1(name));
        action->setCheckable(true);
        action->setChecked(settings.value(key, byDefault).toBool());
        action->setStatusTip(tip);
        connect(action, &QAction::toggled, this, [this, key](bool on) {
            QSettings().setValue(key, on);
            apply();
        });
        return action;
    };
    m_surface = make("actionShowSurface", tr("&Surface"), kSurfaceKey, defaults.surface,
                     tr("Draw a cloth, or any spring mesh with triangles, as a shaded sheet; torn springs open holes"));
    m_spheres = make("actionSurfaceSpheres", tr("S&pheres on Surface"), kSpheresKey, defaults.surfaceSpheres,
                     tr("Also draw the spheres of the particles the sheet joins"));
    m_springs = make("actionSurfaceSprings", tr("Sp&rings on Surface"), kSpringsKey, defaults.surfaceSprings,
                     tr("Also draw the springs that lie in the sheet, coloured by their strain"));
    apply();
}

void ViewLayerActions::apply()
{
    // the spheres and springs of the sheet are its options, offered while it is drawn
    m_spheres->setEnabled(m_surface->isChecked());
    m_springs->setEnabled(m_surface->isChecked());
    m_viewport->setLayers({m_surface->isChecked(), m_spheres->isChecked(), m_springs->isChecked()});
}

}  // namespace ui
