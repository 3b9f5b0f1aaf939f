// Impacts located in time: a particle that meets a collider or another particle during the sub-step
// is stopped at the moment they touch, found along both paths (particle_path.h) by conservative
// advancement. The impulse with restitution and friction is applied there, and the particle goes on
// for the rest of the sub-step with its new velocity, on a new path. Every path an impact changed
// is searched again from that moment, against the colliders and its neighbours, so one sub-step
// resolves every impact in the order they happen: a ball struck into a row of touching balls hands
// the impulse on through the row at that instant, each pair an elastic (or, with e < 1, inelastic)
// two-body impact, as the closed form of a Newton's cradle has it; a ball that bounces back meets
// what it bounces into; and a pair 4 m apart closing at 400 m/s still meets. Each impact is a two-body
// impulse, so none adds energy. A sub-step that meets more than kMaxImpactEvents (a jammed crowd of
// elastic balls) leaves the rest to the resting contacts, which brake them, and counts them.

#include "core/contacts/broad_phase.h"
#include "core/contacts/contact_spin.h"
#include "core/contacts/particle_path.h"
#include "core/geometry.h"
#include "core/parallel.h"
#include "core/passes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace core {

namespace {

constexpr double kFast = 4.0;  // radii moved in a sub-step past which a particle is fast (out of the grid)
constexpr int kBroadPhaseRounds = 3;  // broad phases a sub-step, for paths that impacts sent astray
// impacts a sub-step a particle has before its next is a jam (resolveJam); and, times the particle
// count, the most a sub-step resolves
constexpr std::uint64_t kEventsPerParticle = 64;
// impacts after which a touching neighbour closing at any speed joins a jam's zone (resolveJam)
constexpr std::uint64_t kNearlyJammed = kEventsPerParticle * 3 / 4;
constexpr int kCheckAllBelow = 256;  // particles up to which a stray path is checked against all at once

// a particle's path from the start of its current segment: the integrator's whole path, or the rest
// of it after its last impact
struct TimedPath {
    ParticlePath path;
    double start = 0.0;  // s: the time path's t = 0 stands for

    // (a path that begins at the sub-step's end has no length: it stays where it begins)
    Eigen::Vector3d position(double t) const { return path.h > 0.0 ? path.position(t - start) : path.x0; }
    Eigen::Vector3d velocity(double t) const { return path.h > 0.0 ? path.velocity(t - start) : path.v0; }
    double speedBound() const { return path.h > 0.0 ? path.speedBound() : 0.0; }
    // the rest of the path from time t (before its end) to the sub-step's end, as a path of its own
    ParticlePath from(double t) const
    {
        return ParticlePath{path.shape, position(t), velocity(t), path.x1, path.v1, start + path.h - t};
    }
};

TimedPath pathOf(const Model &model, const State &state, const ContactScratch &scratch, int i, double h)
{
    const PathShape shape = pathShape(model.integrator);
    const int segment = scratch.segmentOf[std::size_t(i)];
    if (segment < 0)
        return {ParticlePath{shape, scratch.startPosition.col(i), scratch.startVelocity.col(i), state.position.col(i),
                             state.velocity.col(i), h},
                0.0};
    const PathSegment &s = scratch.segments[std::size_t(segment)];
    return {ParticlePath{shape, s.position, s.velocity, state.position.col(i), state.velocity.col(i), h - s.time}, s.time};
}

// how far a path strays from the straight line between its ends: none for the Euler schemes; for a
// Hermite curve h · 4/27 · (|v0 - v̄| + |v1 - v̄|), v̄ the mean velocity, since the curve less its
// chord is h (s(1 - s)² (v0 - v̄) - s²(1 - s) (v1 - v̄)) at s = t / h
double bulge(const ParticlePath &path)
{
    if (path.shape != PathShape::Hermite || !(path.h > 0.0))
        return 0.0;
    const Eigen::Vector3d mean = (path.x1 - path.x0) / path.h;
    return path.h * (4.0 / 27.0) * ((path.v0 - mean).norm() + (path.v1 - mean).norm());
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
        if (!(speed > 0.0) || !(t < h))
            return std::nullopt;
        // (never past h: a touch at the sub-step's very end, a step of g / speed that rounds a
        // hair over h, is still a touch)
        t = std::min(t + g / speed, h);
        g = gap(t);
    }
    // a grazing path closes ever more slowly: near enough counts as touching
    if (g <= 1e-6 * contactDistance)
        return t;
    // A path that moves far faster across the contact than into it (a ball landing as it rolls at
    // 18 m/s, its gap closing at 0.6) closes only a few per cent of its gap an advancement, and 64
    // of them can end short of the touch: the ball then passed into the floor unseen, and the
    // resting solve bounced it from the sub-step's end (a third of its fall's energy gained, in
    // the invariants' seed 81). Nothing touches before t; where the sub-step ends inside, the touch
    // is found between t and the end by bisection
    // Nor may a path that passes through and out again before the sub-step ends (a ball overtaking
    // another within it) be missed for ending outside: the gap's least value after t is looked for
    // (by golden-section search: the distance along a straight relative path has one minimum, and
    // a Hermite curve's differs from its chord by far less than a radius), and a touch is found
    // between t and there
    double inside = h;
    if (!(gap(h) <= close)) {
        constexpr double kGolden = 0.6180339887498949;
        double lo = t, hi = h;
        double a = hi - kGolden * (hi - lo), b = lo + kGolden * (hi - lo);
        double ga = gap(a), gb = gap(b);
        for (int narrowing = 0; narrowing < 96 && ga > close && gb > close && lo < hi; ++narrowing) {
            if (ga < gb) {
                hi = b, b = a, gb = ga;
                a = hi - kGolden * (hi - lo);
                ga = gap(a);
            } else {
                lo = a, a = b, ga = gb;
                b = lo + kGolden * (hi - lo);
                gb = gap(b);
            }
        }
        if (ga <= close)
            inside = a;
        else if (gb <= close)
            inside = b;
        else
            return std::nullopt;
    }
    double outside = t;
    for (int halving = 0; halving < 64 && outside < inside; ++halving) {
        const double middle = 0.5 * (outside + inside);
        if (middle <= outside || middle >= inside)
            break;
        (gap(middle) <= close ? inside : outside) = middle;
    }
    return inside;
}

// how fast two things already touching must close for an impact rather than a resting contact:
// twice what gravity adds to a speed in a sub-step, whatever the direction. A pile's neighbours
// touch and close at the speeds the resting solve leaves them, some of which gravity's pull along
// the pair (zero for a pair side by side) would not cover; those are the resting solve's, not a
// cascade of impacts. A ball struck into a row closes far faster
double touchingThreshold(const Model &model)
{
    return 2.0 * model.gravity.norm() * model.subStep();
}

// the heap's order: std::push_heap keeps the largest on top, so the order is reversed
bool later(const Impact &a, const Impact &b)
{
    return b < a;
}

// an impact found: into the heap of impacts to come (scratch.impacts), or into the list of a
// thread's share of a parallel search, which joinShares() adds to the heap. The heap pops in the
// impacts' total order (time, then particles), so the order they were found in makes no difference
void push(const ContactScratch &scratch, std::vector<Impact> &out, double time, int i, int j)
{
    const std::uint32_t vj = j >= 0 ? scratch.version[std::size_t(j)] : 0;
    out.push_back({time, i, j, scratch.version[std::size_t(i)], vj});
    if (&out == &scratch.impacts)
        std::push_heap(out.begin(), out.end(), later);
}

// the impacts of every thread's share added to the heap
void joinShares(ContactScratch &scratch, int shares)
{
    for (int share = 0; share < shares; ++share) {
        const std::vector<Impact> &found = scratch.impactShares[std::size_t(share)];
        scratch.impacts.insert(scratch.impacts.end(), found.begin(), found.end());
    }
    std::make_heap(scratch.impacts.begin(), scratch.impacts.end(), later);
}

// a share's list for each thread, emptied
int startShares(ContactScratch &scratch, int count)
{
    const int shares = twoPhaseShares(count);
    if (int(scratch.impactShares.size()) < shares)
        scratch.impactShares.resize(std::size_t(shares));
    for (int share = 0; share < shares; ++share)
        scratch.impactShares[std::size_t(share)].clear();
    return shares;
}

// particle i's impacts with each collider from time `from` on, if any: at `from` already where it
// touches the collider there and approaches it faster than a resting contact, else where its path
// meets it. (Its path, and where it is at `from` and at the end, are found once for all colliders:
// a box's walls were each finding them again for every ball)
void colliderImpacts(const Model &model, const State &state, const ContactScratch &scratch, std::vector<Impact> &out,
                     int i, double from, double h)
{
    if (model.colliders.empty())
        return;
    const double r = model.radius[i];
    const TimedPath a = pathOf(model, state, scratch, i, h);
    const double t0 = std::max(from, a.start);
    const Eigen::Vector3d x0 = a.position(t0);
    const Eigen::Vector3d x1 = state.position.col(i);
    const double reach = r + bulge(a.path);
    for (int k = 0; k < static_cast<int>(model.colliders.size()); ++k) {
        const Collider &c = model.colliders[std::size_t(k)];
        // the side it is on at t0: the side it keeps (a two-sided plane is never crossed). Not the
        // side it began the sub-step on: a ball may pass round a table's edge on the way
        const double side = sideOf(c, x0);
        const Separation s0 = separation(c, x0, side);
        if (!(s0.distance > r)) {
            // touching (or not finite): an impact now if it comes in fast, else a resting contact
            if (-s0.normal.dot(a.velocity(t0)) > touchingThreshold(model))
                push(scratch, out, t0, i, -1 - k);
            continue;
        }
        const bool crossed = c.twoSided && sideOf(c, x1) != side;
        if (!(separation(c, x1, side).distance <= reach || crossed))
            continue;  // clear at both ends, and on the same side
        // the distance to the collider, on whichever side the path is: advancing never steps past a
        // touch, so a change of side found on the way is a pass round a rectangle's edge, and a path
        // through the sheet touches it first. (Measured from the side at t0, a ball passing round a
        // table's edge and on over the top was found 0.4 m inside it, struck back from there and
        // left 9 cm inside the ball below: the invariants' seed 72646)
        const auto gap = [&](double t) {
            const Eigen::Vector3d x = a.position(t0 + t);
            return separation(c, x, sideOf(c, x)).distance - r;
        };
        const std::optional<double> t = firstTouch(gap, a.speedBound(), h - t0, r);
        if (!t)
            continue;  // passed the rectangle's edge
        const Eigen::Vector3d x = a.position(t0 + *t);
        const Separation s = separation(c, x, sideOf(c, x));
        if (-s.normal.dot(a.velocity(t0 + *t)) > restingThreshold(model, s.normal))
            push(scratch, out, t0 + *t, i, -1 - k);
    }
}

// one pair from time `from` on: an impact at `from` if they touch then and close faster than a
// resting contact, else where conservative advancement along their paths finds them touching
void pairImpact(const Model &model, const State &state, const ContactScratch &scratch, std::vector<Impact> &out, int i,
                int j, double from, double h)
{
    if (model.invMass[i] == 0.0 && model.invMass[j] == 0.0)
        return;
    if (model.invMass[i] == 0.0)
        std::swap(i, j);  // i the free one, as the impulse reads it
    const TimedPath a = pathOf(model, state, scratch, i, h);
    const TimedPath b = pathOf(model, state, scratch, j, h);
    const double t0 = std::max({from, a.start, b.start});
    const double contact = model.radius[i] + model.radius[j];
    const auto closing = [&](double t, bool touching) {
        const Eigen::Vector3d d = a.position(t) - b.position(t);
        const double distance = d.norm();
        const Eigen::Vector3d normal = apart(distance) ? Eigen::Vector3d(d / distance) : coincidentAxis(i, j);
        return -normal.dot(a.velocity(t) - b.velocity(t)) >
               (touching ? touchingThreshold(model) : restingThreshold(model, normal));
    };
    const Eigen::Vector3d d0 = a.position(t0) - b.position(t0);
    if (!(d0.squaredNorm() > contact * contact)) {
        if (closing(t0, true))  // touching and closing: the impulse passes on now
            push(scratch, out, t0, i, j);
        return;
    }
    // the chords of the two paths from t0: clear of each other all along them by more than the paths
    // can bulge, they cannot meet
    const Eigen::Vector3d d1 = state.position.col(i) - state.position.col(j);
    const Eigen::Vector3d chord = d1 - d0;
    const double along = chord.squaredNorm() > 0.0 ? std::clamp(-d0.dot(chord) / chord.squaredNorm(), 0.0, 1.0) : 0.0;
    if (!((d0 + along * chord).norm() <= contact + bulge(a.path) + bulge(b.path)))
        return;
    std::optional<double> t;
    if (!(h - t0 > 0.0))
        return;
    if (a.start == b.start) {
        // i relative to j: a path of the same shape, since a path is linear in its ends' positions
        // and velocities. Its speed bound is the bound on how fast the gap can close, which for
        // neighbours moving together is far less than the sum of their speeds
        const ParticlePath relative{a.path.shape, a.path.x0 - b.path.x0, a.path.v0 - b.path.v0,
                                    a.path.x1 - b.path.x1, a.path.v1 - b.path.v1, a.path.h};
        const auto gap = [&](double s) { return relative.position(t0 - a.start + s).norm() - contact; };
        t = firstTouch(gap, relative.speedBound(), h - t0, contact);
    } else {
        // paths that began at different times (an impact changed one of them): each taken from t0
        // on as a path of its own (a cubic or a line restricted to part of itself is one of the
        // same kind), and i relative to j from there as above. The sum of their speed bounds
        // instead let a ball at 129 m/s overtake one at 92 unseen: closing at 37 m/s, each
        // advancement took a sixth of the gap, 64 of them ended 0.3 µm short, and at the sub-step's
        // end the two were apart again on the wrong sides (the invariants' seed 4031)
        const ParticlePath pa = a.from(t0), pb = b.from(t0);
        const ParticlePath relative{pa.shape, pa.x0 - pb.x0, pa.v0 - pb.v0, pa.x1 - pb.x1, pa.v1 - pb.v1, h - t0};
        const auto gap = [&](double s) { return relative.position(s).norm() - contact; };
        t = firstTouch(gap, relative.speedBound(), h - t0, contact);
    }
    if (t && closing(t0 + *t, false))
        push(scratch, out, t0 + *t, i, j);
}

// each particle's sphere holding its path through the rest of the sub-step, for the broad phase; a
// particle that moves more than a few radii stays out of the grid (its sphere would make every
// particle its neighbour, and the grid quadratic) and is checked against every particle instead
void sweep(const Model &model, const State &state, ContactScratch &scratch, double h)
{
    const int n = model.particleCount();
    scratch.sweptCentre.resize(3, n);
    scratch.sweptRadius.resize(n);
    scratch.isFast.assign(std::size_t(n), 0);
    // in parallel shares, each listing its fast particles; the lists joined in share order
    const int shares = twoPhaseShares(n);
    if (int(scratch.fastShares.size()) < shares)
        scratch.fastShares.resize(std::size_t(shares));
    parallelShares(n, [&](int share, int begin, int end) {
        std::vector<int> &fast = scratch.fastShares[std::size_t(share)];
        fast.clear();
        for (int i = begin; i < end; ++i) {
            const TimedPath a = pathOf(model, state, scratch, i, h);
            const double reach = 0.5 * (a.path.x1 - a.path.x0).norm() + bulge(a.path);
            if (reach > kFast * model.radius[i]) {
                fast.push_back(i);
                scratch.isFast[std::size_t(i)] = 1;
                scratch.sweptCentre.col(i).setConstant(std::numeric_limits<double>::quiet_NaN());  // out of the grid
            } else {
                scratch.sweptCentre.col(i) = 0.5 * (a.path.x0 + a.path.x1);
            }
            // a hair larger than the path, so that a pair touching exactly (a row of balls placed
            // side by side, a ball that ends its move touching the next) is a candidate: the
            // broad phase counts only overlaps
            scratch.sweptRadius[i] = (model.radius[i] + reach) * (1.0 + 1e-9);
        }
    });
    scratch.fast.clear();
    for (int share = 0; share < shares; ++share)
        scratch.fast.insert(scratch.fast.end(), scratch.fastShares[std::size_t(share)].begin(),
                            scratch.fastShares[std::size_t(share)].end());
}

// the broad phase's pairs as adjacency lists (both ways)
void listCandidates(int n, const std::vector<ContactPair> &pairs, ContactScratch &scratch)
{
    scratch.candidateStart.assign(std::size_t(n) + 1, 0);
    for (const ContactPair &p : pairs) {
        scratch.candidateStart[std::size_t(p.i) + 1] += 1;
        scratch.candidateStart[std::size_t(p.j) + 1] += 1;
    }
    for (int p = 0; p < n; ++p)
        scratch.candidateStart[std::size_t(p) + 1] += scratch.candidateStart[std::size_t(p)];
    scratch.candidates.resize(std::size_t(scratch.candidateStart[std::size_t(n)]));
    std::vector<int> &fill = scratch.queue;  // borrowed as the fill cursor
    fill.assign(scratch.candidateStart.begin(), scratch.candidateStart.end() - 1);
    for (const ContactPair &p : pairs) {
        scratch.candidates[std::size_t(fill[std::size_t(p.i)]++)] = p.j;
        scratch.candidates[std::size_t(fill[std::size_t(p.j)]++)] = p.i;
    }
}

// the broad phase over the paths as they now are, and the impacts of its pairs from `from` on: of
// every pair the first time (strays empty), else of the pairs with a stray in them
void impactsOfPairs(const Model &model, const State &state, Workspace &work, double from, double h)
{
    ContactScratch &scratch = work.contactSolver;
    const int n = model.particleCount();
    sweep(model, state, scratch, h);
    ContactGrid &grid = work.contacts;
    if (grid.bruteForce)
        findContactsBruteForce(model, scratch.sweptCentre, scratch.sweptRadius, grid.pairs);
    else
        findContacts(model, scratch.sweptCentre, scratch.sweptRadius, grid);
    if (stopsHere(work))
        return;
    listCandidates(n, grid.pairs, scratch);
    const bool all = scratch.strays.empty();
    const auto wanted = [&](int i, int j) { return all || scratch.isStray[std::size_t(i)] || scratch.isStray[std::size_t(j)]; };
    // the pairs, and each fast particle against every other, searched in parallel shares
    const int pairs = int(grid.pairs.size());
    const int fast = int(scratch.fast.size());
    const int shares = startShares(scratch, std::max(pairs, fast));
    parallelShares(pairs, [&](int share, int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const ContactPair &pair = grid.pairs[std::size_t(k)];
            if (wanted(pair.i, pair.j))
                pairImpact(model, state, scratch, scratch.impactShares[std::size_t(share)], pair.i, pair.j, from, h);
        }
    });
    parallelShares(fast, [&](int share, int begin, int end) {
        for (int f = begin; f < end; ++f) {
            const int i = scratch.fast[std::size_t(f)];
            for (int j = 0; j < n; ++j)
                if (j != i && !(scratch.isFast[std::size_t(j)] && j < i) && wanted(i, j))
                    pairImpact(model, state, scratch, scratch.impactShares[std::size_t(share)], std::min(i, j),
                               std::max(i, j), from, h);
        }
    });
    joinShares(scratch, shares);
}

// the impulse of one impact at its time: restitution along the normal, Coulomb friction across it
// (sticking while μs times the normal impulse can stop the sliding, else μk times it)
// With spin (`turn`: the levers and both sides' spins), the sliding is that of the points of
// contact, and the friction turns both sides as well (contact_spin.h)
struct ImpactSpin {
    ContactLevers levers;
    Eigen::Vector3d *omegaI = nullptr;
    Eigen::Vector3d *omegaJ = nullptr;
};

void impulseAt(const Model &model, const Eigen::Vector3d &normal, double friction, double staticFriction, double wi,
               double wj, Eigen::Vector3d &vi, Eigen::Vector3d &vj, const ImpactSpin *turn = nullptr)
{
    const double w = wi + wj;
    const Eigen::Vector3d relative = vi - vj;
    const double approach = normal.dot(relative);
    const double jn = -(1.0 + model.restitution) * approach / w;
    Eigen::Vector3d slip = relative - approach * normal;
    double sliding = w;
    if (turn) {
        slip += spinSlip(turn->levers, *turn->omegaI, *turn->omegaJ, normal);
        sliding += turn->levers.turning();
    }
    const double slipSpeed = slip.norm();
    double jt = 0.0;
    if (slipSpeed > 0.0) {
        const double stop = slipSpeed / sliding;
        jt = stop <= staticFriction * jn ? stop : std::min(stop, friction * jn);
    }
    const Eigen::Vector3d surface = slipSpeed > 0.0 ? Eigen::Vector3d(-jt / slipSpeed * slip) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d impulse = jn * normal + surface;
    vi += wi * impulse;
    vj -= wj * impulse;
    if (turn)
        turnBy(turn->levers, normal, surface, *turn->omegaI, *turn->omegaJ);
}

// the spin of an impact of particle i with particle j (j < 0: a collider), where the plan has it
std::optional<ImpactSpin> impactSpin(const Model &model, const State &state, int i, int j, Eigen::Vector3d &omegaI,
                                     Eigen::Vector3d &omegaJ)
{
    if (!model.plan.spin)
        return std::nullopt;
    ImpactSpin turn;
    turn.levers.ri = model.radius[i];
    turn.levers.ai = model.invInertia[i];
    omegaI = state.angularVelocity.col(i);
    omegaJ.setZero();
    if (j >= 0) {
        turn.levers.rj = model.radius[j];
        turn.levers.aj = model.invInertia[j];
        omegaJ = state.angularVelocity.col(j);
    }
    turn.omegaI = &omegaI;
    turn.omegaJ = &omegaJ;
    return turn;
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

// particle p's path changed at time t to velocity v: on to the sub-step's end along the same kind
// of motion, a new segment from t, and every impact found on its old path stale
void redirect(ContactScratch &scratch, State &state, int p, const TimedPath &path, double t, const Eigen::Vector3d &v)
{
    Eigen::Vector3d x = path.position(t), vEnd = v;
    const Eigen::Vector3d at = x;
    // an impact at the sub-step's very end leaves a path of no length: it ends where it is, with
    // the new velocity (a Hermite curve a few ulps long would read its velocity from rounding)
    const double end = path.start + path.path.h;
    if (end - t > 1e-9 * path.path.h)
        path.path.goOn(t - path.start, v, x, vEnd);
    else
        t = end;
    state.position.col(p) = x;
    state.velocity.col(p) = vEnd;
    int &segment = scratch.segmentOf[std::size_t(p)];
    if (segment < 0) {
        segment = int(scratch.segments.size());
        scratch.segments.push_back(PathSegment{t, at, v});
    } else {
        scratch.segments[std::size_t(segment)] = PathSegment{t, at, v};
    }
    scratch.version[std::size_t(p)] += 1;
}

// one impact: both particles taken to its time along their paths, the impulse, then on to the
// sub-step's end with the new velocities and the acceleration they had there
void resolve(const Model &model, State &state, ContactScratch &scratch, const Impact &impact, double h)
{
    const int i = impact.i;
    const TimedPath a = pathOf(model, state, scratch, i, h);
    Eigen::Vector3d vi = a.velocity(impact.time);
    if (impact.j < 0) {
        const Collider &c = model.colliders[std::size_t(-1 - impact.j)];
        const Eigen::Vector3d x = a.position(impact.time);
        const Separation s = separation(c, x, sideOf(c, x));  // (touching: on the side it came from)
        const double approach = -s.normal.dot(vi);
        Eigen::Vector3d still = Eigen::Vector3d::Zero();
        Eigen::Vector3d omegaI, omegaJ;
        const std::optional<ImpactSpin> turn = impactSpin(model, state, i, -1, omegaI, omegaJ);
        impulseAt(model, s.normal, c.friction, c.staticFriction, model.invMass[i], 0.0, vi, still, turn ? &*turn : nullptr);
        if (turn)
            state.angularVelocity.col(i) = omegaI;
        if (a.path.shape != PathShape::Hermite)
            vi += (eulerRebound(model, s.normal, approach, impact.time, h) - s.normal.dot(vi)) * s.normal;
        redirect(scratch, state, i, a, impact.time, vi);
        return;
    }
    const int j = impact.j;
    const TimedPath b = pathOf(model, state, scratch, j, h);
    Eigen::Vector3d vj = b.velocity(impact.time);
    const Eigen::Vector3d d = a.position(impact.time) - b.position(impact.time);
    const double distance = d.norm();
    const Eigen::Vector3d normal = apart(distance) ? Eigen::Vector3d(d / distance) : coincidentAxis(i, j);
    Eigen::Vector3d omegaI, omegaJ;
    const std::optional<ImpactSpin> turn = impactSpin(model, state, i, j, omegaI, omegaJ);
    impulseAt(model, normal, model.friction, model.staticFriction, model.invMass[i], model.invMass[j], vi, vj,
              turn ? &*turn : nullptr);
    if (turn) {
        state.angularVelocity.col(i) = omegaI;
        state.angularVelocity.col(j) = omegaJ;
    }
    redirect(scratch, state, i, a, impact.time, vi);
    if (model.invMass[j] != 0.0)
        redirect(scratch, state, j, b, impact.time, vj);
}

// whether particle p's new path still lies in the sphere the broad phase held its old one in, so
// that its candidates are all it can meet
bool withinItsSphere(const Model &model, const ContactScratch &scratch, int p, const TimedPath &a)
{
    if (scratch.isFast[std::size_t(p)])
        return true;  // checked against every particle
    const double room = scratch.sweptRadius[p] - model.radius[p] - bulge(a.path);
    const auto centre = scratch.sweptCentre.col(p);
    return (a.path.x0 - centre).norm() <= room && (a.path.x1 - centre).norm() <= room;
}

// the impacts of particle p's new path from time t: with the colliders, and with its candidates
void impactsOf(const Model &model, const State &state, ContactScratch &scratch, int p, double t, double h)
{
    if (model.invMass[p] == 0.0)
        return;
    if (model.plan.planeCollisions)
        colliderImpacts(model, state, scratch, scratch.impacts, p, t, h);
    if (!model.plan.particleCollisions)
        return;
    // a fast path, or one an impact sent out of its sphere in a scene small enough, is checked
    // against every particle at once; in a large scene a stray waits for the next broad phase
    const TimedPath a = pathOf(model, state, scratch, p, h);
    const bool stray = !scratch.isFast[std::size_t(p)] && !withinItsSphere(model, scratch, p, a);
    const bool small = model.particleCount() <= kCheckAllBelow;
    if (scratch.isFast[std::size_t(p)] || (stray && small)) {
        // a stray is no longer in the candidates of those it may now meet: marked, so that their
        // later new paths are checked against it too
        if (stray)
            scratch.isStray[std::size_t(p)] = 1;
        // (a sphere about p's new path first: most particles are nowhere near it)
        const Eigen::Vector3d centre = 0.5 * (a.path.x0 + a.path.x1);
        const double reach = model.radius[p] + 0.5 * (a.path.x1 - a.path.x0).norm() + bulge(a.path);
        for (int q = 0; q < model.particleCount(); ++q) {
            if (q == p)
                continue;
            // (a particle still on the path the broad phase swept is within its sphere)
            if (!scratch.isFast[std::size_t(q)] && scratch.segmentOf[std::size_t(q)] < 0 &&
                (scratch.sweptCentre.col(q) - centre).norm() > reach + scratch.sweptRadius[q])
                continue;
            pairImpact(model, state, scratch, scratch.impacts, std::min(p, q), std::max(p, q), t, h);
        }
    } else {
        for (int e = scratch.candidateStart[std::size_t(p)]; e < scratch.candidateStart[std::size_t(p) + 1]; ++e) {
            const int q = scratch.candidates[std::size_t(e)];
            pairImpact(model, state, scratch, scratch.impacts, std::min(p, q), std::max(p, q), t, h);
        }
        // a fast particle is out of the grid, so in no one's candidates: its impact with p, found
        // on p's old path, is stale now and must be looked for again on the new one (a ball at
        // 95 m/s passed through the one ahead of it once that one's path changed)
        for (int q : scratch.fast)
            if (q != p)
                pairImpact(model, state, scratch, scratch.impacts, std::min(p, q), std::max(p, q), t, h);
        // and likewise the strays of a small scene (in a large one the next broad phase finds
        // them): a ball squeezed out of its sphere by one neighbour met another whose new path
        // stayed in its own, and they passed through each other
        if (small)
            for (int q = 0; q < model.particleCount(); ++q)
                if (q != p && scratch.isStray[std::size_t(q)])
                    pairImpact(model, state, scratch, scratch.impacts, std::min(p, q), std::max(p, q), t, h);
        if (stray && !scratch.isStray[std::size_t(p)]) {
            scratch.isStray[std::size_t(p)] = 1;
            scratch.strays.push_back(p);
        }
    }
}

// the particles p can meet from time t: its candidates and the fast ones, or every particle in a
// small scene or when p is fast or a stray
template <typename Visit>
void forEachNear(const Model &model, const ContactScratch &scratch, int p, const Visit &visit)
{
    if (scratch.isFast[std::size_t(p)] || scratch.isStray[std::size_t(p)] || model.particleCount() <= kCheckAllBelow) {
        for (int q = 0; q < model.particleCount(); ++q)
            if (q != p)
                visit(q);
        return;
    }
    for (int e = scratch.candidateStart[std::size_t(p)]; e < scratch.candidateStart[std::size_t(p) + 1]; ++e)
        visit(scratch.candidates[std::size_t(e)]);
    for (int q : scratch.fast)
        if (q != p)
            visit(q);
}

// a jam: an impact of a particle that has had kEventsPerParticle already this sub-step (a row
// crushed between a heavy ball and a wall, where each two-body impact leaves the next pair closing
// and the impacts would go on without end). Rigid impact zones (Bridson, Fedkiw and Anderson 2002)
// end it: the impact's particles and every particle touching one of them and closing on it at that
// moment go on as one from it, at their mass-weighted mean velocity (momentum kept, kinetic
// energy never gained; still if a member is pinned); where a member touches a collider the zone
// rebounds from it as one body, at e times its approach (so its kinetic energy at most e² times
// what it had); the zone grows until nothing touching closes on it. Nothing in it can then pass
// through anything else in it; what it meets later is found as any other impact
void resolveJam(const Model &model, State &state, ContactScratch &scratch, const Impact &impact, double h)
{
    const double t = impact.time;
    std::vector<int> &members = scratch.zoneMembers;
    std::vector<std::uint8_t> &inZone = scratch.inZone;
    std::vector<int> &pinnedMet = scratch.zonePinnedMet;
    // (inZone is all clear between jams, sized once a sub-step: clearing the whole of it for each
    // jam cost a pass over every particle per jam, which in a large box was most of a jam's time)
    members.assign({impact.i});
    pinnedMet.clear();
    inZone[std::size_t(impact.i)] = 1;
    if (impact.j >= 0 && model.invMass[impact.j] != 0.0) {
        members.push_back(impact.j);
        inZone[std::size_t(impact.j)] = 1;
    }
    bool pinned = impact.j >= 0 && model.invMass[impact.j] == 0.0;
    const auto touches = [&](const Eigen::Vector3d &d, double contact) { return d.norm() <= contact * (1.0 + 1e-6); };
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (std::size_t grown = 0; grown <= std::size_t(model.particleCount()); ++grown) {
        // the zone's velocity: its momentum over its mass, less its approach to the colliders
        double mass = 0.0;
        Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
        for (int p : members) {
            const double m = 1.0 / model.invMass[p];
            momentum += m * pathOf(model, state, scratch, p, h).velocity(t);
            mass += m;
        }
        v = pinned ? Eigen::Vector3d::Zero() : Eigen::Vector3d(momentum / mass);
        if (model.plan.planeCollisions)
            for (int pass = 0; pass < 2; ++pass)
                for (int p : members) {
                    const Eigen::Vector3d x = pathOf(model, state, scratch, p, h).position(t);
                    for (const Collider &c : model.colliders) {
                        const Separation s = separation(c, x, sideOf(c, x));
                        const double approach = s.normal.dot(v);
                        if (!(s.distance <= model.radius[p] * (1.0 + 1e-6) && approach < 0.0))
                            continue;
                        // a zone struck into a collider rebounds from it as one body, with e
                        const bool bounces = -approach > restingThreshold(model, s.normal);
                        v -= (bounces ? 1.0 + model.restitution : 1.0) * approach * s.normal;
                    }
                }
        // the particles touching a member and closing on the zone join it
        bool joined = false;
        if (model.plan.particleCollisions)
            for (std::size_t k = 0; k < members.size(); ++k) {
                const int p = members[k];
                const Eigen::Vector3d x = pathOf(model, state, scratch, p, h).position(t);
                forEachNear(model, scratch, p, [&](int q) {
                    if (inZone[std::size_t(q)])
                        return;
                    const TimedPath b = pathOf(model, state, scratch, q, h);
                    const Eigen::Vector3d d = x - b.position(t);
                    if (!touches(d, model.radius[p] + model.radius[q]))
                        return;
                    const double distance = d.norm();
                    const Eigen::Vector3d normal = apart(distance) ? Eigen::Vector3d(d / distance) : coincidentAxis(p, q);
                    // closing faster than a resting contact (2 |g| h), or at all where the
                    // neighbour is (nearly) jammed too, three quarters of its kEventsPerParticle
                    // impacts spent: else a zone of two balls left a jammed neighbour closing on
                    // it below the threshold yet meeting it as an impact again, then that pair the
                    // next, hundreds of two-ball zones at one instant, each halving what closes,
                    // until the sub-step's events ran out and a row struck by a heavy ball ended
                    // three quarters inside itself. Resting neighbours stay out: a pile's zones
                    // taking in every ball settling on them left a 210-ball pyramid drifting half
                    // again as far. (At the full count rather than three quarters, a struck stack
                    // collapsing between walls left two balls 12 mm inside each other)
                    const bool jammed = scratch.version[std::size_t(q)] >= kNearlyJammed;
                    if (-normal.dot(v - b.velocity(t)) <= (jammed ? 0.0 : touchingThreshold(model)))
                        return;
                    inZone[std::size_t(q)] = 1;
                    if (model.invMass[q] == 0.0) {
                        pinnedMet.push_back(q);
                        pinned = true;
                        return;
                    }
                    members.push_back(q);
                    joined = true;
                });
            }
        if (!joined && !(pinned && !v.isZero()))
            break;
    }
    for (int p : members) {
        redirect(scratch, state, p, pathOf(model, state, scratch, p, h), t, v);
        inZone[std::size_t(p)] = 0;
    }
    for (int p : pinnedMet)
        inZone[std::size_t(p)] = 0;
    scratch.zonesMade += 1;
}

}  // namespace

void resolveImpacts(const Model &model, State &state, Workspace &work, double h)
{
    ContactScratch &scratch = work.contactSolver;
    const int n = model.particleCount();
    scratch.impacts.clear();
    scratch.segments.clear();
    scratch.segmentOf.assign(std::size_t(n), -1);
    scratch.version.assign(std::size_t(n), 0);
    scratch.strays.clear();
    scratch.isStray.assign(std::size_t(n), 0);
    scratch.candidateStart.assign(std::size_t(n) + 1, 0);
    scratch.candidates.clear();
    scratch.isFast.assign(std::size_t(n), 0);
    scratch.inZone.assign(std::size_t(n), 0);
    if (model.plan.planeCollisions) {
        const int free = int(model.freeParticles.size());
        const int shares = startShares(scratch, free);
        parallelShares(free, [&](int share, int begin, int end) {
            std::vector<Impact> &out = scratch.impactShares[std::size_t(share)];
            for (int f = begin; f < end; ++f)
                colliderImpacts(model, state, scratch, out, model.freeParticles[std::size_t(f)], 0.0, h);
        });
        joinShares(scratch, shares);
    }
    if (model.plan.particleCollisions && !stopsHere(work))
        impactsOfPairs(model, state, work, 0.0, h);
    if (stopsHere(work))
        return;

    // in the order they happen; each resolved impact searches the paths it changed again from its
    // time, so the impulse passes on through whatever the particles touch
    const std::uint64_t most = kEventsPerParticle * std::uint64_t(std::max(n, 1));
    std::uint64_t events = 0;
    for (int round = 0;; ++round) {
        while (!scratch.impacts.empty()) {
            // a stop asked for (a Pause, the editor closing an accuracy plan) is heard between two
            // impacts too: a jam's can take seconds. Not a counted stop point (stopAtPoint numbers
            // the stages), and the caller puts the state back as at any other
            if (interruptRequested(work)) {
                work.interrupted = true;
                break;
            }
            std::pop_heap(scratch.impacts.begin(), scratch.impacts.end(), later);
            const Impact impact = scratch.impacts.back();
            scratch.impacts.pop_back();
            if (impact.versionI != scratch.version[std::size_t(impact.i)] ||
                (impact.j >= 0 && impact.versionJ != scratch.version[std::size_t(impact.j)]))
                continue;  // found on a path an earlier impact has changed
            if (events == most) {
                scratch.impactsLeft += 1;
                continue;
            }
            const bool jammed = scratch.version[std::size_t(impact.i)] >= kEventsPerParticle ||
                                (impact.j >= 0 && scratch.version[std::size_t(impact.j)] >= kEventsPerParticle);
            events += 1;
            if (jammed) {
                resolveJam(model, state, scratch, impact, h);
                // (copied: impactsOf may not be handed the list it is filling)
                scratch.zoneQueue.assign(scratch.zoneMembers.begin(), scratch.zoneMembers.end());
                for (int p : scratch.zoneQueue)
                    impactsOf(model, state, scratch, p, impact.time, h);
                continue;
            }
            resolve(model, state, scratch, impact, h);
            scratch.impactsResolved += 1;
            impactsOf(model, state, scratch, impact.i, impact.time, h);
            if (impact.j >= 0)
                impactsOf(model, state, scratch, impact.j, impact.time, h);
        }
        // paths sent out of their spheres: a broad phase over the paths as they now are, for the
        // pairs they are in
        if (scratch.strays.empty() || round + 1 == kBroadPhaseRounds || events == most || stopsHere(work))
            break;
        impactsOfPairs(model, state, work, 0.0, h);
        for (int p : scratch.strays)
            scratch.isStray[std::size_t(p)] = 0;
        scratch.strays.clear();
    }
}

}  // namespace core
