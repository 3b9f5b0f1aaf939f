#include "animation_export.h"

#include "safe_write.h"

#include <QDir>
#include <QFileInfo>

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace io {

namespace {

using namespace Qt::Literals::StringLiterals;

QString shownExportPath(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

// the frame k's step: the first whose time is at least from + k / fps (a time a hair past a whole
// number of steps is that step, not the next)
std::uint64_t frameStep(double time, double timeStep)
{
    const double steps = time / timeStep;
    const double nearest = std::round(steps);
    return std::uint64_t(std::abs(steps - nearest) <= 1e-9 * std::max(1.0, nearest) ? nearest : std::ceil(steps));
}

// a file name of the mesh's name: letters, digits, '-' and '_' kept, the rest '_'
QString fileStem(const std::string &name)
{
    QString stem = QString::fromStdString(name);
    for (QChar &c : stem)
        if (!c.isLetterOrNumber() && c != u'-' && c != u'_')
            c = u'_';
    return stem.isEmpty() ? u"mesh"_s : stem;
}

}  // namespace

// one mesh's point cache, written as it goes into FILE.part and renamed at the end
struct AnimationExport::Cache {
    QString path;
    QFile file;
    std::vector<float> frame;
};

QStringList meshExportExtensions()
{
    QStringList extensions;
    Assimp::Exporter exporter;
    for (std::size_t i = 0; i < exporter.GetExportFormatCount(); ++i) {
        const QString extension = QString::fromLatin1(exporter.GetExportFormatDescription(i)->fileExtension);
        if (!extensions.contains(extension))
            extensions << extension;
    }
    return extensions;
}

QString meshExportFormat(const QString &extension)
{
    Assimp::Exporter exporter;
    const QString wanted = extension.toLower();
    for (std::size_t i = 0; i < exporter.GetExportFormatCount(); ++i) {
        const aiExportFormatDesc *format = exporter.GetExportFormatDescription(i);
        // the first of a kind is the newest or the plainest: glTF 2 before glTF 1, text before binary
        if (QString::fromLatin1(format->fileExtension) == wanted)
            return QString::fromLatin1(format->id);
    }
    return {};
}

QString writeMeshFrame(const QString &path, const Eigen::Matrix3Xd &vertices, const std::vector<std::array<int, 3>> &faces,
                       const std::string &name)
{
    const QString format = meshExportFormat(QFileInfo(path).suffix());
    if (format.isEmpty())
        return shownExportPath(path) + u": no mesh format has the extension \"."_s + QFileInfo(path).suffix() + u"\" (known: "_s +
               meshExportExtensions().join(u", "_s) + u')';
    if (const QString refused = refuseToReplace(path); !refused.isEmpty())
        return shownExportPath(path) + u": cannot save: "_s + refused;

    // a scene of one mesh; aiScene's destructor frees what is made here with new
    aiScene scene;
    scene.mRootNode = new aiNode(name);
    scene.mRootNode->mNumMeshes = 1;
    scene.mRootNode->mMeshes = new unsigned[1]{0};
    scene.mNumMaterials = 1;
    scene.mMaterials = new aiMaterial *[1] { new aiMaterial };
    scene.mNumMeshes = 1;
    scene.mMeshes = new aiMesh *[1] { new aiMesh };
    aiMesh &mesh = *scene.mMeshes[0];
    mesh.mName = aiString(name);
    mesh.mMaterialIndex = 0;
    mesh.mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh.mNumVertices = unsigned(vertices.cols());
    mesh.mVertices = new aiVector3D[mesh.mNumVertices];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v)
        mesh.mVertices[v] = aiVector3D(float(vertices(0, v)), float(vertices(1, v)), float(vertices(2, v)));
    mesh.mNumFaces = unsigned(faces.size());
    mesh.mFaces = new aiFace[mesh.mNumFaces];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        mesh.mFaces[f].mNumIndices = 3;
        mesh.mFaces[f].mIndices = new unsigned[3]{unsigned(faces[f][0]), unsigned(faces[f][1]), unsigned(faces[f][2])};
    }
    Assimp::Exporter exporter;
    if (exporter.Export(&scene, format.toStdString(), QFile::encodeName(path).toStdString()) != aiReturn_SUCCESS)
        return shownExportPath(path) + u": cannot save: "_s + QString::fromUtf8(exporter.GetErrorString());
    return {};
}

QString writeObjFrame(const QString &path, const Eigen::Matrix3Xd &vertices, const std::vector<std::array<int, 3>> &faces,
                      const std::string &name, const QString &comment)
{
    QByteArray text;
    text.reserve(vertices.cols() * 40 + qsizetype(faces.size()) * 24 + 128);
    text += "# " + comment.toUtf8() + "\no " + fileStem(name).toUtf8() + '\n';
    char line[96];
    for (Eigen::Index v = 0; v < vertices.cols(); ++v) {
        // float32's nine digits: what the point cache holds too
        const int n = std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(float(vertices(0, v))),
                                    double(float(vertices(1, v))), double(float(vertices(2, v))));
        text.append(line, n);
    }
    for (const std::array<int, 3> &f : faces) {
        const int n = std::snprintf(line, sizeof line, "f %d %d %d\n", f[0] + 1, f[1] + 1, f[2] + 1);
        text.append(line, n);
    }
    if (const QString failure = writeFileAtomically(path, text); !failure.isEmpty())
        return shownExportPath(path) + u": cannot save: "_s + failure;
    return {};
}

AnimationExport::AnimationExport() = default;

AnimationExport::~AnimationExport()
{
    // an export never finished leaves nothing half-written behind
    for (const auto &cache : m_caches)
        if (cache->file.isOpen()) {
            cache->file.close();
            cache->file.remove();
        }
}

QString AnimationExport::open(const ExportOptions &options, const core::SceneDesc &scene, double timeStep,
                              std::uint64_t totalSteps)
{
    m_options = options;
    if (options.pc2Path.isEmpty() && options.objFolder.isEmpty() && options.meshPath.isEmpty())
        return u"nothing to export: name a PC2 file, an OBJ folder or a mesh file"_s;
    if (!(options.fps > 0.0) || !std::isfinite(options.fps) || options.fps > 10000.0)
        return u"the frame rate must be a number of frames per second from above 0 to 10000 (got %1)"_s.arg(options.fps);
    if (!(options.from >= 0.0) || !std::isfinite(options.from))
        return u"the export's first frame must be at a time of 0 s or later (got %1 s)"_s.arg(options.from);
    if (options.to && !(*options.to >= options.from))
        return u"the export's last frame (%1 s) is before its first (%2 s)"_s.arg(*options.to).arg(options.from);
    m_meshes = core::exportedMeshes(scene);
    m_particleCount = scene.particles.size();
    if (m_meshes.empty())
        return u"nothing to export: the scene has no surface (import a mesh, or make a cloth)"_s;

    // the frames: from `from` to `to` (or the run's end) at fps
    const double end = std::min(options.to.value_or(double(totalSteps) * timeStep), double(totalSteps) * timeStep);
    m_firstFrame = int(std::lround(options.from * options.fps));
    m_steps.clear();
    for (long long k = 0;; ++k) {
        const double time = options.from + double(k) / options.fps;
        if (time > end * (1.0 + 1e-12) + 1e-12)
            break;
        if (k >= 10'000'000)
            return u"the export asks for more than 10^7 frames: lower the frame rate or the duration"_s;
        m_steps.push_back(std::min(frameStep(time, timeStep), totalSteps));
    }
    if (m_steps.empty())
        return u"the export's first frame (%1 s) is after the run's end (%2 s)"_s.arg(options.from).arg(end);

    // the point caches: FILE.pc2 for one mesh, FILE-NAME.pc2 for each of several
    if (!options.pc2Path.isEmpty()) {
        const QFileInfo target(options.pc2Path);
        for (const core::MeshDesc &mesh : m_meshes) {
            auto cache = std::make_unique<Cache>();
            cache->path = m_meshes.size() == 1 ? options.pc2Path
                                               : target.dir().filePath(target.completeBaseName() + u'-' + fileStem(mesh.name) + u".pc2"_s);
            if (const QString refused = refuseToReplace(cache->path); !refused.isEmpty())
                return shownExportPath(cache->path) + u": cannot save: "_s + refused;
            if (!QDir().mkpath(QFileInfo(cache->path).absolutePath()))
                return shownExportPath(cache->path) + u": cannot make its folder"_s;
            cache->file.setFileName(cache->path + u".part"_s);
            if (!cache->file.open(QIODevice::WriteOnly | QIODevice::Truncate))
                return shownExportPath(cache->path) + u": cannot save: "_s + cache->file.errorString();
            struct {
                char signature[12];
                std::int32_t version, points;
                float start, sampling;
                std::int32_t samples;
            } header{};
            static_assert(sizeof header == kPc2HeaderBytes);
            std::memcpy(header.signature, kPc2Signature, sizeof header.signature);
            header.version = 1;
            header.points = mesh.vertexCount();
            header.start = float(m_firstFrame);
            header.sampling = 1.0f;  // a sample every frame
            header.samples = 0;      // set by finish() to those written
            if (cache->file.write(reinterpret_cast<const char *>(&header), sizeof header) != sizeof header)
                return shownExportPath(cache->path) + u": cannot save: "_s + cache->file.errorString();
            cache->frame.resize(std::size_t(3 * mesh.vertexCount()));
            m_caches.push_back(std::move(cache));
        }
    }
    if (!options.objFolder.isEmpty() && !QDir().mkpath(options.objFolder))
        return shownExportPath(options.objFolder) + u": cannot make the folder"_s;
    if (!options.meshPath.isEmpty() && !QDir().mkpath(QFileInfo(options.meshPath).absolutePath()))
        return shownExportPath(options.meshPath) + u": cannot make its folder"_s;
    if (!options.meshPath.isEmpty() && meshExportFormat(QFileInfo(options.meshPath).suffix()).isEmpty())
        return shownExportPath(options.meshPath) + u": no mesh format has the extension \"."_s + QFileInfo(options.meshPath).suffix() +
               u"\" (known: "_s + meshExportExtensions().join(u", "_s) + u')';
    m_written = 0;
    return {};
}

std::uint64_t AnimationExport::nextStep(std::uint64_t totalSteps) const
{
    return m_written < frameCount() ? m_steps[std::size_t(m_written)] : totalSteps;
}

QString AnimationExport::writeDue(std::uint64_t step, const Eigen::Matrix3Xd &positions)
{
    // the surfaces name the particles of the scene the export was opened with: a scene edited
    // since (particles added or removed) has other particles under those numbers
    if (positions.cols() != Eigen::Index(m_particleCount))
        return u"the scene has %1 particles now, not the %2 it had when the export began: it was edited during "
               "the export"_s.arg(positions.cols()).arg(m_particleCount);
    m_lastFrame.resize(m_meshes.size());
    for (; m_written < frameCount() && m_steps[std::size_t(m_written)] == step; ++m_written) {
        const int frame = m_firstFrame + m_written;
        for (std::size_t m = 0; m < m_meshes.size(); ++m) {
            const core::MeshDesc &mesh = m_meshes[m];
            core::meshVertexPositions(mesh, positions, m_lastFrame[m], m_options.space);
            const Eigen::Matrix3Xd &vertices = m_lastFrame[m];
            if (m < m_caches.size()) {
                Cache &cache = *m_caches[m];
                for (Eigen::Index v = 0; v < vertices.cols(); ++v)
                    for (int a = 0; a < 3; ++a)
                        cache.frame[std::size_t(3 * v + a)] = float(vertices(a, v));
                const qint64 bytes = qint64(cache.frame.size() * sizeof(float));
                if (cache.file.write(reinterpret_cast<const char *>(cache.frame.data()), bytes) != bytes)
                    return shownExportPath(cache.path) + u": cannot save: "_s + cache.file.errorString();
                // beside the cache, its first frame as an OBJ: the mesh the modifier goes on
                if (m_written == 0) {
                    const QFileInfo info(cache.path);
                    const QString obj = info.dir().filePath(info.completeBaseName() + u".obj"_s);
                    if (const QString failure = writeObjFrame(obj, vertices, mesh.faces, mesh.name,
                                                              u"Springlab: the first frame of "_s + info.fileName());
                        !failure.isEmpty())
                        return failure;
                    m_files << obj;
                }
            }
            if (!m_options.objFolder.isEmpty()) {
                const QString path = QDir(m_options.objFolder).filePath(fileStem(mesh.name) + u"_%1.obj"_s.arg(frame, 5, 10, QLatin1Char('0')));
                if (const QString failure = writeObjFrame(path, vertices, mesh.faces, mesh.name,
                                                          u"Springlab: frame %1, t = %2 s"_s.arg(frame).arg(double(frame) / m_options.fps));
                    !failure.isEmpty())
                    return failure;
                m_files << path;
            }
        }
    }
    return {};
}

QString AnimationExport::finish()
{
    for (const auto &cache : m_caches) {
        // the samples written, in the header's last field
        const std::int32_t samples = m_written;
        if (!cache->file.seek(kPc2HeaderBytes - 4) ||
            cache->file.write(reinterpret_cast<const char *>(&samples), sizeof samples) != sizeof samples ||
            !cache->file.flush())
            return shownExportPath(cache->path) + u": cannot save: "_s + cache->file.errorString();
        cache->file.close();
        QFile::remove(cache->path);
        if (!QFile::rename(cache->file.fileName(), cache->path))
            return shownExportPath(cache->path) + u": cannot save: cannot rename "_s + shownExportPath(cache->file.fileName()) + u" to it"_s;
        m_files << cache->path;
    }
    if (!m_options.meshPath.isEmpty() && !m_lastFrame.empty()) {
        const QFileInfo target(m_options.meshPath);
        for (std::size_t m = 0; m < m_meshes.size(); ++m) {
            const QString path = m_meshes.size() == 1
                                     ? m_options.meshPath
                                     : target.dir().filePath(target.completeBaseName() + u'-' + fileStem(m_meshes[m].name) + u'.' + target.suffix());
            if (const QString failure = writeMeshFrame(path, m_lastFrame[m], m_meshes[m].faces, m_meshes[m].name); !failure.isEmpty())
                return failure;
            m_files << path;
        }
    }
    return {};
}

void AnimationExport::cancel()
{
    for (const auto &cache : m_caches)
        if (cache->file.isOpen()) {
            cache->file.close();
            cache->file.remove();
        }
    for (const QString &path : std::as_const(m_files))
        QFile::remove(path);
    m_files.clear();
}

}  // namespace io
