#pragma once
// Snapshot: what the viewport and panels read of one step. Immutable once published; floats,
// since it is for drawing and display. The worker builds one after a step and publishes it
// through a latest-wins mailbox; the viewport never waits for a step.

#include "core/model/diagnostics.h"
#include "core/model/model.h"
#include "core/blowup.h"
#include "core/model/state.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace core {

struct Snapshot {
    std::uint64_t step = 0;  // the step these values belong to: a frame never mixes two steps
    double time = 0.0;       // s

    std::vector<float> positions;   // xyz per particle, m
    std::vector<float> velocities;  // xyz per particle, m/s
    // wxyz per particle, unit quaternions; empty where the scene cannot turn
    std::vector<float> orientations;
    std::vector<float> angularVelocities;  // xyz per particle, rad/s; empty likewise
    std::vector<float> radii;      // per particle, m
    std::vector<std::uint8_t> pinned;  // 1 per pinned particle
    std::vector<float> springEnds;     // xyz of end a, then xyz of end b, per spring
    std::vector<float> springStrain;   // (l - l0) / l0 per spring (0 when l0 = 0)
    // 1 per broken spring (drawn as nothing); empty when no spring of the scene can break
    std::vector<std::uint8_t> springBroken;
    std::uint64_t breakCount = 0;  // springs broken so far
    // the spring mesh's triangles (the model's, shared); null or empty when it has none
    std::shared_ptr<const SpringTriangles> triangles;
    // the soft bodies' surfaces (the model's, shared) and their vertices, xyz each, m; null and
    // empty when the scene has none
    std::shared_ptr<const EmbeddedSurface> embedded;
    std::vector<float> embeddedPositions;

    Energies energies;
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    std::optional<Blowup> blowup;

    int particleCount() const { return static_cast<int>(radii.size()); }
    int springCount() const { return static_cast<int>(springStrain.size()); }
    bool isBroken(int spring) const
    {
        return !springBroken.empty() && springBroken[static_cast<std::size_t>(spring)] != 0;
    }
};

// fills a snapshot of the state (the model gives radii, pins and spring ends), and of how its run
// blew up, if it did (Workspace::blowup)
std::shared_ptr<const Snapshot> makeSnapshot(const Model &model, const State &state,
                                             const std::optional<Blowup> &blowup = std::nullopt);
// the same into `into`, every value replaced, its arrays' memory reused: a snapshot of 10⁶
// particles and 6·10⁶ springs is 200 MB, and memory that size taken fresh is paged in again
// each time (most of a second of its making on a busy machine)
void fillSnapshot(Snapshot &into, const Model &model, const State &state,
                  const std::optional<Blowup> &blowup = std::nullopt);

}  // namespace core
