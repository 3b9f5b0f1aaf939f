#pragma once
// Checks a SceneDesc's values before it is compiled: every number finite and in its range, every
// spring joining two distinct existing particles, every plane normal non-zero. Shared by the file
// loader and the editor, so both give the same message.

#include "core/model/scene.h"

#include <optional>
#include <string>

namespace core {

struct SceneProblem {
    std::string path;     // where, as a JSON path: "particles[3].mass"
    std::string message;  // why: "must be greater than 0 kg (got -1 kg)"
};

// the first problem in the scene, in file order; nullopt when it can be simulated
std::optional<SceneProblem> findProblem(const SceneDesc &scene);

// the first problem with one particle of the scene (its path "particles[i]..."): what an edit of a
// few particles checks, where checking the whole scene would cost a pass over every particle
std::optional<SceneProblem> findParticleProblem(const SceneDesc &scene, std::size_t index);

// the first problem with a run's contact impulses (SceneDesc::contactImpulses, a session's state)
// in a scene of that many particles and planes; paths as "contactImpulses[k].plane"
std::optional<SceneProblem> findContactImpulseProblem(const std::vector<ContactImpulse> &impulses, std::size_t particles,
                                                      std::size_t planes);

// the most particles a mesh's vertex rides on: a lattice cell's eight corners
inline constexpr int kMostMeshBindings = 8;

// the first problem with one imported mesh in a scene of that many particles; paths relative to
// the mesh ("vertices[4]", "faces[2][1]")
std::optional<SceneProblem> findMeshProblem(const MeshDesc &mesh, std::size_t particles);

// planes are stored with unit normals; this makes one so without disturbing one that already is
// (so that loading a saved file gives back the same bits)
Eigen::Vector3d unitNormal(const Eigen::Vector3d &normal);

}  // namespace core
