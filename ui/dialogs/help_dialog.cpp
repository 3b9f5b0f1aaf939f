#include "help_dialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QVBoxLayout>

namespace ui {

HelpDialog::HelpDialog(const QMenuBar &menus, QWidget *parent) : QDialog(parent), m_table(new QTableWidget(0, 2, this))
{
    setWindowTitle(tr("Keyboard and mouse"));
    m_table->setHorizontalHeaderLabels({tr("Keys"), tr("What they do")});
    m_table->verticalHeader()->hide();
    // the keys as wide as their longest, kept so whenever the font changes (a desktop's font or
    // scale applied after the dialog was built), and the descriptions wrapped to what is left
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setShowGrid(false);
    m_table->setWordWrap(true);
    m_table->setTextElideMode(Qt::ElideNone);

    // the keys: every action of the menus that has a shortcut, in menu order
    addSection(tr("Keyboard"));
    for (const QAction *action : menus.actions())
        if (const QMenu *menu = action->menu())
            addMenu(*menu, menu->title().remove(QLatin1Char('&')));

    // the mouse, in the 3D view
    addSection(tr("Mouse, in the 3D view"));
    addEntry(tr("Right drag"), tr("Orbit the camera around its target (left drag on empty space too, "
                                   "except with the Select tool)"));
    addEntry(tr("Middle drag, or Shift + left drag on empty space"), tr("Pan"));
    addEntry(tr("Wheel"), tr("Zoom towards the point under the cursor"));
    addEntry(tr("Select tool (1)"),
             tr("Click a particle or spring to select it; Shift or Ctrl + click adds or removes; drag on empty "
                "space selects the particles in a box (Ctrl + drag adds them)"));
    addEntry(tr("Add Particle tool (2)"),
             tr("Click to place a particle resting on the surface under the cursor (a plane, a table, or the "
                "ground y = 0 in a scene without planes); over no surface, on the plane facing you through the "
                "one selected particle; Snap in the toolbar rounds to the grid"));
    addEntry(tr("Pin tool (3)"), tr("Click a particle to pin or free it"));
    addEntry(tr("Spring tool (4)"),
             tr("Click one particle, then another, or drag from one to another: a spring with the toolbar's k "
                "and kc, at rest at their distance; a dashed line follows the cursor meanwhile"));
    addEntry(tr("Drag tool (5)"),
             tr("Running: hold a particle to pull it toward the cursor, and turn the wheel meanwhile to spin it "
                "about the line of sight (a turn per second a notch), so that it flies off spinning. Paused: drag "
                "to move the selection (one undo step)"));
    addEntry(tr("Measure tool (6)"),
             tr("Click one particle, then another, or drag from one to another: a line between them labelled with "
                "their distance, which follows them while the run plays; the status bar gives the distance with its "
                "x, y and z parts, and the pair becomes the selection"));
    addEntry(tr("Hover"), tr("What a click would pick is highlighted"));

    // the camera: what View's keys above do not say
    addSection(tr("Camera"));
    addEntry(tr("A new scene, Edit › Generate"),
             tr("A new scene is framed once it is shown; what Generate adds is framed with the rest of the scene "
                "only when some of it is out of view"));
    addEntry(tr("View › Orthographic"),
             tr("Picking, zooming at the cursor, panning and the grid work as in perspective; kept for the next "
                "session"));
    addEntry(tr("Ground grid"),
             tr("On the scene's floors (planes facing up, within about 8°), at their height; none in a scene "
                "without a floor"));

    // files: what the menus do not show
    addSection(tr("Files"));
    addEntry(tr("Drop a .json file on the window"), tr("Open it (after asking about unsaved changes)"));
    addEntry(tr("springlab SCENE.json"), tr("Start the editor on that scene"));
    addEntry(tr("File › Open Recent"), tr("The last 10 scenes opened or saved; a missing file is removed"));
    addEntry(tr("File › Autosave"),
             tr("Unsaved changes go to a recovery file every minute (or as chosen); after a crash the next start "
                "offers them back"));
    addEntry(tr("View › Undo History"), tr("Every edit of the scene; click one to go back to it"));

    // models: in through File › Import Mesh, out through File › Export Animation
    addSection(tr("Meshes"));
    addEntry(tr("File › Import Mesh… (Ctrl+I)"),
             tr("A model file (OBJ, PLY, STL, glTF, FBX, Collada, ...) as a cloth (a particle per vertex, springs "
                "along and across the triangles, a material preset), a soft body (a closed mesh filled with "
                "particles on a lattice, its surface carried along and drawn) or a collider (a fixed triangle "
                "mesh), scaled, turned from Z-up and placed; into this scene or a new one, one undo step. A file "
                "that is not a mesh, or has no triangles or a bad number, is named and nothing changes"));
    addEntry(tr("File › Export Animation…"),
             tr("Run on from the current state, or replay the recorded run from the timeline between two times, and "
                "write the motion of the imported meshes (or of the scene's "
                "triangles, where none was imported) for Blender: a PC2 point cache with the OBJ it plays on "
                "(Mesh Cache modifier), an OBJ per frame, or the last frame as glTF, PLY or STL; an imported mesh "
                "in its file's own units and axes. A progress dialog can cancel it and keeps the frames written"));
    addEntry(tr("springlab-sim --import MESH"),
             tr("The same import with no window (--as cloth|soft|collider, --output SCENE.json); "
                "--export-pc2, --export-obj and --export-mesh write a run's animation"));

    // generators: what Edit › Generate makes
    addSection(tr("Generate"));
    addEntry(tr("Edit › Generate… (Ctrl+G)"),
             tr("A cloth of rows × columns (structural, shear and bend springs, each with its own k), a rope "
                "(touching links), a chain, a block or ball of loose particles (granular, with a seeded jitter) or "
                "a soft ball (points on a sphere joined to their neighbours, optionally to a centre particle). The "
                "preview and the counts follow every value, wrong options are named and not generated, and the "
                "result, its middle where you say, is one undo step and becomes the selection"));

    // numeric edits of the selection
    addSection(tr("Transform"));
    addEntry(tr("Edit › Transform Selection… (Ctrl+T)"),
             tr("Move by x, y, z metres, rotate by degrees about x, y, z or a typed axis, and scale by a factor "
                "(uniform or per axis), the rotation and the factor about the selection's centroid: the initial "
                "positions of the selected particles (pinned ones too), their velocities turned with them. Springs "
                "keep their rest lengths unless Scale the rest lengths is checked. A value that cannot be used is "
                "named and nothing changes; each Apply is one undo step. The dialog stays open and follows the "
                "selection"));

    // export: the image is in the keys above (Shift+F2); the rest has no key
    addSection(tr("Export"));
    addEntry(tr("File › Export › Image Sequence"),
             tr("Run on from the current state and write frame-00000.png, ... at a frame rate, for a duration, at "
                "any size; frame k shows the first step at or after k / rate. A progress dialog can cancel it"));
    addEntry(tr("MP4 (with the sequence)"),
             tr("Where ffmpeg is installed, the frames also become an MP4 in their folder (H.264, or MPEG-4 "
                "without libx264); the dialog says so when ffmpeg is not found"));
    addEntry(tr("File › Export › Trace CSV"),
             tr("Run on from the current state and write step,time,particle,x,y,z,vx,vy,vz every K steps, as "
                "springlab-sim --trace does"));
    addEntry(tr("springlab-sim SCENE.json --render DIR"),
             tr("The same frames with no window, for batch work (--fps, --size WxH, --duration); it needs an X "
                "display, so run it under xvfb-run -a on a machine without one"));

    // accuracy: the integrator, and the figures that say how accurate the run is
    addSection(tr("Accuracy"));
    addEntry(tr("Parameters › Integrator"),
             tr("How each sub-step is integrated: symplectic-euler, explicit-euler, velocity-verlet, rk4, "
                "implicit-euler, adaptive-rk45, xpbd (springs as constraints), or for stiff materials projective "
                "(projective dynamics: a prefactored solve) and vbd (vertex block descent) (undoable)"));
    addEntry(tr("Parameters › Tolerance"), tr("The local error per step adaptive-rk45 keeps under (only for it)"));
    addEntry(tr("Parameters › Solver iterations"),
             tr("projective's and vbd's iterations of the implicit Euler solve in each sub-step; the stability "
                "line says how far they converged"));
    addEntry(tr("Status bar: local error ≈"),
             tr("The local position error of one step of the integrator, by step doubling every few steps"));
    addEntry(tr("Status bar: ΔE"),
             tr("The change of the total energy since the last reset, in % of it (in J when it is about 0)"));

    // contacts: the parameters dock's group and the inspector's planes
    addSection(tr("Contacts"));
    addEntry(tr("Parameters › Solver"),
             tr("Iterative (the default: impacts located in time within the sub-step, then the resting contacts "
                "solved together, so stacks and piles come to rest) or Handout (the course's single pass per "
                "sub-step); undoable"));
    addEntry(tr("Parameters › Restitution"),
             tr("1 elastic … 0 fully inelastic, for every contact: the share of the approach speed a contact "
                "gives back"));
    addEntry(tr("Parameters › Friction"),
             tr("The kinetic Coulomb coefficient μk (0 to 10): a sliding contact's friction is μk times the force "
                "pressing it; live and undoable"));
    addEntry(tr("Parameters › Static friction"),
             tr("The static coefficient μs: a contact sticks while the friction it needs stays within μs times "
                "that force. It follows Friction until set; Static follows friction makes it follow again"));
    addEntry(tr("Inspector › Planes"),
             tr("Two-sided: a thin wall instead of a half-space. Own friction: this plane's coefficient, static "
                "and kinetic, instead of the scene's. Size w × h: a rectangle (two-sided, with edges, drawn as "
                "itself) at Centre with its width along Axis; 0 is the whole plane"));

    // the timeline and tearing
    addSection(tr("Timeline"));
    addEntry(tr("Timeline slider, under the view"),
             tr("Scrub through the recorded run (the exact recorded state of every step); scrubbing pauses. Play, "
                "or any edit, goes on from the step shown and drops what was recorded after it"));
    addEntry(tr("Timeline ◀ ▶ buttons"), tr("One step back or forward through the recording (Shift+F6, F6)"));
    addEntry(tr("Timeline budget (MB)"),
             tr("The memory the recording may use, shown as used / budget; past it the oldest steps go"));
    addEntry(tr("Inspector › Breaking strain"),
             tr("A spring stretched past (l - l0) / l0 = this breaks for good during the run (0: never); red "
                "ticks on the timeline mark the steps springs broke in; Reset mends them"));

    // plots: what they show, what "lost" means, and the exports
    addSection(tr("Plots"));
    addEntry(tr("View › Plots (F8)"),
             tr("Energies (kinetic, gravitational, spring, total), momentum, or the selected particle's position or "
                "velocity against time, chosen in the dock's box; every step of the run, however seldom the view is "
                "drawn (every 2nd, 4th, … step once a plot holds 20 000), started over at a reset or another scene"));
    addEntry(tr("Plots: lost since reset"),
             tr("The total energy at the last reset less the total now: what damping, drag and inelastic contacts "
                "took, and also the integrator's own drift and work done by the mouse, the steering or edits"));
    addEntry(tr("Plots: Export PNG…, Export CSV…"),
             tr("Save the plot shown as an image, or its samples as CSV: step, time, one column per curve, a row "
                "per step kept (also on a right-click on the plot)"));

    // rows as tall as their wrapped descriptions
    connect(m_table->horizontalHeader(), &QHeaderView::sectionResized, m_table, &QTableWidget::resizeRowsToContents);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(640, 640);
}

void HelpDialog::addMenu(const QMenu &menu, const QString &path)
{
    for (const QAction *action : menu.actions()) {
        if (const QMenu *submenu = action->menu()) {
            addMenu(*submenu, path + QStringLiteral(" › ") + submenu->title().remove(QLatin1Char('&')));
            continue;
        }
        const QList<QKeySequence> shortcuts = action->shortcuts();
        if (shortcuts.isEmpty())
            continue;
        QStringList keys;
        for (const QKeySequence &shortcut : shortcuts)
            keys << shortcut.toString(QKeySequence::NativeText);
        QString description = action->text().remove(QLatin1Char('&')).remove(QStringLiteral("..."));
        description = path + QStringLiteral(" › ") + description.remove(QChar(0x2026));
        if (!action->statusTip().isEmpty())
            description += QStringLiteral(": ") + action->statusTip();
        addEntry(keys.join(QStringLiteral(", ")), description);
    }
}

void HelpDialog::addSection(const QString &title)
{
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    auto *item = new QTableWidgetItem(title);
    QFont bold = item->font();
    bold.setBold(true);
    item->setFont(bold);
    m_table->setItem(row, 0, item);
    m_table->setSpan(row, 0, 1, 2);
}

void HelpDialog::addEntry(const QString &keys, const QString &description)
{
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    m_table->setItem(row, 0, new QTableWidgetItem(keys));
    m_table->setItem(row, 1, new QTableWidgetItem(description));
}

QStringList HelpDialog::entries() const
{
    QStringList rows;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QTableWidgetItem *description = m_table->item(row, 1);
        if (description)
            rows << m_table->item(row, 0)->text() + QLatin1Char('\t') + description->text();
    }
    return rows;
}

}  // namespace ui
