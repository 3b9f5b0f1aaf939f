#include "camera_actions.h"

#include "session/simulation_frame.h"
#include "ui/viewport/viewport.h"

#include <QAction>
#include <QSettings>

namespace ui {

namespace {

const QString kOrthographicKey = QStringLiteral("view/orthographic");

}  // namespace

CameraActions::CameraActions(Viewport *viewport, QObject *parent) : QObject(parent), m_viewport(viewport)
{
    // the presets: Ctrl and the digits a keypad's views have elsewhere (7 above, 1 in front, 3 to
    // the side, 5 the projection), since the plain digits choose the tools
    struct Preset {
        const char *name;
        const char *text;
        const char *tip;
        QKeySequence key;
        ViewPreset preset;
    };
    const Preset presets[] = {
        {"actionViewTop", QT_TR_NOOP("&Top View"), QT_TR_NOOP("Look straight down (along -y) at the camera's target, the whole scene in view"),
         QKeySequence(Qt::CTRL | Qt::Key_7), ViewPreset::Top},
        {"actionViewFront", QT_TR_NOOP("Fro&nt View"), QT_TR_NOOP("Look along -z at the camera's target, the whole scene in view"),
         QKeySequence(Qt::CTRL | Qt::Key_1), ViewPreset::Front},
        {"actionViewSide", QT_TR_NOOP("S&ide View"), QT_TR_NOOP("Look along -x at the camera's target, the whole scene in view"),
         QKeySequence(Qt::CTRL | Qt::Key_3), ViewPreset::Side},
        {"actionViewDefault", QT_TR_NOOP("D&efault View"),
         QT_TR_NOOP("Back to the direction a scene opens with, framing the whole scene"), QKeySequence(Qt::CTRL | Qt::Key_0),
         ViewPreset::Default},
    };
    for (const Preset &p : presets) {
        auto *action = new QAction(tr(p.text), this);
        action->setObjectName(QString::fromLatin1(p.name));
        action->setShortcut(p.key);
        action->setStatusTip(tr(p.tip));
        const ViewPreset preset = p.preset;
        connect(action, &QAction::triggered, m_viewport, [this, preset] { m_viewport->viewAlong(preset); });
        m_actions << action;
    }

    auto *separator = new QAction(this);
    separator->setSeparator(true);
    m_actions << separator;

    // the projection, as the last session left it
    m_orthographic = new QAction(tr("&Orthographic"), this);
    m_orthographic->setObjectName(QStringLiteral("actionOrthographic"));
    m_orthographic->setCheckable(true);
    m_orthographic->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_5));
    m_orthographic->setStatusTip(tr("Parallel projection: sizes do not shrink with distance, as in a technical drawing"));
    m_orthographic->setChecked(QSettings().value(kOrthographicKey, false).toBool());
    auto applyProjection = [this](bool on) {
        m_viewport->setProjection(on ? Projection::Orthographic : Projection::Perspective);
    };
    applyProjection(m_orthographic->isChecked());
    connect(m_orthographic, &QAction::toggled, this, [applyProjection](bool on) {
        QSettings().setValue(kOrthographicKey, on);
        applyProjection(on);
    });
    m_actions << m_orthographic;

    // following the selection: for this session only, as a surprise in the next one otherwise
    m_follow = new QAction(tr("Fo&llow Selection"), this);
    m_follow->setObjectName(QStringLiteral("actionFollowSelection"));
    m_follow->setCheckable(true);
    m_follow->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F));
    m_follow->setStatusTip(tr("Keep the camera's target on the selected particles' centroid while the run plays; off, "
                              "the camera stays where it is"));
    connect(m_follow, &QAction::toggled, m_viewport, &Viewport::setFollowSelection);
    m_actions << m_follow;
}

void CameraActions::frameAllWhenShown(std::uint64_t sequence)
{
    m_frameAfter = sequence;
    m_frameAll = true;
    m_newParticles.clear();
}

void CameraActions::frameWhenShownIfHidden(std::uint64_t sequence, std::vector<int> particles)
{
    // a new scene still awaited frames everything anyway
    if (m_frameAfter != 0 && m_frameAll)
        return;
    m_frameAfter = sequence;
    m_frameAll = false;
    m_newParticles = std::move(particles);
}

void CameraActions::frameShown(const SimulationFrame &frame)
{
    if (m_frameAfter == 0 || frame.appliedMessage < m_frameAfter)
        return;
    m_frameAfter = 0;
    if (m_frameAll || !m_viewport->particlesInView(m_newParticles))
        m_viewport->frameAll();
    m_newParticles.clear();
}

}  // namespace ui
