#pragma once
// The imported surfaces of a scene (SceneDesc::meshes) as the run moves them: each vertex where its
// particles put it. What the viewport draws and what the exports write.

#include "core/model/scene.h"

#include <Eigen/Core>
#include <optional>
#include <string_view>

namespace core {

// "cloth", "soft", "collider": the words of the scene format and of springlab-sim --as
std::string_view meshKindName(MeshKind kind);
std::optional<MeshKind> meshKindNamed(std::string_view name);
// "cloth, soft, collider"
std::string_view knownMeshKinds();

// where the mesh's vertices are written: in the scene, or where the file it came from has them
// (its placement undone: MeshDesc::scale, zUp, offset)
enum class MeshSpace { Scene, File };

// the mesh's vertices, in its order, from the particles' positions (one column a particle);
// `out` is resized to 3 × the mesh's vertex count
void meshVertexPositions(const MeshDesc &mesh, const Eigen::Matrix3Xd &positions, Eigen::Matrix3Xd &out,
                         MeshSpace space = MeshSpace::Scene);

// the surfaces an export writes: the scene's imported meshes, or, in a scene with none, one of
// every particle (in their order) with the scene's triangles, named after the scene; empty when
// the scene has no triangles either. Beside imported meshes, the triangles none of them covers (a
// generated cloth) are one more surface, "NAME-sheets", over their particles in increasing order
std::vector<MeshDesc> exportedMeshes(const SceneDesc &scene);

// a cloth's or a collider's mesh: vertex v on particle particleOf[v], weight 1
MeshDesc meshOnParticles(const std::vector<int> &particleOf, std::vector<std::array<int, 3>> faces);

}  // namespace core
