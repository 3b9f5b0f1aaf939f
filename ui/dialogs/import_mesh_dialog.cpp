#include "import_mesh_dialog.h"

#include "generate_preview.h"
#include "core/io/mesh_file.h"
#include "ui/panels/slider_scale.h"
#include "ui/panels/value_spin_box.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace ui {

namespace {

// how the arrows step each value (any value can be typed; the import says what is wrong); the
// optional ones start at exactly 0, "the material's" (or "automatic")
constexpr SliderScale kScaleScale{1e-4, 1e4, core::Scale::Log, false, 1000};
constexpr SliderScale kDensityScale{1e-3, 1e4, core::Scale::Log, true, 1000};    // kg/m² or kg/m³
constexpr SliderScale kMeshStiffnessScale{1e-1, 1e7, core::Scale::Log, true, 1000};  // N/m
constexpr SliderScale kMeshDampingScale{1e-4, 1e3, core::Scale::Log, true, 1000};    // N·s/m
constexpr SliderScale kSpacingScale{1e-3, 10.0, core::Scale::Log, true, 1000};   // m
constexpr SliderScale kMeshPositionScale{-10.0, 10.0, core::Scale::Linear, false, 1000};  // m

// the kinds in the order of their box, and the sides in the order of theirs
constexpr core::MeshKind kKinds[] = {core::MeshKind::Cloth, core::MeshKind::Soft, core::MeshKind::Collider};
constexpr core::PinSide kSides[] = {core::PinSide::None, core::PinSide::Top,   core::PinSide::Bottom, core::PinSide::Left,
                                    core::PinSide::Right, core::PinSide::Front, core::PinSide::Back};
constexpr core::ClothMaterial kMaterials[] = {core::ClothMaterial::Cotton, core::ClothMaterial::Silk,
                                              core::ClothMaterial::Denim, core::ClothMaterial::RubberSheet};

ValueSpinBox *valueBox(const SliderScale &scale, const char *name, double value, QWidget *parent)
{
    auto *box = new ValueSpinBox(scale, parent);
    box->setObjectName(QLatin1String(name));
    box->setValue(value);
    // a typed value counts once it is finished (Return, Tab or leaving the field)
    box->setKeyboardTracking(false);
    box->setMinimumWidth(110);
    return box;
}

QHBoxLayout *withUnit(QWidget *box, QLabel *unit)
{
    auto *row = new QHBoxLayout;
    row->addWidget(box, 1);
    row->addWidget(unit);
    return row;
}

}  // namespace

ImportMeshDialog::ImportMeshDialog(BrowseFunction browse, QWidget *parent)
    : QDialog(parent), m_browse(std::move(browse)), m_count(new QLabel(this)), m_problem(new QLabel(this))
{
    setObjectName(QStringLiteral("importMeshDialog"));
    setWindowTitle(tr("Import Mesh"));

    // the file
    m_path = new QLineEdit(this);
    m_path->setObjectName(QStringLiteral("importPath"));
    m_path->setToolTip(tr("A mesh file: %1").arg(io::meshFileFilter()));
    auto *browseButton = new QPushButton(tr("&Browse..."), this);
    browseButton->setObjectName(QStringLiteral("importBrowse"));
    browseButton->setAutoDefault(false);
    connect(browseButton, &QPushButton::clicked, this, &ImportMeshDialog::browse);
    connect(m_path, &QLineEdit::editingFinished, this, [this] {
        if (m_path->isModified()) {
            m_path->setModified(false);
            readFile();
        }
    });
    auto *fileRow = new QHBoxLayout;
    fileRow->addWidget(m_path, 1);
    fileRow->addWidget(browseButton);
    m_name = new QLineEdit(this);
    m_name->setObjectName(QStringLiteral("importName"));
    m_name->setToolTip(tr("The body's name in the scene and in exported files"));

    // what it becomes, and that kind's options
    m_kind = new QComboBox(this);
    m_kind->setObjectName(QStringLiteral("importKind"));
    m_kind->addItems({tr("Cloth"), tr("Soft body"), tr("Collider")});
    m_kind->setToolTip(tr("Cloth: a particle per vertex, springs along the edges and across them. Soft body: a closed "
                          "mesh filled with a lattice of particles that carries the surface. Collider: a pinned "
                          "surface that particles and cloth collide with"));
    m_material = new QComboBox(this);
    m_material->setObjectName(QStringLiteral("importMaterial"));
    for (core::ClothMaterial material : kMaterials)
        m_material->addItem(QString::fromLatin1(core::clothMaterial(material).name.data(),
                                                qsizetype(core::clothMaterial(material).name.size())));
    m_densityUnit = new QLabel(this);
    m_density = valueBox(kDensityScale, "importDensity", 0.0, this);
    m_density->setToolTip(tr("0: the material's (a soft body: %1 kg/m³)").arg(core::kDefaultSoftDensity));
    m_stiffness = valueBox(kMeshStiffnessScale, "importStiffness", 0.0, this);
    m_stiffness->setToolTip(tr("A cloth's edge springs (its shear and bend springs keep the material's proportions) "
                               "or every spring of a soft body; 0: the material's"));
    m_damping = valueBox(kMeshDampingScale, "importDamping", 0.0, this);
    m_damping->setToolTip(tr("Every spring's; 0: the material's (a soft body: 0.5 N·s/m)"));
    m_spacing = valueBox(kSpacingScale, "importSpacing", 0.0, this);
    m_spacing->setToolTip(tr("The soft body's lattice spacing; 0: a tenth of the longest side of its box"));
    m_pin = new QComboBox(this);
    m_pin->setObjectName(QStringLiteral("importPin"));
    m_pin->addItems({tr("None"), tr("Top (+y)"), tr("Bottom (-y)"), tr("Left (-x)"), tr("Right (+x)"), tr("Front (+z)"),
                     tr("Back (-z)")});
    m_pin->setToolTip(tr("Pin the vertices on this side of the body's box (after the placement)"));

    // how it is placed
    m_scale = valueBox(kScaleScale, "importScale", 1.0, this);
    m_scale->setToolTip(tr("Metres per unit of the file (0.01 for a file in centimetres)"));
    m_up = new QComboBox(this);
    m_up->setObjectName(QStringLiteral("importUp"));
    m_up->addItems({tr("Y up"), tr("Z up (Blender, 3ds Max)")});
    m_place = new QCheckBox(tr("Put its bottom middle at"), this);
    m_place->setObjectName(QStringLiteral("importPlace"));
    m_place->setChecked(true);
    m_place->setToolTip(tr("Off: where the file's coordinates put it"));
    auto *where = new QHBoxLayout;
    const char *names[] = {"importAtX", "importAtY", "importAtZ"};
    const double start[] = {0.0, 0.5, 0.0};
    for (int axis = 0; axis < 3; ++axis) {
        m_at[axis] = valueBox(kMeshPositionScale, names[axis], start[axis], this);
        m_at[axis]->setMinimumWidth(70);
        where->addWidget(m_at[axis], 1);
        connect(m_at[axis], &QDoubleSpinBox::valueChanged, this, &ImportMeshDialog::remake);
    }
    where->addWidget(new QLabel(tr("m"), this));
    m_into = new QComboBox(this);
    m_into->setObjectName(QStringLiteral("importInto"));
    m_into->addItems({tr("Add to this scene"), tr("A new scene (with a floor under it)")});

    auto *form = new QFormLayout;
    form->addRow(tr("File"), fileRow);
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Import as"), m_kind);
    form->addRow(tr("Material"), m_material);
    form->addRow(tr("Density (0: material's)"), withUnit(m_density, m_densityUnit));
    form->addRow(tr("Stiffness (0: material's)"), withUnit(m_stiffness, new QLabel(tr("N/m"), this)));
    form->addRow(tr("Damping (0: material's)"), withUnit(m_damping, new QLabel(tr("N·s/m"), this)));
    form->addRow(tr("Lattice spacing (0: auto)"), withUnit(m_spacing, new QLabel(tr("m"), this)));
    form->addRow(tr("Pin side"), m_pin);
    form->addRow(tr("Scale"), withUnit(m_scale, new QLabel(tr("m per unit"), this)));
    form->addRow(tr("Up axis"), m_up);
    form->addRow(m_place, where);
    form->addRow(tr("Into"), m_into);

    for (QComboBox *box : {m_kind, m_material, m_pin, m_up})
        connect(box, &QComboBox::currentIndexChanged, this, &ImportMeshDialog::remake);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &ImportMeshDialog::updateKindFields);
    for (ValueSpinBox *box : {m_density, m_stiffness, m_damping, m_spacing, m_scale})
        connect(box, &QDoubleSpinBox::valueChanged, this, &ImportMeshDialog::remake);
    connect(m_place, &QCheckBox::toggled, this, [this](bool on) {
        for (ValueSpinBox *box : m_at)
            box->setEnabled(on);
        remake();
    });
    connect(m_name, &QLineEdit::editingFinished, this, &ImportMeshDialog::remake);

    // the body it makes, or why it cannot
    m_preview = new GeneratePreview(this);
    m_preview->setObjectName(QStringLiteral("importPreview"));
    m_count->setObjectName(QStringLiteral("importCount"));
    m_count->setWordWrap(true);
    m_problem->setObjectName(QStringLiteral("importProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #d04030"));

    // Import is never the default button: Return in a field only shows the value in the preview
    m_import = new QPushButton(tr("&Import"), this);
    m_import->setObjectName(QStringLiteral("importAccept"));
    auto *cancel = new QPushButton(tr("Cancel"), this);
    for (QPushButton *button : {cancel, m_import})
        button->setAutoDefault(false);
    connect(m_import, &QPushButton::clicked, this, &QDialog::accept);
    connect(cancel, &QPushButton::clicked, this, &QDialog::reject);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(cancel);
    buttons->addWidget(m_import);

    auto *columns = new QHBoxLayout;
    columns->addLayout(form);
    columns->addWidget(m_preview, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(columns, 1);
    layout->addWidget(m_count);
    layout->addWidget(m_problem);
    layout->addLayout(buttons);
    updateKindFields();
    remake();
}

ImportMeshDialog::~ImportMeshDialog()
{
    // a field losing focus as its neighbours are deleted finishes its edit: it must not remake the
    // preview into labels already gone
    for (QObject *child : findChildren<QObject *>())
        child->disconnect(this);
}

void ImportMeshDialog::setPath(const QString &path)
{
    m_path->setText(path);
    m_path->setModified(false);
    readFile();
}

QString ImportMeshDialog::path() const
{
    return m_path->text().trimmed();
}

bool ImportMeshDialog::intoNewScene() const
{
    return m_into->currentIndex() == 1;
}

QString ImportMeshDialog::countText() const
{
    return m_count->text();
}

QString ImportMeshDialog::problemText() const
{
    return m_problem->text();
}

core::MeshImportOptions ImportMeshDialog::options() const
{
    core::MeshImportOptions options;
    options.kind = kKinds[std::max(0, m_kind->currentIndex())];
    options.name = m_name->text().trimmed().toStdString();
    options.source = path().toStdString();
    options.placement.scale = m_scale->typedValue();
    options.placement.zUp = m_up->currentIndex() == 1;
    if (m_place->isChecked())
        options.placement.at = Eigen::Vector3d(m_at[0]->typedValue(), m_at[1]->typedValue(), m_at[2]->typedValue());
    options.material = kMaterials[std::max(0, m_material->currentIndex())];
    // 0 leaves the value to the material (the field says so)
    if (m_density->typedValue() != 0.0)
        options.density = m_density->typedValue();
    if (m_stiffness->typedValue() != 0.0)
        options.stiffness = m_stiffness->typedValue();
    if (m_damping->typedValue() != 0.0)
        options.damping = m_damping->typedValue();
    options.spacing = m_spacing->typedValue();
    options.pin = kSides[std::max(0, m_pin->currentIndex())];
    return options;
}

void ImportMeshDialog::browse()
{
    if (!m_browse)
        return;
    const QString chosen = m_browse(path());
    if (!chosen.isEmpty())
        setPath(chosen);
}

void ImportMeshDialog::readFile()
{
    m_mesh.reset();
    m_readError.clear();
    m_readNotes.clear();
    const QString file = path();
    if (!file.isEmpty()) {
        io::MeshReadResult read = io::readMeshFile(file);
        if (read.ok())
            m_mesh = std::make_shared<const core::TriangleMesh>(std::move(*read.mesh));
        else
            m_readError = read.error;
        m_readNotes = read.notes;
        // the body is named after its file until the user names it
        if (m_name->text().isEmpty() || m_name->property("fromFile").toBool()) {
            m_name->setText(QFileInfo(file).completeBaseName());
            m_name->setProperty("fromFile", true);
        }
    }
    remake();
}

void ImportMeshDialog::updateKindFields()
{
    const core::MeshKind kind = kKinds[std::max(0, m_kind->currentIndex())];
    const bool cloth = kind == core::MeshKind::Cloth, soft = kind == core::MeshKind::Soft;
    m_material->setEnabled(cloth);
    m_density->setEnabled(kind != core::MeshKind::Collider);
    m_stiffness->setEnabled(kind != core::MeshKind::Collider);
    m_damping->setEnabled(kind != core::MeshKind::Collider);
    m_spacing->setEnabled(soft);
    m_pin->setEnabled(kind != core::MeshKind::Collider);
    m_densityUnit->setText(soft ? tr("kg/m³") : tr("kg/m²"));
}

void ImportMeshDialog::remake()
{
    if (m_name->isModified()) {
        m_name->setModified(false);
        m_name->setProperty("fromFile", false);
    }
    m_made.reset();
    QString problem;
    QString count;
    if (path().isEmpty()) {
        problem = tr("Choose a mesh file");
    } else if (!m_mesh) {
        problem = tr("Cannot import: %1").arg(m_readError);
    } else {
        auto made = std::make_shared<core::SceneDesc>();
        const core::MeshImportResult result = core::addMeshToScene(*made, *m_mesh, options());
        if (!result.ok()) {
            problem = tr("Cannot import: %1").arg(QString::fromStdString(result.error));
        } else {
            count = tr("%n particle(s)", nullptr, result.particles) + QStringLiteral(", ") +
                    tr("%n spring(s)", nullptr, result.springs) + QStringLiteral(", ") +
                    (result.triangles > 0 || !m_mesh
                         ? tr("%n triangle(s)", nullptr, result.triangles)
                         : tr("drawn by its %n triangle(s)", nullptr, int(m_mesh->faces.size())));
            if (result.mass > 0.0)
                count += tr("; %1 kg").arg(result.mass, 0, 'g', 4);
            if (result.volume > 0.0)
                count += tr(", %1 m³").arg(result.volume, 0, 'g', 4);
            else if (result.area > 0.0)
                count += tr(", %1 m²").arg(result.area, 0, 'g', 4);
            if (made->settings.substeps > 1)
                count += tr("; its springs need at least %1 substeps").arg(made->settings.substeps);
            QStringList notes = m_readNotes;
            for (const std::string &note : result.notes)
                notes << QString::fromStdString(note);
            if (!notes.isEmpty())
                count += QStringLiteral("\n") + notes.join(QStringLiteral("; "));
            m_made = std::move(made);
        }
    }
    m_count->setText(count);
    m_problem->setText(problem);
    m_preview->setScene(m_made);
    m_import->setEnabled(m_made != nullptr);
}

}  // namespace ui
