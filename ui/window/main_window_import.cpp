// MainWindow's File › Import Mesh: the dialog (ui/dialogs/import_mesh_dialog.h), and what it makes
// applied to the document as one undo step, into the open scene or a new one.

#include "main_window.h"

#include "camera_actions.h"
#include "ui/dialogs/import_mesh_dialog.h"
#include "ui/document/document_files.h"
#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "ui/document/scene_edits.h"
#include "ui/panels/status_text.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/edit_tools.h"

#include "core/io/mesh_file.h"

#include <QStatusBar>

#include <numeric>

namespace ui {

namespace {

constexpr int kImportMessageMs = 10000;

}  // namespace

void MainWindow::showImportMesh()
{
    if (!m_importMesh) {
        auto browse = [this](const QString &current) {
            return m_prompts.chooseFile(Prompts::FileDialogMode::Open, tr("Import mesh"),
                                        current.isEmpty() ? m_document->folder() : current,
                                        tr("Meshes (%1);;All files (*)").arg(io::meshFileFilter()));
        };
        m_importMesh = new ImportMeshDialog(browse, this);
        connect(m_importMesh, &QDialog::accepted, this, &MainWindow::addImportedMesh);
    }
    m_importMesh->open();
}

void MainWindow::addImportedMesh()
{
    const std::shared_ptr<const core::TriangleMesh> mesh = m_importMesh->mesh();
    if (!mesh)
        return;
    const bool fresh = m_importMesh->intoNewScene();
    const core::MeshImportOptions options = m_importMesh->options();
    const QString name = QString::fromStdString(options.name.empty() ? std::string("mesh") : options.name);
    if (!fresh) {
        if (const std::optional<std::size_t> total = particlesPastLimit(m_document->scene(), mesh->vertices.size())) {
            showWarning(particleLimitText(tr("Not imported"), *total));
            return;
        }
    }
    // the scene it makes, checked whole before the document sees it
    auto edited = std::make_shared<core::SceneDesc>(fresh ? core::SceneDesc{} : m_document->scene());
    const int before = fresh ? 0 : int(edited->particles.size());
    const core::MeshImportResult result =
        fresh ? core::sceneFromMesh(*edited, *mesh, options) : core::addMeshToScene(*edited, *mesh, options);
    if (!result.ok()) {
        showWarning(tr("Not imported: %1").arg(QString::fromStdString(result.error)));
        return;
    }
    // a new scene replaces the open one as New does (its unsaved changes asked about first), and
    // the import is its first undo step
    if (fresh && !m_files->newDocument())
        return;
    m_document->undoStack()->push(new SceneCommand(*m_document, tr("Import %1").arg(name), std::move(edited)));
    Selection added;
    added.particles.resize(std::size_t(result.particles));
    std::iota(added.particles.begin(), added.particles.end(), before);
    m_tools->setSelection(added);
    m_cameraActions->frameWhenShownIfHidden(m_controller->sync(), added.particles);
    statusBar()->showMessage(tr("Imported %1: ").arg(name) + m_importMesh->countText().section(QLatin1Char('\n'), 0, 0),
                             kImportMessageMs);
}

}  // namespace ui
