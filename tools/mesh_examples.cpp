#include "tools/mesh_examples.h"

#include "core/io/mesh_file.h"
#include "core/meshes/mesh_import.h"

#include <QDir>

namespace tools {

namespace {

using Eigen::Vector3d;

// reads resources/meshes/FILE; the options' source names it as the repository does
std::optional<core::TriangleMesh> readExample(const QString &folder, const QString &file, core::MeshImportOptions &options,
                                              QString *error)
{
    io::MeshReadResult read = io::readMeshFile(QDir(folder).filePath(file));
    if (!read.ok()) {
        *error = read.error;
        return std::nullopt;
    }
    options.name = QFileInfo(file).completeBaseName().toStdString();
    options.source = "resources/meshes/" + file.toStdString();
    return std::move(read.mesh);
}

bool imported(const core::MeshImportResult &result, const QString &what, QString *error)
{
    if (!result.ok())
        *error = what + QStringLiteral(": ") + QString::fromStdString(result.error);
    return result.ok();
}

// the table of table.obj, where the file has it (its legs on y = 0), as a collider with a floor
bool tableScene(const QString &folder, core::SceneDesc &scene, QString *error)
{
    core::MeshImportOptions table;
    table.kind = core::MeshKind::Collider;
    const auto mesh = readExample(folder, QStringLiteral("table.obj"), table, error);
    return mesh && imported(core::sceneFromMesh(scene, *mesh, table), QStringLiteral("table.obj"), error);
}

}  // namespace

std::vector<core::SceneDesc> meshExamples(const QString &folder, QString *error)
{
    // a silk flag, written Z-up as Blender writes it and lying in the file's ground plane, held
    // along its left edge (a pole jutting out of a wall) 2 m up: it falls from straight out,
    // swings down past the pole and comes to hang from it
    core::SceneDesc flag;
    core::MeshImportOptions flagOptions;
    flagOptions.material = core::ClothMaterial::Silk;
    flagOptions.placement.zUp = true;
    flagOptions.placement.at = Vector3d(0.0, 2.0, 0.0);
    flagOptions.pin = core::PinSide::Left;
    const auto flagMesh = readExample(folder, QStringLiteral("flag.obj"), flagOptions, error);
    if (!flagMesh || !imported(core::sceneFromMesh(flag, *flagMesh, flagOptions), QStringLiteral("flag.obj"), error))
        return {};
    flag.name = "mesh-flag";
    // the air: silk weighs 0.4 g a particle here, so the air's drag on a flag matters as much as
    // gravity (a plate of the particle's 85 cm² share at 1 m/s feels about 6 mN); a viscous medium
    // of 2 g/s a particle damps the swing within a few seconds, as a flag's swing is damped
    flag.settings.viscosity = 0.002;

    // a cotton tablecloth dropped a little off-centre onto the table: it drapes over the top's
    // edges and hangs between the legs, on neither side of the table's triangles
    core::SceneDesc tablecloth;
    if (!tableScene(folder, tablecloth, error))
        return {};
    core::MeshImportOptions clothOptions;
    clothOptions.placement.at = Vector3d(0.1, 0.95, 0.05);
    const auto clothMesh = readExample(folder, QStringLiteral("tablecloth.obj"), clothOptions, error);
    if (!clothMesh || !imported(core::addMeshToScene(tablecloth, *clothMesh, clothOptions), QStringLiteral("tablecloth.obj"), error))
        return {};
    tablecloth.name = "mesh-tablecloth";

    // a foam ball (the icosphere of ball.obj filled with a lattice) dropped onto the table: it
    // squashes, bounces and comes to rest on it
    core::SceneDesc soft;
    if (!tableScene(folder, soft, error))
        return {};
    core::MeshImportOptions ballOptions;
    ballOptions.kind = core::MeshKind::Soft;
    ballOptions.placement.at = Vector3d(0.3, 1.3, 0.0);
    const auto ballMesh = readExample(folder, QStringLiteral("ball.obj"), ballOptions, error);
    if (!ballMesh || !imported(core::addMeshToScene(soft, *ballMesh, ballOptions), QStringLiteral("ball.obj"), error))
        return {};
    soft.name = "mesh-soft-ball";
    return {flag, tablecloth, soft};
}

}  // namespace tools
