#include "mesh_import.h"

#include "bench_common.h"

#include "core/io/animation_export.h"
#include "core/io/mesh_file.h"
#include "core/meshes/mesh_import.h"
#include "core/meshes/mesh_surface.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "core/model/workspace.h"
#include "core/step.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <cmath>
#include <functional>

namespace bench {

namespace {

// a sheet of rows × cols vertices 1 cm apart, two triangles a cell: an open mesh, as a garment
// panel or a flag is
core::TriangleMesh sheet(int rows, int cols)
{
    core::TriangleMesh m;
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j)
            m.vertices.emplace_back(0.01 * j, 0.0, 0.01 * i);
    for (int i = 0; i + 1 < rows; ++i)
        for (int j = 0; j + 1 < cols; ++j) {
            const int a = i * cols + j, b = a + 1, c = a + cols, d = c + 1;
            m.faces.push_back({a, c, b});
            m.faces.push_back({b, c, d});
        }
    return m;
}

// a closed sphere of 0.3 m radius, `slices` around and `rings` from pole to pole, one vertex at
// each pole: 2 × slices × (rings − 1) triangles, as a scanned or sculpted closed model has
core::TriangleMesh sphere(int slices, int rings)
{
    constexpr double kRadius = 0.3;
    core::TriangleMesh m;
    m.vertices.emplace_back(0.0, kRadius, 0.0);
    for (int r = 1; r < rings; ++r) {
        const double polar = M_PI * r / rings;
        for (int s = 0; s < slices; ++s) {
            const double around = 2.0 * M_PI * s / slices;
            m.vertices.emplace_back(kRadius * std::sin(polar) * std::cos(around), kRadius * std::cos(polar),
                                    kRadius * std::sin(polar) * std::sin(around));
        }
    }
    m.vertices.emplace_back(0.0, -kRadius, 0.0);
    const int south = int(m.vertices.size()) - 1;
    const auto at = [slices](int ring, int s) { return 1 + (ring - 1) * slices + (s % slices); };
    for (int s = 0; s < slices; ++s) {
        // counter-clockwise seen from outside
        m.faces.push_back({0, at(1, s + 1), at(1, s)});
        for (int r = 1; r + 1 < rings; ++r) {
            m.faces.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
            m.faces.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
        }
        m.faces.push_back({south, at(rings - 1, s), at(rings - 1, s + 1)});
    }
    return m;
}

// the median wall time of `runs` calls after one untimed, ms; false when a call fails
bool timed(int runs, const std::function<bool()> &call, double &ms)
{
    if (!call())
        return false;
    std::vector<double> samples;
    for (int run = 0; run < runs; ++run) {
        QElapsedTimer clock;
        clock.start();
        if (!call())
            return false;
        samples.push_back(double(clock.nsecsElapsed()) * 1e-6);
    }
    ms = median(samples);
    return true;
}

// the process's peak resident memory since the last reset, kB (VmHWM); -1 where it cannot be read
long long peakResidentKb()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n'))
        if (line.startsWith("VmHWM:"))
            return line.mid(6).trimmed().split(' ').first().toLongLong();
    return -1;
}

// starts the peak over from the memory resident now (Linux: "5" to clear_refs); false where not
bool resetPeakResident()
{
    QFile refs(QStringLiteral("/proc/self/clear_refs"));
    return refs.open(QIODevice::WriteOnly) && refs.write("5") == 1;
}

// a PC2 export of `frames` frames, a frame a step, of the sheet falling freely (its springs left
// out, so that the run costs nothing beside the export); the growth of the peak resident memory
// over what the scene and its run hold before the export opens, kB; -1 if it failed
long long exportGrowthKb(const core::SceneDesc &scene, const QString &path, int frames, double &seconds, QTextStream &out)
{
    const auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    core::Workspace work;
    core::step(*model, state, work);  // the workspace made before the baseline
    state = core::makeState(*model, scene);
    const double h = scene.settings.timeStep;
    if (!resetPeakResident())
        return -1;
    const long long before = peakResidentKb();
    io::ExportOptions options;
    options.pc2Path = path;
    options.fps = 1.0 / h;
    io::AnimationExport exported;
    QElapsedTimer clock;
    clock.start();
    QString failure = exported.open(options, scene, h, std::uint64_t(frames - 1));
    if (failure.isEmpty())
        failure = exported.writeDue(0, state.position);
    while (failure.isEmpty() && state.step + 1 < std::uint64_t(frames)) {
        core::step(*model, state, work);
        failure = exported.writeDue(state.step, state.position);
    }
    if (failure.isEmpty())
        failure = exported.finish();
    seconds = double(clock.nsecsElapsed()) * 1e-9;
    if (!failure.isEmpty()) {
        out << failure << '\n';
        return -1;
    }
    const long long after = peakResidentKb();
    QFile::remove(path);
    QFile::remove(QFileInfo(path).dir().filePath(QFileInfo(path).completeBaseName() + QStringLiteral(".obj")));
    return after - before;
}

struct BenchMesh {
    QString name;
    core::TriangleMesh mesh;
    std::vector<core::MeshKind> kinds;  // a soft body only of the closed one
};

}  // namespace

int runMeshImport(const MeshImportOptions &options, QTextStream &out)
{
    const std::optional<QDir> dir = outputFolder(options.outDir, out);
    QTemporaryDir files;
    if (!dir || !files.isValid()) {
        out << "cannot make the folders for the mesh files\n";
        return 1;
    }
    const int runs = options.quick ? 1 : std::max(1, options.runs);
    // 225 × 225 vertices: 100 352 triangles; 320 × 160: 101 760 (quick: about 2 000 each)
    const std::vector<BenchMesh> meshes{
        {QStringLiteral("sheet"), options.quick ? sheet(33, 33) : sheet(225, 225),
         {core::MeshKind::Cloth, core::MeshKind::Collider}},
        {QStringLiteral("sphere"), options.quick ? sphere(40, 26) : sphere(320, 160),
         {core::MeshKind::Cloth, core::MeshKind::Soft, core::MeshKind::Collider}}};
    const QStringList formats{QStringLiteral("obj"), QStringLiteral("ply"), QStringLiteral("stl"), QStringLiteral("glb")};

    out << "Mesh import: " << machineDescription() << ", " << loadText() << "\n"
        << "median of " << runs << " run(s) after one untimed, wall time\n\n";
    // peak_growth_kb: an export's only (its memory beyond the run's)
    QStringList csv{QStringLiteral("mesh,triangles,stage,what,bytes,particles,springs,median_ms,peak_growth_kb")};
    const RunClock clock;
    for (const BenchMesh &bench : meshes) {
        const int triangles = int(bench.mesh.faces.size());
        Eigen::Matrix3Xd vertices(3, Eigen::Index(bench.mesh.vertices.size()));
        for (std::size_t v = 0; v < bench.mesh.vertices.size(); ++v)
            vertices.col(Eigen::Index(v)) = bench.mesh.vertices[v];

        // the file in each format, read as File › Import Mesh reads it
        std::optional<core::TriangleMesh> read;
        for (const QString &format : formats) {
            const QString path = files.filePath(bench.name + u'.' + format);
            if (const QString failure = io::writeMeshFrame(path, vertices, bench.mesh.faces, bench.name.toStdString());
                !failure.isEmpty()) {
                out << failure << '\n';
                return 1;
            }
            double ms = 0.0;
            QString error;
            const bool ok = timed(runs, [&] {
                io::MeshReadResult result = io::readMeshFile(path);
                error = result.error;
                if (result.ok() && format == u"obj")
                    read = std::move(result.mesh);
                return result.ok();
            }, ms);
            if (!ok) {
                out << error << '\n';
                return 1;
            }
            const qint64 bytes = QFileInfo(path).size();
            out << QStringLiteral("%1 (%2 triangles) read from %3 (%4 MB): %5 ms\n")
                       .arg(bench.name)
                       .arg(triangles)
                       .arg(format)
                       .arg(double(bytes) / 1e6, 0, 'f', 1)
                       .arg(ms, 0, 'f', 1);
            csv << QStringLiteral("%1,%2,read,%3,%4,,,%5,").arg(bench.name).arg(triangles).arg(format).arg(bytes).arg(ms, 0, 'f', 2);
        }

        // the body of each kind made of what the OBJ gave, then the scene compiled as the editor
        // compiles it when the import lands
        for (const core::MeshKind kind : bench.kinds) {
            const QString kindName = QString::fromLatin1(core::meshKindName(kind).data(), qsizetype(core::meshKindName(kind).size()));
            core::MeshImportOptions import;
            import.kind = kind;
            import.name = bench.name.toStdString();
            core::SceneDesc scene;
            core::MeshImportResult made;
            double makeMs = 0.0, compileMs = 0.0;
            const bool ok = timed(runs, [&] {
                scene = core::SceneDesc{};
                made = core::sceneFromMesh(scene, *read, import);
                return made.ok();
            }, makeMs) && timed(runs, [&] { return core::compileModel(scene) != nullptr; }, compileMs);
            if (!ok) {
                out << bench.name << " as " << kindName << ": " << QString::fromStdString(made.error) << '\n';
                return 1;
            }
            out << QStringLiteral("%1 as %2: %3 particles, %4 springs; made in %5 ms, compiled in %6 ms\n")
                       .arg(bench.name, kindName)
                       .arg(made.particles)
                       .arg(made.springs)
                       .arg(makeMs, 0, 'f', 1)
                       .arg(compileMs, 0, 'f', 1);
            csv << QStringLiteral("%1,%2,make,%3,,%4,%5,%6,")
                       .arg(bench.name)
                       .arg(triangles)
                       .arg(kindName)
                       .arg(made.particles)
                       .arg(made.springs)
                       .arg(makeMs, 0, 'f', 2);
            csv << QStringLiteral("%1,%2,compile,%3,,%4,%5,%6,")
                       .arg(bench.name)
                       .arg(triangles)
                       .arg(kindName)
                       .arg(made.particles)
                       .arg(made.springs)
                       .arg(compileMs, 0, 'f', 2);
        }
        out << '\n';
    }
    // the export streamed: its peak memory at a few frames and at many
    {
        core::SceneDesc scene;
        core::MeshImportOptions import;
        import.name = "sheet";
        const int side = options.quick ? 20 : 200;
        if (!core::sceneFromMesh(scene, sheet(side, side), import).ok()) {
            out << "the export's sheet cannot be made\n";
            return 1;
        }
        scene.springs.clear();
        scene.planes.clear();
        scene.settings.autoSubsteps = false;
        scene.settings.substeps = 1;
        scene.settings.particleCollisions = false;
        scene.settings.triangleCollisions = false;
        const int points = side * side;
        for (const int frames : {options.quick ? 10 : 100, options.quick ? 100 : options.frames}) {
            double seconds = 0.0;
            const long long growth = exportGrowthKb(scene, files.filePath(QStringLiteral("export.pc2")), frames, seconds, out);
            if (growth < 0) {
                out << "the export's memory cannot be measured here (/proc/self/status, clear_refs)\n";
                return 1;
            }
            const double megabytes = double(frames) * points * 12.0 / 1e6;
            out << QStringLiteral("PC2 export of %1 points, %2 frames (%3 MB written) in %4 s: peak memory grew %5 MB\n")
                       .arg(points)
                       .arg(frames)
                       .arg(megabytes, 0, 'f', 0)
                       .arg(seconds, 0, 'f', 2)
                       .arg(double(growth) / 1024.0, 0, 'f', 1);
            csv << QStringLiteral("sheet-%1,%2,export,pc2 %3 frames,%4,%5,0,%6")
                       .arg(side)
                       .arg(2 * (side - 1) * (side - 1))
                       .arg(frames)
                       .arg(qint64(megabytes * 1e6))
                       .arg(points)
                       .arg(seconds * 1e3, 0, 'f', 2);
            csv.last() += QStringLiteral(",%1").arg(growth);
        }
    }
    out << "done: " << clock.text() << ", " << loadText() << '\n';
    return writeLines(*dir, QStringLiteral("mesh-import.csv"), csv, out) ? 0 : 1;
}

}  // namespace bench
