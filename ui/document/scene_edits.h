#pragma once
// Scene edits: the structural changes the editing tools make to a SceneDesc, as pure functions
// with no Qt, so that each can be unit-tested on its own and wrapped in one undo command
// (SceneCommand, scene_commands.h). Particle indices refer to scene.particles; functions that
// remove or add particles keep the springs and the steerable index pointing at the same particles.

#include "core/model/generators.h"
#include "core/model/scene.h"
#include "core/model/validate.h"

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

namespace ui {

// what the editor has selected; indices sorted and unique
struct Selection {
    std::vector<int> particles;
    std::vector<int> springs;

    bool empty() const { return particles.empty() && springs.empty(); }
    bool hasParticle(int i) const;
    bool hasSpring(int i) const;
    // adds or removes one item, keeping the order
    void toggleParticle(int i);
    void toggleSpring(int i);
    // drops indices that the scene no longer has
    void clamp(const core::SceneDesc &scene);
    bool operator==(const Selection &) const = default;
};

// sorts and removes duplicates
void normalise(std::vector<int> &indices);

// the selected particles and the two ends of each selected spring, sorted, those the scene has:
// what an edit of "the selection's particles" moves (Copy, Transform Selection)
std::vector<int> selectedParticles(const core::SceneDesc &scene, const Selection &selection);

// the particles and springs among them, cut out of a scene: what Copy puts on the clipboard
struct Fragment {
    std::vector<core::ParticleDesc> particles;
    std::vector<core::SpringDesc> springs;  // indices into particles
    std::vector<std::array<int, 3>> triangles;  // indices into particles; empty: its springs'
    bool empty() const { return particles.empty(); }
};

// the first problem with a particle that `after` adds to `before` or changes (added, moved, its
// motion or mass edited): what an edit must not bring into the document, since a scene the file
// format refuses could not be saved or opened again (a particle past the world's edge). Only the
// changed particles are checked, so a drag on a large scene costs what it moves
std::optional<core::SceneProblem> changedParticleProblem(const core::SceneDesc &before, const core::SceneDesc &after);

// the most particles a scene may grow to in the editor, by Generate, Duplicate, Paste or Add
// Particle: the generators' limit, so that one number holds everywhere. A scene file with more
// still opens (core/io has its own, larger limit for files written by springlab-sim and the
// benchmarks), but the editor adds nothing to it.
inline constexpr std::size_t kMaxSceneParticles = core::kMaxGeneratedParticles;
// the particles the scene would have with `added` more, when that is past kMaxSceneParticles
std::optional<std::size_t> particlesPastLimit(const core::SceneDesc &scene, std::size_t added);

// appends a particle; returns its index
int addParticle(core::SceneDesc &scene, const core::ParticleDesc &particle);

// joins a and b with their current distance as the rest length; returns the spring's index, or -1
// when a == b, either is out of range, or a spring already joins them
int addSpring(core::SceneDesc &scene, int a, int b, double stiffness, double damping);

// flips pinned on each particle; a pinned particle is at rest, so its velocity is cleared
void togglePinned(core::SceneDesc &scene, const std::vector<int> &particles);
// sets pinned on each particle
void setPinned(core::SceneDesc &scene, const std::vector<int> &particles, bool pinned);

// removes the springs, then the particles with every spring attached to them
void removeItems(core::SceneDesc &scene, const Selection &selection);

// the selected particles and the springs with both ends among them (a selected spring brings its
// two ends along)
Fragment copyItems(const core::SceneDesc &scene, const Selection &selection);

// appends the fragment moved by offset; returns the selection of what was added
Selection pasteFragment(core::SceneDesc &scene, const Fragment &fragment, const Eigen::Vector3d &offset);

// appends a generated scene (core/model/generators.h) with the middle of its particles' bounding box at
// `centre`: its particles and springs, and its substeps where they are more than the scene's (a
// cloth's stiff springs need them); the rest of its settings are not taken. Returns the selection
// of what was added.
Selection addGenerated(core::SceneDesc &scene, const core::SceneDesc &generated, const Eigen::Vector3d &centre);

// places each particle at from[k] + delta, from[k] being where particles[k] was seen (the drag
// starts from what is on screen, which is not the initial position once the run has moved on)
void moveParticles(core::SceneDesc &scene, const std::vector<int> &particles, const std::vector<Eigen::Vector3d> &from,
                   const Eigen::Vector3d &delta);

// Edit › Transform Selection: a numeric change of some particles' initial conditions. Each
// position p becomes c + t + R S (p - c), c being the centroid of their positions before: scaled
// along x, y and z, then rotated, both about c, then moved by t. Velocities turn with R (and flip
// along an axis a negative factor mirrors); their sizes stay. Masses and radii stay.
struct SelectionTransform {
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // m
    double angleDegrees = 0.0;                              // right-handed about axis
    Eigen::Vector3d axis = Eigen::Vector3d::UnitY();        // any length but zero
    Eigen::Vector3d scale = Eigen::Vector3d::Ones();        // factors along x, y, z; none zero
    // springs with both ends among the particles take the change of their length as their new
    // rest length, so that a scaled body starts at rest; off, they keep theirs and the body starts
    // stretched or squeezed. A spring to a particle outside always keeps its rest length.
    bool scaleRestLengths = false;

    // no change at all: no move, no turn, every factor 1
    bool isIdentity() const;
};

// the mean of the particles' initial positions (zero for none)
Eigen::Vector3d centroid(const core::SceneDesc &scene, const std::vector<int> &particles);

// applies the transform to the particles (indices the scene has, each once; the axis non-zero and
// no factor zero); the saved contact impulses of those particles are dropped, as they were for
// where the particles were
void transformParticles(core::SceneDesc &scene, const std::vector<int> &particles, const SelectionTransform &transform);

// the nearest multiple of step in each coordinate; step <= 0 leaves the point as it is
Eigen::Vector3d snapToGrid(const Eigen::Vector3d &point, double step);

}  // namespace ui
