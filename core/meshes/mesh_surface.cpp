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
    const std::vector<std::array<int, 3>> triangles = listedTriangles(scene);
    const std::string name = scene.name.empty() ? "surface" : scene.name;
    if (scene.meshes.empty()) {
        if (triangles.empty())
            return {};
        std::vector<int> every(scene.particles.size());
        for (std::size_t i = 0; i < every.size(); ++i)
            every[i] = int(i);
        MeshDesc mesh = meshOnParticles(every, triangles);
        mesh.name = name;
        return {mesh};
    }
    // the imported meshes, and the sheets none of them covers (a cloth generated over an imported
    // table) as one more surface over their own particles, in the particles' order
    std::vector<MeshDesc> meshes = scene.meshes;
    std::vector<char> imported(scene.particles.size(), 0);
    for (const MeshDesc &mesh : scene.meshes)
        for (const int p : mesh.particles)
            if (p >= 0 && std::size_t(p) < imported.size())
                imported[std::size_t(p)] = 1;
    std::vector<int> vertexOf(scene.particles.size(), -1);
    std::vector<std::array<int, 3>> rest;
    for (const std::array<int, 3> &t : triangles)
        if (!imported[std::size_t(t[0])] && !imported[std::size_t(t[1])] && !imported[std::size_t(t[2])]) {
            rest.push_back(t);
            for (const int p : t)
                vertexOf[std::size_t(p)] = 0;
        }
    if (rest.empty())
        return meshes;
    std::vector<int> particleOf;
    for (std::size_t p = 0; p < vertexOf.size(); ++p)
        if (vertexOf[p] == 0) {
            vertexOf[p] = int(particleOf.size());
            particleOf.push_back(int(p));
        }
    for (std::array<int, 3> &t : rest)
        for (int &corner : t)
            corner = vertexOf[std::size_t(corner)];
    MeshDesc sheets = meshOnParticles(particleOf, std::move(rest));
    sheets.name = name + "-sheets";
    meshes.push_back(std::move(sheets));
    return meshes;
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
