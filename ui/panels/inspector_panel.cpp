#include "inspector_panel.h"

#include "ui/viewport/edit_tools.h"
#include "inspector_edits.h"
#include "inspector_field.h"
#include "inspector_planes.h"
#include "status_text.h"
#include "ui/document/scene_document.h"
#include "ui/document/scene_edits.h"

#include "core/model/snapshot.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QStringList>
#include <QVBoxLayout>
#include <algorithm>
#include <initializer_list>
#include <optional>

namespace ui {

namespace {

// the width of one axis of a vector, its field or its current value: 8 significant digits with
// the sign and the point, whatever the value shown
int vectorFieldWidth(const QWidget *widget)
{
    return widget->fontMetrics().horizontalAdvance(QStringLiteral("-12.345678")) + 12;
}

// one value of a particle: a scalar member, or one axis of a vector member
struct ParticleField {
    const char *key;    // object name and undo merge key: "mass", "position.x"
    const char *label;  // in messages and undo text: "Position x"
    core::Parameter parameter;
    double core::ParticleDesc::*scalar;
    Eigen::Vector3d core::ParticleDesc::*vector;
    int axis;
};

const ParticleField kParticleFields[] = {
    {"mass", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Mass"), core::Parameter::Mass, &core::ParticleDesc::mass,
     nullptr, 0},
    {"radius", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Radius"), core::Parameter::Radius,
     &core::ParticleDesc::radius, nullptr, 0},
    {"position.x", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Position x"), core::Parameter::Coordinate, nullptr,
     &core::ParticleDesc::position, 0},
    {"position.y", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Position y"), core::Parameter::Coordinate, nullptr,
     &core::ParticleDesc::position, 1},
    {"position.z", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Position z"), core::Parameter::Coordinate, nullptr,
     &core::ParticleDesc::position, 2},
    {"velocity.x", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Velocity x"), core::Parameter::Speed, nullptr,
     &core::ParticleDesc::velocity, 0},
    {"velocity.y", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Velocity y"), core::Parameter::Speed, nullptr,
     &core::ParticleDesc::velocity, 1},
    {"velocity.z", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Velocity z"), core::Parameter::Speed, nullptr,
     &core::ParticleDesc::velocity, 2},
    // ω: a pinned particle may be given one too (it turns in place, a wheel that drives what it touches)
    {"spin.x", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Spin x"), core::Parameter::AngularSpeed, nullptr,
     &core::ParticleDesc::angularVelocity, 0},
    {"spin.y", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Spin y"), core::Parameter::AngularSpeed, nullptr,
     &core::ParticleDesc::angularVelocity, 1},
    {"spin.z", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Spin z"), core::Parameter::AngularSpeed, nullptr,
     &core::ParticleDesc::angularVelocity, 2},
};

struct SpringField {
    const char *key;
    const char *label;
    core::Parameter parameter;
    double core::SpringDesc::*member;
};

const SpringField kSpringFields[] = {
    {"stiffness", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Stiffness"), core::Parameter::Stiffness,
     &core::SpringDesc::stiffness},
    {"damping", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Damping"), core::Parameter::Damping,
     &core::SpringDesc::damping},
    {"restLength", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Rest length"), core::Parameter::RestLength,
     &core::SpringDesc::restLength},
    {"breakStrain", QT_TRANSLATE_NOOP("ui::InspectorPanel", "Breaking strain"), core::Parameter::BreakStrain,
     &core::SpringDesc::breakStrain},
};

// the field's value in a particle, for reading (const) or writing
template <class Particle>
decltype(auto) valueOf(Particle &particle, const ParticleField &field)
{
    return field.scalar ? particle.*field.scalar : (particle.*field.vector)[field.axis];
}

// the selected indices the scene still has (the tools clamp the selection, but a refresh may run
// before they have)
std::vector<std::size_t> present(const std::vector<int> &indices, std::size_t count)
{
    std::vector<std::size_t> kept;
    for (int i : indices)
        if (i >= 0 && std::size_t(i) < count)
            kept.push_back(std::size_t(i));
    return kept;
}

// the value every item shares, or nullopt when they differ
template <class Read>
std::optional<double> sharedValue(const std::vector<std::size_t> &indices, Read read)
{
    const double first = read(indices.front());
    for (std::size_t i : indices)
        if (!(read(i) == first))
            return std::nullopt;
    return first;
}

void showIn(InspectorSpinBox *field, const std::optional<double> &value, double start)
{
    if (value)
        field->showValue(*value);
    else
        field->showMixed(start);
}

QString unitOf(core::Parameter parameter)
{
    const std::string_view unit = core::parameterInfo(parameter).unit;
    return QString::fromUtf8(unit.data(), qsizetype(unit.size()));
}

// "Stiffness (N/m)", or "Breaking strain" for a value without a unit, not "Breaking strain ()"
QString withUnit(const QString &text, const QString &unit)
{
    return unit.isEmpty() ? text : QStringLiteral("%1 (%2)").arg(text, unit);
}

QString tooltipOf(core::Parameter parameter)
{
    const std::string_view tip = core::parameterInfo(parameter).tooltip;
    return QString::fromUtf8(tip.data(), qsizetype(tip.size()));
}

}  // namespace

InspectorPanel::InspectorPanel(SceneDocument *document, EditTools *tools, QWidget *parent)
    : QWidget(parent), m_document(document), m_tools(tools), m_edits(new InspectorEdits(document, this)),
      m_title(new QLabel(this)), m_message(new QLabel(this))
{
    auto *layout = new QVBoxLayout(this);
    m_title->setObjectName(QStringLiteral("inspector-title"));
    layout->addWidget(m_title);

    // particles: one row per scalar, one row of three fields per vector
    m_particlesGroup = new QGroupBox(tr("Particles"), this);
    m_particlesGroup->setObjectName(QStringLiteral("inspector-particles"));
    auto *particleForm = new QFormLayout(m_particlesGroup);
    particleForm->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    // a row's label goes above its fields where the dock is too narrow for both side by side: the
    // three fields of a vector and its label need more than a 900-pixel window leaves the dock
    particleForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
    const QString initialTip = tr("The scene's initial conditions, as saved in its file: the run starts from them "
                                  "(Reset returns to them); the running simulation's state is the Current row");
    QHBoxLayout *vectorRow = nullptr;
    for (std::size_t f = 0; f < std::size(kParticleFields); ++f) {
        const ParticleField &field = kParticleFields[f];
        auto *box = new InspectorSpinBox(field.parameter, m_particlesGroup);
        box->setObjectName(QStringLiteral("inspector-") + QLatin1String(field.key));
        const QString unit = unitOf(field.parameter);
        box->setToolTip(field.vector ? withUnit(tr(field.label), unit) + QStringLiteral(". ") + initialTip
                                     : withUnit(tooltipOf(field.parameter), unit));
        connect(box, &InspectorSpinBox::typed, this, [this, f](double value) { editParticles(f, value, false); });
        connect(box, &InspectorSpinBox::stepped, this, [this, f](double value) { editParticles(f, value, true); });
        m_particleFields.push_back(box);
        if (!field.vector) {
            particleForm->addRow(withUnit(tr(field.label), unit), box);
            continue;
        }
        // three to a row: without arrow buttons (the keys and the wheel still step), and wide
        // enough for a value's 8 significant digits with its sign and point
        box->setButtonSymbols(QAbstractSpinBox::NoButtons);
        box->setSignificantDigits(8);
        box->setMinimumWidth(vectorFieldWidth(box));
        if (field.axis == 0) {
            vectorRow = new QHBoxLayout;
            const QString name = field.vector == &core::ParticleDesc::position   ? tr("Initial position")
                                 : field.vector == &core::ParticleDesc::velocity ? tr("Initial velocity")
                                                                                 : tr("Initial spin");
            particleForm->addRow(withUnit(name, unit), vectorRow);
        }
        vectorRow->addWidget(box);
    }
    m_pinned = new QCheckBox(tr("Pinned"), m_particlesGroup);
    m_pinned->setObjectName(QStringLiteral("inspector-pinned"));
    m_pinned->setToolTip(tr("A pinned particle never moves (and starts at rest)"));
    // pinned sits after the radius, before the vectors
    particleForm->insertRow(2, QString(), m_pinned);
    // the run's current position and velocity, read-only, after the initial ones
    const QString currentTip = tr("The running simulation's, at the time the status bar shows: it changes as "
                                  "the run goes on and is not for editing (the initial conditions above are)");
    for (std::size_t c = 0; c < m_currentFields.size(); ++c) {
        const std::size_t vector = c / 3;  // 0 position, 1 velocity, 2 spin
        const char axis = "xyz"[c % 3];
        auto *value = new QLabel(m_particlesGroup);
        const QString key = vector == 0 ? QStringLiteral("position")
                            : vector == 1 ? QStringLiteral("velocity")
                                          : QStringLiteral("spin");
        value->setObjectName(QStringLiteral("inspector-current-%1.%2").arg(key).arg(QLatin1Char(axis)));
        value->setToolTip(currentTip);
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        // as wide as the initial fields above, whatever the value: a width that followed the text
        // would widen the dock, and narrow the view, as a run or a drag changes it
        value->setMinimumWidth(vectorFieldWidth(value));
        m_currentFields[c] = value;
        if (c % 3 == 0) {
            vectorRow = new QHBoxLayout;
            const QString name = vector == 0 ? tr("Current position")
                                 : vector == 1 ? tr("Current velocity")
                                               : tr("Current spin");
            const core::Parameter parameter = vector == 0   ? core::Parameter::Coordinate
                                              : vector == 1 ? core::Parameter::Speed
                                                            : core::Parameter::AngularSpeed;
            particleForm->addRow(withUnit(name, unitOf(parameter)), vectorRow);
        }
        vectorRow->addWidget(value, 1);
    }
    connect(m_pinned, &QCheckBox::clicked, this, &InspectorPanel::pinSelection);
    layout->addWidget(m_particlesGroup);

    // two particles: how far apart they are, now and at the start
    m_distanceGroup = new QGroupBox(this);
    m_distanceGroup->setObjectName(QStringLiteral("inspector-distance"));
    auto *distanceForm = new QFormLayout(m_distanceGroup);
    distanceForm->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    m_currentDistance = new QLabel(m_distanceGroup);
    m_currentDistance->setObjectName(QStringLiteral("inspector-distance-current"));
    m_currentDistance->setToolTip(tr("The distance in the running simulation, from the first particle to the "
                                     "second, with its x, y and z parts; it changes as the run goes on"));
    m_initialDistance = new QLabel(m_distanceGroup);
    m_initialDistance->setObjectName(QStringLiteral("inspector-distance-initial"));
    m_initialDistance->setToolTip(tr("The distance between the initial positions (where Reset puts them)"));
    for (QLabel *value : {m_currentDistance, m_initialDistance})
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    distanceForm->addRow(tr("Current"), m_currentDistance);
    distanceForm->addRow(tr("Initial"), m_initialDistance);
    layout->addWidget(m_distanceGroup);

    // springs: their values, and the particles they join
    m_springsGroup = new QGroupBox(tr("Springs"), this);
    m_springsGroup->setObjectName(QStringLiteral("inspector-springs"));
    auto *springForm = new QFormLayout(m_springsGroup);
    springForm->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    m_springEnds = new QLabel(m_springsGroup);
    m_springEnds->setObjectName(QStringLiteral("inspector-springEnds"));
    springForm->addRow(tr("Joins"), m_springEnds);
    for (std::size_t f = 0; f < std::size(kSpringFields); ++f) {
        const SpringField &field = kSpringFields[f];
        auto *box = new InspectorSpinBox(field.parameter, m_springsGroup);
        box->setObjectName(QStringLiteral("inspector-") + QLatin1String(field.key));
        const QString unit = unitOf(field.parameter);
        box->setToolTip(withUnit(tooltipOf(field.parameter), unit));
        connect(box, &InspectorSpinBox::typed, this, [this, f](double value) { editSprings(f, value, false); });
        connect(box, &InspectorSpinBox::stepped, this, [this, f](double value) { editSprings(f, value, true); });
        springForm->addRow(withUnit(tr(field.label), unit), box);
        m_springFields.push_back(box);
    }
    layout->addWidget(m_springsGroup);

    // the scene's planes, whatever is selected
    m_planes = new InspectorPlanes(m_edits, this);
    layout->addWidget(m_planes);

    // refusals show below until the next accepted change
    m_message->setObjectName(QStringLiteral("inspector-message"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #b00020"));
    m_message->hide();
    layout->addWidget(m_message);
    layout->addStretch(1);

    // leaving a field ends its step sequence and shows the scene's value again (a field left
    // empty or mixed shows what the items hold)
    for (const std::vector<InspectorSpinBox *> *fields : {&m_particleFields, &m_springFields})
        for (InspectorSpinBox *box : *fields)
            connect(box, &QAbstractSpinBox::editingFinished, this, [this] {
                m_edits->endSession();
                refresh();
            });

    connect(m_edits, &InspectorEdits::valueRefused, this, &InspectorPanel::showRefusal);
    connect(m_edits, &InspectorEdits::applied, m_message, &QWidget::hide);
    connect(m_document, &SceneDocument::sceneChanged, this, &InspectorPanel::refresh);
    connect(m_tools, &EditTools::selectionChanged, this, [this] {
        m_edits->endSession();
        refresh();
    });
    // as wide as its widest group from the start (each polished first: the style sets its frames'
    // and fields' sizes): the groups show as the selection changes, and a panel that widened with
    // them narrowed the view under the cursor (the dock grew 38 pixels at the first particle
    // selected, in the middle of a drag)
    int widest = 0;
    for (QWidget *group : std::initializer_list<QWidget *>{m_particlesGroup, m_distanceGroup, m_springsGroup, m_planes}) {
        group->ensurePolished();
        widest = std::max(widest, group->minimumSizeHint().width());
    }
    setMinimumWidth(widest + layout->contentsMargins().left() + layout->contentsMargins().right());
    refresh();
}

InspectorPanel::~InspectorPanel()
{
    // closing the window moves the focus out of a field, whose editingFinished must not reach a
    // panel that is half destroyed
    for (InspectorSpinBox *box : findChildren<InspectorSpinBox *>())
        disconnect(box, nullptr, this, nullptr);
}

InspectorSpinBox *InspectorPanel::particleField(const QString &key) const
{
    for (std::size_t f = 0; f < std::size(kParticleFields); ++f)
        if (key == QLatin1String(kParticleFields[f].key))
            return m_particleFields[f];
    return nullptr;
}

InspectorSpinBox *InspectorPanel::springField(const QString &key) const
{
    for (std::size_t f = 0; f < std::size(kSpringFields); ++f)
        if (key == QLatin1String(kSpringFields[f].key))
            return m_springFields[f];
    return nullptr;
}

QLabel *InspectorPanel::currentField(const QString &key) const
{
    for (QLabel *value : m_currentFields)
        if (value->objectName() == QStringLiteral("inspector-current-") + key)
            return value;
    return nullptr;
}

QLabel *InspectorPanel::distanceField(const QString &key) const
{
    return key == QLatin1String("current") ? m_currentDistance : key == QLatin1String("initial") ? m_initialDistance : nullptr;
}

std::optional<std::pair<std::size_t, std::size_t>> InspectorPanel::selectedPair() const
{
    const std::vector<std::size_t> particles =
        present(m_tools->selection().particles, m_document->scene().particles.size());
    if (particles.size() != 2)
        return std::nullopt;
    return std::pair(particles[0], particles[1]);
}

void InspectorPanel::showSnapshot(std::shared_ptr<const core::Snapshot> snapshot)
{
    m_snapshot = std::move(snapshot);
    refreshCurrent();
}

void InspectorPanel::refreshCurrent()
{
    // the selected particles' values in the latest snapshot; a dash until it has them (none yet,
    // or the worker has not caught up with an edit that added particles)
    if (m_particlesGroup->isHidden())
        return;
    const std::vector<std::size_t> particles =
        present(m_tools->selection().particles, m_document->scene().particles.size());
    const core::Snapshot *snapshot = m_snapshot.get();
    const bool known = snapshot && !particles.empty() && snapshot->particleCount() == int(m_document->scene().particles.size());
    for (std::size_t c = 0; c < m_currentFields.size(); ++c) {
        if (!known) {
            m_currentFields[c]->setText(QStringLiteral("—"));
            continue;
        }
        const std::vector<float> &values = c < 3 ? snapshot->positions
                                           : c < 6 ? snapshot->velocities
                                                   : snapshot->angularVelocities;
        // a scene that cannot turn has no spins: none turns
        const std::optional<double> shared = sharedValue(
            particles, [&](std::size_t i) { return values.empty() ? 0.0 : double(values[3 * i + c % 3]); });
        m_currentFields[c]->setText(shared ? QString::number(*shared, 'g', 6) : tr("mixed"));
    }

    // the pair's distance in the same snapshot
    if (const auto pair = selectedPair(); pair && known) {
        const auto at = [&](std::size_t i) {
            const float *p = snapshot->positions.data() + 3 * i;
            return Eigen::Vector3d(double(p[0]), double(p[1]), double(p[2]));
        };
        m_currentDistance->setText(distanceLines(at(pair->second) - at(pair->first)));
    } else {
        m_currentDistance->setText(QStringLiteral("—"));
    }
}

QString InspectorPanel::message() const
{
    return m_message->isHidden() ? QString() : m_message->text();
}

void InspectorPanel::refresh()
{
    const core::SceneDesc &scene = m_document->scene();
    const Selection &selection = m_tools->selection();
    const std::vector<std::size_t> particles = present(selection.particles, scene.particles.size());
    const std::vector<std::size_t> springs = present(selection.springs, scene.springs.size());

    // the title says what is selected
    QStringList parts;
    if (!particles.empty())
        parts << (particles.size() == 1 ? tr("1 particle") : tr("%1 particles").arg(particles.size()));
    if (!springs.empty())
        parts << (springs.size() == 1 ? tr("1 spring") : tr("%1 springs").arg(springs.size()));
    m_title->setText(parts.isEmpty() ? tr("Nothing selected") : parts.join(QStringLiteral(", ")));

    // particles: a shared value shows, differing ones show as mixed
    m_particlesGroup->setVisible(!particles.empty());
    if (!particles.empty()) {
        for (std::size_t f = 0; f < std::size(kParticleFields); ++f) {
            const ParticleField &field = kParticleFields[f];
            const auto read = [&](std::size_t i) { return valueOf(scene.particles[i], field); };
            showIn(m_particleFields[f], sharedValue(particles, read), read(particles.front()));
        }
        // a pinned particle is at rest: its velocity is not for editing
        const bool anyFree = std::any_of(particles.begin(), particles.end(),
                                         [&](std::size_t i) { return !scene.particles[i].pinned; });
        for (std::size_t f = 0; f < std::size(kParticleFields); ++f)
            if (kParticleFields[f].vector == &core::ParticleDesc::velocity)
                m_particleFields[f]->setEnabled(anyFree);
        const QSignalBlocker block(m_pinned);
        const std::optional<double> pinned =
            sharedValue(particles, [&](std::size_t i) { return scene.particles[i].pinned ? 1.0 : 0.0; });
        if (pinned) {
            m_pinned->setTristate(false);
            m_pinned->setChecked(*pinned != 0.0);
        } else {
            m_pinned->setCheckState(Qt::PartiallyChecked);
        }
        refreshCurrent();
    }

    // two particles: their distance
    const auto pair = selectedPair();
    m_distanceGroup->setVisible(pair.has_value());
    if (pair) {
        m_distanceGroup->setTitle(tr("Distance from particle %1 to %2").arg(pair->first).arg(pair->second));
        m_initialDistance->setText(
            distanceLines(scene.particles[pair->second].position - scene.particles[pair->first].position));
    }

    // springs: the same, and which particles they join
    m_springsGroup->setVisible(!springs.empty());
    if (!springs.empty()) {
        for (std::size_t f = 0; f < std::size(kSpringFields); ++f) {
            const auto read = [&](std::size_t i) { return scene.springs[i].*kSpringFields[f].member; };
            showIn(m_springFields[f], sharedValue(springs, read), read(springs.front()));
        }
        // one line, whatever the count: the first pairs, then how many more (all of them, up to a
        // screenful, in the tooltip)
        constexpr std::size_t kListed = 3;
        constexpr std::size_t kInTooltip = 60;
        const auto pairsOf = [&](std::size_t count) {
            QStringList pairs;
            for (std::size_t k = 0; k < springs.size() && k < count; ++k)
                pairs << QStringLiteral("%1–%2").arg(scene.springs[springs[k]].a).arg(scene.springs[springs[k]].b);
            return pairs.join(QStringLiteral(", "));
        };
        if (springs.size() == 1)
            m_springEnds->setText(
                tr("particles %1 and %2").arg(scene.springs[springs.front()].a).arg(scene.springs[springs.front()].b));
        else if (springs.size() <= kListed)
            m_springEnds->setText(pairsOf(kListed));
        else
            m_springEnds->setText(tr("%1 and %n more", nullptr, int(springs.size() - kListed)).arg(pairsOf(kListed)));
        m_springEnds->setToolTip(springs.size() > kInTooltip ? pairsOf(kInTooltip) + QStringLiteral(", …")
                                                             : pairsOf(kInTooltip));
    }

    m_planes->refresh();
}

void InspectorPanel::showRefusal(const QString &message)
{
    m_message->setText(message);
    m_message->show();
    // the field goes back to the scene's value
    refresh();
    emit valueRefused(message);
}

void InspectorPanel::editParticles(std::size_t f, double value, bool step)
{
    const ParticleField &field = kParticleFields[f];
    const std::vector<std::size_t> particles =
        present(m_tools->selection().particles, m_document->scene().particles.size());
    if (particles.empty())
        return;
    const QString label = tr(field.label);
    const QString text = particles.size() == 1
                             ? tr("Set %1 of particle %2 to %3").arg(label).arg(particles.front()).arg(value, 0, 'g', 6)
                             : tr("Set %1 of %2 particles to %3").arg(label).arg(particles.size()).arg(value, 0, 'g', 6);
    m_edits->apply(
        text, field.parameter, label, value,
        [&](core::SceneDesc &scene) {
            for (std::size_t i : particles)
                if (field.vector != &core::ParticleDesc::velocity || !scene.particles[i].pinned)
                    valueOf(scene.particles[i], field) = value;
        },
        step ? QStringLiteral("particle.") + QLatin1String(field.key) : QString());
}

void InspectorPanel::editSprings(std::size_t f, double value, bool step)
{
    const SpringField &field = kSpringFields[f];
    const std::vector<std::size_t> springs = present(m_tools->selection().springs, m_document->scene().springs.size());
    if (springs.empty())
        return;
    const QString label = tr(field.label);
    const QString text = springs.size() == 1
                             ? tr("Set %1 of spring %2 to %3").arg(label).arg(springs.front()).arg(value, 0, 'g', 6)
                             : tr("Set %1 of %2 springs to %3").arg(label).arg(springs.size()).arg(value, 0, 'g', 6);
    m_edits->apply(
        text, field.parameter, label, value,
        [&](core::SceneDesc &scene) {
            for (std::size_t i : springs)
                scene.springs[i].*field.member = value;
        },
        step ? QStringLiteral("spring.") + QLatin1String(field.key) : QString());
}

void InspectorPanel::pinSelection()
{
    // a click on a partly checked box checks it: every selected particle is pinned
    const bool pinned = m_pinned->checkState() != Qt::Unchecked;
    const Selection &selection = m_tools->selection();
    auto edited = std::make_shared<core::SceneDesc>(m_document->scene());
    ui::setPinned(*edited, selection.particles, pinned);
    m_edits->push(pinned ? tr("Pin particles") : tr("Free particles"), tr("Pinned"), std::move(edited));
    refresh();
}

}  // namespace ui
