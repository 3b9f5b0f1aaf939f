#include "parameters_panel.h"

#include "parameter_row.h"
#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "status_text.h"

#include "core/contacts/solver_names.h"
#include "core/integrators/stability.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QUndoStack>
#include <QVBoxLayout>
#include <array>

namespace ui {

namespace {

enum class Group { Time, World, Contacts, Springs };

// one row: which parameter of the table it shows, and where that value lives in the scene
struct Binding {
    const char *key;  // the row's name and the undo merge key
    core::Parameter parameter;
    Group group;
    const char *suffix;                                  // after the table's label: "Gravity x"
    double (*read)(const core::SceneDesc &);             // the value shown
    void (*writeSetting)(core::Settings &, double);      // for a setting; null for a spring value
    double core::SpringDesc::*springField;               // for a spring value; null for a setting
};

// the first spring's value stands for all of them
template <double core::SpringDesc::*field>
double firstSpring(const core::SceneDesc &scene)
{
    const core::Parameter parameter = field == &core::SpringDesc::stiffness ? core::Parameter::Stiffness
                                                                             : core::Parameter::Damping;
    return scene.springs.empty() ? core::parameterInfo(parameter).defaultValue : scene.springs.front().*field;
}

const Binding kBindings[] = {
    {"timeStep", core::Parameter::TimeStep, Group::Time, "",
     [](const core::SceneDesc &s) { return s.settings.timeStep; },
     [](core::Settings &s, double v) { s.timeStep = v; }, nullptr},
    {"substeps", core::Parameter::Substeps, Group::Time, "",
     [](const core::SceneDesc &s) { return double(s.settings.substeps); },
     [](core::Settings &s, double v) { s.substeps = int(v); }, nullptr},
    {"xpbdIterations", core::Parameter::XpbdIterations, Group::Time, "",
     [](const core::SceneDesc &s) { return double(s.settings.xpbdIterations); },
     [](core::Settings &s, double v) { s.xpbdIterations = int(v); }, nullptr},
    {"solverIterations", core::Parameter::SolverIterations, Group::Time, "",
     [](const core::SceneDesc &s) { return double(s.settings.solverIterations); },
     [](core::Settings &s, double v) { s.solverIterations = int(v); }, nullptr},
    {"tolerance", core::Parameter::Tolerance, Group::Time, "",
     [](const core::SceneDesc &s) { return s.settings.tolerance; },
     [](core::Settings &s, double v) { s.tolerance = v; }, nullptr},
    {"gravity.x", core::Parameter::Gravity, Group::World, " x",
     [](const core::SceneDesc &s) { return s.settings.gravity.x(); },
     [](core::Settings &s, double v) { s.gravity.x() = v; }, nullptr},
    {"gravity.y", core::Parameter::Gravity, Group::World, " y",
     [](const core::SceneDesc &s) { return s.settings.gravity.y(); },
     [](core::Settings &s, double v) { s.gravity.y() = v; }, nullptr},
    {"gravity.z", core::Parameter::Gravity, Group::World, " z",
     [](const core::SceneDesc &s) { return s.settings.gravity.z(); },
     [](core::Settings &s, double v) { s.gravity.z() = v; }, nullptr},
    {"viscosity", core::Parameter::Viscosity, Group::World, "",
     [](const core::SceneDesc &s) { return s.settings.viscosity; },
     [](core::Settings &s, double v) { s.viscosity = v; }, nullptr},
    {"restitution", core::Parameter::Restitution, Group::Contacts, "",
     [](const core::SceneDesc &s) { return s.settings.restitution; },
     [](core::Settings &s, double v) { s.restitution = v; }, nullptr},
    {"friction", core::Parameter::Friction, Group::Contacts, "",
     [](const core::SceneDesc &s) { return s.settings.friction; },
     [](core::Settings &s, double v) { s.friction = v; }, nullptr},
    // unset, the static coefficient follows friction and the row shows friction's; editing it sets it
    {"staticFriction", core::Parameter::Friction, Group::Contacts, "",
     [](const core::SceneDesc &s) { return s.settings.staticFriction.value_or(s.settings.friction); },
     [](core::Settings &s, double v) { s.staticFriction = v; }, nullptr},
    {"rollingFriction", core::Parameter::Friction, Group::Contacts, "",
     [](const core::SceneDesc &s) { return s.settings.rollingFriction; },
     [](core::Settings &s, double v) { s.rollingFriction = v; }, nullptr},
    {"spinningFriction", core::Parameter::Friction, Group::Contacts, "",
     [](const core::SceneDesc &s) { return s.settings.spinningFriction; },
     [](core::Settings &s, double v) { s.spinningFriction = v; }, nullptr},
    // 0: each sheet's own thickness, from its particles' radii
    {"thickness", core::Parameter::Thickness, Group::Contacts, "",
     [](const core::SceneDesc &s) { return s.settings.thickness; },
     [](core::Settings &s, double v) { s.thickness = v; }, nullptr},
    {"stiffness", core::Parameter::Stiffness, Group::Springs, "", firstSpring<&core::SpringDesc::stiffness>,
     nullptr, &core::SpringDesc::stiffness},
    {"damping", core::Parameter::Damping, Group::Springs, "", firstSpring<&core::SpringDesc::damping>, nullptr,
     &core::SpringDesc::damping},
};

QString fromView(std::string_view text)
{
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

// what each integrator is, for its entry's tooltip
QString integratorTip(core::Integrator integrator)
{
    switch (integrator) {
    case core::Integrator::SymplecticEuler:
        return ParametersPanel::tr("First order, one force evaluation per step; the handout's scheme");
    case core::Integrator::ExplicitEuler:
        return ParametersPanel::tr("First order, one force evaluation per step; gains energy on springs");
    case core::Integrator::VelocityVerlet:
        return ParametersPanel::tr("Second order and symplectic, two force evaluations per step");
    case core::Integrator::Rk4: return ParametersPanel::tr("Fourth order, four force evaluations per step");
    case core::Integrator::ImplicitEuler:
        return ParametersPanel::tr("First order, stable at any step but damps; a linear solve per step");
    case core::Integrator::AdaptiveRk45:
        return ParametersPanel::tr("Fifth order, shortens its steps to keep the local error under the tolerance");
    case core::Integrator::Xpbd:
        return ParametersPanel::tr("Springs as constraints with compliance 1/k: no stability limit, first order; "
                                   "use many sub-steps");
    case core::Integrator::Projective:
        return ParametersPanel::tr("Implicit Euler by projective dynamics: a prefactored solve, no stability limit, "
                                   "damps like implicit Euler; set its iterations");
    case core::Integrator::Vbd:
        return ParametersPanel::tr("Implicit Euler by vertex block descent: a Newton step per particle, colour by "
                                   "colour, no stability limit; set its iterations");
    }
    return QString();
}

// the contact solvers as the panel names them, in core::kContactSolvers order
QString contactSolverLabel(core::ContactSolver solver)
{
    switch (solver) {
    case core::ContactSolver::Iterative: return ParametersPanel::tr("Iterative");
    case core::ContactSolver::Handout: return ParametersPanel::tr("Handout");
    }
    return QString();
}

QString contactSolverTip(core::ContactSolver solver)
{
    switch (solver) {
    case core::ContactSolver::Iterative:
        return ParametersPanel::tr("Impacts located in time within the sub-step, then every resting contact solved "
                                   "together with Coulomb friction, so stacks and piles come to rest (the default)");
    case core::ContactSolver::Handout:
        return ParametersPanel::tr("The course handout's single pass: each contact pushed apart and given an impulse "
                                   "once per sub-step");
    }
    return QString();
}

}  // namespace

ParametersPanel::ParametersPanel(SceneDocument &document, QWidget *parent)
    : QWidget(parent), m_document(document), m_message(new QLabel(this))
{
    // one group box per group, in this order
    auto *layout = new QVBoxLayout(this);
    const std::array<QString, 4> titles = {tr("Time"), tr("World"), tr("Contacts"), tr("Springs")};
    std::array<QFormLayout *, 4> forms{};
    for (std::size_t g = 0; g < titles.size(); ++g) {
        auto *box = new QGroupBox(titles[g], this);
        forms[g] = new QFormLayout(box);
        forms[g]->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
        layout->addWidget(box);
        if (Group(g) == Group::Springs)
            m_springsGroup = box;
    }

    // the integrator heads the time group; its tolerance row follows the substeps
    m_integrator = new QComboBox(this);
    m_integrator->setObjectName(QStringLiteral("parameter-integrator"));
    m_integrator->setToolTip(tr("How each sub-step advances the particles"));
    for (core::Integrator integrator : core::kIntegrators) {
        m_integrator->addItem(fromView(core::integratorName(integrator)));
        m_integrator->setItemData(m_integrator->count() - 1, integratorTip(integrator), Qt::ToolTipRole);
    }
    forms[std::size_t(Group::Time)]->addRow(tr("Integrator"), m_integrator);
    connect(m_integrator, &QComboBox::activated, this, &ParametersPanel::setIntegrator);

    // the contact solver heads the contacts group
    m_contactSolver = new QComboBox(this);
    m_contactSolver->setObjectName(QStringLiteral("parameter-contactSolver"));
    m_contactSolver->setToolTip(tr("How contacts between particles, and with planes, are resolved"));
    for (core::ContactSolver solver : core::kContactSolvers) {
        m_contactSolver->addItem(contactSolverLabel(solver));
        m_contactSolver->setItemData(m_contactSolver->count() - 1, contactSolverTip(solver), Qt::ToolTipRole);
    }
    forms[std::size_t(Group::Contacts)]->addRow(tr("Solver"), m_contactSolver);
    connect(m_contactSolver, &QComboBox::activated, this, &ParametersPanel::setContactSolver);

    // the springs group says what its values apply to
    m_springsNote = new QLabel(m_springsGroup);
    m_springsNote->setWordWrap(true);
    forms[std::size_t(Group::Springs)]->addRow(m_springsNote);

    // a row per binding, made from the parameter table
    for (std::size_t b = 0; b < std::size(kBindings); ++b) {
        const Binding &binding = kBindings[b];
        const core::ParameterInfo &info = core::parameterInfo(binding.parameter);
        const QString label = fromView(info.label) + QString::fromLatin1(binding.suffix);
        const bool integral =
            binding.parameter == core::Parameter::Substeps || binding.parameter == core::Parameter::XpbdIterations ||
            binding.parameter == core::Parameter::SolverIterations;
        auto *row = new ParameterRow(info, label, integral, this);
        row->setObjectName(QStringLiteral("parameter-") + QString::fromLatin1(binding.key));
        forms[std::size_t(binding.group)]->addRow(row->label(), row);
        connect(row, &ParameterRow::valueEdited, this, [this, b](double value) { edit(b, value); });
        connect(row, &ParameterRow::valueRefused, this, &ParametersPanel::showRefusal);
        m_rows.push_back(row);
    }

    // auto substeps and the stability limit follow the substeps row
    QFormLayout *time = forms[std::size_t(Group::Time)];
    int substepsRow = 0;
    time->getWidgetPosition(row(QStringLiteral("substeps")), &substepsRow, nullptr);
    m_autoSubsteps = new QCheckBox(tr("Auto substeps"), this);
    m_autoSubsteps->setObjectName(QStringLiteral("parameter-autoSubsteps"));
    m_autoSubsteps->setToolTip(tr("Raise the substeps (the value above is then the least) to keep each sub-step "
                                  "under 90% of the stability limit, as stiffness and masses change"));
    time->insertRow(substepsRow + 1, QString(), m_autoSubsteps);
    connect(m_autoSubsteps, &QCheckBox::toggled, this, &ParametersPanel::setAutoSubsteps);
    m_stabilityNote = new QLabel(this);
    m_stabilityNote->setObjectName(QStringLiteral("parameter-stability"));
    m_stabilityNote->setWordWrap(true);
    m_stabilityNote->setToolTip(tr("The largest sub-step the explicit integrators stay stable at, from the highest "
                                   "frequency of the springs (timeStep / substeps must stay under it)"));
    time->insertRow(substepsRow + 2, QString(), m_stabilityNote);

    // the two friction rows share the table's entry; each says which coefficient it is, and a
    // check box below them lets the static one follow the kinetic one again
    ParameterRow *friction = row(QStringLiteral("friction"));
    friction->setToolTip(tr("Kinetic Coulomb coefficient μk: a sliding contact's friction is μk times the force "
                            "pressing it; a plane with friction of its own (Inspector) overrides it"));
    ParameterRow *staticFriction = row(QStringLiteral("staticFriction"));
    staticFriction->label()->setText(tr("Static friction"));
    staticFriction->setToolTip(tr("Static Coulomb coefficient μs: a contact sticks while the friction it needs stays "
                                  "within μs times the force pressing it; follows Friction until set here"));
    ParameterRow *rolling = row(QStringLiteral("rollingFriction"));
    rolling->label()->setText(tr("Rolling resistance"));
    rolling->setToolTip(tr("μr: a rolling ball is held back as by a force of μr times the force pressing it, so "
                           "that it rolls to a stop; a plane may have its own (scene file)"));
    ParameterRow *spinning = row(QStringLiteral("spinningFriction"));
    spinning->label()->setText(tr("Spinning friction"));
    spinning->setToolTip(tr("The same against a ball spinning about the contact's normal, like a top on a table"));
    QFormLayout *contacts = forms[std::size_t(Group::Contacts)];
    int staticRow = 0;
    contacts->getWidgetPosition(staticFriction, &staticRow, nullptr);
    m_staticFollows = new QCheckBox(tr("Static follows friction"), this);
    m_staticFollows->setObjectName(QStringLiteral("parameter-staticFollows"));
    m_staticFollows->setToolTip(tr("The static coefficient equals the kinetic one (the file then leaves "
                                   "staticFriction out); editing Static friction sets it apart"));
    contacts->insertRow(staticRow + 1, QString(), m_staticFollows);
    connect(m_staticFollows, &QCheckBox::toggled, this, &ParametersPanel::setStaticFollows);

    // the collision switches
    m_planeCollisions = new QCheckBox(tr("Plane collisions"), this);
    m_planeCollisions->setObjectName(QStringLiteral("parameter-planeCollisions"));
    m_planeCollisions->setToolTip(tr("Particles bounce off the scene's planes"));
    m_particleCollisions = new QCheckBox(tr("Particle collisions"), this);
    m_particleCollisions->setObjectName(QStringLiteral("parameter-particleCollisions"));
    m_particleCollisions->setToolTip(tr("Particles bounce off each other"));
    forms[std::size_t(Group::Contacts)]->addRow(m_planeCollisions);
    forms[std::size_t(Group::Contacts)]->addRow(m_particleCollisions);
    connect(m_planeCollisions, &QCheckBox::toggled, this,
            [this](bool on) { setCollisions(on, m_document.scene().settings.particleCollisions); });
    connect(m_particleCollisions, &QCheckBox::toggled, this,
            [this](bool on) { setCollisions(m_document.scene().settings.planeCollisions, on); });
    // the balls turn, so that friction rolls them
    m_spin = new QCheckBox(tr("Spin (balls roll)"), this);
    m_spin->setObjectName(QStringLiteral("parameter-spin"));
    m_spin->setToolTip(tr("Contacts act at the balls' surfaces: friction turns them, so a struck ball slides, then "
                          "rolls. Off: contacts act at the centres and nothing turns, as in the handout"));
    forms[std::size_t(Group::Contacts)]->addRow(m_spin);
    connect(m_spin, &QCheckBox::toggled, this, [this](bool on) {
        core::Settings settings = m_document.scene().settings;
        settings.spin = on;
        pushSettings(settings, tr("Switch spin"));
    });
    // the sheets' triangles as surfaces, and a sheet against itself
    m_triangleCollisions = new QCheckBox(tr("Sheet collisions"), this);
    m_triangleCollisions->setObjectName(QStringLiteral("parameter-triangleCollisions"));
    m_triangleCollisions->setToolTip(tr("A cloth is a surface: particles and other sheets stay on their side of its "
                                        "triangles, at the thickness, whatever their speed"));
    m_selfCollision = new QCheckBox(tr("Self-collision"), this);
    m_selfCollision->setObjectName(QStringLiteral("parameter-selfCollision"));
    m_selfCollision->setToolTip(tr("A sheet does not pass through itself when it folds"));
    forms[std::size_t(Group::Contacts)]->addRow(m_triangleCollisions);
    forms[std::size_t(Group::Contacts)]->addRow(m_selfCollision);
    connect(m_triangleCollisions, &QCheckBox::toggled, this, [this](bool on) {
        core::Settings settings = m_document.scene().settings;
        settings.triangleCollisions = on;
        pushSettings(settings, tr("Switch sheet collisions"));
    });
    connect(m_selfCollision, &QCheckBox::toggled, this, [this](bool on) {
        core::Settings settings = m_document.scene().settings;
        settings.selfCollision = on;
        pushSettings(settings, tr("Switch self-collision"));
    });

    // refusals show below the groups until the next accepted change
    m_message->setObjectName(QStringLiteral("parameter-message"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #b00020"));
    m_message->hide();
    layout->addWidget(m_message);
    layout->addStretch(1);

    connect(&m_document, &SceneDocument::sceneChanged, this, &ParametersPanel::refresh);
    refresh();
}

ParameterRow *ParametersPanel::row(const QString &key) const
{
    for (std::size_t b = 0; b < std::size(kBindings); ++b)
        if (key == QLatin1String(kBindings[b].key))
            return m_rows[b];
    return nullptr;
}

QString ParametersPanel::message() const
{
    return m_message->isHidden() ? QString() : m_message->text();
}

void ParametersPanel::refresh()
{
    // every row shows the document's value
    const core::SceneDesc &scene = m_document.scene();
    for (std::size_t b = 0; b < std::size(kBindings); ++b)
        m_rows[b]->setValue(kBindings[b].read(scene));
    const core::Integrator integrator = scene.settings.integrator;
    for (std::size_t i = 0; i < std::size(core::kIntegrators); ++i)
        if (core::kIntegrators[i] == integrator)
            m_integrator->setCurrentIndex(int(i));
    row(QStringLiteral("tolerance"))->setEnabled(integrator == core::Integrator::AdaptiveRk45);
    row(QStringLiteral("xpbdIterations"))->setEnabled(integrator == core::Integrator::Xpbd);
    row(QStringLiteral("solverIterations"))->setEnabled(core::isVariational(integrator));
    for (std::size_t i = 0; i < std::size(core::kContactSolvers); ++i)
        if (core::kContactSolvers[i] == scene.settings.contactSolver)
            m_contactSolver->setCurrentIndex(int(i));
    {
        const QSignalBlocker blockFollows(m_staticFollows);
        m_staticFollows->setChecked(!scene.settings.staticFriction.has_value());
    }
    {
        const QSignalBlocker blockAuto(m_autoSubsteps);
        m_autoSubsteps->setChecked(scene.settings.autoSubsteps);
    }
    {
        const QSignalBlocker blockPlanes(m_planeCollisions);
        const QSignalBlocker blockParticles(m_particleCollisions);
        m_planeCollisions->setChecked(scene.settings.planeCollisions);
        m_particleCollisions->setChecked(scene.settings.particleCollisions);
        const QSignalBlocker blockSheets(m_triangleCollisions);
        const QSignalBlocker blockSelf(m_selfCollision);
        m_triangleCollisions->setChecked(scene.settings.triangleCollisions);
        m_selfCollision->setChecked(scene.settings.selfCollision);
        m_selfCollision->setEnabled(scene.settings.triangleCollisions);
        const QSignalBlocker blockSpin(m_spin);
        m_spin->setChecked(scene.settings.spin);
    }

    // spring values apply to every spring; say so, and say when they differ now
    const std::size_t springs = scene.springs.size();
    m_springsGroup->setEnabled(springs > 0);
    bool uniform = true;
    for (const core::SpringDesc &spring : scene.springs)
        uniform = uniform && spring.stiffness == scene.springs.front().stiffness &&
                  spring.damping == scene.springs.front().damping;
    const QString count = springs == 1 ? tr("1 spring") : tr("%1 springs").arg(springs);
    if (springs == 0)
        m_springsNote->setText(tr("This scene has no springs."));
    else if (uniform)
        m_springsNote->setText(tr("Applies to all springs (%1).").arg(count));
    else
        m_springsNote->setText(
            tr("Applies to all springs (%1); their values differ now, the first spring's are shown.").arg(count));
}

void ParametersPanel::showRefusal(const QString &message)
{
    m_message->setText(message);
    m_message->show();
    emit valueRefused(message);
}

void ParametersPanel::edit(std::size_t b, double value)
{
    m_message->hide();
    const Binding &binding = kBindings[b];
    const QString text = tr("Set %1 to %2").arg(m_rows[b]->label()->text()).arg(value, 0, 'g', 6);
    if (binding.writeSetting) {
        core::Settings settings = m_document.scene().settings;
        binding.writeSetting(settings, value);
        m_document.undoStack()->push(new SettingsCommand(m_document, text, QString::fromLatin1(binding.key), settings));
    } else {
        m_document.undoStack()->push(new SpringValueCommand(m_document, text, binding.springField, value));
    }
}

void ParametersPanel::setIntegrator(int index)
{
    if (index < 0 || index >= int(std::size(core::kIntegrators)))
        return;
    const core::Integrator integrator = core::kIntegrators[index];
    if (integrator == m_document.scene().settings.integrator)
        return;
    m_message->hide();
    core::Settings settings = m_document.scene().settings;
    settings.integrator = integrator;
    m_document.undoStack()->push(new SettingsCommand(
        m_document, tr("Set integrator to %1").arg(fromView(core::integratorName(integrator))),
        QString(), settings));
}

void ParametersPanel::setContactSolver(int index)
{
    if (index < 0 || index >= int(std::size(core::kContactSolvers)))
        return;
    const core::ContactSolver solver = core::kContactSolvers[index];
    if (solver == m_document.scene().settings.contactSolver)
        return;
    m_message->hide();
    core::Settings settings = m_document.scene().settings;
    settings.contactSolver = solver;
    m_document.undoStack()->push(new SettingsCommand(
        m_document, tr("Set contact solver to %1").arg(fromView(core::contactSolverName(solver))), QString(),
        settings));
}

void ParametersPanel::setStaticFollows(bool follows)
{
    // following: unset; set apart: it keeps the value it showed, friction's
    core::Settings settings = m_document.scene().settings;
    if (follows == !settings.staticFriction.has_value())
        return;
    m_message->hide();
    settings.staticFriction = follows ? std::nullopt : std::optional<double>(settings.friction);
    m_document.undoStack()->push(new SettingsCommand(
        m_document, follows ? tr("Let static friction follow friction") : tr("Set static friction apart"), QString(),
        settings));
}

void ParametersPanel::setAutoSubsteps(bool on)
{
    if (on == m_document.scene().settings.autoSubsteps)
        return;
    m_message->hide();
    core::Settings settings = m_document.scene().settings;
    settings.autoSubsteps = on;
    m_document.undoStack()->push(new SettingsCommand(
        m_document, on ? tr("Switch auto substeps on") : tr("Switch auto substeps off"), QString(), settings));
}

void ParametersPanel::showStability(const core::StabilityLimit &limit, const core::Model &model,
                                    const QString &solver)
{
    const StabilityNote note =
        stabilityNote(limit.maxSubStep(model.integrator), model.subStep(), model.timeStep, model.integrator);
    QString text = note.text;
    if (!solver.isEmpty())
        text += QStringLiteral("; ") + solver;
    if (m_document.scene().settings.autoSubsteps)
        text += tr("; auto: %n substep(s)", nullptr, model.substeps);
    m_stabilityNote->setText(text);
    switch (note.level) {
    case StabilityLevel::Safe: m_stabilityNote->setStyleSheet(QString()); break;
    case StabilityLevel::Near: m_stabilityNote->setStyleSheet(QStringLiteral("color: #b06000")); break;
    case StabilityLevel::Past: m_stabilityNote->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold")); break;
    }
}

void ParametersPanel::pushSettings(const core::Settings &settings, const QString &text)
{
    m_message->hide();
    m_document.undoStack()->push(new SettingsCommand(m_document, text, QStringLiteral("collisions"), settings));
}

void ParametersPanel::setCollisions(bool planes, bool particles)
{
    m_message->hide();
    core::Settings settings = m_document.scene().settings;
    settings.planeCollisions = planes;
    settings.particleCollisions = particles;
    m_document.undoStack()->push(new SettingsCommand(m_document, tr("Switch collisions"), QStringLiteral("collisions"),
                                                     settings));
}

}  // namespace ui
