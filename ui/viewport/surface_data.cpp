#include "surface_data.h"

#include <QVector3D>

#include <algorithm>
#include <cmath>

namespace ui {

SurfaceDraw packSurface(const core::Snapshot &snapshot)
{
    SurfaceDraw draw;
    const core::SpringTriangles *triangles = snapshot.triangles.get();
    const int n = std::min<int>(snapshot.particleCount(), int(snapshot.positions.size() / 3));
    const int springs = snapshot.springCount();
    // triangles of another scene than the snapshot's (a hand-made snapshot) are not drawn
    const bool sheet = triangles && !triangles->empty() && triangles->springEnds.size() == 2 * std::size_t(springs) &&
                       std::all_of(triangles->corners.begin(), triangles->corners.end(),
                                   [n](int c) { return c >= 0 && c < n; });
    const core::EmbeddedSurface *embedded = snapshot.embedded.get();
    const bool soft = embedded && !embedded->empty() &&
                      snapshot.embeddedPositions.size() == 3 * std::size_t(embedded->vertexCount()) &&
                      std::all_of(embedded->particles.begin(), embedded->particles.end(),
                                  [n](int p) { return p >= 0 && p < n; });
    if (!sheet && !soft)
        return draw;

    // the triangles whose three springs all hold
    draw.coveredParticles.assign(std::size_t(n), 0);
    if (sheet) {
        draw.indices.reserve(triangles->corners.size());
        for (int t = 0; t < triangles->count(); ++t) {
            const int *sides = triangles->sides.data() + 3 * t;
            if (snapshot.isBroken(sides[0]) || snapshot.isBroken(sides[1]) || snapshot.isBroken(sides[2]))
                continue;
            for (int c = 0; c < 3; ++c) {
                const int corner = triangles->corners[std::size_t(3 * t + c)];
                draw.indices.push_back(std::uint32_t(corner));
                draw.coveredParticles[std::size_t(corner)] = 1;
            }
        }
    }
    // a soft body's surface, its vertices after the particles; its lattice lies inside it
    if (soft) {
        for (int c : embedded->corners)
            draw.indices.push_back(std::uint32_t(n + c));
        for (int p : embedded->particles)
            draw.coveredParticles[std::size_t(p)] = 1;
        draw.extraVertices = embedded->vertexCount();
    }

    // a spring lies in the sheet when both its ends are corners of it
    draw.coveredSprings.assign(std::size_t(springs), 0);
    if (triangles && triangles->springEnds.size() == 2 * std::size_t(springs))
        for (int k = 0; k < springs; ++k) {
            const int a = triangles->springEnds[std::size_t(2 * k)], b = triangles->springEnds[std::size_t(2 * k + 1)];
            draw.coveredSprings[std::size_t(k)] = a >= 0 && b >= 0 && a < n && b < n &&
                                                  draw.coveredParticles[std::size_t(a)] &&
                                                  draw.coveredParticles[std::size_t(b)];
        }
    return draw;
}

void surfacePositions(const core::Snapshot &snapshot, const SurfaceDraw &draw, std::vector<float> &positions)
{
    const std::size_t n = 3 * std::size_t(std::min<int>(snapshot.particleCount(), int(snapshot.positions.size() / 3)));
    positions.assign(snapshot.positions.begin(), snapshot.positions.begin() + std::ptrdiff_t(n));
    if (draw.extraVertices > 0 && snapshot.embeddedPositions.size() == 3 * std::size_t(draw.extraVertices))
        positions.insert(positions.end(), snapshot.embeddedPositions.begin(), snapshot.embeddedPositions.end());
}

void surfaceNormals(const std::vector<float> &positions, const std::vector<std::uint32_t> &indices,
                    std::vector<float> &normals)
{
    const std::size_t n = positions.size() / 3;
    normals.assign(3 * n, 0.0f);
    auto at = [&](std::uint32_t i) {
        const float *p = positions.data() + 3 * std::size_t(i);
        return QVector3D(p[0], p[1], p[2]);
    };

    // the cross product of two sides is the normal times twice the area
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        if (a >= n || b >= n || c >= n)
            continue;
        const QVector3D weighted = QVector3D::crossProduct(at(b) - at(a), at(c) - at(a));
        if (!std::isfinite(weighted.x()) || !std::isfinite(weighted.y()) || !std::isfinite(weighted.z()))
            continue;
        for (const std::uint32_t i : {a, b, c}) {
            normals[3 * i] += weighted.x();
            normals[3 * i + 1] += weighted.y();
            normals[3 * i + 2] += weighted.z();
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        float *v = normals.data() + 3 * i;
        const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (length > 0.0f && std::isfinite(length)) {
            v[0] /= length;
            v[1] /= length;
            v[2] /= length;
        } else {
            v[0] = v[1] = v[2] = 0.0f;
        }
    }
}

bool SurfaceKey::matches(const core::Snapshot &snapshot) const
{
    return m_valid && m_triangles == snapshot.triangles && m_embedded == snapshot.embedded &&
           m_broken == snapshot.springBroken &&
           m_particles == snapshot.particleCount() && m_springs == snapshot.springCount();
}

void SurfaceKey::remember(const core::Snapshot &snapshot)
{
    m_triangles = snapshot.triangles;
    m_embedded = snapshot.embedded;
    m_broken = snapshot.springBroken;
    m_particles = snapshot.particleCount();
    m_springs = snapshot.springCount();
    m_valid = true;
}

void SurfaceKey::clear()
{
    m_valid = false;
    m_triangles.reset();
    m_embedded.reset();
    m_broken.clear();
}

}  // namespace ui
