#include "inspector_planes.h"

#include "inspector_edits.h"
#include "inspector_field.h"
#include "ui/document/scene_document.h"

#include "core/contacts/contact_impulses.h"
#include "core/model/validate.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace ui {

namespace {

const char *const kAxes[] = {"x", "y", "z"};
const char *const kSides[] = {"width", "height"};

QString describe(const core::PlaneDesc &plane)
{
    QString text = InspectorPlanes::tr("n = (%1, %2, %3), offset %4 m")
                       .arg(plane.normal.x(), 0, 'g', 4)
                       .arg(plane.normal.y(), 0, 'g', 4)
                       .arg(plane.normal.z(), 0, 'g', 4)
                       .arg(plane.offset, 0, 'g', 6);
    if (plane.bounded())
        text += InspectorPlanes::tr(", %1 × %2 m rectangle").arg(plane.size[0], 0, 'g', 4).arg(plane.size[1], 0, 'g', 4);
    else if (plane.twoSided)
        text += InspectorPlanes::tr(", two-sided");
    if (plane.friction)
        text += InspectorPlanes::tr(", μ %1").arg(*plane.friction, 0, 'g', 4);
    return text;
}

// three spin boxes side by side, for a vector
QWidget *vectorRow(std::array<InspectorSpinBox *, 3> &boxes, core::Parameter parameter, const QString &name,
                   QWidget *parent)
{
    auto *row = new QWidget(parent);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    for (int axis = 0; axis < 3; ++axis) {
        auto *box = new InspectorSpinBox(parameter, row);
        box->setObjectName(QStringLiteral("inspector-plane-%1.%2").arg(name, QLatin1String(kAxes[axis])));
        layout->addWidget(box);
        boxes[std::size_t(axis)] = box;
    }
    return row;
}

}  // namespace

InspectorPlanes::InspectorPlanes(InspectorEdits *edits, QWidget *parent)
    : QGroupBox(tr("Planes"), parent), m_edits(edits), m_list(new QListWidget(this)),
      m_add(new QPushButton(tr("Add"), this)), m_remove(new QPushButton(tr("Remove"), this)),
      m_offset(new InspectorSpinBox(core::Parameter::Coordinate, this)),
      m_twoSided(new QCheckBox(tr("Two-sided"), this)), m_ownFriction(new QCheckBox(tr("Own"), this)),
      m_friction(new InspectorSpinBox(core::Parameter::Friction, this))
{
    setObjectName(QStringLiteral("inspector-planes"));
    m_list->setObjectName(QStringLiteral("inspector-planeList"));
    m_list->setMaximumHeight(100);
    m_add->setObjectName(QStringLiteral("inspector-addPlane"));
    m_add->setToolTip(tr("Add a ground plane y = 0"));
    m_remove->setObjectName(QStringLiteral("inspector-removePlane"));
    m_remove->setToolTip(tr("Remove the chosen plane"));
    m_offset->setObjectName(QStringLiteral("inspector-plane-offset"));
    m_offset->setToolTip(tr("The plane is n·p = offset (m); particles stay on the side n points to"));
    m_twoSided->setObjectName(QStringLiteral("inspector-plane-twoSided"));
    m_ownFriction->setObjectName(QStringLiteral("inspector-plane-ownFriction"));
    m_ownFriction->setToolTip(tr("The plane has a Coulomb coefficient of its own, static and kinetic alike; "
                                 "unchecked it takes the scene's friction (Parameters)"));
    m_friction->setObjectName(QStringLiteral("inspector-plane-friction"));
    m_friction->setToolTip(tr("This plane's Coulomb coefficient, static and kinetic: a contact's friction is at "
                              "most this times the force pressing it"));

    // the list with its buttons, then the chosen plane's fields
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_list);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    m_form = new QFormLayout;
    m_form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    auto *normalRow = new QHBoxLayout;
    for (int axis = 0; axis < 3; ++axis) {
        auto *box = new InspectorSpinBox(core::Parameter::Coordinate, this);
        box->setObjectName(QStringLiteral("inspector-plane-normal.") + QLatin1String(kAxes[axis]));
        box->setToolTip(tr("Normal %1: the normal is made unit length when applied, and may not be zero")
                            .arg(QLatin1String(kAxes[axis])));
        connect(box, &InspectorSpinBox::typed, this, [this, axis](double value) { editNormal(axis, value, false); });
        connect(box, &InspectorSpinBox::stepped, this, [this, axis](double value) { editNormal(axis, value, true); });
        normalRow->addWidget(box);
        m_normal[std::size_t(axis)] = box;
    }
    m_form->addRow(tr("Normal"), normalRow);
    m_form->addRow(tr("Offset (m)"), m_offset);
    connect(m_offset, &InspectorSpinBox::typed, this, [this](double value) { editOffset(value, false); });
    connect(m_offset, &InspectorSpinBox::stepped, this, [this](double value) { editOffset(value, true); });

    // the contact: which sides, what friction
    m_form->addRow(QString(), m_twoSided);
    connect(m_twoSided, &QCheckBox::toggled, this, &InspectorPlanes::setTwoSided);
    auto *frictionRow = new QHBoxLayout;
    frictionRow->addWidget(m_ownFriction);
    frictionRow->addWidget(m_friction, 1);
    m_form->addRow(tr("Friction"), frictionRow);
    connect(m_ownFriction, &QCheckBox::toggled, this, &InspectorPlanes::setOwnFriction);
    connect(m_friction, &InspectorSpinBox::typed, this, [this](double value) { editFriction(value, false); });
    connect(m_friction, &InspectorSpinBox::stepped, this, [this](double value) { editFriction(value, true); });

    // the rectangle: its size, then (for a rectangle only) its centre and width axis
    auto *sizeRow = new QHBoxLayout;
    for (int side = 0; side < 2; ++side) {
        auto *box = new InspectorSpinBox(core::Parameter::Extent, this);
        box->setObjectName(QStringLiteral("inspector-plane-size.") + QLatin1String(kSides[side]));
        box->setToolTip(side == 0 ? tr("The rectangle's width (m), along its axis; 0 makes the plane whole, and a "
                                       "side typed on a whole plane makes a square")
                                  : tr("The rectangle's height (m), along normal × axis; 0 makes the plane whole, "
                                       "and a side typed on a whole plane makes a square"));
        connect(box, &InspectorSpinBox::typed, this, [this, side](double value) { editSize(side, value, false); });
        connect(box, &InspectorSpinBox::stepped, this, [this, side](double value) { editSize(side, value, true); });
        sizeRow->addWidget(box);
        m_size[std::size_t(side)] = box;
    }
    m_form->addRow(tr("Size w × h (m)"), sizeRow);
    m_centreRow = vectorRow(m_centre, core::Parameter::Coordinate, QStringLiteral("centre"), this);
    m_axisRow = vectorRow(m_axis, core::Parameter::Coordinate, QStringLiteral("axis"), this);
    for (int axis = 0; axis < 3; ++axis) {
        const QLatin1String name(kAxes[axis]);
        m_centre[std::size_t(axis)]->setToolTip(
            tr("Centre %1 (m): the rectangle's centre is the point of the plane nearest this").arg(name));
        m_axis[std::size_t(axis)]->setToolTip(
            tr("Axis %1: the width's direction, projected onto the plane; zero takes the viewport's own").arg(name));
        for (const bool isAxis : {false, true}) {
            InspectorSpinBox *box = (isAxis ? m_axis : m_centre)[std::size_t(axis)];
            connect(box, &InspectorSpinBox::typed, this,
                    [this, isAxis, axis](double value) { editPoint(isAxis, axis, value, false); });
            connect(box, &InspectorSpinBox::stepped, this,
                    [this, isAxis, axis](double value) { editPoint(isAxis, axis, value, true); });
        }
    }
    m_form->addRow(tr("Centre (m)"), m_centreRow);
    m_form->addRow(tr("Axis"), m_axisRow);
    layout->addLayout(m_form);

    // leaving a field or choosing another plane ends a step sequence
    for (InspectorSpinBox *box : fields())
        connect(box, &QAbstractSpinBox::editingFinished, this, [this] {
            m_edits->endSession();
            showChosen();
        });
    connect(m_list, &QListWidget::currentRowChanged, this, [this] {
        m_edits->endSession();
        showChosen();
    });
    connect(m_add, &QPushButton::clicked, this, &InspectorPlanes::addPlane);
    connect(m_remove, &QPushButton::clicked, this, &InspectorPlanes::removePlane);
    refresh();
}

InspectorPlanes::~InspectorPlanes()
{
    // as for the panel: a field losing the focus must not reach a half destroyed section
    for (InspectorSpinBox *box : findChildren<InspectorSpinBox *>())
        disconnect(box, nullptr, this, nullptr);
    disconnect(m_list, nullptr, this, nullptr);
}

std::vector<InspectorSpinBox *> InspectorPlanes::fields() const
{
    std::vector<InspectorSpinBox *> all(m_normal.begin(), m_normal.end());
    all.push_back(m_offset);
    all.push_back(m_friction);
    all.insert(all.end(), m_size.begin(), m_size.end());
    all.insert(all.end(), m_centre.begin(), m_centre.end());
    all.insert(all.end(), m_axis.begin(), m_axis.end());
    return all;
}

int InspectorPlanes::currentPlane() const
{
    const int row = m_list->currentRow();
    return row >= 0 && row < int(m_edits->document()->scene().planes.size()) ? row : -1;
}

void InspectorPlanes::setCurrentPlane(int plane)
{
    m_list->setCurrentRow(plane);
    showChosen();
}

void InspectorPlanes::refresh()
{
    // one line per plane; the chosen one stays chosen, or the nearest one that is left
    const std::vector<core::PlaneDesc> &planes = m_edits->document()->scene().planes;
    {
        const QSignalBlocker block(m_list);
        const int chosen = m_list->currentRow();
        while (m_list->count() > int(planes.size()))
            delete m_list->takeItem(m_list->count() - 1);
        while (m_list->count() < int(planes.size()))
            m_list->addItem(QString());
        for (std::size_t i = 0; i < planes.size(); ++i)
            m_list->item(int(i))->setText(describe(planes[i]));
        const int last = int(planes.size()) - 1;
        m_list->setCurrentRow(chosen < 0 ? (last >= 0 ? 0 : -1) : std::min(chosen, last));
    }
    showChosen();
}

void InspectorPlanes::showChosen()
{
    // the fields show the chosen plane; with none they are disabled
    const int plane = currentPlane();
    const core::SceneDesc &scene = m_edits->document()->scene();
    m_remove->setEnabled(plane >= 0);
    for (InspectorSpinBox *box : fields())
        box->setEnabled(plane >= 0);
    m_twoSided->setEnabled(plane >= 0);
    m_ownFriction->setEnabled(plane >= 0);
    const QSignalBlocker blockTwoSided(m_twoSided);
    const QSignalBlocker blockOwnFriction(m_ownFriction);
    if (plane < 0) {
        for (InspectorSpinBox *box : fields())
            box->showValue(0.0);
        m_twoSided->setChecked(false);
        m_ownFriction->setChecked(false);
        m_form->setRowVisible(m_centreRow, false);
        m_form->setRowVisible(m_axisRow, false);
        return;
    }
    const core::PlaneDesc &desc = scene.planes[std::size_t(plane)];
    for (int axis = 0; axis < 3; ++axis)
        m_normal[std::size_t(axis)]->showValue(desc.normal[axis]);
    m_offset->showValue(desc.offset);

    // a rectangle is two-sided whatever its flag says, so the box shows that and cannot change it
    const bool bounded = desc.bounded();
    m_twoSided->setChecked(desc.twoSided || bounded);
    m_twoSided->setEnabled(!bounded);
    m_twoSided->setToolTip(bounded ? tr("A rectangle is always two-sided: a thin sheet with edges")
                                   : tr("A thin wall: a particle stays on the side it came from; unchecked, the "
                                        "plane is a half-space and particles live on the side n points to"));

    // its own friction, or the scene's shown greyed
    m_ownFriction->setChecked(desc.friction.has_value());
    m_friction->setEnabled(desc.friction.has_value());
    m_friction->showValue(desc.friction.value_or(scene.settings.friction));

    // the size; centre and axis only mean something for a rectangle
    for (int side = 0; side < 2; ++side)
        m_size[std::size_t(side)]->showValue(desc.size[side]);
    for (int axis = 0; axis < 3; ++axis) {
        m_centre[std::size_t(axis)]->showValue(desc.centre[axis]);
        m_axis[std::size_t(axis)]->showValue(desc.axis[axis]);
    }
    m_form->setRowVisible(m_centreRow, bounded);
    m_form->setRowVisible(m_axisRow, bounded);
}

void InspectorPlanes::addPlane()
{
    // the default plane is the ground: n = (0, 1, 0), offset 0
    auto edited = std::make_shared<core::SceneDesc>(m_edits->document()->scene());
    edited->planes.push_back(core::PlaneDesc{});
    const int added = int(edited->planes.size()) - 1;
    if (m_edits->push(tr("Add plane"), tr("New plane"), std::move(edited)))
        setCurrentPlane(added);
}

void InspectorPlanes::removePlane()
{
    const int plane = currentPlane();
    if (plane < 0)
        return;
    auto edited = std::make_shared<core::SceneDesc>(m_edits->document()->scene());
    edited->planes.erase(edited->planes.begin() + plane);
    core::removePlaneFromContactImpulses(edited->contactImpulses, plane);
    const int left = int(edited->planes.size());
    if (m_edits->push(tr("Remove plane %1").arg(plane), tr("Plane %1").arg(plane), std::move(edited)))
        setCurrentPlane(std::min(plane, left - 1));
}

void InspectorPlanes::editNormal(int axis, double value, bool step)
{
    const int plane = currentPlane();
    if (plane < 0)
        return;
    const QString label = tr("Plane normal %1").arg(QLatin1String(kAxes[axis]));
    if (const std::optional<QString> refused = InspectorEdits::refusal(core::Parameter::Coordinate, label, value)) {
        m_edits->refuse(*refused);
        return;
    }

    // the normal as typed must be usable (not zero); then it is stored with unit length
    auto edited = std::make_shared<core::SceneDesc>(m_edits->document()->scene());
    core::PlaneDesc &desc = edited->planes[std::size_t(plane)];
    desc.normal[axis] = value;
    if (const std::optional<QString> problem = m_edits->problemIn(*edited, tr("Plane normal"))) {
        m_edits->refuse(*problem);
        return;
    }
    desc.normal = core::unitNormal(desc.normal);
    m_edits->push(tr("Set plane %1 normal").arg(plane), tr("Plane normal"), std::move(edited),
                  step ? QStringLiteral("plane%1.normal.%2").arg(plane).arg(QLatin1String(kAxes[axis])) : QString());
}

void InspectorPlanes::editOffset(double value, bool step)
{
    const int plane = currentPlane();
    if (plane < 0)
        return;
    m_edits->apply(
        tr("Set plane %1 offset to %2").arg(plane).arg(value, 0, 'g', 6), core::Parameter::Coordinate,
        tr("Plane offset"), value, [plane, value](core::SceneDesc &scene) { scene.planes[std::size_t(plane)].offset = value; },
        step ? QStringLiteral("plane%1.offset").arg(plane) : QString());
}

void InspectorPlanes::setTwoSided(bool on)
{
    const int plane = currentPlane();
    if (plane < 0)
        return;
    auto edited = std::make_shared<core::SceneDesc>(m_edits->document()->scene());
    edited->planes[std::size_t(plane)].twoSided = on;
    m_edits->push(on ? tr("Make plane %1 two-sided").arg(plane) : tr("Make plane %1 one-sided").arg(plane),
                  tr("Plane two-sided"), std::move(edited));
    showChosen();
}

void InspectorPlanes::setOwnFriction(bool own)
{
    // its own starts from the scene's friction, which the field showed
    const int plane = currentPlane();
    if (plane < 0)
        return;
    auto edited = std::make_shared<core::SceneDesc>(m_edits->document()->scene());
    core::PlaneDesc &desc = edited->planes[std::size_t(plane)];
    desc.friction = own ? std::optional<double>(edited->settings.friction) : std::nullopt;
    m_edits->push(own ? tr("Give plane %1 its own friction").arg(plane)
                      : tr("Let plane %1 take the scene's friction").arg(plane),
                  tr("Plane friction"), std::move(edited));
    showChosen();
}

void InspectorPlanes::editFriction(double value, bool step)
{
    const int plane = currentPlane();
    if (plane < 0)
        return;
    m_edits->apply(
        tr("Set plane %1 friction to %2").arg(plane).arg(value, 0, 'g', 6), core::Parameter::Friction,
        tr("Plane friction"), value,
        [plane, value](core::SceneDesc &scene) { scene.planes[std::size_t(plane)].friction = value; },
        step ? QStringLiteral("plane%1.friction").arg(plane) : QString());
}

void InspectorPlanes::editSize(int side, double value, bool step)
{
    const int plane = currentPlane();
    if (plane < 0)
        return;
    const QString label = side == 0 ? tr("Plane width") : tr("Plane height");
    if (const std::optional<QString> refused = InspectorEdits::refusal(core::Parameter::Extent, label, value)) {
        m_edits->refuse(*refused);
        return;
    }

    // both sides or neither: a side on a whole plane makes a square, a zero side makes it whole
    auto edited = std::make_shared<core::SceneDesc>(m_edits->document()->scene());
    core::PlaneDesc &desc = edited->planes[std::size_t(plane)];
    QString text;
    if (!(value > 0.0)) {
        desc.size = Eigen::Vector2d::Zero();
        text = tr("Make plane %1 unbounded").arg(plane);
    } else if (!desc.bounded()) {
        desc.size = Eigen::Vector2d(value, value);
        text = tr("Make plane %1 a %2 × %2 m rectangle").arg(plane).arg(value, 0, 'g', 6);
    } else {
        desc.size[side] = value;
        text = (side == 0 ? tr("Set plane %1 width to %2 m") : tr("Set plane %1 height to %2 m"))
                   .arg(plane)
                   .arg(value, 0, 'g', 6);
    }
    // making or unmaking a rectangle is a step of its own; steps of a side in between merge
    const bool resized = desc.bounded() && m_edits->document()->scene().planes[std::size_t(plane)].bounded();
    m_edits->push(text, label, std::move(edited),
                  step && resized ? QStringLiteral("plane%1.size.%2").arg(plane).arg(QLatin1String(kSides[side]))
                                  : QString());
    showChosen();
}

void InspectorPlanes::editPoint(bool axisVector, int axis, double value, bool step)
{
    const int plane = currentPlane();
    if (plane < 0)
        return;
    const QLatin1String name(kAxes[axis]);
    const QString text = axisVector ? tr("Set plane %1 axis %2 to %3") : tr("Set plane %1 centre %2 to %3");
    m_edits->apply(
        text.arg(plane).arg(name).arg(value, 0, 'g', 6), core::Parameter::Coordinate,
        (axisVector ? tr("Plane axis %1") : tr("Plane centre %1")).arg(name), value,
        [plane, axisVector, axis, value](core::SceneDesc &scene) {
            core::PlaneDesc &desc = scene.planes[std::size_t(plane)];
            (axisVector ? desc.axis : desc.centre)[axis] = value;
        },
        step ? QStringLiteral("plane%1.%2.%3").arg(plane).arg(axisVector ? u"axis" : u"centre").arg(name) : QString());
}

}  // namespace ui
