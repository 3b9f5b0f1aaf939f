// Impacts located in time: a particle that was clear of a collider or of another particle at the
// start of the sub-step and meets it during the sub-step is stopped at the moment they touch, found
// along both paths (particle_path.h) by conservative advancement. The impulse with restitution and
// friction is applied there, and the particle goes on for the rest of the sub-step with its new
// velocity. A bounce then loses or gains nothing the integrator would not, and a pair 4 m apart
// closing at 400 m/s still meets: nothing passes through anything in one sub-step.

#include "core/contacts/broad_phase.h"
#include "core/contacts/particle_path.h"
#include "core/passes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace core {

namespace {

// the path of particle i through the sub-step (a pinned particle rests where it is)
ParticlePath pathOf(const Model &model, const State &state, const ContactScratch &scratch, int i, double h)
{
    return ParticlePath{pathShape(model.integrator), scratch.startPosition.col(i), scratch.startVelocity.col(i),
                        state.position.col(i), state.velocity.col(i), h};
}

// how far a particle's path strays from the straight line between its ends: none for the Euler
// schemes; for a Hermite curve h · 4/27 · (|v0 - v̄| + |v1 - v̄|), v̄ the mean velocity, since the
// curve less its chord is h (s(1 - s)² (v0 - v̄) - s²(1 - s) (v1 - v̄)) at s = t / h
double bulge(const Model &model, const State &state, const ContactScratch &scratch, int i, double h)
{
    if (pathShape(model.integrator) != PathShape::Hermite)
        return 0.0;
    const Eigen::Vector3d mean = (state.position.col(i) - scratch.startPosition.col(i)) / h;
    return h * (4.0 / 27.0) *
           ((scratch.startVelocity.col(i) - mean).norm() + (Eigen::Vector3d(state.velocity.col(i)) - mean).norm());
}

// the first time in [0, h] at which gap(t) ≤ 0, or none: the gap (the distance less the contact
// distance) shrinks no faster than `speed`, so advancing by gap / speed never steps over it
template <typename Gap>
std::optional<double> firstTouch(const Gap &gap, double speed, double h, double contactDistance)
{
    const double close = 1e-12 * contactDistance;  // m: touching, to the precision of the positions
    double t = 0.0;
    double g = gap(t);
    for (int iteration = 0; iteration < 64; ++iteration) {
        if (g <= close)
            return t;
        if (!(speed > 0.0))
            return std::nullopt;
        t += g / speed;
        if (!(t <= h))
            return std::nullopt;
        g = gap(t);
    }
    // a grazing path closes ever more slowly: near enough counts as touching
    return g <= 1e-6 * contactDistance ? std::optional<double>(t) : std::nullopt;
}

// the impacts of the free particles with the colliders
void collidersAlongPaths(const Model &model, const State &state, ContactScratch &scratch, double h)
{
    for (int i : model.freeParticles) {
        const double r = model.radius[i];
        const auto x0 = scratch.startPosition.col(i);
        const auto x1 = state.position.col(i);
        for (int k = 0; k < static_cast<int>(model.colliders.size()); ++k) {
            const Collider &c = model.colliders[std::size_t(k)];
            const double side = sideOf(c, x0);
            if (!(separation(c, x0, side).distance > r))
                continue;  // touching from the start: a resting contact, or not finite
            const bool crossed = c.twoSided && sideOf(c, x1) != side;
            if (!(separation(c, x1, side).distance <= r || crossed))
                continue;  // clear at both ends, and on the same side
            const ParticlePath path = pathOf(model, state, scratch, i, h);
            const auto gap = [&](double t) { return separation(c, path.position(t), side).distance - r; };
            const std::optional<double> t = firstTouch(gap, path.speedBound(), h, r);
            if (!t)
                continue;  // passed the rectangle's edge
            const Separation s = separation(c, path.position(*t), side);
            if (-s.normal.dot(path.velocity(*t)) > restingThreshold(model, s.normal))
                scratch.impacts.push_back({*t, i, -1 - k});
        }
    }
}

// one candidate pair: an impact if the two were apart at the start, their chords come within reach
// of each other, and conservative advancement along their paths finds them touching faster than a
// resting contact
void pairAlongPaths(const Model &model, const State &state, ContactScratch &scratch, int i, int j, double h)
{
    if (model.invMass[i] == 0.0 && model.invMass[j] == 0.0)
        return;
    const double contact = model.radius[i] + model.radius[j];
    const Eigen::Vector3d d0 = scratch.startPosition.col(i) - scratch.startPosition.col(j);
    if (!(d0.squaredNorm() > contact * contact))
        return;  // touching from the start: a resting contact (or not finite)
    // the chords of the two paths: clear of each other all along them by more than the paths can
    // bulge, they cannot meet
    const Eigen::Vector3d d1 = state.position.col(i) - state.position.col(j);
    const Eigen::Vector3d chord = d1 - d0;
    const double along = chord.squaredNorm() > 0.0 ? std::clamp(-d0.dot(chord) / chord.squaredNorm(), 0.0, 1.0) : 0.0;
    if (!((d0 + along * chord).norm() <= contact + bulge(model, state, scratch, i, h) + bulge(model, state, scratch, j, h)))
        return;
    const ParticlePath a = pathOf(model, state, scratch, i, h);
    const ParticlePath b = pathOf(model, state, scratch, j, h);
    // i relative to j: a path of the same shape, since a path is linear in its ends' positions and
    // velocities. Its speed bound is the bound on how fast the gap can close, which for neighbours
    // moving together is far less than the sum of their speeds, so conservative advancement takes
    // few steps where the sum would take dozens
    const ParticlePath relative{a.shape, a.x0 - b.x0, a.v0 - b.v0, a.x1 - b.x1, a.v1 - b.v1, h};
    const auto gap = [&](double t) { return relative.position(t).norm() - contact; };
    const std::optional<double> t = firstTouch(gap, relative.speedBound(), h, contact);
    if (!t)
        return;
    const Eigen::Vector3d normal = (a.position(*t) - b.position(*t)).normalized();
    if (-normal.dot(a.velocity(*t) - b.velocity(*t)) > restingThreshold(model, normal))
        scratch.impacts.push_back({*t, i, j});
}

// the impacts of pairs. A particle that moves less than a few radii in the sub-step goes into the
// broad phase as a sphere about its path's midpoint holding the whole path; a faster one stays out
// of it (its sphere would make every particle its neighbour, and the grid quadratic) and has its
// chord checked against every particle instead, which stores nothing
void pairsAlongPaths(const Model &model, const State &state, Workspace &work, double h)
{
    constexpr double kFast = 4.0;  // radii moved in a sub-step past which a particle is fast
    ContactScratch &scratch = work.contactSolver;
    const int n = model.particleCount();
    scratch.sweptCentre.resize(3, n);
    scratch.sweptRadius.resize(n);
    scratch.fast.clear();
    scratch.isFast.assign(std::size_t(n), 0);
    for (int i = 0; i < n; ++i) {
        const auto x0 = scratch.startPosition.col(i);
        const auto x1 = state.position.col(i);
        const double sweep = 0.5 * (x1 - x0).norm() + bulge(model, state, scratch, i, h);
        if (sweep > kFast * model.radius[i]) {
            scratch.fast.push_back(i);
            scratch.isFast[std::size_t(i)] = 1;
            scratch.sweptCentre.col(i).setConstant(std::numeric_limits<double>::quiet_NaN());  // out of the grid
        } else {
            scratch.sweptCentre.col(i) = 0.5 * (x0 + x1);
        }
        scratch.sweptRadius[i] = model.radius[i] + sweep;
    }
    ContactGrid &grid = work.contacts;
    if (grid.bruteForce)
        findContactsBruteForce(model, scratch.sweptCentre, scratch.sweptRadius, grid.pairs);
    else
        findContacts(model, scratch.sweptCentre, scratch.sweptRadius, grid);
    if (stopsHere(work))
        return;
    for (const ContactPair &pair : grid.pairs)
        pairAlongPaths(model, state, scratch, pair.i, pair.j, h);
    for (int i : scratch.fast)
        for (int j = 0; j < n; ++j)
            if (j != i && !(scratch.isFast[std::size_t(j)] && j < i))
                pairAlongPaths(model, state, scratch, std::min(i, j), std::max(i, j), h);
}

// the impulse of one impact at its time: restitution along the normal, Coulomb friction across it
// (sticking while μs times the normal impulse can stop the sliding, else μk times it)
void impulseAt(const Model &model, const Eigen::Vector3d &normal, double friction, double staticFriction, double wi,
               double wj, Eigen::Vector3d &vi, Eigen::Vector3d &vj)
{
    const double w = wi + wj;
    const Eigen::Vector3d relative = vi - vj;
    const double approach = normal.dot(relative);
    const double jn = -(1.0 + model.restitution) * approach / w;
    const Eigen::Vector3d slip = relative - approach * normal;
    const double slipSpeed = slip.norm();
    double jt = 0.0;
    if (slipSpeed > 0.0) {
        const double stop = slipSpeed / w;
        jt = stop <= staticFriction * jn ? stop : std::min(stop, friction * jn);
    }
    const Eigen::Vector3d impulse = jn * normal - (slipSpeed > 0.0 ? Eigen::Vector3d(jt / slipSpeed * slip)
                                                                  : Eigen::Vector3d::Zero());
    vi += wi * impulse;
    vj -= wj * impulse;
}

// the speed an Euler scheme's particle leaves a collider with. Under gravity alone the Euler
// schemes keep not the energy but a quantity of their own, Q = ½ v² + g s ∓ ½ g h v (v and s the
// speed and the distance along the normal, g the gravity towards the collider; − for symplectic and
// implicit Euler, + for explicit Euler). A rebound at the speed it came in with changes Q by
// g u (h − 2t), t the impact's time in the sub-step, so a ball with e = 1 would bounce up to a few
// per cent higher or lower by where in its sub-step the floor came. Leaving at the speed v that
// keeps Q, scaled by e² as the energy is, puts it back on the flight it came from: u the speed it
// came in with along its straight path, c = g (h/2 − t), ½ v² + c v = e² (½ u² − c u). Between two
// particles gravity pulls both alike and adds nothing to their relative motion, so it is only here
double eulerRebound(const Model &model, const Eigen::Vector3d &normal, double approach, double t, double h)
{
    const double e2 = model.restitution * model.restitution;
    if (e2 == 0.0)
        return 0.0;  // fully inelastic: it stays, as with any other scheme
    const double towards = -model.gravity.dot(normal);
    const double c = towards * (0.5 * h - t);
    return std::max(-c + std::sqrt(std::max(c * c + e2 * (approach * approach - 2.0 * c * approach), 0.0)), 0.0);
}

// one impact: both particles taken to its time along their paths, the impulse, then on to the
// sub-step's end with the new velocities and the acceleration they had there
void resolve(const Model &model, State &state, ContactScratch &scratch, const Impact &impact, double h)
{
    const auto goOn = [&](int p, const ParticlePath &path, const Eigen::Vector3d &v) {
        Eigen::Vector3d x, vEnd;
        path.goOn(impact.time, v, x, vEnd);
        state.position.col(p) = x;
        state.velocity.col(p) = vEnd;
        scratch.impacted[std::size_t(p)] = 1;
    };
    const int i = impact.i;
    const ParticlePath a = pathOf(model, state, scratch, i, h);
    Eigen::Vector3d vi = a.velocity(impact.time);
    if (impact.j < 0) {
        const Collider &c = model.colliders[std::size_t(-1 - impact.j)];
        const double side = sideOf(c, scratch.startPosition.col(i));
        const Separation s = separation(c, a.position(impact.time), side);
        const double approach = -s.normal.dot(vi);
        Eigen::Vector3d still = Eigen::Vector3d::Zero();
        impulseAt(model, s.normal, c.friction, c.staticFriction, model.invMass[i], 0.0, vi, still);
        if (a.shape != PathShape::Hermite)
            vi += (eulerRebound(model, s.normal, approach, impact.time, h) - s.normal.dot(vi)) * s.normal;
        goOn(i, a, vi);
        return;
    }
    const int j = impact.j;
    const ParticlePath b = pathOf(model, state, scratch, j, h);
    Eigen::Vector3d vj = b.velocity(impact.time);
    const Eigen::Vector3d normal = (a.position(impact.time) - b.position(impact.time)).normalized();
    impulseAt(model, normal, model.friction, model.staticFriction, model.invMass[i], model.invMass[j], vi, vj);
    goOn(i, a, vi);
    if (model.invMass[j] != 0.0)
        goOn(j, b, vj);
}

}  // namespace

void resolveImpacts(const Model &model, State &state, Workspace &work, double h)
{
    ContactScratch &scratch = work.contactSolver;
    scratch.impacts.clear();
    scratch.impacted.assign(std::size_t(model.particleCount()), 0);
    if (model.plan.planeCollisions)
        collidersAlongPaths(model, state, scratch, h);
    if (model.plan.particleCollisions && !stopsHere(work))
        pairsAlongPaths(model, state, work, h);
    if (stopsHere(work))
        return;

    // in the order they happen; a particle takes part in one impact per sub-step, and any later
    // meeting of its new path is left to the resting contacts
    std::sort(scratch.impacts.begin(), scratch.impacts.end());
    for (const Impact &impact : scratch.impacts) {
        if (scratch.impacted[std::size_t(impact.i)] || (impact.j >= 0 && scratch.impacted[std::size_t(impact.j)]))
            continue;
        resolve(model, state, scratch, impact, h);
        scratch.impactsResolved += 1;
    }
}

}  // namespace core
