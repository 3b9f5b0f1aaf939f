#include "sim_import.h"

#include "core/io/mesh_file.h"
#include "core/io/scene_file.h"

#include <QDir>
#include <QElapsedTimer>
#include <QTextStream>

namespace app {

using namespace Qt::Literals::StringLiterals;

int runImport(const SimOptions &options)
{
    const ImportRequest &request = *options.import;
    QTextStream err(stderr);
    const auto fail = [&](const QString &message) {
        err << "springlab-sim: " << message << '\n';
        return 2;
    };

    // the scene it goes into, first: a bad one stops the import before the mesh is read
    core::SceneDesc scene;
    if (!request.intoPath.isEmpty()) {
        const io::LoadResult loaded = io::loadScene(request.intoPath);
        if (!loaded.ok())
            return fail(loaded.error);
        scene = *loaded.scene;
    }

    QElapsedTimer clock;
    clock.start();
    const io::MeshReadResult read = io::readMeshFile(request.meshPath);
    if (!read.ok())
        return fail(read.error);
    const qint64 readMs = clock.elapsed();

    core::MeshImportOptions made;
    made.kind = request.kind;
    made.name = request.name.toStdString();
    made.source = request.meshPath.toStdString();
    made.placement.scale = request.scale;
    made.placement.zUp = request.zUp;
    made.placement.at = request.at;
    made.material = request.material;
    made.density = request.density;
    made.stiffness = request.stiffness;
    made.damping = request.damping;
    made.spacing = request.spacing;
    made.pin = request.pin;
    const core::MeshImportResult result = request.intoPath.isEmpty() ? core::sceneFromMesh(scene, *read.mesh, made)
                                                                     : core::addMeshToScene(scene, *read.mesh, made);
    if (!result.ok())
        return fail(QDir::toNativeSeparators(request.meshPath) + u": "_s + QString::fromStdString(result.error));
    const qint64 totalMs = clock.elapsed();

    if (const io::SaveResult saved = io::saveScene(options.outputPath, scene); !saved.ok())
        return fail(saved.error);
    if (!options.quiet) {
        QTextStream out(stdout);
        for (const QString &note : read.notes)
            out << "springlab-sim: note: " << note << '\n';
        const std::string_view kind = core::meshKindName(request.kind);
        out << "springlab-sim: " << QDir::toNativeSeparators(request.meshPath) << ": " << read.mesh->vertices.size()
            << " vertices, " << read.mesh->faces.size() << " triangles, imported as "
            << QString::fromLatin1(kind.data(), qsizetype(kind.size())) << " in " << totalMs << " ms (" << readMs
            << " ms reading the file)\n";
        out << "  made       " << result.particles << " particles, " << result.springs << " springs, " << result.triangles
            << " triangles";
        if (result.mass > 0.0)
            out << QString::asprintf(", %.6g kg", result.mass);
        if (result.area > 0.0)
            out << QString::asprintf(", %.6g m²", result.area);
        if (result.volume > 0.0)
            out << QString::asprintf(", %.6g m³", result.volume);
        out << '\n';
        for (const std::string &note : result.notes)
            out << "  note       " << QString::fromStdString(note) << '\n';
        out << "  output     " << options.outputPath << '\n';
    }
    return 0;
}

}  // namespace app
