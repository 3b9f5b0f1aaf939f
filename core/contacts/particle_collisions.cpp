#include "core/contacts/broad_phase.h"
#include "core/geometry.h"
#include "core/passes.h"

#include <cmath>

namespace core {

namespace {

// resolves one overlapping pair as the handout does, with inverse masses so that a pinned
// particle (inverse mass 0) is the immovable side
void resolvePair(const Model &model, State &state, int i, int j)
{
    const double wi = model.invMass[i];
    const double wj = model.invMass[j];
    const double w = wi + wj;
    if (w == 0.0)
        return;  // two pinned particles: nothing can move

    const Eigen::Vector3d d = state.position.col(i) - state.position.col(j);
    const double contact = model.radius[i] + model.radius[j];
    const double squared = d.squaredNorm();
    if (!(squared < contact * contact))
        return;  // apart (or NaN: a contact never spreads a NaN to a neighbour)
    const double distance = std::sqrt(squared);
    const Eigen::Vector3d k = distance > 0.0 ? Eigen::Vector3d(d / distance) : coincidentAxis(i, j);

    // position: each moves by the penetration weighted by the other's mass (m_j/(m_i+m_j) = w_i/w)
    const double penetration = contact - distance;
    state.position.col(i) += (wi / w * penetration) * k;
    state.position.col(j) -= (wj / w * penetration) * k;

    // velocity: an impulse along k with restitution, only if the two are approaching
    const double approach = k.dot(state.velocity.col(i) - state.velocity.col(j));
    if (approach >= 0.0)
        return;
    const double a = (1.0 + contactRestitution(model, approach)) * approach / w;
    state.velocity.col(i) -= (a * wi) * k;
    state.velocity.col(j) += (a * wj) * k;
}

}  // namespace

// the pairs that overlap at the start of the pass, found by the grid (or by brute force, its
// reference), resolved in lexicographic order: each is checked again when its turn comes, since
// the pairs before it move particles. A pair that only comes into contact during the pass waits
// for the next sub-step. Then the planes once more: a pair pushed into a plane is put back in
// front of it, so the floor holds a stack however tall (the pairs may then overlap a little,
// never the planes)
void collideParticles(const Model &model, State &state, Workspace &work)
{
    if (!model.plan.particleCollisions)
        return;
    ContactGrid &contacts = work.contacts;
    if (contacts.bruteForce)
        findContactsBruteForce(model, state.position, contacts.pairs);
    else
        findContacts(model, state.position, contacts);
    for (const ContactPair &pair : contacts.pairs)
        resolvePair(model, state, pair.i, pair.j);
    collidePlanes(model, state, work);
}

}  // namespace core
