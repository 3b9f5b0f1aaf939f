// MainWindow's editing: the tools' toolbar with the values new items get, the Edit menu's
// actions on the selection, its generators and Transform Selection, and the inspector dock.

#include "main_window.h"

#include "camera_actions.h"
#include "ui/viewport/edit_tools.h"
#include "ui/dialogs/generate_dialog.h"
#include "ui/dialogs/transform_dialog.h"
#include "ui/panels/inspector_panel.h"
#include "ui/panels/status_text.h"
#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "ui/panels/value_spin_box.h"
#include "ui/simulation/simulation_controller.h"

#include "core/model/validate.h"

#include <QAction>
#include <QCheckBox>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

namespace ui {

namespace {

// how long a tool's message stays in the status bar, ms
constexpr int kToolMessageMs = 6000;

struct DefaultField {
    const char *name;
    const char *label;
    const char *tip;
    double ItemDefaults::*field;
    SliderScale scale;
};

// a toolbar field wide enough for a value like 0.00125, so that the toolbar fits one row
int compactWidth(const QAbstractSpinBox *box)
{
    return box->fontMetrics().horizontalAdvance(QStringLiteral("0.000000")) + 2 * box->sizeHint().height();
}

}  // namespace

void MainWindow::createEditing()
{
    m_tools = new EditTools(m_viewport, m_document, m_controller, this);
    connect(m_tools, &EditTools::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, kToolMessageMs); });
    connect(m_tools, &EditTools::refused, this, &MainWindow::showWarning);

    // the tools, then what new particles and springs get
    m_toolBar = addToolBar(tr("Tools"));
    m_toolBar->setObjectName(QStringLiteral("toolsToolBar"));
    for (QAction *action : m_tools->toolActions())
        m_toolBar->addAction(action);
    m_viewMenu->addAction(m_toolBar->toggleViewAction());
    // what new particles and springs get, a toolbar of its own: on the tools' row where the window
    // is wide enough, else on a row of its own (fitToolBars), never behind "»"
    m_itemsToolBar = addToolBar(tr("New Items"));
    m_itemsToolBar->setObjectName(QStringLiteral("newItemsToolBar"));

    const DefaultField fields[] = {
        {"defaultMass", QT_TR_NOOP("Mass"), QT_TR_NOOP("Mass of new particles, kg"), &ItemDefaults::mass,
         {1e-3, 1e3, core::Scale::Log, false, 1000}},
        {"defaultRadius", QT_TR_NOOP("Radius"), QT_TR_NOOP("Radius of new particles, m"), &ItemDefaults::radius,
         {1e-3, 10.0, core::Scale::Log, false, 1000}},
        {"defaultStiffness", QT_TR_NOOP("k"), QT_TR_NOOP("Stiffness of new springs, N/m"), &ItemDefaults::stiffness,
         {1e-1, 1e6, core::Scale::Log, false, 1000}},
        {"defaultDamping", QT_TR_NOOP("kc"), QT_TR_NOOP("Damping of new springs, N·s/m"), &ItemDefaults::damping,
         {1e-3, 1e3, core::Scale::Log, true, 1000}},
    };
    for (const DefaultField &f : fields) {
        auto *label = new QLabel(tr(f.label), m_itemsToolBar);
        auto *box = new ValueSpinBox(f.scale, m_itemsToolBar);
        box->setObjectName(QString::fromLatin1(f.name));
        box->setToolTip(tr(f.tip));
        label->setToolTip(tr(f.tip));
        box->setMaximumWidth(compactWidth(box));
        box->setValue(m_tools->defaults().*f.field);
        double ItemDefaults::*field = f.field;
        const SliderScale scale = f.scale;
        const QString what = tr(f.tip);
        // any number can be typed: one out of range is refused with a message, the old value kept
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, box, field, scale, what](double value) {
            const double low = scale.zeroAtStart ? 0.0 : scale.minimum;
            if (!(value >= low && value <= scale.maximum)) {
                showWarning(tr("%1 must be from %2 to %3; %4 was not used").arg(what).arg(low).arg(scale.maximum).arg(value));
                const QSignalBlocker block(box);
                box->setValue(m_tools->defaults().*field);
                return;
            }
            m_tools->defaults().*field = value;
        });
        m_itemsToolBar->addWidget(label);
        m_itemsToolBar->addWidget(box);
    }

    auto *snap = new QCheckBox(tr("Snap"), m_itemsToolBar);
    snap->setObjectName(QStringLiteral("defaultSnap"));
    snap->setToolTip(tr("Place new particles on a grid"));
    auto *step = new ValueSpinBox({1e-3, 10.0, core::Scale::Log, false, 1000}, m_itemsToolBar);
    step->setObjectName(QStringLiteral("gridStep"));
    step->setToolTip(tr("Grid step, m"));
    step->setMaximumWidth(compactWidth(step));
    step->setValue(m_tools->defaults().gridStep);
    step->setEnabled(false);
    connect(snap, &QCheckBox::toggled, this, [this, step](bool on) {
        m_tools->defaults().snap = on;
        step->setEnabled(on);
    });
    connect(step, &QDoubleSpinBox::valueChanged, this, [this, step](double value) {
        if (!(value >= 1e-3 && value <= 10.0)) {
            showWarning(tr("The grid step must be from 0.001 to 10 m; %1 was not used").arg(value));
            const QSignalBlocker block(step);
            step->setValue(m_tools->defaults().gridStep);
            return;
        }
        m_tools->defaults().gridStep = value;
    });
    m_itemsToolBar->addWidget(snap);
    m_itemsToolBar->addWidget(step);
    m_viewMenu->addAction(m_itemsToolBar->toggleViewAction());

    // the selection's actions join undo and redo in the Edit menu
    m_editMenu->addSeparator();
    for (QAction *action : m_tools->editActions()) {
        m_editMenu->addAction(action);
        // the viewport's keys, not a spin box's: Delete and Backspace edit text there
        action->setShortcutContext(Qt::WindowShortcut);
    }
    // the generators: a cloth, rope, chain, granular block or ball, or soft ball in one undo step
    QAction *generate = m_editMenu->addAction(tr("&Generate..."), this, &MainWindow::showGenerate);
    generate->setObjectName(QStringLiteral("actionGenerate"));
    generate->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_G));
    generate->setStatusTip(tr("Add a cloth, rope, chain, block or ball of particles, or a soft ball, previewed first "
                              "(one undo step)"));
    // the selection moved, turned or scaled by typed amounts, one undo step each Apply
    QAction *transform = m_editMenu->addAction(tr("&Transform Selection..."), this, &MainWindow::showTransform);
    transform->setObjectName(QStringLiteral("actionTransformSelection"));
    transform->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
    transform->setStatusTip(tr("Move, rotate or scale the selected particles' initial positions by typed amounts, "
                               "about their centroid (one undo step)"));
    m_editMenu->addSeparator();
    QMenu *tools = m_editMenu->addMenu(tr("&Tool"));
    for (QAction *action : m_tools->toolActions())
        tools->addAction(action);

    // the inspector: the selection's values, and the planes, below the parameters
    m_inspector = new InspectorPanel(m_document, m_tools);
    m_inspector->setObjectName(QStringLiteral("inspector"));
    auto *dock = new QDockWidget(tr("Inspector"), this);
    dock->setObjectName(QStringLiteral("inspectorDock"));
    dock->setWidget(inScrollArea(m_inspector));
    addDockWidget(Qt::RightDockWidgetArea, dock);
    m_viewMenu->addAction(dock->toggleViewAction());
    connect(m_inspector, &InspectorPanel::valueRefused, this, &MainWindow::showWarning);
}

void MainWindow::showGenerate()
{
    if (!m_generate) {
        m_generate = new GenerateDialog(this);
        connect(m_generate, &QDialog::accepted, this, &MainWindow::addGenerated);
    }
    m_generate->open();
}

void MainWindow::showTransform()
{
    // not modal: the selection can change while it is open, and it follows
    if (!m_transform) {
        m_transform = new TransformDialog(m_document, m_tools, this);
        connect(m_transform, &TransformDialog::applied, this,
                [this](const QString &text) { statusBar()->showMessage(text, kToolMessageMs); });
    }
    m_transform->show();
    m_transform->raise();
    m_transform->activateWindow();
}

void MainWindow::addGenerated()
{
    // the dialog's scene, moved to where it says, as one undo step; the new particles are selected
    const std::shared_ptr<const core::SceneDesc> generated = m_generate->generated();
    if (!generated)
        return;
    if (const std::optional<std::size_t> total = particlesPastLimit(m_document->scene(), generated->particles.size())) {
        showWarning(particleLimitText(tr("Not generated"), *total));
        return;
    }
    auto edited = std::make_shared<core::SceneDesc>(m_document->scene());
    const Selection added = ui::addGenerated(*edited, *generated, m_generate->position());
    if (const std::optional<core::SceneProblem> problem = core::findProblem(*edited)) {
        showWarning(tr("Not generated: %1 %2")
                        .arg(QString::fromStdString(problem->path), QString::fromStdString(problem->message)));
        return;
    }
    const QString what = m_generate->kindName();
    m_document->undoStack()->push(new SceneCommand(*m_document, tr("Generate %1").arg(what), std::move(edited)));
    m_tools->setSelection(added);
    // once the worker shows it: framed with the rest if any of it is out of view
    m_cameraActions->frameWhenShownIfHidden(m_controller->sync(), added.particles);
    statusBar()->showMessage(tr("Added %1: ").arg(what) + m_generate->countText(), kToolMessageMs);
}

}  // namespace ui
