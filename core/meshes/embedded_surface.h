#pragma once
// The imported surfaces whose vertices are not particles of their own: a soft body's, each vertex
// carried by the lattice cell around it (MeshDesc's weights). Compiled once per model; every
// snapshot carries their vertices where the particles put them, so that the viewport draws the
// body as its shaded surface rather than as its lattice.

#include "core/model/scene.h"

#include <Eigen/Core>
#include <vector>

namespace core {

struct EmbeddedSurface {
    // vertex v is the sum of weights[k] × particles[k]'s position for k in [offsets[v], offsets[v + 1])
    std::vector<int> offsets{0};
    std::vector<int> particles;
    std::vector<double> weights;
    std::vector<int> corners;  // three vertex indices per triangle, counter-clockwise outside

    int vertexCount() const { return static_cast<int>(offsets.size()) - 1; }
    int triangleCount() const { return static_cast<int>(corners.size() / 3); }
    bool empty() const { return corners.empty(); }
};

// the scene's soft bodies' surfaces, one after another (cloths and colliders are drawn by their
// own particles, through the scene's triangles)
EmbeddedSurface makeEmbeddedSurface(const SceneDesc &scene);

// xyz per vertex at these positions (one column a particle)
void embeddedPositions(const EmbeddedSurface &surface, const Eigen::Matrix3Xd &positions, std::vector<float> &out);

}  // namespace core
