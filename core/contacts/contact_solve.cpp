// The resting contacts: every particle overlapping a collider or another particle at the end of the
// sub-step, solved together by sequential impulses (Gauss-Seidel over the contacts, impulses
// accumulated and clamped: a contact pushes, never pulls, and its friction stays inside the
// Coulomb cone), then by the same iteration on positions. Velocities and positions are solved
// apart, so that pushing an overlap out adds no speed. Contacts are solved from the ground up:
// a particle's level is the number of contacts between it and a collider or a pinned particle,
// and in the last iteration of each solve the lower particle of a pair counts as immovable, so a
// stack or a pile carries its weight down to the ground in one sweep ("shock propagation",
// Guendelman, Bridson and Fedkiw 2003) instead of sinking a little every sub-step. The velocity
// iterations are warm started from the impulses each contact ended the last sub-step with
// (State::contactImpulses), so that a deep pile's weight, which 8 iterations from nothing do not
// carry to the ground, is there from the first iteration.
//
// The solve comes after the integrator has moved the particles, so a resting particle ends each
// sub-step sunk into its support by what gravity adds in it (g h² for symplectic Euler, 1 mm at
// h = 0.01). Pushing that out in the position solve, sub-step after sub-step, slid particles along
// their other contacts, where the position solve's friction is only as strong as its own push, and
// piles crept without end (a 1000-ball pile sank 1–3 cm in 6 s at any number of sub-steps). So each
// velocity change of the solve also moves the particle as it would have moved had the contact acted
// from the sub-step's start: by β h times the change (driftWeight: β = 1 for the kick-drift Euler
// schemes, ½ for the second-order ones), and the target speeds are set for where the sub-step then
// ends. A resting particle ends where it began, and a pile comes to rest for good.

#include "core/contacts/broad_phase.h"
#include "core/geometry.h"
#include "core/contacts/particle_path.h"
#include "core/parallel.h"
#include "core/passes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace core {

namespace {

constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 4;
// how far, as a share of its radius, the solve may move a particle past the margin its gathering
// allowed for before its neighbours are looked at again: no pair can end a sub-step deeper inside
// each other than this share of their radii without being found (gatherNewOverlaps)
constexpr double kUnwatchedMove = 0.05;
// rounds of finding the pairs the solve pushed together and solving them: each round's pushes
// may press another pair, as far as the top of a column
constexpr int kOverlapRounds = 3;
constexpr int kUnreached = std::numeric_limits<int>::max();
// the overlap of two particles with friction, as a share of their radii's sum, that the position
// solve leaves in place. Pushing out every last hair of a pile's overlaps, each push letting the
// contact's friction hold the pair back by as much, lifted it: 1000 balls settled without friction,
// then given μ = 0.5 and e = 0, gained 5.5 J in 1.5 s and never came to rest (0.1 J of jitter).
// Leaving 0.1% (a tenth of a millimetre for two 5 cm balls; Box2D leaves a linear slop likewise)
// let it settle, 3.5 J lower, with 3e-6 J of motion left
constexpr double kOverlapSlop = 1e-3;

// the separating normal speed a contact should end the sub-step with, from the relative normal
// speed it has now (approach, negative while closing) and its gap (negative: overlap). With drift =
// β h > 0 the solve's change of speed moves the end of the sub-step too, and the contact asks for
// the end to touch, not overlap: approach - gap / drift at least, which for a resting particle is
// 0, and for a near miss lets it close its gap within the sub-step; but never for a separating
// speed: a contact pushes to stop a closing, not to keep two particles parting (an overlap the
// sub-step did not make is the position solve's to push out). Holding a pair that was parting to
// its speed made it push whenever another contact slowed it, and that fed energy in: a row struck
// through itself went from 1010 J to 1135 J in one step. Without drift (explicit Euler, whose
// position moved with the old speed) the target looks ahead to the next sub-step: no closer than
// the gap in it, and no closing speed once touching
double restingTarget(double approach, double gap, double drift, double h)
{
    if (drift > 0.0)
        return std::min(approach - gap / drift, 0.0);
    return gap > 0.0 ? -gap / h : 0.0;
}

// the contacts at the end of the sub-step: every overlap, and every near miss closer than a resting
// contact comes in a sub-step that is not closing faster than one (a speculative contact: it may
// close its gap but not overlap). The near misses let a stack stop as one: when the floor stops
// the bottom ball, the ball on it, still falling with it, is already a contact.
void gather(const Model &model, State &state, Workspace &work, double h)
{
    ContactScratch &scratch = work.contactSolver;
    scratch.contacts.clear();
    // m: how near counts as a near miss; never more than a particle's radius, so that a huge gravity
    // or step cannot make every particle a near miss of every other
    const double reach = model.restingSpeed * h;
    // gathered in parallel shares, each into its own list, joined in share order: the order one
    // thread gathers them in, whatever the count
    const auto add = [&](std::vector<Contact> &out, int i, int j, double side, const Eigen::Vector3d &normal, double gap,
                         double friction, double staticFriction, double rollingFriction, double spinningFriction) {
        const Eigen::Vector3d vj = j >= 0 ? Eigen::Vector3d(state.velocity.col(j)) : Eigen::Vector3d::Zero();
        const double approach = normal.dot(state.velocity.col(i) - vj);
        const bool fast = -approach > restingThreshold(model, normal);
        Contact c;
        // an impact to come, unless it is inside a pile (decided below)
        c.deferred = gap >= 0.0 && fast;
        c.i = i;
        c.j = j;
        c.side = side;
        c.normal = normal;
        c.friction = friction;
        c.staticFriction = staticFriction;
        c.rollingFriction = rollingFriction;
        c.spinningFriction = spinningFriction;
        // restitution once, after the compression; a contact slower than gravity makes it in a
        // sub-step along its normal is resting, and stays put (a bounce moves nothing: the particle may have been in an impact earlier in the
        // sub-step, or come in partway through it, and moving it as if the bounce had been at the
        // sub-step's start gained energy: 10% in 20 s of a 1000-ball elastic box)
        // A bounce is solved in two phases (solveVelocities): its compression, to no closing speed,
        // with every other contact, and then e times the compression's impulse again (Poisson's rule)
        c.bounce = gap <= 0.0 && fast;
        c.drift = c.bounce ? 0.0 : scratch.drift;
        c.targetSpeed = c.bounce ? 0.0 : restingTarget(approach, gap, c.drift, h);
        out.push_back(c);
    };
    const auto startShares = [&](int count) {
        const int shares = twoPhaseShares(count);
        if (int(scratch.contactShares.size()) < shares)
            scratch.contactShares.resize(std::size_t(shares));
        for (int share = 0; share < shares; ++share)
            scratch.contactShares[std::size_t(share)].clear();
        return shares;
    };
    const auto joinShares = [&](int shares) {
        for (int share = 0; share < shares; ++share)
            scratch.contacts.insert(scratch.contacts.end(), scratch.contactShares[std::size_t(share)].begin(),
                                    scratch.contactShares[std::size_t(share)].end());
    };

    if (model.plan.planeCollisions) {
        const int free = int(model.freeParticles.size());
        const int shares = startShares(free);
        parallelShares(free, [&](int share, int begin, int end) {
            for (int f = begin; f < end; ++f) {
                const int i = model.freeParticles[std::size_t(f)];
                for (int k = 0; k < static_cast<int>(model.colliders.size()); ++k) {
                    const Collider &collider = model.colliders[std::size_t(k)];
                    const double side = sideOf(collider, scratch.sidePointOf(i));
                    const Separation s = separation(collider, state.position.col(i), side);
                    const double gap = s.distance - model.radius[i];
                    if (gap < std::min(reach, model.radius[i]))
                        add(scratch.contactShares[std::size_t(share)], i, -1 - k, side, s.normal, gap, collider.friction,
                            collider.staticFriction, collider.rollingFriction, collider.spinningFriction);
                }
            }
        });
        joinShares(shares);
    }

    if (model.plan.particleCollisions && !stopsHere(work)) {
        ContactGrid &grid = work.contacts;
        scratch.sweptRadius = model.radius.array() + model.radius.array().min(0.5 * reach);
        if (grid.bruteForce)
            findContactsBruteForce(model, state.position, scratch.sweptRadius, grid.pairs);
        else
            findContacts(model, state.position, scratch.sweptRadius, grid);
        if (stopsHere(work))
            return;
        const int pairs = int(grid.pairs.size());
        const int shares = startShares(pairs);
        parallelShares(pairs, [&](int share, int begin, int end) {
            for (int k = begin; k < end; ++k) {
                const ContactPair &pair = grid.pairs[std::size_t(k)];
                // i the free one: a pinned particle never moves, whichever end it is
                const bool swap = model.invMass[pair.i] == 0.0;
                const int i = swap ? pair.j : pair.i;
                const int j = swap ? pair.i : pair.j;
                const Eigen::Vector3d d = state.position.col(i) - state.position.col(j);
                const double distance = d.norm();
                const Eigen::Vector3d normal =
                    apart(distance) ? Eigen::Vector3d(d / distance) : coincidentAxis(pair.i, pair.j);
                add(scratch.contactShares[std::size_t(share)], i, j, 1.0, normal,
                    distance - model.radius[i] - model.radius[j], model.friction, model.staticFriction,
                    model.rollingFriction, model.spinningFriction);
            }
        });
        joinShares(shares);
    }

    // a near miss closing fast is an impact to come, located in time in the next sub-step, when
    // neither particle touches anything else: braking it here would take energy from a bounce. In
    // a pile it is braked now, since the impact would be resolved as if the two were alone
    if (std::none_of(scratch.contacts.begin(), scratch.contacts.end(), [](const Contact &c) { return c.deferred; }))
        return;
    std::vector<int> &touching = scratch.queue;  // borrowed: per particle, contacts that are not impacts to come
    touching.assign(std::size_t(model.particleCount()), 0);
    for (const Contact &c : scratch.contacts)
        if (!c.deferred) {
            touching[std::size_t(c.i)] += 1;
            if (!c.withCollider())
                touching[std::size_t(c.j)] += 1;
        }
    const auto alone = [&](const Contact &c) {
        return c.deferred && touching[std::size_t(c.i)] == 0 && (c.withCollider() || touching[std::size_t(c.j)] == 0);
    };
    scratch.contacts.erase(std::remove_if(scratch.contacts.begin(), scratch.contacts.end(), alone), scratch.contacts.end());
}

// each particle's level above the ground, and the contacts sorted by it
void sortByLevel(const Model &model, ContactScratch &scratch)
{
    const int n = model.particleCount();
    scratch.level.assign(std::size_t(n), kUnreached);
    scratch.neighbourStart.assign(std::size_t(n) + 1, 0);
    scratch.queue.clear();
    const auto ground = [&](int p) {
        if (scratch.level[std::size_t(p)] != 0) {
            scratch.level[std::size_t(p)] = 0;
            scratch.queue.push_back(p);
        }
    };
    // the ground: a collider that carries weight (facing against gravity within 60°), or a pinned
    // particle; a wall holds nothing up, and without gravity nothing is above anything
    const double weight = model.gravity.norm();
    const auto carries = [&](const Eigen::Vector3d &normal) { return weight > 0.0 && -normal.dot(model.gravity) > 0.5 * weight; };
    for (const Contact &c : scratch.contacts) {
        if (c.withCollider()) {
            if (carries(c.normal))
                ground(c.i);
            continue;
        }
        if (model.invMass[c.j] == 0.0 && carries(c.normal))
            ground(c.i);
        scratch.neighbourStart[std::size_t(c.i) + 1] += 1;
        scratch.neighbourStart[std::size_t(c.j) + 1] += 1;
    }
    for (int p = 0; p < n; ++p)
        scratch.neighbourStart[std::size_t(p) + 1] += scratch.neighbourStart[std::size_t(p)];
    scratch.neighbours.resize(std::size_t(scratch.neighbourStart[std::size_t(n)]));
    std::vector<int> &fill = scratch.levelStart;  // borrowed as the fill cursor
    fill.assign(scratch.neighbourStart.begin(), scratch.neighbourStart.end() - 1);
    for (const Contact &c : scratch.contacts)
        if (!c.withCollider()) {
            scratch.neighbours[std::size_t(fill[std::size_t(c.i)]++)] = c.j;
            scratch.neighbours[std::size_t(fill[std::size_t(c.j)]++)] = c.i;
        }

    // breadth first from the ground, through free particles only
    for (std::size_t head = 0; head < scratch.queue.size(); ++head) {
        const int p = scratch.queue[head];
        const int next = scratch.level[std::size_t(p)] + 1;
        for (int e = scratch.neighbourStart[std::size_t(p)]; e < scratch.neighbourStart[std::size_t(p) + 1]; ++e) {
            const int q = scratch.neighbours[std::size_t(e)];
            if (model.invMass[q] != 0.0 && scratch.level[std::size_t(q)] == kUnreached) {
                scratch.level[std::size_t(q)] = next;
                scratch.queue.push_back(q);
            }
        }
    }

    // the contacts by level, stable: colliders and pinned partners first, then upwards; contacts
    // out of reach of the ground last
    int top = 0;
    for (Contact &c : scratch.contacts) {
        const int li = scratch.level[std::size_t(c.i)];
        const int lj = c.withCollider() || model.invMass[c.j] == 0.0 ? -1 : scratch.level[std::size_t(c.j)];
        const int low = std::min(li, lj);
        c.order = low == kUnreached ? -2 : low + 1;  // -2: marks "unreached" until the sort below
        top = std::max(top, c.order);
    }
    const int unreached = top + 1;
    for (Contact &c : scratch.contacts)
        if (c.order == -2)
            c.order = unreached;
    scratch.levelStart.assign(std::size_t(unreached) + 2, 0);
    for (const Contact &c : scratch.contacts)
        scratch.levelStart[std::size_t(c.order) + 1] += 1;
    for (std::size_t l = 1; l < scratch.levelStart.size(); ++l)
        scratch.levelStart[l] += scratch.levelStart[l - 1];
    // moved into their places in the same array, following the permutation's cycles: a sorted copy
    // would double the solver's largest scratch (about 200 bytes a contact)
    std::vector<int> &place = scratch.place;
    place.resize(scratch.contacts.size());
    for (std::size_t k = 0; k < scratch.contacts.size(); ++k)
        place[k] = scratch.levelStart[std::size_t(scratch.contacts[k].order)]++;
    for (std::size_t k = 0; k < place.size(); ++k)
        while (place[k] != int(k)) {
            const auto to = std::size_t(place[k]);
            std::swap(scratch.contacts[k], scratch.contacts[to]);
            std::swap(place[k], place[to]);
        }
}

// the inverse masses of each contact's two sides, in the iterations and in the last, where the side
// nearer the ground stands still; found once, since every iteration of both solves reads them
void setWeights(const Model &model, ContactScratch &scratch)
{
    for (Contact &c : scratch.contacts) {
        c.weights = Weights{};
        c.weights.i = model.invMass[c.i];
        c.weights.j = c.withCollider() ? 0.0 : model.invMass[c.j];
        c.shockWeights = c.weights;
        if (c.weights.j != 0.0) {
            const int li = scratch.level[std::size_t(c.i)];
            const int lj = scratch.level[std::size_t(c.j)];
            if (li < lj)
                c.shockWeights.i = 0.0;
            else if (lj < li)
                c.shockWeights.j = 0.0;
        }
        for (Weights *w : {&c.weights, &c.shockWeights}) {
            w->mass = w->sum() > 0.0 ? 1.0 / w->sum() : 0.0;
            w->tangentMass = w->mass;
            if (!scratch.spin)
                continue;
            // a side that stands still does not turn either
            ContactLevers &l = w->levers;
            l.ri = model.radius[c.i];
            l.rj = c.withCollider() ? 0.0 : model.radius[c.j];
            l.ai = w->i > 0.0 ? model.invInertia[c.i] : 0.0;
            l.aj = w->j > 0.0 ? model.invInertia[c.j] : 0.0;
            const double sliding = w->sum() + l.turning();
            w->tangentMass = sliding > 0.0 ? 1.0 / sliding : 0.0;
            w->angularMass = l.ai + l.aj > 0.0 ? 1.0 / (l.ai + l.aj) : 0.0;
        }
    }
}

const Weights &weights(const Contact &c, bool shock)
{
    return shock ? c.shockWeights : c.weights;
}

void applyImpulse(State &state, const Contact &c, const Weights &w, const Eigen::Vector3d &impulse)
{
    state.velocity.col(c.i) += w.i * impulse;
    if (!c.withCollider())
        state.velocity.col(c.j) -= w.j * impulse;
}

// an impulse of the velocity solve: the speed, and the end of the sub-step with it (drift = β h)
void applyImpulse(State &state, const Contact &c, const Weights &w, const Eigen::Vector3d &impulse, double drift)
{
    applyImpulse(state, c, w, impulse);
    if (!(drift > 0.0))
        return;
    state.position.col(c.i) += (drift * w.i) * impulse;
    if (!c.withCollider())
        state.position.col(c.j) -= (drift * w.j) * impulse;
}

Eigen::Vector3d relativeVelocity(const State &state, const Contact &c)
{
    return c.withCollider() ? Eigen::Vector3d(state.velocity.col(c.i))
                            : Eigen::Vector3d(state.velocity.col(c.i) - state.velocity.col(c.j));
}

// the other side's spin: a collider's is none
Eigen::Vector3d spinOfJ(const State &state, const Contact &c)
{
    return c.withCollider() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(state.angularVelocity.col(c.j));
}

// how the contact's surfaces slide over each other: the relative velocity along the surface, and
// with spin what the turning of each adds at the point of contact
Eigen::Vector3d slipOf(const State &state, const Contact &c, bool spin)
{
    const Eigen::Vector3d v = relativeVelocity(state, c);
    Eigen::Vector3d slip = v - c.normal.dot(v) * c.normal;
    if (spin)
        slip += spinSlip(c.weights.levers, state.angularVelocity.col(c.i), spinOfJ(state, c), c.normal);
    return slip;
}

// a friction impulse along the surface: the speeds (and the sub-step's end, by drift), and with
// spin the turn it gives each side
void turnByFriction(State &state, const Contact &c, const Weights &w, const Eigen::Vector3d &impulse)
{
    Eigen::Vector3d still = Eigen::Vector3d::Zero();
    if (c.withCollider())
        turnBy(w.levers, c.normal, impulse, state.angularVelocity.col(c.i), still);
    else
        turnBy(w.levers, c.normal, impulse, state.angularVelocity.col(c.i), state.angularVelocity.col(c.j));
}

void applyFriction(State &state, const Contact &c, const Weights &w, const Eigen::Vector3d &impulse, double drift,
                   bool spin)
{
    applyImpulse(state, c, w, impulse, drift);
    if (spin)
        turnByFriction(state, c, w, impulse);
}

// rolling resistance and spinning friction: angular impulses against the two sides turning one
// against the other, across the contact (rolling) and about its normal (spinning), each bounded by
// its coefficient times the normal impulse times the rolling radius
void resistTurning(State &state, Contact &c, const Weights &w)
{
    if (!(w.angularMass > 0.0) || !(c.rollingFriction > 0.0 || c.spinningFriction > 0.0))
        return;
    const double reach = rollingRadius(c.weights.levers) * c.normalImpulse;
    const Eigen::Vector3d turning = state.angularVelocity.col(c.i) - spinOfJ(state, c);
    const double about = c.normal.dot(turning);
    Eigen::Vector3d change = Eigen::Vector3d::Zero();
    if (c.rollingFriction > 0.0) {
        Eigen::Vector3d rolling = c.rollingImpulse - (turning - about * c.normal) * w.angularMass;
        const double most = c.rollingFriction * reach;
        if (rolling.squaredNorm() > most * most)
            rolling *= most / rolling.norm();
        change += rolling - c.rollingImpulse;
        c.rollingImpulse = rolling;
    }
    if (c.spinningFriction > 0.0) {
        const double most = c.spinningFriction * reach;
        const double spinning = std::clamp(c.spinningImpulse - about * w.angularMass, -most, most);
        change += (spinning - c.spinningImpulse) * c.normal;
        c.spinningImpulse = spinning;
    }
    state.angularVelocity.col(c.i) += w.levers.ai * change;
    if (!c.withCollider())
        state.angularVelocity.col(c.j) -= w.levers.aj * change;
}

// warm starting: each contact starts from the impulses it ended the last sub-step with, applied
// at once, so that the iterations go on converging where the last sub-step's left off instead of
// from nothing (a pile's weight takes many more than 8 iterations to reach the ground from
// nothing). The friction is turned into the contact's surface as it is now, and kept in its cone
void warmStart(State &state, ContactScratch &scratch)
{
    const std::vector<ContactImpulse> &last = state.contactImpulses;
    if (last.empty())
        return;
    for (Contact &c : scratch.contacts) {
        if (c.bounce)
            continue;  // an impact, not a support carried over: its compression starts from nothing
        ContactImpulse key;
        key.i = c.i;
        key.j = c.j;
        const auto found = std::lower_bound(last.begin(), last.end(), key);
        if (found == last.end() || found->i != c.i || found->j != c.j)
            continue;
        const Weights &w = weights(c, false);
        if (!(w.sum() > 0.0))
            continue;
        c.normalImpulse = found->normal;
        Eigen::Vector3d friction = found->friction - c.normal.dot(found->friction) * c.normal;
        const double size = friction.norm();
        if (size > c.staticFriction * c.normalImpulse)
            friction *= c.friction * c.normalImpulse / size;
        c.frictionImpulse = friction;
        applyImpulse(state, c, w, c.normalImpulse * c.normal + c.frictionImpulse, c.drift);
        if (scratch.spin)  // the friction's turn too
            turnByFriction(state, c, w, c.frictionImpulse);
    }
}

// what the next sub-step starts from: the contacts that pushed, sorted for warmStart's search
void keepImpulses(State &state, const ContactScratch &scratch)
{
    std::vector<ContactImpulse> &kept = state.contactImpulses;
    kept.clear();
    for (const Contact &c : scratch.contacts)
        if (c.normalImpulse > 0.0 && !c.bounce)
            kept.push_back(ContactImpulse{c.i, c.j, c.normalImpulse, c.frictionImpulse});
    std::sort(kept.begin(), kept.end());
}

// the bounces' restitution, after the compression: each gets e times the normal impulse its
// compression took, all at once (Poisson's rule). With the compression solved, the contacts that
// pushed close at no speed, so the kinetic energy after is that before the solve less (1 − e²) times
// what the compression took: with e ≤ 1 it never rises, however many bounces share a particle.
// Newton's rule inside the iterations (a target of −e times the approach) gained energy wherever
// a ball had two bounces at once: a row pushed through itself by a striker took a random scene
// without gravity from 983 J to 6000 J in five steps
void rebound(State &state, ContactScratch &scratch, double restitution)
{
    if (!(restitution > 0.0))
        return;
    for (Contact &c : scratch.contacts) {
        if (!c.bounce || !(c.normalImpulse > 0.0))
            continue;
        const double extra = restitution * c.normalImpulse;
        applyImpulse(state, c, weights(c, false), extra * c.normal);
        c.normalImpulse += extra;
    }
}

// the fail-safe, after the velocity solve (Bridson, Fedkiw and Anderson's rigid impact zones, 2002,
// for balls): a bounce still closing after the iterations (a cluster pressed against a wall by a
// heavy ball, where 8 iterations carry too little of the push through) would let its balls pass
// into each other. Its particles, with those of every other such bounce that shares one, go on as
// one: each zone moves at its mass-weighted mean velocity (momentum kept; the kinetic energy can
// only fall), with a pinned member holding it still, less its approach to any collider a member
// touches. A zone may now close on a neighbour through any contact, so the closing contacts of the
// zones' members are found again from the new velocities and merged until nothing closes: each
// round merges two zones or stops one on a collider, so it ends. (A resting contact alone is left
// to the iterations: taking those in too moved ordinary scenes, a net falling on a floor among them)
void stopClosingContacts(const Model &model, State &state, ContactScratch &scratch, double h)
{
    const int n = model.particleCount();
    std::vector<std::uint8_t> &member = scratch.isStray;  // borrowed: in a zone
    member.assign(std::size_t(n), 0);
    // closing: short of its target by more than a resting contact's speed, and by enough to sink a
    // thousandth of the contact distance in a sub-step (what the iterations leave of a converged
    // solve is far less)
    const auto closing = [&](const Contact &c) {
        if (!c.bounce && !member[std::size_t(c.i)] && (c.withCollider() || !member[std::size_t(c.j)]))
            return false;
        const double shortfall = c.targetSpeed - c.normal.dot(relativeVelocity(state, c));
        const double distance = model.radius[c.i] + (c.withCollider() ? 0.0 : model.radius[c.j]);
        return shortfall > restingThreshold(model, c.normal) && shortfall * h > 1e-3 * distance;
    };
    if (std::none_of(scratch.contacts.begin(), scratch.contacts.end(), closing))
        return;
    if (scratch.zoneMomentum.cols() < n)
        scratch.zoneMomentum.resize(3, n);
    std::vector<int> &zone = scratch.zoneOf;
    zone.resize(std::size_t(n));
    for (int p = 0; p < n; ++p)
        zone[std::size_t(p)] = p;
    const auto root = [&](int p) {
        while (zone[std::size_t(p)] != p)
            p = zone[std::size_t(p)] = zone[std::size_t(zone[std::size_t(p)])];
        return p;
    };
    // (a particle that never closes on anything is a zone of its own, and is left as it is)
    Eigen::Matrix3Xd &velocity = scratch.zoneMomentum;  // each zone's momentum, then its velocity
    std::vector<double> &mass = scratch.zoneMass;
    // every round merges two zones or stops one on a collider; corners of several colliders may
    // need a few more, so the count is bounded
    const std::size_t rounds = scratch.contacts.size() + 8;
    for (std::size_t round = 0; round < rounds; ++round) {
        bool any = false;
        for (const Contact &c : scratch.contacts)
            if (closing(c)) {
                any = true;
                member[std::size_t(c.i)] = 1;
                if (!c.withCollider()) {
                    member[std::size_t(c.j)] = 1;
                    zone[std::size_t(root(c.i))] = root(c.j);
                }
            }
        if (!any)
            break;
        mass.assign(std::size_t(n), 0.0);
        for (int p = 0; p < n; ++p)
            if (member[std::size_t(p)])
                velocity.col(root(p)).setZero();
        for (int p = 0; p < n; ++p) {
            if (!member[std::size_t(p)])
                continue;
            const int r = root(p);
            if (model.invMass[p] == 0.0 || !std::isfinite(mass[std::size_t(r)])) {
                mass[std::size_t(r)] = std::numeric_limits<double>::infinity();  // pinned: the zone stands
                continue;
            }
            velocity.col(r) += state.velocity.col(p) / model.invMass[p];
            mass[std::size_t(r)] += 1.0 / model.invMass[p];
        }
        for (int p = 0; p < n; ++p)
            if (member[std::size_t(p)] && root(p) == p)
                velocity.col(p) = std::isfinite(mass[std::size_t(p)]) ? Eigen::Vector3d(velocity.col(p) / mass[std::size_t(p)])
                                                                    : Eigen::Vector3d::Zero();
        // less its approach to each collider a member touches (twice over, for a corner)
        for (int pass = 0; pass < 2; ++pass)
            for (const Contact &c : scratch.contacts)
                if (c.withCollider() && member[std::size_t(c.i)]) {
                    auto v = velocity.col(root(c.i));
                    const double approach = c.normal.dot(v);
                    if (approach < 0.0)
                        v -= approach * c.normal;
                }
        for (int p = 0; p < n; ++p)
            if (member[std::size_t(p)] && model.invMass[p] != 0.0)
                state.velocity.col(p) = velocity.col(root(p));
    }
}

// sequential impulses: the normal impulse towards the target speed, then friction within the cone;
// then the bounces' restitution
void solveVelocities(State &state, ContactScratch &scratch, double restitution)
{
    warmStart(state, scratch);
    for (int iteration = 0; iteration < kVelocityIterations; ++iteration) {
        const bool shock = iteration == kVelocityIterations - 1;
        for (Contact &c : scratch.contacts) {
            const Weights &w = weights(c, shock);
            if (!(w.sum() > 0.0))
                continue;
            const double speed = c.normal.dot(relativeVelocity(state, c));
            const double total = std::max(c.normalImpulse + (c.targetSpeed - speed) * w.mass, 0.0);
            applyImpulse(state, c, w, (total - c.normalImpulse) * c.normal, c.drift);
            c.normalImpulse = total;

            const Eigen::Vector3d slip = slipOf(state, c, scratch.spin);
            Eigen::Vector3d accumulated = c.frictionImpulse - slip * w.tangentMass;
            // (squared: most contacts stick, and then no square root is taken)
            const double hold = c.staticFriction * c.normalImpulse;
            if (accumulated.squaredNorm() > hold * hold)
                accumulated *= c.friction * c.normalImpulse / accumulated.norm();  // sliding: kinetic friction
            applyFriction(state, c, w, accumulated - c.frictionImpulse, c.drift, scratch.spin);
            c.frictionImpulse = accumulated;
            if (scratch.spin)
                resistTurning(state, c, w);
        }
    }
    rebound(state, scratch, restitution);
}

// how far i lies into the surface of the contact's other side, along the current normal
double overlapOf(const Model &model, const State &state, Contact &c)
{
    if (c.withCollider()) {
        const Separation s = separation(model.colliders[std::size_t(c.collider())], state.position.col(c.i), c.side);
        c.normal = s.normal;
        return model.radius[c.i] - s.distance;
    }
    const Eigen::Vector3d d = state.position.col(c.i) - state.position.col(c.j);
    const double distance = d.norm();
    if (apart(distance))
        c.normal = d / distance;
    return model.radius[c.i] + model.radius[c.j] - distance;
}

// the overlaps pushed out, weighted by inverse mass, each followed by friction on the contact's
// displacement along its surface since the sub-step began: while that is within μs times the push
// it is undone (the contact sticks), else it is held back by μk times the push (it slides). Both are
// accumulated and clamped like the impulses, so the iterations converge on one answer
void solvePositions(const Model &model, State &state, ContactScratch &scratch)
{
    for (int iteration = 0; iteration < kPositionIterations; ++iteration) {
        const bool shock = iteration == kPositionIterations - 1;
        for (Contact &c : scratch.contacts) {
            const Weights &w = weights(c, shock);
            if (!(w.sum() > 0.0))
                continue;
            // (a collider's contact is pushed out to the last hair: a wall is never crossed; and a
            // frictionless pair's too, whose pushes hold nothing back, so cannot pump: a
            // frictionless pyramid of 20 rows left its slop sank 4.3 mm at the top)
            const bool pushedOutFully = c.withCollider() || !(c.staticFriction > 0.0 || c.friction > 0.0);
            const double slop = pushedOutFully ? 0.0 : kOverlapSlop * (model.radius[c.i] + model.radius[c.j]);
            const double overlap = overlapOf(model, state, c) - slop;
            if (overlap > 0.0) {
                const double push = overlap * w.mass;
                state.position.col(c.i) += (w.i * push) * c.normal;
                if (!c.withCollider())
                    state.position.col(c.j) -= (w.j * push) * c.normal;
                c.pushed += push;
            }
            if (!(c.pushed > 0.0))
                continue;
            Eigen::Vector3d moved = state.position.col(c.i) - scratch.startPosition.col(c.i);
            if (!c.withCollider())
                moved -= state.position.col(c.j) - scratch.startPosition.col(c.j);
            Eigen::Vector3d slide = moved - c.normal.dot(moved) * c.normal;
            // with spin, the points of contact's: a ball rolling along does not slide
            if (scratch.spin)
                slide += scratch.subStep * spinSlip(c.weights.levers, state.angularVelocity.col(c.i),
                                                    spinOfJ(state, c), c.normal);
            Eigen::Vector3d held = c.heldBack + slide * w.mass;
            const double hold = c.staticFriction * c.pushed;
            c.stuck = !(held.squaredNorm() > hold * hold);
            if (!c.stuck)
                held *= c.friction * c.pushed / held.norm();
            const Eigen::Vector3d correction = held - c.heldBack;
            state.position.col(c.i) -= w.i * correction;
            if (!c.withCollider())
                state.position.col(c.j) += w.j * correction;
            c.heldBack = held;
        }
    }
}

// the colliders have the last word: a particle the solve moved (a pair may push it into a collider
// it was clear of when the contacts were gathered) is put back on every collider's surface, so a
// wall or a floor is never crossed, however the pairs are packed (they may overlap a little)
void keepOutOfColliders(const Model &model, State &state, ContactScratch &scratch)
{
    const auto keepOut = [&](int p) {
        for (const Collider &collider : model.colliders) {
            const Separation s =
                separation(collider, state.position.col(p), sideOf(collider, scratch.sidePointOf(p)));
            if (s.distance < model.radius[p])
                state.position.col(p) += (model.radius[p] - s.distance) * s.normal;
        }
    };
    for (const Contact &c : scratch.contacts) {
        keepOut(c.i);
        if (!c.withCollider() && model.invMass[c.j] != 0.0)
            keepOut(c.j);
    }
}

// a contact whose position stuck moves as one along its surface: the slip left in the velocities
// (the velocity solve's cone is set by the impulses, which a pile's weight need not reach) is taken
// out, so that what stays put also stands still
// With spin, a stuck contact whose rolling resistance held (short of its bound) stops rolling too:
// both the slip s and the two sides' turning across it ρ are taken out at once, by a surface impulse
// J and an angular one L. With T the sliding's inverse mass, A = a_i + a_j and c = a_i r_i − a_j r_j,
// they change s by T J + c n × L and ρ by A L − c n × J, so J = (−s + (c/A) n × ρ) / (T − c²/A)
// and L = (−ρ + c n × J) / A (for a ball on a floor T − c²/A = 1/m: it stands as if welded).
// Taking them out one after the other left a ball on a slope creeping 2.4 mm/s.
bool stopRolling(State &state, const Contact &c, const Weights &w)
{
    const ContactLevers &l = w.levers;
    const double bound = c.rollingFriction * c.normalImpulse * rollingRadius(c.weights.levers);
    const double a = l.ai + l.aj;
    if (!(c.rollingFriction > 0.0) || !(a > 0.0) || !(c.rollingImpulse.norm() < bound))
        return false;
    const double coupling = l.ai * l.ri - l.aj * l.rj;
    const double mass = w.sum() + l.turning() - coupling * coupling / a;
    if (!(mass > 1e-12 * (w.sum() + l.turning())))
        return false;
    const Eigen::Vector3d slip = slipOf(state, c, true);
    const Eigen::Vector3d turning = state.angularVelocity.col(c.i) - spinOfJ(state, c);
    const Eigen::Vector3d rolling = turning - c.normal.dot(turning) * c.normal;
    const Eigen::Vector3d impulse = (-slip + (coupling / a) * c.normal.cross(rolling)) / mass;
    const Eigen::Vector3d angular = (-rolling + coupling * c.normal.cross(impulse)) / a;
    // only while both stay within their bounds: else it slides or rolls, as the iterations left it
    const double hold = c.staticFriction * c.normalImpulse;
    if (!((c.frictionImpulse + impulse).squaredNorm() <= hold * hold) ||
        !((c.rollingImpulse + angular).squaredNorm() <= bound * bound))
        return false;
    applyFriction(state, c, w, impulse, c.drift, true);  // (the sub-step's end too, as every impulse of the solve)
    state.angularVelocity.col(c.i) += l.ai * angular;
    if (!c.withCollider())
        state.angularVelocity.col(c.j) -= l.aj * angular;
    return true;
}

// with spin, after the velocity iterations: each resting contact that rolling resistance holds stops
// rolling and slipping at once (stopRolling), which 8 iterations from a cold start leave creeping
void holdRolling(State &state, ContactScratch &scratch)
{
    for (const Contact &c : scratch.contacts)
        if (!c.bounce && c.normalImpulse > 0.0 && c.rollingFriction > 0.0)
            stopRolling(state, c, weights(c, false));
}

void stopStuckSlip(State &state, ContactScratch &scratch)
{
    for (const Contact &c : scratch.contacts) {
        if (!c.stuck)
            continue;
        const Weights &w = weights(c, false);
        if (!(w.sum() > 0.0))
            continue;
        if (scratch.spin && stopRolling(state, c, w))
            continue;
        applyFriction(state, c, w, -slipOf(state, c, scratch.spin) * w.tangentMass, 0.0, scratch.spin);
    }
}

// The solve moves the particles it holds (the velocity solve's drift, the position solve's pushes),
// and may move one into a neighbour it was clear of when the contacts were gathered: a column
// pushed up out of its overlaps into the ball falling onto it ended a sub-step with the two 9 mm
// (21% of their contact distance) inside each other (seed 18445 of the contact invariants). The
// pairs gathered are every pair within the margins m = min(r, reach / 2) of each other, so a pair
// not gathered can overlap at the end only if one of the two moved farther than its margin. Those
// particles that moved farther than it and kUnwatchedMove of their radius are checked against
// every neighbour, and a pair found overlapping is added as a resting contact; true when there are
// such pairs, for the positions to be solved again. (In a still pile nothing moves that far, and
// this costs one pass over the contacts.)
bool gatherNewOverlaps(const Model &model, const State &state, Workspace &work)
{
    ContactScratch &scratch = work.contactSolver;
    if (!model.plan.particleCollisions || scratch.gatherPosition.cols() != state.position.cols())
        return false;
    const int n = model.particleCount();
    const double reach = model.restingSpeed * scratch.subStep;
    scratch.movedFar.resize(std::size_t(n), 0);
    scratch.movers.clear();
    const auto check = [&](int p) {
        if (scratch.movedFar[std::size_t(p)])
            return;
        const double r = model.radius[p];
        const double allowed = std::min(r, 0.5 * reach) + kUnwatchedMove * r;
        if ((state.position.col(p) - scratch.gatherPosition.col(p)).squaredNorm() > allowed * allowed) {
            scratch.movedFar[std::size_t(p)] = 1;
            scratch.movers.push_back(p);
        }
    };
    for (const Contact &c : scratch.contacts) {
        check(c.i);
        if (!c.withCollider())
            check(c.j);
    }
    if (scratch.movers.empty())
        return false;
    std::sort(scratch.movers.begin(), scratch.movers.end());  // (the order the pairs are added in)

    const auto key = [n](int a, int b) { return std::uint64_t(std::min(a, b)) * std::uint64_t(n) + std::uint64_t(std::max(a, b)); };
    scratch.pairKeys.clear();
    for (const Contact &c : scratch.contacts)
        if (!c.withCollider())
            scratch.pairKeys.push_back(key(c.i, c.j));
    std::sort(scratch.pairKeys.begin(), scratch.pairKeys.end());
    const std::size_t before = scratch.contacts.size();
    const auto addIfNew = [&](int a, int b) {
        const Eigen::Vector3d d = state.position.col(a) - state.position.col(b);
        const double distance = d.norm();
        if (!(distance < model.radius[a] + model.radius[b]) || (model.invMass[a] == 0.0 && model.invMass[b] == 0.0) ||
            std::binary_search(scratch.pairKeys.begin(), scratch.pairKeys.end(), key(a, b)))
            return;
        // i the free one, as gather has it
        const bool swap = model.invMass[a] == 0.0;
        Contact c;
        c.i = swap ? b : a;
        c.j = swap ? a : b;
        c.normal = apart(distance) ? Eigen::Vector3d((swap ? -d : d) / distance) : coincidentAxis(c.i, c.j);
        c.friction = model.friction;
        c.staticFriction = model.staticFriction;
        c.rollingFriction = model.rollingFriction;
        c.spinningFriction = model.spinningFriction;
        c.drift = scratch.drift;
        scratch.contacts.push_back(c);
    };
    // a few movers are each tested against every particle; past that one broad phase over the
    // scene is cheaper
    const auto tests = std::uint64_t(scratch.movers.size()) * std::uint64_t(n);
    ContactGrid &grid = work.contacts;
    if (tests <= std::uint64_t(16) * std::uint64_t(n) + 65536 || grid.bruteForce) {
        for (int p : scratch.movers)
            for (int q = 0; q < n; ++q)
                if (q != p && !(scratch.movedFar[std::size_t(q)] && q < p))  // a pair of movers once
                    addIfNew(p, q);
    } else {
        findContacts(model, state.position, grid);
        for (const ContactPair &pair : grid.pairs)
            if (scratch.movedFar[std::size_t(pair.i)] || scratch.movedFar[std::size_t(pair.j)])
                addIfNew(pair.i, pair.j);
    }
    for (int p : scratch.movers)
        scratch.movedFar[std::size_t(p)] = 0;
    scratch.overlapsCaught += scratch.contacts.size() - before;
    return scratch.contacts.size() > before;
}

}  // namespace

void solveRestingContacts(const Model &model, State &state, Workspace &work, double h)
{
    ContactScratch &scratch = work.contactSolver;
    scratch.drift = driftWeight(pathShape(model.integrator)) * h;
    scratch.subStep = h;
    scratch.spin = model.plan.spin;
    // (the stages of 10⁶ particles take tens of milliseconds each: a waiting Pause stops between
    // them, and inside gather around its broad phase)
    gather(model, state, work, h);
    if (work.interrupted)
        return;
    if (model.plan.particleCollisions)
        scratch.gatherPosition = state.position;
    if (scratch.contacts.empty()) {
        state.contactImpulses.clear();
        return;
    }
    if (stopsHere(work))
        return;
    sortByLevel(model, scratch);
    setWeights(model, scratch);
    if (stopsHere(work))
        return;
    solveVelocities(state, scratch, model.restitution);
    if (scratch.spin)
        holdRolling(state, scratch);
    stopClosingContacts(model, state, scratch, h);
    keepImpulses(state, scratch);
    if (stopsHere(work))
        return;
    solvePositions(model, state, scratch);
    keepOutOfColliders(model, state, scratch);
    // the pairs the solve pushed together, solved with the rest, as far as the pushes carry
    for (int round = 0; round < kOverlapRounds && gatherNewOverlaps(model, state, work); ++round) {
        sortByLevel(model, scratch);
        setWeights(model, scratch);
        solvePositions(model, state, scratch);
        keepOutOfColliders(model, state, scratch);
    }
    stopStuckSlip(state, scratch);
}

}  // namespace core
