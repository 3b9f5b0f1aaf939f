#include "core/meshes/embedded_surface.h"

namespace core {

EmbeddedSurface makeEmbeddedSurface(const SceneDesc &scene)
{
    EmbeddedSurface surface;
    for (const MeshDesc &mesh : scene.meshes) {
        if (mesh.kind != MeshKind::Soft)
            continue;
        const int base = surface.vertexCount();
        const int bound = int(surface.particles.size());
        for (std::size_t v = 1; v < mesh.offsets.size(); ++v)
            surface.offsets.push_back(bound + mesh.offsets[v]);
        surface.particles.insert(surface.particles.end(), mesh.particles.begin(), mesh.particles.end());
        surface.weights.insert(surface.weights.end(), mesh.weights.begin(), mesh.weights.end());
        for (const std::array<int, 3> &f : mesh.faces)
            for (int c : f)
                surface.corners.push_back(base + c);
    }
    return surface;
}

void embeddedPositions(const EmbeddedSurface &surface, const Eigen::Matrix3Xd &positions, std::vector<float> &out)
{
    const int vertices = surface.vertexCount();
    out.resize(3 * std::size_t(vertices));
    for (int v = 0; v < vertices; ++v) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (int k = surface.offsets[std::size_t(v)]; k < surface.offsets[std::size_t(v) + 1]; ++k)
            sum += surface.weights[std::size_t(k)] * positions.col(surface.particles[std::size_t(k)]);
        for (int a = 0; a < 3; ++a)
            out[3 * std::size_t(v) + std::size_t(a)] = float(sum[a]);
    }
}

}  // namespace core
