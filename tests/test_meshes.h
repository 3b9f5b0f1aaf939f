#pragma once
// Meshes the tests make: an icosphere, a flat panel, a cube whose vertices are split at its edges
// (as a file with a normal per face has them), a non-manifold fan, an open box. Header-only.

#include "core/meshes/triangle_mesh.h"

#include <Eigen/Geometry>
#include <cmath>
#include <map>

namespace test {

// a sphere of `radius` about the origin: an icosahedron subdivided `levels` times, its vertices
// pushed out to the sphere; 20 × 4^levels faces, closed, counter-clockwise outside
inline core::TriangleMesh icosphere(int levels, double radius = 1.0)
{
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    core::TriangleMesh m;
    for (const Eigen::Vector3d &v : {Eigen::Vector3d(-1, t, 0), Eigen::Vector3d(1, t, 0), Eigen::Vector3d(-1, -t, 0),
                                     Eigen::Vector3d(1, -t, 0), Eigen::Vector3d(0, -1, t), Eigen::Vector3d(0, 1, t),
                                     Eigen::Vector3d(0, -1, -t), Eigen::Vector3d(0, 1, -t), Eigen::Vector3d(t, 0, -1),
                                     Eigen::Vector3d(t, 0, 1), Eigen::Vector3d(-t, 0, -1), Eigen::Vector3d(-t, 0, 1)})
        m.vertices.push_back(v.normalized() * radius);
    m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
               {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<int, int>, int> middle;
        const auto mid = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            const auto it = middle.find(key);
            if (it != middle.end())
                return it->second;
            m.vertices.push_back((m.vertices[std::size_t(a)] + m.vertices[std::size_t(b)]).normalized() * radius);
            return middle[key] = int(m.vertices.size()) - 1;
        };
        std::vector<std::array<int, 3>> finer;
        for (const auto &f : m.faces) {
            const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
            finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
        }
        m.faces = std::move(finer);
    }
    return m;
}

// a rows × cols grid of vertices `spacing` apart in the plane y = 0, two triangles a cell
inline core::TriangleMesh panel(int rows, int cols, double spacing)
{
    core::TriangleMesh m;
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j)
            m.vertices.emplace_back(j * spacing, 0.0, i * spacing);
    for (int i = 0; i + 1 < rows; ++i)
        for (int j = 0; j + 1 < cols; ++j) {
            const int a = i * cols + j, b = a + 1, c = a + cols, d = c + 1;
            m.faces.push_back({a, c, b});
            m.faces.push_back({b, c, d});
        }
    return m;
}

// a cube of side `side` centred at the origin with four vertices a face (24 in all, each corner
// three times), counter-clockwise outside
inline core::TriangleMesh splitCube(double side = 1.0)
{
    core::TriangleMesh m;
    const double h = 0.5 * side;
    for (int axis = 0; axis < 3; ++axis)
        for (int sign : {-1, 1}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const int base = int(m.vertices.size());
            for (const auto &[a, b] : {std::pair{-1, -1}, std::pair{1, -1}, std::pair{1, 1}, std::pair{-1, 1}}) {
                Eigen::Vector3d p;
                p[axis] = sign * h;
                p[u] = a * h;
                p[v] = b * h;
                m.vertices.push_back(p);
            }
            if (sign > 0) {
                m.faces.push_back({base, base + 1, base + 2});
                m.faces.push_back({base, base + 2, base + 3});
            } else {
                m.faces.push_back({base, base + 2, base + 1});
                m.faces.push_back({base, base + 3, base + 2});
            }
        }
    return m;
}

// three triangles on one edge (a fin on a sheet): non-manifold
inline core::TriangleMesh fan()
{
    core::TriangleMesh m;
    m.vertices = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0.5}, {-1, 0, 0.5}, {0, 1, 0.5}};
    m.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    return m;
}

// a unit cube without its top: open
inline core::TriangleMesh openBox()
{
    core::TriangleMesh m = splitCube(1.0);
    // the +y face is the fourth pair of faces (axis 1, sign +1)
    m.faces.erase(m.faces.begin() + 6, m.faces.begin() + 8);
    return m;
}

}  // namespace test
