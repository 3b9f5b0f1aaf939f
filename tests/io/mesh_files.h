#pragma once
// Mesh files the tests write: OBJ and PLY text and binary STL of the meshes of tests/test_meshes.h.

#include "tests/test_meshes.h"
#include "tests/test_files.h"

#include "core/meshes/mesh_import.h"

#include <QByteArray>
#include <QString>

#include <cstring>

namespace test {

// an OBJ: `v` records in the mesh's order, a face a triangle (1-based)
inline QByteArray objText(const core::TriangleMesh &mesh)
{
    QByteArray text = "# written by a Springlab test\n";
    for (const Eigen::Vector3d &v : mesh.vertices)
        text += "v " + QByteArray::number(v.x(), 'g', 17) + ' ' + QByteArray::number(v.y(), 'g', 17) + ' ' +
                QByteArray::number(v.z(), 'g', 17) + '\n';
    for (const auto &f : mesh.faces)
        text += "f " + QByteArray::number(f[0] + 1) + ' ' + QByteArray::number(f[1] + 1) + ' ' + QByteArray::number(f[2] + 1) + '\n';
    return text;
}

// an ASCII PLY of the mesh, its vertex elements in its order
inline QByteArray plyText(const core::TriangleMesh &mesh)
{
    QByteArray text = "ply\nformat ascii 1.0\nelement vertex " + QByteArray::number(qsizetype(mesh.vertices.size())) +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                      QByteArray::number(qsizetype(mesh.faces.size())) + "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Eigen::Vector3d &v : mesh.vertices)
        text += QByteArray::number(v.x(), 'g', 9) + ' ' + QByteArray::number(v.y(), 'g', 9) + ' ' + QByteArray::number(v.z(), 'g', 9) + '\n';
    for (const auto &f : mesh.faces)
        text += "3 " + QByteArray::number(f[0]) + ' ' + QByteArray::number(f[1]) + ' ' + QByteArray::number(f[2]) + '\n';
    return text;
}

// a binary STL: 80 bytes of header, the count, then per triangle a normal, three corners and two
// bytes of attributes, little-endian float32
inline QByteArray stlBinary(const core::TriangleMesh &mesh)
{
    QByteArray bytes(80, ' ');
    const auto put = [&](const void *data, int size) { bytes.append(static_cast<const char *>(data), size); };
    const std::uint32_t count = std::uint32_t(mesh.faces.size());
    put(&count, 4);
    for (const auto &f : mesh.faces) {
        const Eigen::Vector3d n = (mesh.vertices[std::size_t(f[1])] - mesh.vertices[std::size_t(f[0])])
                                      .cross(mesh.vertices[std::size_t(f[2])] - mesh.vertices[std::size_t(f[0])])
                                      .normalized();
        const float normal[3] = {float(n.x()), float(n.y()), float(n.z())};
        put(normal, 12);
        for (int c = 0; c < 3; ++c) {
            const Eigen::Vector3d &v = mesh.vertices[std::size_t(f[std::size_t(c)])];
            const float corner[3] = {float(v.x()), float(v.y()), float(v.z())};
            put(corner, 12);
        }
        const std::uint16_t attributes = 0;
        put(&attributes, 2);
    }
    return bytes;
}

// a flag: a rows × cols panel of a z-up file in centimetres (upright: it lies in the file's xz
// plane), imported as cloth with its left side pinned, on a floor; *file (if given) is the panel
inline core::SceneDesc flagScene(int rows, int cols, core::TriangleMesh *file = nullptr)
{
    const core::TriangleMesh mesh = panel(rows, cols, 10.0);
    core::MeshImportOptions options;
    options.name = "flag";
    options.placement.scale = 0.01;
    options.placement.zUp = true;
    options.placement.at = Eigen::Vector3d(0.0, 1.0, 0.0);
    options.pin = core::PinSide::Left;
    core::SceneDesc scene;
    if (!core::sceneFromMesh(scene, mesh, options).ok())
        qFatal("the flag did not import");
    if (file)
        *file = mesh;
    return scene;
}

}  // namespace test
