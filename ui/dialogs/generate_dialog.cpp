#include "generate_dialog.h"

#include "generate_preview.h"
#include "ui/panels/slider_scale.h"
#include "ui/panels/value_spin_box.h"

#include "core/model/model.h"
#include "core/model/state.h"
#include "core/model/workspace.h"
#include "core/step.h"

#include <QCheckBox>
#include <QElapsedTimer>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <climits>

namespace ui {

namespace {

// pieces up to this many particles and springs together, times their sub-steps, are timed as they
// are made: a step of that much work takes a few milliseconds, which the dialog can spend on each
// change; a bigger one would stall the typing
constexpr std::size_t kTimedWork = 200000;

std::size_t workOf(const core::SceneDesc &piece)
{
    return (piece.particles.size() + piece.springs.size()) * std::size_t(std::max(1, piece.settings.substeps));
}

// what the piece costs to run, by itself: the wall time of its second step here (the first also
// sizes the step's scratch), or nothing when it is too big to time in the dialog or blows up alone
std::optional<double> secondsAStep(const core::SceneDesc &piece)
{
    if (workOf(piece) > kTimedWork)
        return std::nullopt;
    const std::shared_ptr<const core::Model> model = core::compileModel(piece);
    core::State state = core::makeState(*model, piece);
    core::Workspace work;
    if (!core::step(*model, state, work))
        return std::nullopt;
    QElapsedTimer clock;
    clock.start();
    if (!core::step(*model, state, work))
        return std::nullopt;
    return double(clock.nsecsElapsed()) * 1e-9;
}

// how the arrows step each kind of value (any value can be typed; the check says what is wrong)
constexpr SliderScale kLengthScale{1e-3, 100.0, core::Scale::Log, false, 1000};      // m
constexpr SliderScale kMassScale{1e-4, 1e3, core::Scale::Log, false, 1000};          // kg
constexpr SliderScale kRadiusScale{1e-3, 10.0, core::Scale::Log, false, 1000};       // m
constexpr SliderScale kThicknessScale{0.0, 0.1, core::Scale::Linear, false, 1000};    // m, 0: automatic
constexpr SliderScale kStiffnessScale{1e-1, 1e6, core::Scale::Log, true, 1000};      // N/m
constexpr SliderScale kDampingScale{1e-3, 1e3, core::Scale::Log, true, 1000};        // N·s/m
constexpr SliderScale kJitterScale{1e-4, 1.0, core::Scale::Log, true, 1000};         // m
constexpr SliderScale kPositionScale{-10.0, 10.0, core::Scale::Linear, false, 1000};  // m

// a form of one kind's options: each field shows its option's value and writes it back as it
// changes, then calls `changed`. Fields are named "generate-<kind>-<option>".
template <class Options>
class OptionsForm {
public:
    OptionsForm(Options &options, const char *kind, QWidget *page, std::function<void()> changed)
        : m_options(&options), m_kind(QString::fromLatin1(kind)), m_page(page), m_form(new QFormLayout(page)),
          m_changed(std::move(changed))
    {
    }

    // a count; 0 can be typed, so that the check can say why it is refused
    void count(const char *key, const QString &label, int Options::*field, int most = core::kMaxGeneratedParticles)
    {
        auto *box = new QSpinBox(m_page);
        box->setRange(0, most);
        box->setValue(m_options->*field);
        addField(box, key, label, QString());
        QObject::connect(box, &QSpinBox::valueChanged, m_page, setter(field));
    }

    // a physical value with its unit
    void value(const char *key, const QString &label, const QString &unit, double Options::*field,
               const SliderScale &scale)
    {
        auto *box = new ValueSpinBox(scale, m_page);
        box->setValue(m_options->*field);
        addField(box, key, label, unit);
        QObject::connect(box, &QDoubleSpinBox::valueChanged, m_page, setter(field));
    }

    // a seed of the jitter: the same seed, the same positions
    void seed(const char *key, const QString &label, std::uint64_t Options::*field)
    {
        auto *box = new QSpinBox(m_page);
        box->setRange(0, INT_MAX);
        box->setValue(int(m_options->*field));
        box->setToolTip(QObject::tr("The same seed gives the same jitter"));
        addField(box, key, label, QString());
        QObject::connect(box, &QSpinBox::valueChanged, m_page,
                         [options = m_options, field, changed = m_changed](int value) {
                             options->*field = std::uint64_t(value);
                             changed();
                         });
    }

    void toggle(const char *key, const QString &label, bool Options::*field)
    {
        auto *box = new QCheckBox(label, m_page);
        box->setObjectName(QStringLiteral("generate-%1-%2").arg(m_kind, QLatin1String(key)));
        box->setChecked(m_options->*field);
        m_form->addRow(QString(), box);
        QObject::connect(box, &QCheckBox::toggled, m_page, setter(field));
    }

private:
    template <class Value>
    auto setter(Value Options::*field) const
    {
        return [options = m_options, field, changed = m_changed](Value value) {
            options->*field = value;
            changed();
        };
    }

    void addField(QAbstractSpinBox *box, const char *key, const QString &label, const QString &unit)
    {
        box->setObjectName(QStringLiteral("generate-%1-%2").arg(m_kind, QLatin1String(key)));
        // a typed value counts once it is finished (Return, Tab or leaving the field)
        box->setKeyboardTracking(false);
        box->setMinimumWidth(110);
        if (unit.isEmpty()) {
            m_form->addRow(label, box);
            return;
        }
        auto *row = new QHBoxLayout;
        row->addWidget(box, 1);
        row->addWidget(new QLabel(unit, m_page));
        m_form->addRow(label, row);
    }

    Options *m_options;
    QString m_kind;
    QWidget *m_page;
    QFormLayout *m_form;
    std::function<void()> m_changed;
};

}  // namespace

GenerateDialog::GenerateDialog(QWidget *parent)
    : QDialog(parent), m_kindBox(new QComboBox(this)), m_preview(new GeneratePreview(this)), m_count(new QLabel(this)),
      m_problem(new QLabel(this))
{
    setObjectName(QStringLiteral("generateDialog"));
    setWindowTitle(tr("Generate"));
    // a cloth made here collides as a surface unless the user says otherwise: a ball dropped on it
    // stays on it (the generator's own default stays off for scenes built in code)
    m_cloth.sheetCollisions = true;

    // the kind, and its options
    m_kindBox->setObjectName(QStringLiteral("generateKind"));
    auto *pages = new QStackedWidget(this);
    addKinds(pages);
    connect(m_kindBox, &QComboBox::currentIndexChanged, this, [this, pages](int index) {
        pages->setCurrentIndex(index);
        regenerate();
    });

    // where its middle goes
    auto *where = new QHBoxLayout;
    const char *axes[] = {"x", "y", "z"};
    const double start[] = {0.0, 1.0, 0.0};
    for (int axis = 0; axis < 3; ++axis) {
        m_position[axis] = new ValueSpinBox(kPositionScale, this);
        m_position[axis]->setObjectName(QStringLiteral("generate-%1").arg(QLatin1String(axes[axis])));
        m_position[axis]->setValue(start[axis]);
        m_position[axis]->setKeyboardTracking(false);
        m_position[axis]->setToolTip(tr("Where the middle of what is generated goes, %1 (m)").arg(QLatin1String(axes[axis])));
        connect(m_position[axis], &QDoubleSpinBox::valueChanged, this, &GenerateDialog::regenerate);
        where->addWidget(m_position[axis], 1);
    }
    where->addWidget(new QLabel(tr("m"), this));
    auto *placement = new QFormLayout;
    placement->addRow(tr("Kind"), m_kindBox);
    auto *position = new QFormLayout;
    position->addRow(tr("Middle at x, y, z"), where);

    // what it makes, or why it cannot
    m_count->setObjectName(QStringLiteral("generateCount"));
    m_problem->setObjectName(QStringLiteral("generateProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #d04030"));

    // Add is never the default button (a QDialogButtonBox would make it one): Return in a field only
    // shows the value in the preview
    m_add = new QPushButton(tr("&Add to Scene"), this);
    m_add->setObjectName(QStringLiteral("generateAdd"));
    m_add->setToolTip(tr("Add what the preview shows to the scene (one undo step)"));
    auto *cancel = new QPushButton(tr("Cancel"), this);
    for (QPushButton *button : {cancel, m_add})
        button->setAutoDefault(false);
    connect(m_add, &QPushButton::clicked, this, &QDialog::accept);
    connect(cancel, &QPushButton::clicked, this, &QDialog::reject);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(cancel);
    buttons->addWidget(m_add);

    auto *left = new QVBoxLayout;
    left->addLayout(placement);
    left->addWidget(pages);
    left->addLayout(position);
    left->addStretch(1);
    auto *columns = new QHBoxLayout;
    columns->addLayout(left);
    columns->addWidget(m_preview, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(columns, 1);
    layout->addWidget(m_count);
    layout->addWidget(m_problem);
    layout->addLayout(buttons);
    regenerate();
}

void GenerateDialog::addKinds(QStackedWidget *pages)
{
    const auto changed = [this] { regenerate(); };
    const auto page = [&](const QString &name, auto check, auto make) {
        m_kinds.push_back(KindPage{name, check, make});
        m_kindBox->addItem(name);
        auto *widget = new QWidget(pages);
        pages->addWidget(widget);
        return widget;
    };
    const QString kg = tr("kg"), m = tr("m"), stiffness = tr("N/m"), damping = tr("N·s/m");

    {
        OptionsForm form(m_cloth, "cloth",
                         page(tr("Cloth"), [this] { return core::checkOptions(m_cloth); },
                              [this] { return core::makeCloth(m_cloth); }),
                         changed);
        form.count("rows", tr("Rows"), &core::ClothOptions::rows);
        form.count("cols", tr("Columns"), &core::ClothOptions::cols);
        form.value("spacing", tr("Spacing"), m, &core::ClothOptions::spacing, kLengthScale);
        form.value("mass", tr("Mass each"), kg, &core::ClothOptions::mass, kMassScale);
        form.value("radius", tr("Radius"), m, &core::ClothOptions::radius, kRadiusScale);
        form.value("structural", tr("Structural k"), stiffness, &core::ClothOptions::structuralStiffness,
                   kStiffnessScale);
        form.value("shear", tr("Shear k"), stiffness, &core::ClothOptions::shearStiffness, kStiffnessScale);
        form.value("bend", tr("Bend k"), stiffness, &core::ClothOptions::bendStiffness, kStiffnessScale);
        form.value("damping", tr("Damping kc"), damping, &core::ClothOptions::damping, kDampingScale);
        form.toggle("pin", tr("Pin the two corners of the first row"), &core::ClothOptions::pinCorners);
        form.toggle("sheet", tr("Collides as a surface"), &core::ClothOptions::sheetCollisions);
        form.value("thickness", tr("Thickness (0: automatic)"), m, &core::ClothOptions::thickness, kThicknessScale);
        form.toggle("self", tr("Collides with itself"), &core::ClothOptions::selfCollision);
    }
    {
        OptionsForm form(m_rope, "rope",
                         page(tr("Rope"), [this] { return core::checkOptions(m_rope); },
                              [this] { return core::makeRope(m_rope); }),
                         changed);
        form.value("length", tr("Length"), m, &core::RopeOptions::length, kLengthScale);
        form.count("segments", tr("Segments"), &core::RopeOptions::segments);
        form.value("mass", tr("Mass each"), kg, &core::RopeOptions::mass, kMassScale);
        form.value("stiffness", tr("Stiffness k"), stiffness, &core::RopeOptions::stiffness, kStiffnessScale);
        form.value("damping", tr("Damping kc"), damping, &core::RopeOptions::damping, kDampingScale);
        form.toggle("pin", tr("Pin the first particle"), &core::RopeOptions::pinFirst);
    }
    {
        OptionsForm form(m_chain, "chain",
                         page(tr("Chain"), [this] { return core::checkOptions(m_chain); },
                              [this] { return core::makeChain(m_chain); }),
                         changed);
        form.count("links", tr("Links"), &core::ChainOptions::links);
        form.value("link", tr("Link length"), m, &core::ChainOptions::linkLength, kLengthScale);
        form.value("mass", tr("Mass each"), kg, &core::ChainOptions::mass, kMassScale);
        form.value("radius", tr("Radius"), m, &core::ChainOptions::radius, kRadiusScale);
        form.value("stiffness", tr("Stiffness k"), stiffness, &core::ChainOptions::stiffness, kStiffnessScale);
        form.value("damping", tr("Damping kc"), damping, &core::ChainOptions::damping, kDampingScale);
        form.toggle("pin", tr("Pin the first particle"), &core::ChainOptions::pinFirst);
    }
    {
        OptionsForm form(m_block, "block",
                         page(tr("Block of particles"), [this] { return core::checkOptions(m_block); },
                              [this] { return core::makeBlock(m_block); }),
                         changed);
        form.count("nx", tr("Along x"), &core::BlockOptions::nx);
        form.count("ny", tr("Along y"), &core::BlockOptions::ny);
        form.count("nz", tr("Along z"), &core::BlockOptions::nz);
        form.value("spacing", tr("Spacing"), m, &core::BlockOptions::spacing, kLengthScale);
        form.value("mass", tr("Mass each"), kg, &core::BlockOptions::mass, kMassScale);
        form.value("radius", tr("Radius"), m, &core::BlockOptions::radius, kRadiusScale);
        form.value("jitter", tr("Jitter"), m, &core::BlockOptions::jitter, kJitterScale);
        form.seed("seed", tr("Seed"), &core::BlockOptions::seed);
    }
    {
        OptionsForm form(m_ball, "ball",
                         page(tr("Ball of particles"), [this] { return core::checkOptions(m_ball); },
                              [this] { return core::makeBall(m_ball); }),
                         changed);
        form.value("ballRadius", tr("Ball radius"), m, &core::BallOptions::ballRadius, kLengthScale);
        form.value("spacing", tr("Spacing"), m, &core::BallOptions::spacing, kLengthScale);
        form.value("mass", tr("Mass each"), kg, &core::BallOptions::mass, kMassScale);
        form.value("radius", tr("Radius"), m, &core::BallOptions::radius, kRadiusScale);
        form.value("jitter", tr("Jitter"), m, &core::BallOptions::jitter, kJitterScale);
        form.seed("seed", tr("Seed"), &core::BallOptions::seed);
    }
    {
        OptionsForm form(m_softBall, "softBall",
                         page(tr("Soft ball"), [this] { return core::checkOptions(m_softBall); },
                              [this] { return core::makeSoftBall(m_softBall); }),
                         changed);
        form.count("points", tr("Points on the surface"), &core::SoftBallOptions::points, core::kMaxSoftBallPoints);
        form.value("ballRadius", tr("Ball radius"), m, &core::SoftBallOptions::ballRadius, kLengthScale);
        form.value("mass", tr("Mass each"), kg, &core::SoftBallOptions::mass, kMassScale);
        form.value("radius", tr("Radius"), m, &core::SoftBallOptions::radius, kRadiusScale);
        form.value("stiffness", tr("Surface k"), stiffness, &core::SoftBallOptions::stiffness, kStiffnessScale);
        form.value("damping", tr("Damping kc"), damping, &core::SoftBallOptions::damping, kDampingScale);
        form.toggle("centre", tr("Join every point to a centre particle"), &core::SoftBallOptions::centre);
        form.value("centreStiffness", tr("Centre k"), stiffness, &core::SoftBallOptions::centreStiffness,
                   kStiffnessScale);
    }
}

GenerateDialog::Kind GenerateDialog::kind() const
{
    return static_cast<Kind>(m_kindBox->currentIndex());
}

QString GenerateDialog::kindName() const
{
    return m_kindBox->currentText();
}

Eigen::Vector3d GenerateDialog::position() const
{
    return {m_position[0]->value(), m_position[1]->value(), m_position[2]->value()};
}

QString GenerateDialog::countText() const
{
    return m_count->text();
}

QString GenerateDialog::problemText() const
{
    return m_problem->text();
}

void GenerateDialog::regenerate()
{
    // the options first, then where it goes: both must be in range before anything is made
    const KindPage &kind = m_kinds[std::size_t(std::max(0, m_kindBox->currentIndex()))];
    std::optional<std::string> problem = kind.check();
    const char *axes[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3 && !problem; ++axis)
        if (std::optional<std::string> reason = core::checkParameter(core::Parameter::Coordinate, position()[axis]))
            problem = "position " + std::string(axes[axis]) + " " + *reason;

    if (problem) {
        m_generated = nullptr;
        m_count->clear();
        m_problem->setText(tr("Cannot generate: %1").arg(QString::fromStdString(*problem)));
    } else {
        m_generated = std::make_shared<const core::SceneDesc>(kind.make());
        QString count = tr("%n particle(s)", nullptr, int(m_generated->particles.size())) + QStringLiteral(", ") +
                        tr("%n spring(s)", nullptr, int(m_generated->springs.size()));
        if (m_generated->settings.substeps > 1)
            count += tr("; its springs need at least %1 substeps").arg(m_generated->settings.substeps);
        // what it costs: a step of it alone, timed on this machine, and the speed that allows
        if (const std::optional<double> seconds = secondsAStep(*m_generated)) {
            const double factor = m_generated->settings.timeStep / std::max(*seconds, 1e-9);
            count += tr("; a step of it alone takes %1 ms here, %2 real time")
                         .arg(*seconds * 1e3, 0, 'g', 2)
                         .arg(factor >= 1.0 ? tr("%1× faster than").arg(factor, 0, 'g', 3)
                                            : tr("%1× slower than").arg(1.0 / factor, 0, 'g', 3));
        } else if (workOf(*m_generated) > kTimedWork) {
            count += tr("; too big to time here: run it to see its speed");
        }
        m_count->setText(count);
        m_problem->clear();
    }
    m_preview->setScene(m_generated);
    m_add->setEnabled(m_generated != nullptr);
}

}  // namespace ui
