#include "edit_tools.h"

#include "core/contacts/colliders.h"
#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "ui/panels/status_text.h"
#include "ui/simulation/simulation_controller.h"
#include "guide_line.h"
#include "viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QMouseEvent>
#include <QRubberBand>
#include <QWheelEvent>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace ui {

namespace {

Eigen::Vector3d toEigen(const QVector3D &v)
{
    return {double(v.x()), double(v.y()), double(v.z())};
}

// where a ray meets the plane n·p = n·point; none when it runs parallel or the plane is behind
std::optional<Eigen::Vector3d> rayPlane(const Ray &ray, const Eigen::Vector3d &normal, const Eigen::Vector3d &point)
{
    const Eigen::Vector3d origin = toEigen(ray.origin);
    const Eigen::Vector3d direction = toEigen(ray.direction);
    const double along = normal.dot(direction);
    if (std::abs(along) < 1e-9)
        return std::nullopt;
    const double t = normal.dot(point - origin) / along;
    if (!(t > 0.0))
        return std::nullopt;
    return origin + t * direction;
}

struct ToolInfo {
    Tool tool;
    const char *name;
    const char *text;
    const char *tip;
    Qt::Key key;
};

constexpr ToolInfo kTools[] = {
    {Tool::Select, "toolSelect", "Select",
     "Click a particle or spring to select it, shift-click to add or remove, drag on empty space to select a box",
     Qt::Key_1},
    {Tool::AddParticle, "toolAdd", "Add Particle",
     "Click to place a particle on the ground plane (or, with one particle selected, on the plane through it facing "
     "you)",
     Qt::Key_2},
    {Tool::Pin, "toolPin", "Pin", "Click a particle to pin or free it", Qt::Key_3},
    {Tool::Spring, "toolSpring", "Spring",
     "Click one particle, then another, or drag from one to another, to join them with a spring", Qt::Key_4},
    {Tool::Drag, "toolDrag", "Drag",
     "Running: press on a particle to pull it toward the cursor. Paused: drag the selection to move it", Qt::Key_5},
    {Tool::Measure, "toolMeasure", "Measure",
     "Click one particle, then another, or drag from one to another, to measure their distance; it follows them "
     "while the run plays",
     Qt::Key_6},
};

// the Measure tool's words for a pair: "Particles 3 → 7: 1.22474 m (Δx 1, Δy 0.5, Δz -0.5)"
QString measuredText(int from, int to, const Eigen::Vector3d &delta)
{
    return EditTools::tr("Particles %1 → %2: %3").arg(from).arg(to).arg(distanceText(delta));
}

}  // namespace

EditTools::EditTools(Viewport *viewport, SceneDocument *document, SimulationController *controller, QObject *parent)
    : QObject(parent), m_viewport(viewport), m_document(document), m_controller(controller)
{
    createActions();
    m_band = new GuideLine(m_viewport);
    m_measureLine = new GuideLine(m_viewport);
    m_measureLine->setDashed(false);
    m_particleCount = int(m_document->scene().particles.size());
    m_viewport->installEventFilter(this);
    m_viewport->setMouseTracking(true);  // hover
    connect(m_document, &SceneDocument::sceneChanged, this, &EditTools::sceneChanged);
}

void EditTools::createActions()
{
    m_toolGroup = new QActionGroup(this);
    m_toolGroup->setExclusive(true);
    for (const ToolInfo &info : kTools) {
        auto *action = new QAction(tr(info.text), this);
        action->setObjectName(QString::fromLatin1(info.name));
        action->setCheckable(true);
        action->setShortcut(info.key);
        action->setToolTip(tr("%1 (%2)").arg(tr(info.text), QKeySequence(info.key).toString(QKeySequence::NativeText)));
        action->setStatusTip(tr(info.tip));
        action->setChecked(info.tool == m_tool);
        const Tool tool = info.tool;
        connect(action, &QAction::triggered, this, [this, tool] { setTool(tool); });
        m_toolGroup->addAction(action);
        m_toolActions.push_back(action);
    }

    const auto make = [this](const char *name, const QString &text, const QList<QKeySequence> &keys,
                             void (EditTools::*slot)()) {
        auto *action = new QAction(text, this);
        action->setObjectName(QString::fromLatin1(name));
        action->setShortcuts(keys);
        connect(action, &QAction::triggered, this, slot);
        return action;
    };
    m_delete = make("actionDelete", tr("&Delete"), {QKeySequence::Delete, QKeySequence(Qt::Key_Backspace)},
                    &EditTools::deleteSelection);
    m_duplicate = make("actionDuplicate", tr("D&uplicate"), {QKeySequence(Qt::CTRL | Qt::Key_D)},
                       &EditTools::duplicateSelection);
    m_copy = make("actionCopy", tr("&Copy"), {QKeySequence::Copy}, &EditTools::copySelection);
    m_paste = make("actionPaste", tr("&Paste"), {QKeySequence::Paste}, &EditTools::paste);
    m_selectAll = make("actionSelectAll", tr("Select &All"), {QKeySequence::SelectAll}, &EditTools::selectAll);
    m_clearSelection =
        make("actionClearSelection", tr("Select &None"), {QKeySequence(Qt::Key_Escape)}, &EditTools::clearSelection);
    m_pin = make("actionPinSelection", tr("Pin / &Free Selection"), {QKeySequence(Qt::Key_P)},
                 &EditTools::togglePinSelection);
}

std::vector<QAction *> EditTools::editActions() const
{
    return {m_copy, m_paste, m_duplicate, m_delete, m_pin, m_selectAll, m_clearSelection};
}

QAction *EditTools::toolAction(Tool tool) const
{
    return m_toolActions[static_cast<std::size_t>(tool)];
}

void EditTools::setTool(Tool tool)
{
    if (m_gesture == Gesture::Grab)
        m_controller->grab(-1, Eigen::Vector3d::Zero());
    m_gesture = Gesture::None;
    m_grabbed = -1;
    setBandStart(-1);
    setMeasured(-1, -1);
    m_tool = tool;
    toolAction(tool)->setChecked(true);
    m_viewport->setHover(-1, -1);
    emit toolChanged(tool);
    emit message(toolAction(tool)->statusTip());
}

void EditTools::setSelection(Selection selection)
{
    normalise(selection.particles);
    normalise(selection.springs);
    selection.clamp(m_document->scene());
    if (selection == m_selection)
        return;
    m_selection = std::move(selection);
    m_viewport->setSelection(m_selection.particles);
    m_viewport->setSpringSelection(m_selection.springs);
    emit selectionChanged();
}

void EditTools::sceneChanged(SceneChange change)
{
    // another scene (opened, reverted, recovered): nothing of the old one's selection or measure
    // means anything in it, though its indices may exist there (Delete would hit them)
    if (change == SceneChange::Replace) {
        setSelection(Selection{});
        setBandStart(-1);
        setMeasured(-1, -1);
        m_particleCount = int(m_document->scene().particles.size());
        return;
    }
    // undo can leave indices that are no longer there
    Selection kept = m_selection;
    kept.clamp(m_document->scene());
    setSelection(kept);
    const int count = int(m_document->scene().particles.size());
    if (m_bandStart >= count)
        setBandStart(-1);
    // fewer particles: a deletion may have renumbered the measured pair, so the measure goes
    if (count < m_particleCount)
        setMeasured(-1, -1);
    m_particleCount = count;
}

void EditTools::apply(const QString &text, const std::function<void(core::SceneDesc &)> &edit, const QString &mergeKey)
{
    auto edited = std::make_shared<core::SceneDesc>(m_document->scene());
    edit(*edited);
    // the document holds only scenes the file format takes: a particle added or moved past the
    // world's edge (a click far out in a zoomed-out view) is refused, and nothing changes
    if (const std::optional<core::SceneProblem> problem = changedParticleProblem(m_document->scene(), *edited)) {
        emit refused(tr("Not done: %1 %2").arg(QString::fromStdString(problem->path), QString::fromStdString(problem->message)));
        return;
    }
    m_document->undoStack()->push(new SceneCommand(*m_document, text, std::move(edited), mergeKey));
}

// The picture can be of an older scene than the one being edited for a frame or two after an edit
// (the worker has not stepped the new one yet), so an index picked in it may be past the end of
// the scene now (after a delete): such a pick picks nothing. Indices below the end stay valid
// across every edit but a delete, after which a click within that frame may pick a neighbour, but
// never a particle that is not there.
int EditTools::particleUnder(const QPointF &pixel) const
{
    const int particle = m_viewport->particleAt(pixel);
    return particle < int(m_document->scene().particles.size()) ? particle : -1;
}

int EditTools::springUnder(const QPointF &pixel) const
{
    const int spring = m_viewport->springAt(pixel);
    return spring < int(m_document->scene().springs.size()) ? spring : -1;
}

Eigen::Vector3d EditTools::shownPosition(int i) const
{
    const auto snapshot = m_viewport->snapshot();
    if (snapshot && 3 * std::size_t(i) + 2 < snapshot->positions.size() &&
        snapshot->particleCount() == int(m_document->scene().particles.size())) {
        const float *p = snapshot->positions.data() + 3 * std::size_t(i);
        return {double(p[0]), double(p[1]), double(p[2])};
    }
    return m_document->scene().particles[std::size_t(i)].position;
}

std::optional<Eigen::Vector3d> EditTools::onViewPlane(const QPointF &pixel, const Eigen::Vector3d &through) const
{
    const Camera &camera = m_viewport->camera();
    return rayPlane(camera.unproject(pixel), toEigen(camera.forward()), through);
}

std::optional<Eigen::Vector3d> EditTools::placementAt(const QPointF &pixel) const
{
    // on the surface under the cursor, resting on it: the nearest plane the ray meets from the
    // side the camera is on (a rectangle within its edges), or the ground y = 0 in a scene without
    // planes; the centre one radius off the surface, where the particle touches it
    const core::SceneDesc &scene = m_document->scene();
    const Camera &camera = m_viewport->camera();
    const Ray ray = camera.unproject(pixel);
    const Eigen::Vector3d eye = toEigen(ray.origin);
    std::vector<core::PlaneDesc> surfaces = scene.planes;
    if (surfaces.empty())
        surfaces.push_back(core::PlaneDesc{});  // the ground
    std::optional<Eigen::Vector3d> surface;
    Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    double nearest = std::numeric_limits<double>::infinity();
    for (const core::PlaneDesc &plane : surfaces) {
        const core::Collider collider = core::makeCollider(plane, scene.settings);
        const double side = collider.normal.dot(eye) >= collider.offset ? 1.0 : -1.0;
        const Eigen::Vector3d normal = side * collider.normal;
        // the camera behind a one-sided plane sees no surface there
        if (!collider.twoSided && side < 0.0)
            continue;
        const auto hit = rayPlane(ray, normal, collider.normal * collider.offset);
        if (!hit || (*hit - eye).norm() >= nearest)
            continue;
        // a rectangle: only within its edges (beyond them the nearest point is an edge, farther)
        if (plane.bounded() && core::separation(collider, *hit, side).distance > 1e-9 * (1.0 + hit->norm()))
            continue;
        nearest = (*hit - eye).norm();
        surface = hit;
        up = normal;
    }
    if (surface) {
        if (m_defaults.snap)
            surface = snapToGrid(*surface, m_defaults.gridStep);
        return *surface + m_defaults.radius * up;
    }
    // no surface under the cursor: the plane facing the camera through the one selected particle,
    // or through the camera's target
    std::optional<Eigen::Vector3d> point = m_selection.particles.size() == 1
                                               ? onViewPlane(pixel, shownPosition(m_selection.particles.front()))
                                               : onViewPlane(pixel, toEigen(camera.target()));
    if (point && m_defaults.snap)
        point = snapToGrid(*point, m_defaults.gridStep);
    return point;
}

bool EditTools::eventFilter(QObject *watched, QEvent *event)
{
    if (watched != m_viewport)
        return QObject::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        return press(static_cast<QMouseEvent *>(event));
    case QEvent::MouseMove:
        return move(static_cast<QMouseEvent *>(event));
    case QEvent::MouseButtonRelease:
        return release(static_cast<QMouseEvent *>(event));
    case QEvent::Wheel:
        return m_gesture == Gesture::Grab && spinGrabbed(static_cast<QWheelEvent *>(event));
    case QEvent::Leave:
        m_viewport->setHover(-1, -1);
        return false;
    default:
        return false;
    }
}

bool EditTools::press(QMouseEvent *event)
{
    // the tools use the left button alone; shift+left on empty space still pans
    if (event->button() != Qt::LeftButton || m_gesture != Gesture::None)
        return false;
    const QPointF pixel = event->position();
    const bool shift = event->modifiers().testFlag(Qt::ShiftModifier) ||
                       event->modifiers().testFlag(Qt::ControlModifier);
    const int particle = particleUnder(pixel);
    const core::SceneDesc &scene = m_document->scene();
    m_pressPixel = pixel;

    switch (m_tool) {
    case Tool::Select: {
        const int spring = particle < 0 ? springUnder(pixel) : -1;
        if (particle < 0 && spring < 0) {
            if (event->modifiers().testFlag(Qt::ShiftModifier))
                return false;  // pan
            m_gesture = Gesture::RubberBand;
            m_addToSelection = event->modifiers().testFlag(Qt::ControlModifier);
            if (!m_rubberBand)
                m_rubberBand = new QRubberBand(QRubberBand::Rectangle, m_viewport);
            m_rubberBand->setGeometry(QRect(pixel.toPoint(), QSize()));
            m_rubberBand->show();
            return true;
        }
        Selection next = shift ? m_selection : Selection{};
        if (particle >= 0)
            shift ? next.toggleParticle(particle) : next.particles.assign(1, particle);
        else
            shift ? next.toggleSpring(spring) : next.springs.assign(1, spring);
        setSelection(next);
        return true;
    }
    case Tool::AddParticle: {
        const auto point = placementAt(pixel);
        if (!point) {
            emit message(tr("No place under the cursor: turn the view toward the ground"));
            return true;
        }
        if (!roomFor(1, tr("Not added")))
            return true;
        core::ParticleDesc added;
        added.position = *point;
        added.mass = m_defaults.mass;
        added.radius = m_defaults.radius;
        const int index = int(scene.particles.size());
        apply(tr("Add Particle"), [&](core::SceneDesc &s) { addParticle(s, added); });
        // the new particle becomes the selection only when nothing was, so that a row of particles
        // can be placed on the plane through one that stays selected
        if (m_selection.particles.size() != 1)
            setSelection(Selection{{index}, {}});
        emit message(tr("Particle %1 at (%2, %3, %4) m")
                         .arg(index)
                         .arg(added.position.x(), 0, 'g', 4)
                         .arg(added.position.y(), 0, 'g', 4)
                         .arg(added.position.z(), 0, 'g', 4));
        return true;
    }
    case Tool::Pin: {
        if (particle < 0)
            return false;  // orbit
        const bool pin = !scene.particles[std::size_t(particle)].pinned;
        apply(pin ? tr("Pin Particle") : tr("Free Particle"), [&](core::SceneDesc &s) { togglePinned(s, {particle}); });
        emit message(pin ? tr("Particle %1 pinned").arg(particle) : tr("Particle %1 freed").arg(particle));
        return true;
    }
    case Tool::Spring:
    case Tool::Measure: {
        if (particle < 0) {
            setBandStart(-1);
            return false;  // orbit
        }
        if (m_bandStart < 0 || m_bandStart == particle) {
            // the first particle; a release on another joins or measures them, a click waits for
            // another click
            setBandStart(particle);
            setSelection(Selection{{particle}, {}});
            m_gesture = Gesture::Band;
            followBand(pixel);
            if (m_tool == Tool::Spring) {
                emit message(tr("Spring from particle %1: click the particle to join it to").arg(particle));
            } else {
                setMeasured(-1, -1);
                emit message(tr("Measuring from particle %1: click the particle to measure to").arg(particle));
            }
            return true;
        }
        m_tool == Tool::Spring ? joinSpring(particle) : measureTo(particle);
        return true;
    }
    case Tool::Drag: {
        if (particle < 0)
            return false;  // orbit
        m_dragPlanePoint = shownPosition(particle);
        m_dragStart = onViewPlane(pixel, m_dragPlanePoint).value_or(m_dragPlanePoint);
        if (m_controller->isRunning()) {
            m_gesture = Gesture::Grab;
            m_grabbed = particle;
            m_grabSpin = 0.0;
            m_controller->grab(particle, m_dragPlanePoint);
            return true;
        }
        // paused: the selection moves if the particle is in it, else the particle alone
        if (!m_selection.hasParticle(particle))
            setSelection(Selection{{particle}, {}});
        m_gesture = Gesture::Move;
        m_moving = m_selection.particles;
        m_movingFrom.clear();
        for (int i : m_moving)
            m_movingFrom.push_back(shownPosition(i));
        ++m_moveSerial;
        return true;
    }
    }
    return false;
}

bool EditTools::move(QMouseEvent *event)
{
    const QPointF pixel = event->position();
    switch (m_gesture) {
    case Gesture::None:
        if (event->buttons() == Qt::NoButton) {
            hover(pixel);
            followBand(pixel);
        }
        return false;
    case Gesture::RubberBand:
        m_rubberBand->setGeometry(QRectF(m_pressPixel, pixel).normalized().toRect());
        return true;
    case Gesture::Band:
        hover(pixel);
        followBand(pixel);
        return true;
    case Gesture::Grab:
        if (const auto target = onViewPlane(pixel, m_dragPlanePoint))
            m_controller->grab(m_grabbed, *target - m_dragStart + m_dragPlanePoint);
        return true;
    case Gesture::Move:
        if (const auto at = onViewPlane(pixel, m_dragPlanePoint)) {
            const Eigen::Vector3d delta = *at - m_dragStart;
            apply(tr("Move"), [&](core::SceneDesc &s) { moveParticles(s, m_moving, m_movingFrom, delta); },
                  QStringLiteral("move %1").arg(m_moveSerial));
        }
        return true;
    }
    return false;
}

bool EditTools::spinGrabbed(QWheelEvent *event)
{
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0.0)
        return false;
    // about the line of sight, towards the viewer: a notch away from the user turns the particle
    // counter-clockwise as the view shows it (right-hand rule)
    const QVector3D towardsViewer = -m_viewport->camera().forward();
    const Eigen::Vector3d axis(towardsViewer.x(), towardsViewer.y(), towardsViewer.z());
    m_grabSpin += notches * kFlickTurnsPerNotch;
    m_controller->strike(m_grabbed, Eigen::Vector3d::Zero(),
                         notches * kFlickTurnsPerNotch * 2.0 * std::numbers::pi * axis.normalized());
    const bool turns = m_controller->sceneTurns();
    emit message(turns ? tr("Particle %1 spun %2 turns/s %3 as seen: let go to flick it")
                             .arg(m_grabbed)
                             .arg(std::abs(m_grabSpin), 0, 'g', 3)
                             .arg(m_grabSpin >= 0.0 ? tr("counter-clockwise") : tr("clockwise"))
                       : tr("Nothing in this scene has friction, so particle %1 takes no spin").arg(m_grabbed));
    event->accept();
    return true;
}

bool EditTools::release(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton || m_gesture == Gesture::None)
        return false;
    const Gesture gesture = m_gesture;
    m_gesture = Gesture::None;
    if (gesture == Gesture::Grab) {
        m_controller->grab(-1, Eigen::Vector3d::Zero());
        m_grabbed = -1;
    } else if (gesture == Gesture::Band) {
        // released on another particle: the two are joined or measured; on the first: a click, so
        // the next click ends the spring or the measurement
        const int particle = particleUnder(event->position());
        if (particle >= 0 && particle != m_bandStart)
            m_tool == Tool::Spring ? joinSpring(particle) : measureTo(particle);
    } else if (gesture == Gesture::RubberBand) {
        // the particles whose centres lie inside the box on screen
        const QRectF box = QRectF(m_pressPixel, event->position()).normalized();
        m_rubberBand->hide();
        Selection next = m_addToSelection ? m_selection : Selection{};
        const int n = int(m_document->scene().particles.size());
        for (int i = 0; i < n; ++i) {
            const Eigen::Vector3d p = shownPosition(i);
            const auto pixel = m_viewport->camera().project(QVector3D(float(p.x()), float(p.y()), float(p.z())));
            if (pixel && box.contains(*pixel))
                next.particles.push_back(i);
        }
        setSelection(next);
        emit message(selectionText(m_selection.particles.size(), m_selection.springs.size()));
    }
    return true;
}

void EditTools::setBandStart(int particle)
{
    m_bandStart = particle;
    if (particle < 0)
        m_band->hide();
}

std::optional<QLineF> EditTools::lineBetween(int a, int b) const
{
    const auto onScreen = [this](int i) {
        const Eigen::Vector3d p = shownPosition(i);
        return m_viewport->camera().project(QVector3D(float(p.x()), float(p.y()), float(p.z())));
    };
    const auto from = onScreen(a);
    const auto to = onScreen(b);
    if (!from || !to)
        return std::nullopt;
    return QLineF(*from, *to);
}

void EditTools::followBand(const QPointF &pixel)
{
    if ((m_tool != Tool::Spring && m_tool != Tool::Measure) || m_bandStart < 0) {
        m_band->hide();
        return;
    }
    const int under = particleUnder(pixel);
    const bool onAnother = under >= 0 && under != m_bandStart;
    std::optional<QLineF> line = lineBetween(m_bandStart, onAnother ? under : m_bandStart);
    if (!line) {
        m_band->hide();
        return;
    }
    if (!onAnother)
        line->setP2(pixel);
    // measuring: the distance to the particle under the cursor, before the click
    const QString label = m_tool == Tool::Measure && onAnother
                              ? lengthText((shownPosition(under) - shownPosition(m_bandStart)).norm())
                              : QString();
    m_band->showLine(*line, label);
}

void EditTools::joinSpring(int particle)
{
    const int a = m_bandStart;
    auto edited = std::make_shared<core::SceneDesc>(m_document->scene());
    const int spring = ui::addSpring(*edited, a, particle, m_defaults.stiffness, m_defaults.damping);
    setBandStart(-1);
    if (spring < 0) {
        emit message(tr("Particles %1 and %2 are already joined").arg(a).arg(particle));
        return;
    }
    m_document->undoStack()->push(new SceneCommand(*m_document, tr("Add Spring"), std::move(edited)));
    setSelection(Selection{{}, {spring}});
    emit message(tr("Spring %1 joins particles %2 and %3").arg(spring).arg(a).arg(particle));
}

void EditTools::measureTo(int particle)
{
    const int from = m_bandStart;
    setBandStart(-1);
    setMeasured(from, particle);
    // the pair is the selection, so that the inspector shows their distance too
    setSelection(Selection{{from, particle}, {}});
    emit message(measuredText(from, particle, measurement()->delta));
}

void EditTools::setMeasured(int from, int to)
{
    m_measuredFrom = from;
    m_measuredTo = to;
    if (from < 0 || to < 0) {
        m_measureLine->hide();
        return;
    }
    // asked again at every paint of the view, so that it follows the particles and the camera
    m_measureLine->follow([this]() -> std::optional<GuideLine::Shape> {
        const std::optional<Measurement> measured = measurement();
        if (!measured)
            return std::nullopt;
        const std::optional<QLineF> line = lineBetween(measured->from, measured->to);
        if (!line)
            return std::nullopt;
        return GuideLine::Shape{*line, lengthText(measured->delta.norm())};
    });
}

std::optional<EditTools::Measurement> EditTools::measurement() const
{
    const int count = int(m_document->scene().particles.size());
    if (m_measuredFrom < 0 || m_measuredTo < 0 || m_measuredFrom >= count || m_measuredTo >= count)
        return std::nullopt;
    return Measurement{m_measuredFrom, m_measuredTo, shownPosition(m_measuredTo) - shownPosition(m_measuredFrom)};
}

void EditTools::hover(const QPointF &pixel)
{
    int particle = -1;
    int spring = -1;
    switch (m_tool) {
    case Tool::Select:
        particle = particleUnder(pixel);
        if (particle < 0)
            spring = springUnder(pixel);
        break;
    case Tool::Pin:
    case Tool::Spring:
    case Tool::Drag:
    case Tool::Measure:
        particle = particleUnder(pixel);
        break;
    case Tool::AddParticle:
        break;
    }
    m_viewport->setHover(particle, spring);
}

void EditTools::deleteSelection()
{
    if (m_selection.empty())
        return;
    const Selection gone = m_selection;
    setSelection({});
    apply(tr("Delete"), [&](core::SceneDesc &s) { removeItems(s, gone); });
    emit message(tr("Deleted %n particle(s)", nullptr, int(gone.particles.size())) + QStringLiteral(", ") +
                 tr("%n spring(s)", nullptr, int(gone.springs.size())));
}

Eigen::Vector3d EditTools::copyOffset(const Fragment &fragment) const
{
    // beside the original along x, one particle's width apart
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -lowest;
    double widest = 0.0;
    for (const core::ParticleDesc &p : fragment.particles) {
        lowest = std::min(lowest, p.position.x() - p.radius);
        highest = std::max(highest, p.position.x() + p.radius);
        widest = std::max(widest, 2.0 * p.radius);
    }
    return {highest - lowest + widest, 0.0, 0.0};
}

bool EditTools::roomFor(std::size_t added, const QString &notDone)
{
    const std::optional<std::size_t> total = particlesPastLimit(m_document->scene(), added);
    if (total)
        emit refused(particleLimitText(notDone, *total));
    return !total;
}

void EditTools::duplicateSelection()
{
    const Fragment fragment = copyItems(m_document->scene(), m_selection);
    if (fragment.empty() || !roomFor(fragment.particles.size(), tr("Not duplicated")))
        return;
    Selection added;
    apply(tr("Duplicate"), [&](core::SceneDesc &s) { added = pasteFragment(s, fragment, copyOffset(fragment)); });
    setSelection(added);
}

void EditTools::copySelection()
{
    const Fragment fragment = copyItems(m_document->scene(), m_selection);
    if (fragment.empty())
        return;
    m_clipboard = fragment;
    emit message(tr("Copied %n particle(s)", nullptr, int(fragment.particles.size())));
}

void EditTools::paste()
{
    if (m_clipboard.empty() || !roomFor(m_clipboard.particles.size(), tr("Not pasted")))
        return;
    // into the same scene beside the original; into another scene where it was
    const bool besideOriginal = [&] {
        for (const core::ParticleDesc &p : m_clipboard.particles)
            for (const core::ParticleDesc &q : m_document->scene().particles)
                if (p.position == q.position)
                    return true;
        return false;
    }();
    const Eigen::Vector3d offset = besideOriginal ? copyOffset(m_clipboard) : Eigen::Vector3d::Zero();
    Selection added;
    apply(tr("Paste"), [&](core::SceneDesc &s) { added = pasteFragment(s, m_clipboard, offset); });
    setSelection(added);
    // a second paste goes beside the first
    for (core::ParticleDesc &p : m_clipboard.particles)
        p.position += offset;
}

void EditTools::selectAll()
{
    Selection all;
    for (int i = 0; i < int(m_document->scene().particles.size()); ++i)
        all.particles.push_back(i);
    for (int i = 0; i < int(m_document->scene().springs.size()); ++i)
        all.springs.push_back(i);
    setSelection(all);
    emit message(selectionText(m_selection.particles.size(), m_selection.springs.size()));
}

void EditTools::clearSelection()
{
    setBandStart(-1);
    setMeasured(-1, -1);
    setSelection({});
    emit message(selectionText(0, 0));
}

void EditTools::togglePinSelection()
{
    if (m_selection.particles.empty())
        return;
    // all pinned: free them; else pin them all
    const auto &particles = m_document->scene().particles;
    const bool allPinned = std::all_of(m_selection.particles.begin(), m_selection.particles.end(),
                                       [&](int i) { return particles[std::size_t(i)].pinned; });
    const std::vector<int> chosen = m_selection.particles;
    apply(allPinned ? tr("Free") : tr("Pin"), [&](core::SceneDesc &s) { setPinned(s, chosen, !allPinned); });
}

}  // namespace ui
