// Collisions with the sheets' triangles (docs/physics.md, "Triangle collisions"), after the contacts
// of each sub-step, with either contact solver. Every particle against every triangle it is not a
// corner of, and every sheet edge against every other edge it shares no particle with, at the
// sheets' thickness, in three parts (after Bridson, Fedkiw and Anderson 2002):
//   1. proximity: pairs that end the sub-step closer than the thickness are pushed apart to it and
//      lose their closing velocity (restitution and Coulomb friction as the other contacts);
//   2. continuous: each pair's straight motion from the sub-step's start to its end is searched for
//      the time it would come within half the thickness (additive conservative advancement,
//      triangle_geometry.h), and an impact found stops the pair's closing motion; repeated on the
//      pairs an answer moved, a few passes;
//   3. the fail-safe: pairs still meeting after those passes are merged into impact zones that move
//      as one (their mean motion, or not at all when one of them is pinned), merged further until
//      no pair meets. Nothing then crosses within the sub-step.
// Impulses act on the sub-step's motion (x1 - x0) and on the end velocity, shared among a
// triangle's corners or an edge's ends by their weights in the closest points and their masses.

#include "core/contacts/triangle_geometry.h"
#include "core/passes.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace core {

namespace {

// continuous passes before the fail-safe
constexpr int kPasses = 4;
// rounds of the fail-safe before it stops every particle (which cannot cross anything)
constexpr int kZoneRounds = 64;
// a box over more grid cells than this is checked against every item instead
constexpr long long kMostCells = 512;

using Vec = Eigen::Vector3d;

// the four particles of a pair, and the distance its features keep
struct PairView {
    PairKind kind = PairKind::PointTriangle;
    std::array<int, 4> v{};
    double distance = 0.0;  // m
};

PairView view(const ClothSurface &surface, const TriangleScratch &s, const TrianglePair &pair)
{
    PairView p;
    if (!pair.edges) {
        p.kind = PairKind::PointTriangle;
        p.v = {pair.a, surface.corners[std::size_t(3 * pair.b)], surface.corners[std::size_t(3 * pair.b + 1)],
               surface.corners[std::size_t(3 * pair.b + 2)]};
        p.distance = s.pointRadius[std::size_t(pair.a)] +
                     0.5 * surface.sheetThickness[std::size_t(surface.triangleSheet[std::size_t(pair.b)])];
    } else {
        p.kind = PairKind::EdgeEdge;
        p.v = {surface.edgeEnds[std::size_t(2 * pair.a)], surface.edgeEnds[std::size_t(2 * pair.a + 1)],
               surface.edgeEnds[std::size_t(2 * pair.b)], surface.edgeEnds[std::size_t(2 * pair.b + 1)]};
        p.distance = 0.5 * (surface.sheetThickness[std::size_t(surface.edgeSheet[std::size_t(pair.a)])] +
                            surface.sheetThickness[std::size_t(surface.edgeSheet[std::size_t(pair.b)])]);
    }
    return p;
}

std::array<Vec, 4> gather(const Eigen::Matrix3Xd &x, const std::array<int, 4> &v)
{
    return {x.col(v[0]), x.col(v[1]), x.col(v[2]), x.col(v[3])};
}

// ---- broad phase: a hashed grid of the swept boxes ------------------------------------------

// cells of an edge `size`, cell (x, y, z) holding floor(p / size)
struct Cells {
    double size = 1.0;
    long long index(double p) const
    {
        const double c = std::floor(p / size);
        return static_cast<long long>(std::clamp(c, -1e15, 1e15));
    }
};

// the cell's coordinates, 21 bits each (modulo 2^21): cells that share a key lie 2^21 cells
// apart, never within one box (a box over more than kMostCells cells is not put in the grid)
std::uint64_t cellKey(long long x, long long y, long long z)
{
    constexpr std::uint64_t mask = (std::uint64_t(1) << 21) - 1;
    return ((std::uint64_t(x) & mask) << 42) | ((std::uint64_t(y) & mask) << 21) | (std::uint64_t(z) & mask);
}

struct CellRange {
    long long lo[3], hi[3];
    long long count() const
    {
        long long c = 1;
        for (int a = 0; a < 3; ++a) {
            const long long span = hi[a] - lo[a] + 1;
            if (span > kMostCells)
                return kMostCells + 1;
            c *= span;
            if (c > kMostCells)
                return kMostCells + 1;
        }
        return c;
    }
};

CellRange rangeOf(const Cells &cells, const Vec &low, const Vec &high)
{
    CellRange r;
    for (int a = 0; a < 3; ++a) {
        r.lo[a] = cells.index(low[a]);
        r.hi[a] = cells.index(high[a]);
    }
    return r;
}

bool overlap(const Vec &aLow, const Vec &aHigh, const Vec &bLow, const Vec &bHigh)
{
    return aLow.x() <= bHigh.x() && bLow.x() <= aHigh.x() && aLow.y() <= bHigh.y() && bLow.y() <= aHigh.y() &&
           aLow.z() <= bHigh.z() && bLow.z() <= aHigh.z();
}

// whether cell (x, y, z) is the one holding the low corner of the two boxes' overlap: a pair met
// in several cells is kept in that one alone
bool firstCell(const Cells &cells, const Vec &aLow, const Vec &bLow, long long x, long long y, long long z)
{
    const Vec corner = aLow.cwiseMax(bLow);
    return cells.index(corner.x()) == x && cells.index(corner.y()) == y && cells.index(corner.z()) == z;
}

void addCells(const Cells &cells, const Vec &low, const Vec &high, int item,
              std::vector<std::pair<std::uint64_t, int>> &entries, std::vector<int> &big)
{
    const CellRange r = rangeOf(cells, low, high);
    if (r.count() > kMostCells) {
        big.push_back(item);
        return;
    }
    for (long long x = r.lo[0]; x <= r.hi[0]; ++x)
        for (long long y = r.lo[1]; y <= r.hi[1]; ++y)
            for (long long z = r.lo[2]; z <= r.hi[2]; ++z)
                entries.emplace_back(cellKey(x, y, z), item);
}

// calls visit(item) for every item whose box overlaps the box low..high, each once: the items of
// `entries` by the grid, the big ones all; a query box over too many cells tries every active item
template <typename Visit>
void query(const Cells &cells, const Vec &low, const Vec &high, const std::vector<std::pair<std::uint64_t, int>> &entries,
           const Eigen::Matrix3Xd &itemLow, const Eigen::Matrix3Xd &itemHigh, const std::vector<std::uint8_t> &active,
           const std::vector<int> &big, Visit &&visit)
{
    const CellRange r = rangeOf(cells, low, high);
    if (r.count() > kMostCells) {
        for (int item = 0; item < int(active.size()); ++item)
            if (active[std::size_t(item)] && overlap(low, high, itemLow.col(item), itemHigh.col(item)))
                visit(item);
        return;
    }
    for (long long x = r.lo[0]; x <= r.hi[0]; ++x)
        for (long long y = r.lo[1]; y <= r.hi[1]; ++y)
            for (long long z = r.lo[2]; z <= r.hi[2]; ++z) {
                const std::uint64_t key = cellKey(x, y, z);
                auto it = std::lower_bound(entries.begin(), entries.end(), std::pair<std::uint64_t, int>{key, -1});
                for (; it != entries.end() && it->first == key; ++it) {
                    const int item = it->second;
                    if (overlap(low, high, itemLow.col(item), itemHigh.col(item)) &&
                        firstCell(cells, low, itemLow.col(item), x, y, z))
                        visit(item);
                }
            }
    for (const int item : big)
        if (overlap(low, high, itemLow.col(item), itemHigh.col(item)))
            visit(item);
}

// the pair's distance at positions x
double pairDistance(const Eigen::Matrix3Xd &x, const PairView &pair)
{
    return std::sqrt(closest(pair.kind, gather(x, pair.v)).squaredDistance);
}

// The candidate pairs: those whose boxes, swept over the sub-step and grown by each particle's
// margin, overlap. They serve the following sub-steps too, as long as every particle stays within
// its margin of the box it was found with (stale()): a sheet at rest finds them once. They are kept
// in one order, by kind and index, so that which sub-step found them changes no answer.
void findCandidates(const Model &model, const ClothSurface &surface, const Eigen::Matrix3Xd &x0,
                    const Eigen::Matrix3Xd &x1, TriangleScratch &s)
{
    const int n = model.particleCount();
    const int triangles = surface.triangleCount();
    const int edges = surface.edgeCount();
    s.built = x1;
    s.builtFor = &surface;
    s.builtActive = s.triangleActive;
    s.builtLow.resize(3, n);
    s.builtHigh.resize(3, n);
    s.particleMargin.resize(std::size_t(n));
    s.pointLow.resize(3, n);
    s.pointHigh.resize(3, n);
    s.triangleLow.resize(3, triangles);
    s.triangleHigh.resize(3, triangles);
    s.edgeLow.resize(3, edges);
    s.edgeHigh.resize(3, edges);
    std::vector<std::uint8_t> &finite = s.finite;
    finite.assign(std::size_t(n), 1);
    for (int i = 0; i < n; ++i) {
        // room for a few sub-steps of the particle's present motion, and at least a thickness
        const double margin = std::max(s.margin, 4.0 * (x1.col(i) - x0.col(i)).norm());
        s.particleMargin[std::size_t(i)] = std::isfinite(margin) ? margin : s.margin;
        s.builtLow.col(i) = x0.col(i).cwiseMin(x1.col(i));
        s.builtHigh.col(i) = x0.col(i).cwiseMax(x1.col(i));
        const double pad = s.pointRadius[std::size_t(i)] + s.particleMargin[std::size_t(i)];
        s.pointLow.col(i) = s.builtLow.col(i).array() - pad;
        s.pointHigh.col(i) = s.builtHigh.col(i).array() + pad;
        finite[std::size_t(i)] = s.pointLow.col(i).allFinite() && s.pointHigh.col(i).allFinite();
    }
    auto featureBox = [&](const int *v, int count, double half, Eigen::Ref<Vec> low, Eigen::Ref<Vec> high) {
        double margin = 0.0;
        low = s.builtLow.col(v[0]);
        high = s.builtHigh.col(v[0]);
        for (int k = 0; k < count; ++k) {
            low = low.cwiseMin(s.builtLow.col(v[k]));
            high = high.cwiseMax(s.builtHigh.col(v[k]));
            margin = std::max(margin, s.particleMargin[std::size_t(v[k])]);
        }
        low.array() -= half + margin;
        high.array() += half + margin;
    };
    double extent = 0.0;
    int counted = 0;
    for (int t = 0; t < triangles; ++t) {
        if (!s.triangleActive[std::size_t(t)])
            continue;
        const double half = 0.5 * surface.sheetThickness[std::size_t(surface.triangleSheet[std::size_t(t)])];
        featureBox(&surface.corners[std::size_t(3 * t)], 3, half, s.triangleLow.col(t), s.triangleHigh.col(t));
        if (s.triangleLow.col(t).allFinite() && s.triangleHigh.col(t).allFinite()) {
            extent += (s.triangleHigh.col(t) - s.triangleLow.col(t)).maxCoeff();
            ++counted;
        }
    }
    for (int e = 0; e < edges; ++e) {
        if (!s.edgeActive[std::size_t(e)])
            continue;
        const double half = 0.5 * surface.sheetThickness[std::size_t(surface.edgeSheet[std::size_t(e)])];
        featureBox(&surface.edgeEnds[std::size_t(2 * e)], 2, half, s.edgeLow.col(e), s.edgeHigh.col(e));
    }
    Cells cells;
    cells.size = counted > 0 && extent > 0.0 ? extent / counted : 1.0;

    s.triangleCells.clear();
    s.bigTriangles.clear();
    for (int t = 0; t < triangles; ++t)
        if (s.triangleActive[std::size_t(t)] && s.triangleLow.col(t).allFinite() && s.triangleHigh.col(t).allFinite())
            addCells(cells, s.triangleLow.col(t), s.triangleHigh.col(t), t, s.triangleCells, s.bigTriangles);
    std::sort(s.triangleCells.begin(), s.triangleCells.end());
    s.edgeCells.clear();
    s.bigEdges.clear();
    for (int e = 0; e < edges; ++e)
        if (s.edgeActive[std::size_t(e)] && s.edgeLow.col(e).allFinite() && s.edgeHigh.col(e).allFinite())
            addCells(cells, s.edgeLow.col(e), s.edgeHigh.col(e), e, s.edgeCells, s.bigEdges);
    std::sort(s.edgeCells.begin(), s.edgeCells.end());

    // room to spare, so that the candidates of a later build (a tear, a fold) seldom allocate
    if (s.candidates.capacity() == 0)
        s.candidates.reserve(std::size_t(4 * (n + edges)));
    s.candidates.clear();
    // particles against triangles
    for (int i = 0; i < n; ++i) {
        if (!finite[std::size_t(i)])
            continue;
        const Vec low = s.pointLow.col(i), high = s.pointHigh.col(i);
        const int sheet = surface.vertexSheet[std::size_t(i)];
        query(cells, low, high, s.triangleCells, s.triangleLow, s.triangleHigh, s.triangleActive, s.bigTriangles, [&](int t) {
            const int *c = &surface.corners[std::size_t(3 * t)];
            if (c[0] == i || c[1] == i || c[2] == i)
                return;
            if (!surface.selfCollision && sheet == surface.triangleSheet[std::size_t(t)])
                return;
            if (model.invMass[i] == 0.0 && model.invMass[c[0]] == 0.0 && model.invMass[c[1]] == 0.0 &&
                model.invMass[c[2]] == 0.0)
                return;
            s.candidates.push_back({false, i, t});
        });
    }
    // edges against edges, each pair once (a < b)
    for (int e = 0; e < edges; ++e) {
        if (!s.edgeActive[std::size_t(e)] || !s.edgeLow.col(e).allFinite() || !s.edgeHigh.col(e).allFinite())
            continue;
        const Vec low = s.edgeLow.col(e), high = s.edgeHigh.col(e);
        const int a0 = surface.edgeEnds[std::size_t(2 * e)], a1 = surface.edgeEnds[std::size_t(2 * e + 1)];
        const int sheet = surface.edgeSheet[std::size_t(e)];
        query(cells, low, high, s.edgeCells, s.edgeLow, s.edgeHigh, s.edgeActive, s.bigEdges, [&](int f) {
            if (f <= e)
                return;
            const int b0 = surface.edgeEnds[std::size_t(2 * f)], b1 = surface.edgeEnds[std::size_t(2 * f + 1)];
            if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1)
                return;
            if (!surface.selfCollision && sheet == surface.edgeSheet[std::size_t(f)])
                return;
            if (model.invMass[a0] == 0.0 && model.invMass[a1] == 0.0 && model.invMass[b0] == 0.0 &&
                model.invMass[b1] == 0.0)
                return;
            s.candidates.push_back({true, e, f});
        });
    }
    std::sort(s.candidates.begin(), s.candidates.end(), [](const TrianglePair &x, const TrianglePair &y) {
        return x.edges != y.edges ? y.edges : x.a != y.a ? x.a < y.a : x.b < y.b;
    });
    // (a pair is met in one cell only; this is a guard)
    s.candidates.erase(std::unique(s.candidates.begin(), s.candidates.end(),
                                   [](const TrianglePair &x, const TrianglePair &y) {
                                       return x.edges == y.edges && x.a == y.a && x.b == y.b;
                                   }),
                       s.candidates.end());
    s.builtDistance.resize(s.candidates.size());
    for (std::size_t c = 0; c < s.candidates.size(); ++c)
        s.builtDistance[c] = pairDistance(x1, view(surface, s, s.candidates[c]));
}

// how far each particle has been from where the candidates were found, at most, during the
// sub-step (its path is the segment from x0 to x1)
void measureReach(const Eigen::Matrix3Xd &x0, const Eigen::Matrix3Xd &x1, TriangleScratch &s)
{
    s.reach.resize(std::size_t(x1.cols()));
    for (int i = 0; i < x1.cols(); ++i)
        s.reach[std::size_t(i)] = std::max((x0.col(i) - s.built.col(i)).norm(), (x1.col(i) - s.built.col(i)).norm());
}

// whether candidate c is certainly farther apart than its distance all through the sub-step: its
// distance where it was found, less how far each of its features can have come since (a feature's
// closest point moves no farther than its farthest corner). Only for pairs no answer has moved in
// this sub-step
bool surelyApart(const TriangleScratch &s, std::size_t c, const PairView &pair)
{
    const auto r = [&](int k) { return s.reach[std::size_t(pair.v[std::size_t(k)])]; };
    const double first = pair.kind == PairKind::PointTriangle ? r(0) : std::max(r(0), r(1));
    const double second = pair.kind == PairKind::PointTriangle ? std::max({r(1), r(2), r(3)}) : std::max(r(2), r(3));
    return s.builtDistance[c] - first - second > pair.distance;
}

// whether a candidate's features are whole (a tear since they were found takes them away)
bool whole(const TriangleScratch &s, const TrianglePair &pair)
{
    return pair.edges ? s.edgeActive[std::size_t(pair.a)] && s.edgeActive[std::size_t(pair.b)]
                      : s.triangleActive[std::size_t(pair.b)] != 0;
}

// ---- responses ---------------------------------------------------------------------------------

// the friction impulse (per unit of the weights' inverse mass) that opposes the tangential
// relative velocity ut under a normal impulse j: all of it while within the static cone, else the
// kinetic coefficient's share
Vec frictionImpulse(const Model &model, const Vec &ut, double j, double weight)
{
    const double speed = ut.norm();
    if (!(speed > 0.0) || !(j > 0.0))
        return Vec::Zero();
    if (speed <= model.staticFriction * j * weight)
        return ut / weight;
    return std::min(model.friction * j, speed / weight) * (ut / speed);
}

struct Weights4 {
    std::array<double, 4> c{};  // the vertices' weights in the relative position
    std::array<double, 4> w{};  // their inverse masses
    double sum = 0.0;           // Σ c² w
};

Weights4 weightsOf(const Model &model, const std::array<int, 4> &v, const std::array<double, 4> &c)
{
    Weights4 k;
    k.c = c;
    for (std::size_t a = 0; a < 4; ++a) {
        k.w[a] = model.invMass[v[a]];
        k.sum += c[a] * c[a] * k.w[a];
    }
    return k;
}

Vec relative(const Eigen::Matrix3Xd &x, const std::array<int, 4> &v, const std::array<double, 4> &c)
{
    return c[0] * x.col(v[0]) + c[1] * x.col(v[1]) + c[2] * x.col(v[2]) + c[3] * x.col(v[3]);
}

void applyMove(Eigen::Matrix3Xd &x1, const std::array<int, 4> &v, const Weights4 &k, const Vec &impulse, double h,
               std::vector<int> &changedAt, int stamp)
{
    for (std::size_t a = 0; a < 4; ++a)
        if (k.w[a] > 0.0 && k.c[a] != 0.0) {
            x1.col(v[a]) += (h * k.c[a] * k.w[a]) * impulse;
            changedAt[std::size_t(v[a])] = stamp;
        }
}

void applyVelocity(Eigen::Matrix3Xd &v1, const std::array<int, 4> &v, const Weights4 &k, const Vec &impulse)
{
    for (std::size_t a = 0; a < 4; ++a)
        if (k.w[a] > 0.0 && k.c[a] != 0.0)
            v1.col(v[a]) += (k.c[a] * k.w[a]) * impulse;
}

// the end velocity after a contact along n that closed at `closing` (< 0, m/s): separating at the
// restitution's share of that speed at least, with friction
void answerVelocity(const Model &model, State &state, const std::array<int, 4> &v, const Weights4 &k, const Vec &n,
                    double closing)
{
    const Vec u = relative(state.velocity, v, k.c);
    const double un = u.dot(n);
    const double target = -contactRestitution(model, closing) * closing;
    if (un >= target)
        return;
    const double j = (target - un) / k.sum;
    const Vec ut = u - un * n;
    applyVelocity(state.velocity, v, k, j * n - frictionImpulse(model, ut, j, k.sum));
}

// a pair closer than its distance at the sub-step's end: pushed apart to it along the line between
// its closest points, its closing velocity taken away (restitution as a contact's)
bool answerProximity(const Model &model, State &state, const Eigen::Matrix3Xd &x0, const PairView &pair,
                     std::vector<int> &changedAt, int stamp, double h)
{
    const std::array<Vec, 4> x = gather(state.position, pair.v);
    const ClosestPoints cp = closest(pair.kind, x);
    if (!(cp.squaredDistance < pair.distance * pair.distance))
        return false;
    const double d = std::sqrt(cp.squaredDistance);
    if (!(d > 1e-12 * pair.distance))
        return false;  // touching: which side is which is the continuous pass's to judge
    const Vec n = relative(state.position, pair.v, cp.weight) / d;
    if (relative(x0, pair.v, cp.weight).dot(n) <= 0.0)
        return false;  // it was on the other side at the start: a crossing, for the continuous pass
    const Weights4 k = weightsOf(model, pair.v, cp.weight);
    if (!(k.sum > 0.0))
        return false;
    // the move: out to the distance, and friction on what the end velocity's closing impulse allows
    const Vec u1 = relative(state.velocity, pair.v, k.c);
    const double closing = std::min(0.0, u1.dot(n));
    const Vec moved = relative(state.position, pair.v, k.c) - relative(x0, pair.v, k.c);
    const Vec tangentialMove = (moved - moved.dot(n) * n) / h;
    const Vec push = ((pair.distance - d) / (h * k.sum)) * n -
                     frictionImpulse(model, tangentialMove, -closing / k.sum, k.sum);
    applyMove(state.position, pair.v, k, push, h, changedAt, stamp);
    answerVelocity(model, state, pair.v, k, n, closing);
    return true;
}

// an impact found at fraction t of the motion: the pair's closing motion along the line between its
// closest points there is stopped for the whole sub-step, its end velocity bounces
bool answerImpact(const Model &model, State &state, const Eigen::Matrix3Xd &x0, const PairView &pair, double t,
                  std::vector<int> &changedAt, int stamp, double h)
{
    std::array<Vec, 4> y;
    for (std::size_t a = 0; a < 4; ++a)
        y[a] = x0.col(pair.v[a]) + t * (state.position.col(pair.v[a]) - x0.col(pair.v[a]));
    const ClosestPoints cp = closest(pair.kind, y);
    const double d = std::sqrt(cp.squaredDistance);
    if (!(d > 0.0))
        return false;
    Vec n = Vec::Zero();
    for (std::size_t a = 0; a < 4; ++a)
        n += cp.weight[a] * y[a];
    n /= d;
    const Weights4 k = weightsOf(model, pair.v, cp.weight);
    if (!(k.sum > 0.0))
        return false;
    const Vec u = (relative(state.position, pair.v, k.c) - relative(x0, pair.v, k.c)) / h;
    const double un = u.dot(n);
    if (!(un < 0.0))
        return false;  // not closing along n: the next pass, or a zone, takes it
    const double j = -un / k.sum;
    const Vec ut = u - un * n;
    applyMove(state.position, pair.v, k, j * n - frictionImpulse(model, ut, j, k.sum), h, changedAt, stamp);
    answerVelocity(model, state, pair.v, k, n, un);
    return true;
}

// the time of impact of a pair on its motion from x0 to the current positions (above 1: none)
double impactTime(const Eigen::Matrix3Xd &x0, const Eigen::Matrix3Xd &x1, const PairView &pair)
{
    const std::array<Vec, 4> start = gather(x0, pair.v);
    const double d0 = std::sqrt(closest(pair.kind, start).squaredDistance);
    if (!(d0 > 1e-12 * pair.distance))
        return 2.0;  // touching at the start: no side to keep
    // half the distance, or half the start's when it began closer: never zero
    const double keep = std::min(0.5 * pair.distance, 0.5 * d0);
    std::array<Vec, 4> d;
    for (std::size_t a = 0; a < 4; ++a)
        d[a] = x1.col(pair.v[a]) - start[a];
    return additiveImpact(pair.kind, start, d, keep, d0 - keep);
}

bool movedSince(const std::vector<int> &changedAt, const std::array<int, 4> &v, int stamp)
{
    return changedAt[std::size_t(v[0])] >= stamp || changedAt[std::size_t(v[1])] >= stamp ||
           changedAt[std::size_t(v[2])] >= stamp || changedAt[std::size_t(v[3])] >= stamp;
}

// whether a particle (every one, or those an answer moved since `stamp`) left its margin about the
// box the candidates were found for
bool stale(const TriangleScratch &s, const Eigen::Matrix3Xd &x1, int stamp, bool every)
{
    for (int i = 0; i < x1.cols(); ++i) {
        if (!every && s.changedAt[std::size_t(i)] < stamp)
            continue;
        const double m = s.particleMargin[std::size_t(i)];
        const Vec p = x1.col(i);
        if (!((p.array() >= s.builtLow.col(i).array() - m).all() && (p.array() <= s.builtHigh.col(i).array() + m).all()))
            return true;
    }
    return false;
}

int zoneRoot(std::vector<int> &zoneOf, int i)
{
    while (zoneOf[std::size_t(i)] != i) {
        zoneOf[std::size_t(i)] = zoneOf[std::size_t(zoneOf[std::size_t(i)])];
        i = zoneOf[std::size_t(i)];
    }
    return i;
}

void joinZone(TriangleScratch &s, const std::array<int, 4> &v)
{
    for (const int i : v)
        if (!s.inZone[std::size_t(i)]) {
            s.inZone[std::size_t(i)] = 1;
            s.zoneMembers.push_back(i);
        }
    for (std::size_t a = 1; a < 4; ++a) {
        const int r = zoneRoot(s.zoneOf, v[0]), q = zoneRoot(s.zoneOf, v[a]);
        if (r != q)
            s.zoneOf[std::size_t(std::max(r, q))] = std::min(r, q);
    }
}

// every zone moves as one: its members' mean motion and velocity by mass, or none when pinned
void moveZones(const Model &model, State &state, TriangleScratch &s, int stamp)
{
    for (const int i : s.zoneMembers) {
        const int r = zoneRoot(s.zoneOf, i);
        s.zoneMass[std::size_t(r)] = 0.0;
        s.zonePinned[std::size_t(r)] = 0;
        s.zoneMove.col(r).setZero();
        s.zoneVelocity.col(r).setZero();
    }
    for (const int i : s.zoneMembers) {
        const int r = zoneRoot(s.zoneOf, i);
        if (model.invMass[i] == 0.0) {
            s.zonePinned[std::size_t(r)] = 1;
            continue;
        }
        const double m = model.mass[i];
        s.zoneMass[std::size_t(r)] += m;
        s.zoneMove.col(r) += m * (state.position.col(i) - s.start.col(i));
        s.zoneVelocity.col(r) += m * state.velocity.col(i);
    }
    for (const int i : s.zoneMembers) {
        if (model.invMass[i] == 0.0)
            continue;
        const int r = zoneRoot(s.zoneOf, i);
        if (s.zonePinned[std::size_t(r)]) {
            state.position.col(i) = s.start.col(i);
            state.velocity.col(i).setZero();
        } else {
            const double m = s.zoneMass[std::size_t(r)];
            state.position.col(i) = s.start.col(i) + s.zoneMove.col(r) / m;
            state.velocity.col(i) = s.zoneVelocity.col(r) / m;
        }
        s.changedAt[std::size_t(i)] = stamp;
    }
}

void activeParts(const Model &model, const State &state, const ClothSurface &surface, TriangleScratch &s)
{
    s.triangleActive.assign(std::size_t(surface.triangleCount()), 1);
    s.edgeActive.assign(std::size_t(surface.edgeCount()), 1);
    s.pointRadius = surface.contactRadius;
    if (!model.plan.springBreaks || state.springBroken.empty())
        return;
    for (int t = 0; t < surface.triangleCount(); ++t)
        for (int side = 0; side < 3; ++side) {
            const int spring = surface.sides[std::size_t(3 * t + side)];
            if (spring >= 0 && state.isBroken(spring))
                s.triangleActive[std::size_t(t)] = 0;
        }
    for (int e = 0; e < surface.edgeCount(); ++e) {
        const int first = surface.edgeTriangles[std::size_t(2 * e)], second = surface.edgeTriangles[std::size_t(2 * e + 1)];
        s.edgeActive[std::size_t(e)] =
            s.triangleActive[std::size_t(first)] || (second >= 0 && s.triangleActive[std::size_t(second)]);
    }
    // a particle whose every triangle has torn away is a sheet's no longer: a ball of its radius,
    // as in the scene stored from this state, which lists none of those triangles
    std::vector<std::uint8_t> &corner = s.inSheet;
    corner.assign(std::size_t(model.particleCount()), 0);
    for (int t = 0; t < surface.triangleCount(); ++t)
        if (s.triangleActive[std::size_t(t)])
            for (int k = 0; k < 3; ++k)
                corner[std::size_t(surface.corners[std::size_t(3 * t + k)])] = 1;
    for (int i = 0; i < model.particleCount(); ++i)
        if (surface.vertexSheet[std::size_t(i)] >= 0 && !corner[std::size_t(i)])
            s.pointRadius[std::size_t(i)] = model.radius[i];
}

}  // namespace

void rememberTriangleStart(const Model &model, const State &state, Workspace &work)
{
    if (model.plan.triangleCollisions)
        work.triangles.start = state.position;
}

void collideTriangles(const Model &model, State &state, Workspace &work)
{
    if (!model.plan.triangleCollisions)
        return;
    const ClothSurface &surface = *model.surface;
    TriangleScratch &s = work.triangles;
    const Eigen::Matrix3Xd &x0 = s.start;
    const double h = model.subStep();
    const int n = model.particleCount();
    s.margin = *std::max_element(surface.sheetThickness.begin(), surface.sheetThickness.end());
    activeParts(model, state, surface, s);
    s.changedAt.assign(std::size_t(n), -1);
    // the candidates of an earlier sub-step while they hold: the same surface, the same whole
    // triangles (a tear changes the particles' contact radii, a restored state may mend one), and
    // every particle within its margin
    const bool rebuild = s.builtFor != &surface || s.built.cols() != n || s.builtActive != s.triangleActive;
    if (rebuild || stale(s, state.position, 0, true)) {
        findCandidates(model, surface, x0, state.position, s);
        ++s.builds;
    }
    measureReach(x0, state.position, s);

    // 1. proximity at the thickness (stamp 0)
    for (std::size_t c = 0; c < s.candidates.size(); ++c) {
        const PairView pair = view(surface, s, s.candidates[c]);
        if (!whole(s, s.candidates[c]) || (!movedSince(s.changedAt, pair.v, 0) && surelyApart(s, c, pair)))
            continue;
        answerProximity(model, state, x0, pair, s.changedAt, 0, h);
    }

    // 2. continuous passes (stamps 1 ..): a pair is searched again once an answer has moved it, or
    // when its last impact went unanswered (not closing along the line of its closest points)
    int stamp = 0;
    bool searchAll = true;
    std::vector<std::uint8_t> &pending = s.pending;
    pending.assign(s.candidates.size(), 0);
    auto search = [&](int since, bool answer) {
        s.impacted.clear();
        for (std::size_t c = 0; c < s.candidates.size(); ++c) {
            const PairView pair = view(surface, s, s.candidates[c]);
            if (!whole(s, s.candidates[c]))
                continue;
            if (!searchAll && !pending[c] && !movedSince(s.changedAt, pair.v, since))
                continue;
            pending[c] = 0;
            if (!movedSince(s.changedAt, pair.v, 0) && surelyApart(s, c, pair))
                continue;
            const double t = impactTime(x0, state.position, pair);
            if (t > 1.0)
                continue;
            s.impacted.push_back(int(c));
            if (answer && answerImpact(model, state, x0, pair, t, s.changedAt, stamp, h))
                ++s.impacts;
            else
                pending[c] = 1;
        }
        searchAll = false;
    };
    auto refresh = [&](int since) {
        if (!stale(s, state.position, since, false))
            return;
        findCandidates(model, surface, x0, state.position, s);
        measureReach(x0, state.position, s);
        pending.assign(s.candidates.size(), 0);
        searchAll = true;
        ++s.rebuilds;
    };
    for (int pass = 0; pass < kPasses; ++pass) {
        stamp = pass + 1;
        refresh(stamp - 1);
        search(stamp - 1, true);
        if (s.impacted.empty())
            return;
    }
    // what the last pass's answers left meeting
    ++stamp;
    refresh(stamp - 1);
    search(stamp - 1, false);
    if (s.impacted.empty())
        return;

    // 3. the fail-safe: the pairs still meeting become impact zones, merged until none meets
    if (s.zoneOf.size() != std::size_t(n)) {
        s.zoneOf.resize(std::size_t(n));
        s.inZone.assign(std::size_t(n), 0);
        s.zoneMass.resize(std::size_t(n));
        s.zonePinned.resize(std::size_t(n));
        s.zoneMove.resize(3, n);
        s.zoneVelocity.resize(3, n);
    }
    std::iota(s.zoneOf.begin(), s.zoneOf.end(), 0);
    for (const int i : s.zoneMembers)
        s.inZone[std::size_t(i)] = 0;
    s.zoneMembers.clear();
    for (int round = 0; round < kZoneRounds; ++round) {
        ++s.zoneRounds;
        for (const int c : s.impacted)
            joinZone(s, view(surface, s, s.candidates[std::size_t(c)]).v);
        ++stamp;
        moveZones(model, state, s, stamp);
        refresh(stamp - 1);
        search(stamp - 1, false);
        if (s.impacted.empty())
            return;
    }
    // still meeting: every particle stays where the sub-step began, which crosses nothing
    ++s.stops;
    for (const int i : model.freeParticles) {
        state.position.col(i) = x0.col(i);
        state.velocity.col(i).setZero();
    }
}

}  // namespace core
