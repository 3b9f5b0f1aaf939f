#include "inspector_planes.h"

#include "inspector_edits.h"
#include "inspector_field.h"
#include "ui/document/scene_document.h"

#include "core/validate.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace ui {

namespace {

const char *const kAxes[] = {"x", "y", "z"};

QString describe(const core::PlaneDesc &plane)
{
    return InspectorPlanes::tr("n = (%1, %2, %3), offset %4 m")
        .arg(plane.normal.x(), 0, 'g', 4)
        .arg(plane.normal.y(), 0, 'g', 4)
        .arg(plane.normal.z(), 0, 'g', 4)
        .arg(plane.offset, 0, 'g', 6);
}

}  // namespace

InspectorPlanes::InspectorPlanes(InspectorEdits *edits, QWidget *parent)
    : QGroupBox(tr("Planes"), parent), m_edits(edits), m_list(new QListWidget(this)),
      m_add(new QPushButton(tr("Add"), this)), m_remove(new QPushButton(tr("Remove"), this)),
      m_offset(new InspectorSpinBox(core::Parameter::Coordinate, this))
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

    // the list with its buttons, then the chosen plane's fields
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_list);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    auto *form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
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
    form->addRow(tr("Normal"), normalRow);
    form->addRow(tr("Offset (m)"), m_offset);
    layout->addLayout(form);
    connect(m_offset, &InspectorSpinBox::typed, this, [this](double value) { editOffset(value, false); });
    connect(m_offset, &InspectorSpinBox::stepped, this, [this](double value) { editOffset(value, true); });

    // leaving a field or choosing another plane ends a step sequence
    for (InspectorSpinBox *box : {m_normal[0], m_normal[1], m_normal[2], m_offset})
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
    m_remove->setEnabled(plane >= 0);
    for (InspectorSpinBox *box : {m_normal[0], m_normal[1], m_normal[2], m_offset})
        box->setEnabled(plane >= 0);
    if (plane < 0) {
        for (InspectorSpinBox *box : {m_normal[0], m_normal[1], m_normal[2], m_offset})
            box->showValue(0.0);
        return;
    }
    const core::PlaneDesc &desc = m_edits->document()->scene().planes[std::size_t(plane)];
    for (int axis = 0; axis < 3; ++axis)
        m_normal[std::size_t(axis)]->showValue(desc.normal[axis]);
    m_offset->showValue(desc.offset);
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

}  // namespace ui
