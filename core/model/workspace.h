#pragma once
// Workspace: what the step needs besides the State, owned by the thread that steps and never copied
// with the state: the forces of the current sub-step, the integrators' and kernels' scratch, the
// contact grid, the profile, and how the last step ended. Everything in it is made on first use
// and reused, so that a step allocates nothing after the first.

#include "core/contacts/contact_grid.h"
#include "core/contacts/contact_scratch.h"
#include "core/contacts/triangle_scratch.h"
#include "core/blowup.h"
#include "core/profile.h"
#include "core/integrators/xpbd_layout.h"

#include <Eigen/Core>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace core {

struct ProjectiveSolver;  // projective.cpp
struct ImplicitSolver;    // implicit_euler.cpp
struct VbdTornColours;    // vbd.cpp

struct Workspace {
    Eigen::Matrix3Xd force;  // N: the forces of the current sub-step at (x, v)

    // the integrators' scratch arrays (state-sized; scratch() in passes.h makes them)
    std::array<Eigen::Matrix3Xd, 18> scratchArrays;
    // the spring pass's: each spring's force on its end a
    Eigen::Matrix3Xd springForce;
    // the fused lattice sub-step's (spring_blocks.cpp): each thread's window of particles and its
    // block's forces (made again when the thread count changes)
    std::vector<double> blockScratch;
    // xpbd's λ per spring (in XpbdLayout's order), kept across a sub-step's passes when it has several
    std::vector<double> xpbdLambda;
    XpbdConstants xpbdConstants;  // the sub-step's constants per spring, for the last layout and h
    // xpbd's layout without the springs that broke (xpbd.cpp), and the model layout and broken
    // flags it was made for: made again only when a spring breaks or the model changes
    XpbdLayout xpbdTornLayout;
    XpbdLayoutScratch xpbdTornScratch;
    std::uint64_t xpbdTornFrom = 0;
    std::vector<std::uint8_t> xpbdTornFlags;
    // projective's factorisation and implicit-euler's direct solver, made on first use and kept
    // while what they were made for holds (projective.cpp, implicit_euler.cpp)
    std::shared_ptr<ProjectiveSolver> projective;
    std::shared_ptr<ImplicitSolver> implicitSolver;
    // implicit-euler's linear solve (implicit_euler.cpp): Auto, block-Jacobi conjugate gradients
    // until they once stop at their cap, then the sparse Cholesky (LDLᵀ) for this model; or either
    // alone, as the benchmark compares them
    enum class ImplicitSolve { Auto, Direct, ConjugateGradients };
    ImplicitSolve implicitSolve = ImplicitSolve::Auto;
    std::vector<double> springLengths;  // vbd's: each spring's length at the sub-step's start
    // vbd's colours without the springs that broke, so that a torn run colours as its resumed file does
    std::shared_ptr<VbdTornColours> vbdTorn;
    ContactGrid contacts;  // the particle-pair pass's grid and pairs (broad_phase.cpp)
    ContactScratch contactSolver;  // the iterative contact solver's (contacts.cpp)
    TriangleScratch triangles;     // the triangle collisions' (triangle_collisions.cpp)

    Profile profile;
    // set by the step that stopped being finite or bounded; step() refuses to go on until it is
    // cleared (a restored state clears it)
    std::optional<Blowup> blowup;

    // Raised from another thread to stop a long step (null: a step always runs to its end): it
    // stops between two sub-steps, and between the stages of one (stopsHere), so that a sub-step of
    // 10⁶ particles does not hold up a Pause for its whole length. The step then returns false with
    // `interrupted` set and the state half-way through: the caller restores the state it began
    // from, so that a step is whole or not taken.
    const std::atomic<bool> *interrupt = nullptr;
    bool interrupted = false;
    // the stop points the steps passed: how finely a step can be cut
    std::uint64_t stopPoints = 0;
    // fused spring passes (spring_blocks) that the raised flag cut between two blocks of particles,
    // where a stage-long wait would be too long on 10⁶ particles
    std::uint64_t springPassesCut = 0;
    // the stop point (a value of stopPoints) at which a step stops as if asked to: for the tests
    // that cut a step at each of its stop points in turn; 0 in a run
    std::uint64_t stopAtPoint = 0;
};

// whether the step should stop where it is (a relaxed load: the flag orders nothing else)
inline bool interruptRequested(const Workspace &work)
{
    return work.interrupt && work.interrupt->load(std::memory_order_relaxed);
}

// a place where a step may stop: true, with `interrupted` set, when it is asked to. Whatever the
// step has done to the state is undone by the caller; the workspace's scratch is rebuilt by the
// next sub-step
inline bool stopsHere(Workspace &work)
{
    if (work.interrupted)
        return true;
    work.stopPoints += 1;
    if (interruptRequested(work) || work.stopPoints == work.stopAtPoint)
        work.interrupted = true;
    return work.interrupted;
}

}  // namespace core
