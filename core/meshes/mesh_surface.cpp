#include "core/meshes/mesh_surface.h"

#include "core/contacts/cloth_surface.h"

#include <array>

namespace core {

namespace {

constexpr std::array<std::pair<MeshKind, std::string_view>, 3> kMeshKindNames{
    {{MeshKind::Cloth, "cloth"}, {MeshKind::Soft, "soft"}, {MeshKind::Collider, "collider"}}};

}  // namespace

std::string_view meshKindName(MeshKind kind)
{
    for (const auto &[k, name] : kMeshKindNames)
        if (k == kind)
            return name;
    return "cloth";
}

std::optional<MeshKind> meshKindNamed(std::string_view name)
{
    for (const auto &[k, known] : kMeshKindNames)
        if (known == name)
            return k;
    return std::nullopt;
}

std::string_view knownMeshKinds()
{
    return "cloth, soft, collider";
}

void meshVertexPositions(const MeshDesc &mesh, const Eigen::Matrix3Xd &positions, Eigen::Matrix3Xd &out,
                         MeshSpace space)
{
    const int vertices = mesh.vertexCount();
    out.resize(3, vertices);
    for (int v = 0; v < vertices; ++v) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (int k = mesh.offsets[std::size_t(v)]; k < mesh.offsets[std::size_t(v) + 1]; ++k)
            sum += mesh.weights[std::size_t(k)] * positions.col(mesh.particles[std::size_t(k)]);
        if (space == MeshSpace::File) {
            sum -= mesh.offset;
            if (mesh.zUp)
                sum = Eigen::Vector3d(sum.x(), -sum.z(), sum.y());
            sum /= mesh.scale;
        }
        out.col(v) = sum;
    }
}

std::vector<MeshDesc> exportedMeshes(const SceneDesc &scene)
{
    if (!scene.meshes.empty())
        return scene.meshes;
    const std::vector<std::array<int, 3>> triangles = listedTriangles(scene);
    if (triangles.empty())
        return {};
    std::vector<int> every(scene.particles.size());
    for (std::size_t i = 0; i < every.size(); ++i)
        every[i] = int(i);
    MeshDesc mesh = meshOnParticles(every, triangles);
    mesh.name = scene.name.empty() ? "surface" : scene.name;
    return {mesh};
}

MeshDesc meshOnParticles(const std::vector<int> &particleOf, std::vector<std::array<int, 3>> faces)
{
    MeshDesc mesh;
    mesh.offsets.resize(particleOf.size() + 1);
    for (std::size_t v = 0; v <= particleOf.size(); ++v)
        mesh.offsets[v] = int(v);
    mesh.particles = particleOf;
    mesh.weights.assign(particleOf.size(), 1.0);
    mesh.faces = std::move(faces);
    return mesh;
}

}  // namespace core
