#pragma once
// Surface data: a snapshot's spring triangles (core/springs/spring_triangles.h) and its soft bodies'
// surfaces (core/meshes/embedded_surface.h) turned into what the viewport draws them with, without
// GL, so that it can be unit-tested: the indices of the triangles none of whose springs has broken
// (a torn spring opens a hole), which particles and springs the surfaces already show (the
// viewport hides them unless asked), and smooth normals at the current positions. A soft body's
// vertices follow the particles in the vertex list (surfacePositions). The indices change only when the triangles or the broken springs do
// (SurfaceKey); the normals with every new snapshot.

#include "core/model/snapshot.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace ui {

struct SurfaceDraw {
    std::vector<std::uint32_t> indices;            // three particles per drawn triangle
    std::vector<std::uint8_t> coveredParticles;    // per particle: 1 if a corner of a drawn triangle
    std::vector<std::uint8_t> coveredSprings;      // per spring: 1 if both its ends are
    int extraVertices = 0;  // the soft bodies' surface vertices, after the particles'
    int triangleCount() const { return static_cast<int>(indices.size() / 3); }
};

// the drawn triangles of the snapshot and what they cover; empty when it has no triangles, or they
// do not fit its particles and springs
SurfaceDraw packSurface(const core::Snapshot &snapshot);

// the drawn vertices, xyz each: the particles', then the soft bodies' surface vertices
void surfacePositions(const core::Snapshot &snapshot, const SurfaceDraw &draw, std::vector<float> &positions);

// per vertex xyz of `positions`, the unit normal: its drawn triangles' normals summed, each weighted
// by its area; zero for a vertex in none (or where they cancel)
void surfaceNormals(const std::vector<float> &positions, const std::vector<std::uint32_t> &indices,
                    std::vector<float> &normals);

// what a SurfaceDraw was packed from, to tell whether a new snapshot needs a new one
class SurfaceKey {
public:
    bool matches(const core::Snapshot &snapshot) const;
    void remember(const core::Snapshot &snapshot);
    void clear();

private:
    bool m_valid = false;
    std::shared_ptr<const core::SpringTriangles> m_triangles;
    std::shared_ptr<const core::EmbeddedSurface> m_embedded;
    std::vector<std::uint8_t> m_broken;
    int m_particles = 0;
    int m_springs = 0;
};

}  // namespace ui
