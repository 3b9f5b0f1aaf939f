#pragma once
// Mesh files in (OBJ, PLY, STL, glTF 2, FBX, Collada and the rest the Open Asset Import Library
// reads), as a triangle mesh whose vertices are the file's own, in the file's order: an OBJ's `v`
// records, a PLY's vertex elements, a glTF's accessors, node by node. Polygons are split into
// triangles (their vertices kept); points and lines are left out. docs/scene-format.md, "Meshes".

#include "core/meshes/triangle_mesh.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace io {

// a mesh file larger than this is refused before it is read
inline constexpr qint64 kMaxMeshFileBytes = qint64(1) << 30;  // 1 GiB
// and one that holds more faces or vertices than this
inline constexpr qint64 kMaxMeshElements = 20'000'000;

struct MeshReadResult {
    std::optional<core::TriangleMesh> mesh;  // set on success
    QString error;                           // "FILE: why", set on failure
    QStringList notes;                       // "FILE: 12 lines and points left out"
    bool ok() const { return mesh.has_value(); }
};

// reads a mesh file; a file that is no mesh, has no triangles, a coordinate that is not a finite
// number, announces more faces than it holds (a truncated or hostile header) or breaks off is
// refused with a message that says so, before anything is made of it
MeshReadResult readMeshFile(const QString &path);

// the extensions the importer reads ("*.obj *.ply ..."), for a file dialog's filter
QString meshFileFilter();

}  // namespace io
