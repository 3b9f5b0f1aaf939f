#pragma once
// ImportMeshDialog: File › Import Mesh…. A mesh file (read through io::readMeshFile), what it
// becomes (cloth, soft body, collider) with that kind's options (material, density, stiffness,
// damping, lattice spacing, a pinned side), how it is placed (scale, Y-up or Z-up, its bottom
// middle at a point, or where the file has it), whether it joins the open scene or starts a new
// one, and a preview of the body it makes with its counts, or what is wrong (then Import is off).
// The import itself is core's (core/meshes/mesh_import.h); the main window applies the result as
// one undoable edit. Shown with open(), like the Generate dialog, so the tests drive it as widgets.

#include "core/meshes/mesh_import.h"

#include <QDialog>
#include <QString>
#include <functional>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace ui {

class GeneratePreview;
class ValueSpinBox;

class ImportMeshDialog : public QDialog {
    Q_OBJECT

public:
    // asked for a file when Browse is clicked, with the one typed so far; empty: cancelled
    using BrowseFunction = std::function<QString(const QString &current)>;

    explicit ImportMeshDialog(BrowseFunction browse, QWidget *parent = nullptr);
    ~ImportMeshDialog() override;

    // the file to read; read at once, and the preview made again
    void setPath(const QString &path);
    QString path() const;

    // what Import would do: the options as set, the mesh as read (null while the file or the
    // options are wrong), into a new scene or the open one
    core::MeshImportOptions options() const;
    std::shared_ptr<const core::TriangleMesh> mesh() const { return m_mesh; }
    bool intoNewScene() const;
    // the body alone as the preview shows it (null while something is wrong)
    std::shared_ptr<const core::SceneDesc> made() const { return m_made; }

    // "3 120 particles, 18 410 springs, 2 048 triangles; …", or empty while something is wrong
    QString countText() const;
    // what is wrong with the file or the options, or empty
    QString problemText() const;
    GeneratePreview *preview() const { return m_preview; }
    QPushButton *importButton() const { return m_import; }

private:
    void browse();
    void readFile();
    // makes the body again from the mesh and the options, or says why not
    void remake();
    void updateKindFields();

    BrowseFunction m_browse;
    std::shared_ptr<const core::TriangleMesh> m_mesh;
    QString m_readError;
    QStringList m_readNotes;
    std::shared_ptr<const core::SceneDesc> m_made;

    QLineEdit *m_path = nullptr;
    QLineEdit *m_name = nullptr;
    QComboBox *m_kind = nullptr;
    QComboBox *m_material = nullptr;
    QLabel *m_densityUnit = nullptr;
    ValueSpinBox *m_density = nullptr;
    ValueSpinBox *m_stiffness = nullptr;
    ValueSpinBox *m_damping = nullptr;
    ValueSpinBox *m_spacing = nullptr;
    QComboBox *m_pin = nullptr;
    ValueSpinBox *m_scale = nullptr;
    QComboBox *m_up = nullptr;
    QCheckBox *m_place = nullptr;
    ValueSpinBox *m_at[3] = {};
    QComboBox *m_into = nullptr;
    GeneratePreview *m_preview = nullptr;
    QLabel *m_count = nullptr;
    QLabel *m_problem = nullptr;
    QPushButton *m_import = nullptr;
};

}  // namespace ui
