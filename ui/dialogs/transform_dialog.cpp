#include "transform_dialog.h"

#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "ui/panels/value_spin_box.h"
#include "ui/viewport/edit_tools.h"

#include "core/model/validate.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStringList>
#include <QUndoStack>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

namespace {

// how the arrows step each value (any value can be typed; the check says what is wrong)
constexpr SliderScale kMoveScale{-10.0, 10.0, core::Scale::Linear, false, 2000};     // 0.1 m a step
constexpr SliderScale kAngleScale{-360.0, 360.0, core::Scale::Linear, false, 1440};  // 5° a step
constexpr SliderScale kFactorScale{-10.0, 10.0, core::Scale::Linear, false, 2000};   // 0.1 a step
constexpr SliderScale kAxisScale{-1.0, 1.0, core::Scale::Linear, false, 200};        // 0.1 a step

constexpr const char *kAxisNames[] = {"x", "y", "z"};

QString number(double value)
{
    return QString::number(value, 'g', 6);
}

QString vectorText(const Eigen::Vector3d &v)
{
    return QStringLiteral("(%1, %2, %3)").arg(number(v.x()), number(v.y()), number(v.z()));
}

QString particlesText(std::size_t count)
{
    return count == 1 ? TransformDialog::tr("1 particle") : TransformDialog::tr("%1 particles").arg(count);
}

// three fields in a row, named transform-<key>-x, -y, -z
std::array<ValueSpinBox *, 3> fieldRow(QWidget *parent, QFormLayout *form, const QString &label, const char *key,
                                       const SliderScale &scale, double value, const QString &tip)
{
    std::array<ValueSpinBox *, 3> boxes{};
    auto *row = new QHBoxLayout;
    for (int axis = 0; axis < 3; ++axis) {
        auto *box = new ValueSpinBox(scale, parent);
        box->setNonFiniteTypable(true);
        box->setObjectName(QStringLiteral("transform-%1-%2").arg(QLatin1String(key), QLatin1String(kAxisNames[axis])));
        box->setValue(value);
        box->setToolTip(tip);
        row->addWidget(box);
        boxes[std::size_t(axis)] = box;
    }
    form->addRow(label, row);
    return boxes;
}

Eigen::Vector3d valuesOf(const std::array<ValueSpinBox *, 3> &boxes)
{
    return {boxes[0]->typedValue(), boxes[1]->typedValue(), boxes[2]->typedValue()};
}

}  // namespace

QString transformText(std::size_t particles, const SelectionTransform &transform)
{
    QStringList parts;
    if (!transform.translation.isZero(0.0))
        parts << TransformDialog::tr("move by %1 m").arg(vectorText(transform.translation));
    if (transform.angleDegrees != 0.0) {
        const Eigen::Vector3d &a = transform.axis;
        QString about = vectorText(a);
        for (int k = 0; k < 3; ++k)
            if (a[k] > 0.0 && a[(k + 1) % 3] == 0.0 && a[(k + 2) % 3] == 0.0)
                about = QLatin1String(kAxisNames[k]);
        parts << TransformDialog::tr("rotate %1° about %2").arg(number(transform.angleDegrees), about);
    }
    if (transform.scale != Eigen::Vector3d::Ones()) {
        const Eigen::Vector3d &s = transform.scale;
        const QString factor = s.x() == s.y() && s.y() == s.z() ? number(s.x()) : vectorText(s);
        parts << (transform.scaleRestLengths ? TransformDialog::tr("scale ×%1 with rest lengths")
                                             : TransformDialog::tr("scale ×%1"))
                     .arg(factor);
    }
    return TransformDialog::tr("Transform %1: %2").arg(particlesText(particles), parts.join(QStringLiteral(", ")));
}

TransformDialog::TransformDialog(SceneDocument *document, EditTools *tools, QWidget *parent)
    : QDialog(parent), m_document(document), m_tools(tools)
{
    setWindowTitle(tr("Transform Selection"));
    setObjectName(QStringLiteral("transformDialog"));
    auto *layout = new QVBoxLayout(this);
    auto *form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    layout->addLayout(form);

    // move, turn, scale: each left at no change does nothing
    m_move = fieldRow(this, form, tr("Move by x, y, z (m)"), "move", kMoveScale, 0.0,
                      tr("How far the selected particles move, m"));
    m_angle = new ValueSpinBox(kAngleScale, this);
    m_angle->setNonFiniteTypable(true);
    m_angle->setObjectName(QStringLiteral("transform-angle"));
    m_angle->setValue(0.0);
    m_angle->setToolTip(tr("Degrees, counter-clockwise as seen from the tip of the axis (right-handed)"));
    m_axisBox = new QComboBox(this);
    m_axisBox->setObjectName(QStringLiteral("transform-axis"));
    m_axisBox->addItems({tr("about x"), tr("about y"), tr("about z"), tr("about the axis typed below")});
    m_axisBox->setCurrentIndex(int(Axis::Y));
    auto *turnRow = new QHBoxLayout;
    turnRow->addWidget(m_angle);
    turnRow->addWidget(m_axisBox);
    form->addRow(tr("Rotate by (°)"), turnRow);
    m_axis = fieldRow(this, form, tr("Typed axis x, y, z"), "axis", kAxisScale, 0.0,
                      tr("The direction of the rotation axis through the centroid; any length but zero"));
    m_scale = fieldRow(this, form, tr("Scale by x, y, z"), "scale", kFactorScale, 1.0,
                       tr("The factor along each axis about the centroid; negative mirrors, 0 is refused"));
    m_uniform = new QCheckBox(tr("Uniform (the same factor along every axis)"), this);
    m_uniform->setObjectName(QStringLiteral("transform-uniform"));
    m_uniform->setChecked(true);
    form->addRow(QString(), m_uniform);
    m_restLengths = new QCheckBox(tr("Scale the rest lengths of the springs within the selection"), this);
    m_restLengths->setObjectName(QStringLiteral("transform-scale-rest-lengths"));
    m_restLengths->setToolTip(tr("On: each spring with both ends selected is at rest at its new length, so a scaled "
                                 "body starts at rest. Off: springs keep their rest lengths, so a scaled body starts "
                                 "stretched or squeezed and springs back when the run starts"));
    form->addRow(QString(), m_restLengths);

    // what it does, in words
    auto *note = new QLabel(
        tr("Scales, then rotates, both about the selection's centroid, then moves: the initial positions of the "
           "selected particles (pinned ones too) and of the ends of selected springs. Velocities turn with them. "
           "Masses and radii stay. Springs to particles outside the selection keep their rest lengths; springs "
           "within keep theirs unless the box above is checked."),
        this);
    note->setWordWrap(true);
    layout->addWidget(note);
    m_pivot = new QLabel(this);
    m_pivot->setObjectName(QStringLiteral("transform-pivot"));
    m_pivot->setWordWrap(true);
    layout->addWidget(m_pivot);
    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("transform-problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    layout->addWidget(m_problem);

    // Apply keeps the dialog open for another step; OK applies and closes. Neither is the default
    // button (a QDialogButtonBox would make OK one): Return in a field only takes its value
    m_apply = new QPushButton(tr("&Apply"), this);
    m_apply->setObjectName(QStringLiteral("transformApply"));
    m_apply->setToolTip(tr("Apply to the selection now and keep the dialog open (one undo step)"));
    m_ok = new QPushButton(tr("OK"), this);
    m_ok->setObjectName(QStringLiteral("transformOk"));
    m_ok->setToolTip(tr("Apply to the selection and close (one undo step)"));
    auto *close = new QPushButton(tr("Close"), this);
    close->setObjectName(QStringLiteral("transformClose"));
    close->setToolTip(tr("Close without applying what is typed"));
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    for (QPushButton *button : {close, m_apply, m_ok}) {
        button->setAutoDefault(false);
        buttons->addWidget(button);
    }
    layout->addLayout(buttons);
    connect(m_apply, &QPushButton::clicked, this, &TransformDialog::apply);
    connect(m_ok, &QPushButton::clicked, this, [this] {
        if (apply())
            accept();
    });
    connect(close, &QPushButton::clicked, this, &QDialog::reject);

    // checked as a value changes, and as typing ends (a NaN typed leaves the value as it was)
    for (const auto *row : {&m_move, &m_axis, &m_scale})
        for (ValueSpinBox *box : *row) {
            connect(box, &QDoubleSpinBox::valueChanged, this, &TransformDialog::check);
            connect(box, &QAbstractSpinBox::editingFinished, this, &TransformDialog::check);
        }
    connect(m_angle, &QDoubleSpinBox::valueChanged, this, &TransformDialog::check);
    connect(m_angle, &QAbstractSpinBox::editingFinished, this, &TransformDialog::check);
    connect(m_scale[0], &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (!m_uniform->isChecked())
            return;
        for (int axis = 1; axis < 3; ++axis) {
            const QSignalBlocker block(m_scale[std::size_t(axis)]);
            m_scale[std::size_t(axis)]->setValue(value);
        }
        check();
    });
    connect(m_uniform, &QCheckBox::toggled, this, &TransformDialog::uniformToggled);
    connect(m_axisBox, &QComboBox::currentIndexChanged, this, &TransformDialog::axisChosen);
    connect(m_tools, &EditTools::selectionChanged, this, &TransformDialog::refreshPivot);
    connect(m_document, &SceneDocument::sceneChanged, this, &TransformDialog::refreshPivot);
    uniformToggled(true);
    axisChosen();
    refreshPivot();
}

void TransformDialog::axisChosen()
{
    // a named axis shows its direction; only a typed one can be edited
    const auto axis = Axis(m_axisBox->currentIndex());
    for (int k = 0; k < 3; ++k) {
        ValueSpinBox *box = m_axis[std::size_t(k)];
        box->setEnabled(axis == Axis::Typed);
        if (axis != Axis::Typed) {
            const QSignalBlocker block(box);
            box->setValue(int(axis) == k ? 1.0 : 0.0);
        }
    }
    check();
}

void TransformDialog::uniformToggled(bool uniform)
{
    for (int axis = 1; axis < 3; ++axis) {
        ValueSpinBox *box = m_scale[std::size_t(axis)];
        box->setEnabled(!uniform);
        if (uniform) {
            const QSignalBlocker block(box);
            box->setValue(m_scale[0]->value());
        }
    }
    check();
}

std::optional<SelectionTransform> TransformDialog::transform() const
{
    SelectionTransform t;
    t.translation = valuesOf(m_move);
    t.angleDegrees = m_angle->typedValue();
    t.axis = valuesOf(m_axis);
    t.scale = valuesOf(m_scale);
    t.scaleRestLengths = m_restLengths->isChecked();
    const bool finite = t.translation.allFinite() && std::isfinite(t.angleDegrees) && t.axis.allFinite() &&
                        t.scale.allFinite();
    if (!finite || (t.scale.array() == 0.0).any() || (t.angleDegrees != 0.0 && t.axis.isZero(0.0)))
        return std::nullopt;
    return t;
}

void TransformDialog::check()
{
    // the first value that cannot be used, by name
    QString problem;
    const auto name = [](const QString &what, int axis) {
        return QStringLiteral("%1 %2").arg(what, QLatin1String(kAxisNames[axis]));
    };
    const auto notANumber = [](const QString &what, double value) {
        return tr("%1 must be a number (got %2)").arg(what, QString::number(value));
    };
    for (int k = 0; k < 3 && problem.isEmpty(); ++k)
        if (!std::isfinite(m_move[std::size_t(k)]->typedValue()))
            problem = notANumber(name(tr("Move"), k), m_move[std::size_t(k)]->typedValue());
    if (problem.isEmpty() && !std::isfinite(m_angle->typedValue()))
        problem = notANumber(tr("The angle"), m_angle->typedValue());
    for (int k = 0; k < 3 && problem.isEmpty(); ++k)
        if (!std::isfinite(m_axis[std::size_t(k)]->typedValue()))
            problem = notANumber(name(tr("Axis"), k), m_axis[std::size_t(k)]->typedValue());
    if (problem.isEmpty() && m_angle->typedValue() != 0.0 && valuesOf(m_axis).isZero(0.0))
        problem = tr("The rotation axis is zero: type a direction, or rotate about x, y or z");
    for (int k = 0; k < 3 && problem.isEmpty(); ++k) {
        const double factor = m_scale[std::size_t(k)]->typedValue();
        if (!std::isfinite(factor))
            problem = notANumber(name(tr("Scale"), k), factor);
        else if (factor == 0.0)
            problem = tr("%1 must not be 0: it would flatten the selection (1 leaves it as it is)").arg(name(tr("Scale"), k));
    }
    if (problem.isEmpty() && selectedParticles(m_document->scene(), m_tools->selection()).empty())
        problem = tr("Nothing selected: select the particles to transform");
    m_problem->setText(problem);
    m_apply->setEnabled(problem.isEmpty());
    m_ok->setEnabled(problem.isEmpty());
}

void TransformDialog::refreshPivot()
{
    const std::vector<int> particles = selectedParticles(m_document->scene(), m_tools->selection());
    m_pivot->setText(particles.empty()
                         ? tr("Nothing selected")
                         : tr("About the centroid of %1: %2 m")
                               .arg(particlesText(particles.size()), vectorText(centroid(m_document->scene(), particles))));
    check();
}

QString TransformDialog::problemText() const
{
    return m_problem->text();
}

QString TransformDialog::pivotText() const
{
    return m_pivot->text();
}

bool TransformDialog::apply()
{
    check();
    const std::optional<SelectionTransform> t = transform();
    const std::vector<int> particles = selectedParticles(m_document->scene(), m_tools->selection());
    if (!t || particles.empty())
        return false;
    if (t->isIdentity())
        return true;

    // the result must be a scene the file format takes, or nothing changes
    auto edited = std::make_shared<core::SceneDesc>(m_document->scene());
    transformParticles(*edited, particles, *t);
    if (const std::optional<core::SceneProblem> problem = core::findProblem(*edited)) {
        m_problem->setText(tr("Not transformed: %1 %2; nothing was changed")
                               .arg(QString::fromStdString(problem->path), QString::fromStdString(problem->message)));
        return false;
    }
    const QString text = transformText(particles.size(), *t);
    m_document->undoStack()->push(new SceneCommand(*m_document, text, std::move(edited)));
    emit applied(text);
    return true;
}

}  // namespace ui
