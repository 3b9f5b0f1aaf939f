#pragma once
// Export Animation (docs/export.md): the scene's deforming surfaces written frame by frame as a run
// goes, so that no more than one frame is ever held: a PC2 point cache (the binary format that
// Blender's Mesh Cache modifier and 3ds Max read) with the OBJ of its first frame beside it, an OBJ
// a frame, and one frame in any format the Open Asset Import Library writes (glTF 2, PLY, STL, ...).
// An imported mesh's points are the file's own vertices in the file's order, where the file has
// them (its placement undone), so that the cache applies to the very file that was imported.

#include "core/meshes/mesh_surface.h"
#include "core/model/scene.h"

#include <QFile>
#include <QString>
#include <QStringList>

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace io {

struct ExportOptions {
    QString pc2Path;    // FILE.pc2, and FILE.obj beside it; empty: none
    QString objFolder;  // an OBJ a frame in this folder; empty: none
    QString meshPath;   // the last frame, in the format its extension names; empty: none
    double fps = 24.0;  // frames per simulated second
    double from = 0.0;  // s, the first frame's time
    std::optional<double> to;  // s, the last frame's at most; unset: the run's end
    core::MeshSpace space = core::MeshSpace::File;
};

// the PC2 header: "POINTCACHE2\0", version 1, points, start frame, frames between samples, samples
inline constexpr char kPc2Signature[12] = {'P', 'O', 'I', 'N', 'T', 'C', 'A', 'C', 'H', 'E', '2', '\0'};
inline constexpr int kPc2HeaderBytes = 32;

// the formats a single frame may be written in, by extension ("gltf glb ply stl obj ..."), and the
// assimp exporter for one (empty: none)
QStringList meshExportExtensions();
QString meshExportFormat(const QString &extension);

// writes one frame of the surface (vertices as columns, faces over them) to path in the format its
// extension names; empty on success, else the message
QString writeMeshFrame(const QString &path, const Eigen::Matrix3Xd &vertices,
                       const std::vector<std::array<int, 3>> &faces, const std::string &name);

// an OBJ of the surface, vertices in their order; empty on success, else the message
QString writeObjFrame(const QString &path, const Eigen::Matrix3Xd &vertices,
                      const std::vector<std::array<int, 3>> &faces, const std::string &name, const QString &comment);

class AnimationExport {
public:
    AnimationExport();
    ~AnimationExport();
    AnimationExport(const AnimationExport &) = delete;
    AnimationExport &operator=(const AnimationExport &) = delete;

    // checks the options against the scene and opens the outputs for a run of totalSteps steps of
    // timeStep; empty on success, else the message (and nothing is left written)
    QString open(const ExportOptions &options, const core::SceneDesc &scene, double timeStep, std::uint64_t totalSteps);
    // the step of the next frame due, or totalSteps when none is left
    std::uint64_t nextStep(std::uint64_t totalSteps) const;
    // writes every frame due at this step from the particles' positions (one column a particle of
    // the scene it was opened with); empty on success, else the message
    QString writeDue(std::uint64_t step, const Eigen::Matrix3Xd &positions);
    // the caches completed (their sample counts those written) and the last frame's mesh; empty on success
    QString finish();
    // removes every file the export wrote
    void cancel();

    int frameCount() const { return static_cast<int>(m_steps.size()); }
    // the step of each frame, counted from the run's start, non-decreasing
    const std::vector<std::uint64_t> &frameSteps() const { return m_steps; }
    int framesWritten() const { return m_written; }
    const QStringList &files() const { return m_files; }

private:
    struct Cache;
    ExportOptions m_options;
    std::vector<core::MeshDesc> m_meshes;
    std::size_t m_particleCount = 0;               // the scene's when opened: the frames' must match
    std::vector<std::unique_ptr<Cache>> m_caches;  // per mesh, with a PC2 path
    std::vector<std::uint64_t> m_steps;            // the frames' steps
    int m_firstFrame = 0;                          // the frame number of the first (from × fps)
    int m_written = 0;
    QStringList m_files;                           // made so far
    Eigen::Matrix3Xd m_last;                       // scratch: one surface's vertices
    std::vector<Eigen::Matrix3Xd> m_lastFrame;     // the last frame written, for meshPath
};

}  // namespace io
