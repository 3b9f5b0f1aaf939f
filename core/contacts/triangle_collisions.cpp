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

#include "core/contacts/contact_spin.h"
#include "core/contacts/triangle_geometry.h"
#include "core/parallel.h"
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
// how far a particle may move from where the candidates were found before they are found again:
// this share of the thickest sheet's thickness (a sheet at rest keeps its candidates; one that
// moves finds them again each sub-step, the fewer for it)
constexpr double kBoundThickness = 0.5;
// the grid's cell edge over the triangles' mean box (measured on a 64 x 64 sheet crumpling: 1.5
// searches 17% faster than 1, 0.5 and 3 a half and a sixth slower)
constexpr double kCellPerBox = 1.5;
// the share of the triangles and edges that may be loose (found again outside the grid) before the
// whole broad phase is run again instead
constexpr double kMostLoose = 0.25;
// the most candidate pairs a sub-step may test, per particle and edge: a 64 x 64 sheet crumpled on
// the floor has 2.5 at most, a sheet flying apart (springs past their stability limit) millions,
// each costing a time-of-impact search; past this the run stops as blown up instead of hanging
constexpr std::size_t kMostPairsPerItem = 32;
// an empty slot of a grid's hash table (no cell key has every bit set: keys have 63)
constexpr std::uint64_t kNoCell = ~std::uint64_t(0);

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

// ---- broad phase: a hashed grid of boxes ------------------------------------------------------

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

// a cell key's slot in an open-addressing table of mask + 1 slots (a multiplicative hash)
std::size_t slotOf(std::uint64_t key, std::uint64_t mask)
{
    return std::size_t(((key * 0x9E3779B97F4A7C15ull) >> 17) & mask);
}

}  // namespace

long long CellRange::count() const
{
    long long c = 1;
    for (int a = 0; a < 3; ++a) {
        const long long span = hi[a] - lo[a] + 1;
        if (span <= 0)
            return 0;
        if (span > kMostCells)
            return kMostCells + 1;
        c *= span;
        if (c > kMostCells)
            return kMostCells + 1;
    }
    return c;
}

namespace {

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

// The grid of one kind of item (triangles or edges): a hash table from each occupied cell to its
// run of entries, the runs in one array, each run in item order (a counting sort: no comparison
// sort of the entries). A box over too many cells is kept aside and checked against every query.
void fillGrid(const Cells &cells, const Eigen::Matrix3Xd &low, const Eigen::Matrix3Xd &high,
              const std::vector<std::uint8_t> &active, TriangleGrid &grid)
{
    const int items = int(active.size());
    grid.big.clear();
    grid.lowCell.resize(3, items);
    grid.range.resize(std::size_t(items));
    // each item's cells, and the number of entries it makes
    std::size_t entries = 0;
    for (int item = 0; item < items; ++item) {
        CellRange &r = grid.range[std::size_t(item)];
        r.lo[0] = 1;
        r.hi[0] = 0;  // no cells
        if (!active[std::size_t(item)] || !low.col(item).allFinite() || !high.col(item).allFinite())
            continue;
        r = rangeOf(cells, low.col(item), high.col(item));
        for (int a = 0; a < 3; ++a)
            grid.lowCell(a, item) = r.lo[a];
        const long long count = r.count();
        if (count > kMostCells) {
            grid.big.push_back(item);
            r.lo[0] = 1;
            r.hi[0] = 0;
            continue;
        }
        entries += std::size_t(count);
    }
    std::size_t slots = 16;
    while (slots < 2 * entries)
        slots *= 2;
    grid.mask = slots - 1;
    grid.keys.assign(slots, kNoCell);
    grid.first.assign(slots + 1, 0);
    auto slotFor = [&](std::uint64_t key) {
        std::size_t slot = slotOf(key, grid.mask);
        while (grid.keys[slot] != key && grid.keys[slot] != kNoCell)
            slot = (slot + 1) & grid.mask;
        return slot;
    };
    auto forCells = [&](int item, auto &&body) {
        const CellRange &r = grid.range[std::size_t(item)];
        for (long long x = r.lo[0]; x <= r.hi[0]; ++x)
            for (long long y = r.lo[1]; y <= r.hi[1]; ++y)
                for (long long z = r.lo[2]; z <= r.hi[2]; ++z)
                    body(cellKey(x, y, z));
    };
    // count per cell, then each cell's run starts after the runs of the slots before it
    for (int item = 0; item < items; ++item)
        forCells(item, [&](std::uint64_t key) {
            const std::size_t slot = slotFor(key);
            grid.keys[slot] = key;
            ++grid.first[slot + 1];
        });
    for (std::size_t slot = 0; slot < slots; ++slot)
        grid.first[slot + 1] += grid.first[slot];
    grid.fill.assign(grid.first.begin(), grid.first.end() - 1);
    grid.items.resize(entries);
    for (int item = 0; item < items; ++item)
        forCells(item, [&](std::uint64_t key) { grid.items[std::size_t(grid.fill[slotFor(key)]++)] = item; });
}

// calls visit(item) for every item whose box overlaps the box low..high, each once (in the cell
// that holds the low corner of the two boxes' overlap); a query box over too many cells tries every
// active item
template <typename Visit>
void query(const Cells &cells, const Vec &low, const Vec &high, const TriangleGrid &grid,
           const Eigen::Matrix3Xd &itemLow, const Eigen::Matrix3Xd &itemHigh, const std::vector<std::uint8_t> &active,
           int after, Visit &&visit)
{
    const CellRange r = rangeOf(cells, low, high);
    if (r.count() > kMostCells) {
        for (int item = after + 1; item < int(active.size()); ++item)
            if (active[std::size_t(item)] && overlap(low, high, itemLow.col(item), itemHigh.col(item)))
                visit(item);
        return;
    }
    for (long long x = r.lo[0]; x <= r.hi[0]; ++x)
        for (long long y = r.lo[1]; y <= r.hi[1]; ++y)
            for (long long z = r.lo[2]; z <= r.hi[2]; ++z) {
                const std::uint64_t key = cellKey(x, y, z);
                std::size_t slot = slotOf(key, grid.mask);
                while (grid.keys[slot] != key && grid.keys[slot] != kNoCell)
                    slot = (slot + 1) & grid.mask;
                if (grid.keys[slot] == kNoCell)
                    continue;
                // a run is in item order: those up to `after` are skipped at once
                const int *begin = grid.items.data() + grid.first[slot];
                const int *end = grid.items.data() + grid.first[slot + 1];
                for (const int *it = std::upper_bound(begin, end, after); it != end; ++it) {
                    const int item = *it;
                    if (std::max(r.lo[0], grid.lowCell(0, item)) == x && std::max(r.lo[1], grid.lowCell(1, item)) == y &&
                        std::max(r.lo[2], grid.lowCell(2, item)) == z &&
                        overlap(low, high, itemLow.col(item), itemHigh.col(item)))
                        visit(item);
                }
            }
    for (const int item : grid.big)
        if (item > after && overlap(low, high, itemLow.col(item), itemHigh.col(item)))
            visit(item);
}

// the pair's distance at positions x
double pairDistance(const Eigen::Matrix3Xd &x, const PairView &pair)
{
    return std::sqrt(closest(pair.kind, gather(x, pair.v)).squaredDistance);
}

// the farthest each of a pair's two features can move from where the candidates were found while
// they hold: its corners' largest bound
std::pair<double, double> featureBounds(const PairView &pair, const std::vector<double> &perParticle)
{
    const auto r = [&](int k) { return perParticle[std::size_t(pair.v[std::size_t(k)])]; };
    const double first = pair.kind == PairKind::PointTriangle ? r(0) : std::max(r(0), r(1));
    const double second = pair.kind == PairKind::PointTriangle ? std::max({r(1), r(2), r(3)}) : std::max(r(2), r(3));
    return {first, second};
}

// whether a candidate pair may be tested at all: not a feature against itself or a neighbour, not
// within one sheet when self-collision is off, not between four pinned particles
bool pointTriangleAllowed(const Model &model, const ClothSurface &surface, int i, int t)
{
    const int *c = &surface.corners[std::size_t(3 * t)];
    if (c[0] == i || c[1] == i || c[2] == i)
        return false;
    if (!surface.selfCollision && surface.vertexSheet[std::size_t(i)] == surface.triangleSheet[std::size_t(t)])
        return false;
    return !(model.invMass[i] == 0.0 && model.invMass[c[0]] == 0.0 && model.invMass[c[1]] == 0.0 &&
             model.invMass[c[2]] == 0.0);
}

bool edgeEdgeAllowed(const Model &model, const ClothSurface &surface, int e, int f)
{
    const int a0 = surface.edgeEnds[std::size_t(2 * e)], a1 = surface.edgeEnds[std::size_t(2 * e + 1)];
    const int b0 = surface.edgeEnds[std::size_t(2 * f)], b1 = surface.edgeEnds[std::size_t(2 * f + 1)];
    if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1)
        return false;
    if (!surface.selfCollision && surface.edgeSheet[std::size_t(e)] == surface.edgeSheet[std::size_t(f)])
        return false;
    return !(model.invMass[a0] == 0.0 && model.invMass[a1] == 0.0 && model.invMass[b0] == 0.0 &&
             model.invMass[b1] == 0.0);
}

// particle i's path from start to end, grown by its bound (the swept box), and by its radius too
// (the box it is looked up by); whether that is finite
void pointBox(TriangleScratch &s, int i, const Vec &start, const Vec &end, double bound)
{
    s.sweptLow.col(i) = start.cwiseMin(end).array() - bound;
    s.sweptHigh.col(i) = start.cwiseMax(end).array() + bound;
    const double pad = s.pointRadius[std::size_t(i)];
    s.pointLow.col(i) = s.sweptLow.col(i).array() - pad;
    s.pointHigh.col(i) = s.sweptHigh.col(i).array() + pad;
    s.finite[std::size_t(i)] = s.pointLow.col(i).allFinite() && s.pointHigh.col(i).allFinite();
}

// a triangle's or an edge's box: its corners' swept boxes, grown by half its thickness
void cornerBox(const TriangleScratch &s, const int *v, int count, double half, Eigen::Ref<Vec> low,
               Eigen::Ref<Vec> high)
{
    low = s.sweptLow.col(v[0]);
    high = s.sweptHigh.col(v[0]);
    for (int k = 1; k < count; ++k) {
        low = low.cwiseMin(s.sweptLow.col(v[k]));
        high = high.cwiseMax(s.sweptHigh.col(v[k]));
    }
    low.array() -= half;
    high.array() += half;
}

std::size_t mostCandidates(int particles, int edges)
{
    return kMostPairsPerItem * std::size_t(particles + edges);
}

bool pairBefore(const TrianglePair &x, const TrianglePair &y)
{
    return x.edges != y.edges ? y.edges : x.a != y.a ? x.a < y.a : x.b < y.b;
}

// The candidate pairs: those that can come within their distance on this sub-step's path or, later,
// while every particle stays within its bound of where it ends this sub-step (`built`). Found by the
// boxes swept over the sub-step's path and padded by the bound, then kept only where the pair's
// distance at the end, less how far the two features moved relative to each other over the sub-step
// and both features' bounds, is within reach. A sheet moving as a whole (falling, swinging) has
// few: only the pairs that are close, not all those its motion sweeps past. They serve later sub-steps
// while every particle stays within its bound (collectMoved()): a sheet at rest finds them once. Found in
// parallel shares, each item's in index order, joined in share order: one order, by kind and
// index, whichever sub-step or thread count found them. Returns false, the candidates incomplete,
// where there are more than `most` (each share stops once its own are more: the answer is the same
// on any thread count).
bool findCandidates(const Model &model, const ClothSurface &surface, const Eigen::Matrix3Xd &x0,
                    const Eigen::Matrix3Xd &x1, TriangleScratch &s)
{
    const int n = model.particleCount();
    const int triangles = surface.triangleCount();
    const int edges = surface.edgeCount();
    s.built = x1;
    s.builtFor = &surface;
    s.builtActive = s.triangleActive;
    s.bound.resize(std::size_t(n));
    s.sweptLow.resize(3, n);
    s.sweptHigh.resize(3, n);
    s.pointLow.resize(3, n);
    s.pointHigh.resize(3, n);
    s.triangleLow.resize(3, triangles);
    s.triangleHigh.resize(3, triangles);
    s.edgeLow.resize(3, edges);
    s.edgeHigh.resize(3, edges);
    std::vector<std::uint8_t> &finite = s.finite;
    finite.assign(std::size_t(n), 1);
    for (int i = 0; i < n; ++i) {
        const Vec start = x0.col(i) - s.shiftStart;
        const double bound = kBoundThickness * s.margin;
        s.bound[std::size_t(i)] = bound;
        pointBox(s, i, start, x1.col(i), bound);
    }
    auto featureBox = [&](const int *v, int count, double half, Eigen::Ref<Vec> low, Eigen::Ref<Vec> high) {
        cornerBox(s, v, count, half, low, high);
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
    cells.size = counted > 0 && extent > 0.0 ? kCellPerBox * extent / counted : 1.0;
    s.cellSize = cells.size;
    fillGrid(cells, s.triangleLow, s.triangleHigh, s.triangleActive, s.triangleGrid);
    fillGrid(cells, s.edgeLow, s.edgeHigh, s.edgeActive, s.edgeGrid);
    s.looseTriangle.assign(std::size_t(triangles), 0);
    s.looseEdge.assign(std::size_t(edges), 0);
    s.looseTriangleActive.assign(std::size_t(triangles), 0);
    s.looseEdgeActive.assign(std::size_t(edges), 0);
    s.looseCount = 0;

    // a pair found by the boxes is kept when it can come within its distance: on this sub-step's path
    // the two features' closest points close by at most twice the largest move of a corner relative
    // to the first's (a point of a feature moves by its corners' moves averaged)
    auto keep = [&](const TrianglePair &pair, std::vector<TrianglePair> &out, std::vector<double> &distances) {
        const PairView v = view(surface, s, pair);
        const double d = pairDistance(x1, v);
        const Vec reference = x1.col(v.v[0]) - x0.col(v.v[0]);
        double relative = 0.0;
        for (std::size_t k = 1; k < 4; ++k)
            relative = std::max(relative, (x1.col(v.v[k]) - x0.col(v.v[k]) - reference).norm());
        const auto [first, second] = featureBounds(v, s.bound);
        if (!(d - 2.0 * relative > v.distance && d - first - second > v.distance)) {
            out.push_back(pair);
            distances.push_back(d);
        }
    };
    const int shares = std::max(twoPhaseShares(n), twoPhaseShares(edges));
    if (int(s.shareCandidates.size()) < shares) {
        s.shareCandidates.resize(std::size_t(shares));
        s.shareDistances.resize(std::size_t(shares));
        s.shareVisits.resize(std::size_t(shares));
    }
    for (int share = 0; share < shares; ++share) {
        s.shareCandidates[std::size_t(share)].clear();
        s.shareDistances[std::size_t(share)].clear();
    }
    s.candidates.clear();
    s.builtDistance.clear();
    auto join = [&] {
        for (int share = 0; share < shares; ++share) {
            std::vector<TrianglePair> &found = s.shareCandidates[std::size_t(share)];
            std::vector<double> &distances = s.shareDistances[std::size_t(share)];
            s.candidates.insert(s.candidates.end(), found.begin(), found.end());
            s.builtDistance.insert(s.builtDistance.end(), distances.begin(), distances.end());
            found.clear();
            distances.clear();
        }
    };
    const std::size_t most = mostCandidates(n, edges);
    // particles against triangles, each particle's in triangle order
    parallelShares(n, [&](int share, int begin, int end) {
        std::vector<TrianglePair> &out = s.shareCandidates[std::size_t(share)];
        std::vector<double> &distances = s.shareDistances[std::size_t(share)];
        std::vector<int> &visits = s.shareVisits[std::size_t(share)];
        for (int i = begin; i < end && out.size() <= most; ++i) {
            if (!finite[std::size_t(i)])
                continue;
            visits.clear();
            query(cells, s.pointLow.col(i), s.pointHigh.col(i), s.triangleGrid, s.triangleLow, s.triangleHigh,
                  s.triangleActive, -1, [&](int t) {
                      if (pointTriangleAllowed(model, surface, i, t))
                          visits.push_back(t);
                  });
            std::sort(visits.begin(), visits.end());
            visits.erase(std::unique(visits.begin(), visits.end()), visits.end());
            for (const int t : visits)
                keep({false, i, t}, out, distances);
        }
    });
    join();
    if (s.candidates.size() > most)
        return false;
    // edges against edges, each pair once (a < b), each edge's in edge order
    parallelShares(edges, [&](int share, int begin, int end) {
        std::vector<TrianglePair> &out = s.shareCandidates[std::size_t(share)];
        std::vector<double> &distances = s.shareDistances[std::size_t(share)];
        std::vector<int> &visits = s.shareVisits[std::size_t(share)];
        for (int e = begin; e < end && s.candidates.size() + out.size() <= most; ++e) {
            if (!s.edgeActive[std::size_t(e)] || !s.edgeLow.col(e).allFinite() || !s.edgeHigh.col(e).allFinite())
                continue;
            visits.clear();
            query(cells, s.edgeLow.col(e), s.edgeHigh.col(e), s.edgeGrid, s.edgeLow, s.edgeHigh, s.edgeActive, e, [&](int f) {
                if (edgeEdgeAllowed(model, surface, e, f))
                    visits.push_back(f);
            });
            std::sort(visits.begin(), visits.end());
            visits.erase(std::unique(visits.begin(), visits.end()), visits.end());
            for (const int f : visits)
                keep({true, e, f}, out, distances);
        }
    });
    join();
    return s.candidates.size() <= most;
}

// how far each particle has been from where the candidates were found, at most, during the sub-step,
// less the common shift (its path less the shift is the segment from x0 - shiftStart to
// x1 - shiftEnd, and a segment is no farther from a point than its ends)
void measureReach(const Eigen::Matrix3Xd &x0, const Eigen::Matrix3Xd &x1, TriangleScratch &s)
{
    s.reach.resize(std::size_t(x1.cols()));
    for (int i = 0; i < x1.cols(); ++i)
        s.reach[std::size_t(i)] = std::max((x0.col(i) - s.shiftStart - s.built.col(i)).norm(),
                                           (x1.col(i) - s.shiftEnd - s.built.col(i)).norm());
}

// The candidates brought up to date where only some particles (`s.moved`) left their bounds: each is
// found again about where it is now; every triangle or edge with one of them as a corner is fresh,
// and loose from then on (its box no longer the one in the main grid: small grids of the loose and
// of the fresh items are made instead); the pairs of a moved particle or a fresh item are dropped
// and searched again, the rest kept. The
// pairs found are pruned by the distance less each feature's reach (its corners' farthest from
// where they were found, over this sub-step, or the bound). Returns false, changing nothing, when
// so many items would be loose that finding everything again costs less.
bool updateCandidates(const Model &model, const ClothSurface &surface, const Eigen::Matrix3Xd &x0,
                      const Eigen::Matrix3Xd &x1, TriangleScratch &s)
{
    const int n = model.particleCount();
    const int triangles = surface.triangleCount();
    const int edges = surface.edgeCount();
    s.isMoved.assign(std::size_t(n), 0);
    for (const int i : s.moved)
        s.isMoved[std::size_t(i)] = 1;
    auto touches = [&](const int *v, int count) {
        for (int k = 0; k < count; ++k)
            if (s.isMoved[std::size_t(v[k])])
                return true;
        return false;
    };
    int loose = s.looseCount;
    for (int t = 0; t < triangles; ++t)
        if (!s.looseTriangle[std::size_t(t)] && touches(&surface.corners[std::size_t(3 * t)], 3))
            ++loose;
    for (int e = 0; e < edges; ++e)
        if (!s.looseEdge[std::size_t(e)] && touches(&surface.edgeEnds[std::size_t(2 * e)], 2))
            ++loose;
    if (loose > kMostLoose * (triangles + edges))
        return false;

    // the moved particles found again where they end this sub-step
    const double bound = kBoundThickness * s.margin;
    for (const int i : s.moved) {
        const Vec start = x0.col(i) - s.shiftStart;
        const Vec end = x1.col(i) - s.shiftEnd;
        s.built.col(i) = end;
        pointBox(s, i, start, end, bound);
    }
    auto featureBox = [&](const int *v, int count, double half, Eigen::Ref<Vec> low, Eigen::Ref<Vec> high) {
        cornerBox(s, v, count, half, low, high);
    };
    // the items with a moved corner: fresh (their pairs are found again), and loose from now on
    s.freshTriangle.assign(std::size_t(triangles), 0);
    s.freshEdge.assign(std::size_t(edges), 0);
    for (int t = 0; t < triangles; ++t)
        if (s.triangleActive[std::size_t(t)] && touches(&surface.corners[std::size_t(3 * t)], 3)) {
            s.looseTriangle[std::size_t(t)] = 1;
            s.freshTriangle[std::size_t(t)] = 1;
            featureBox(&surface.corners[std::size_t(3 * t)], 3,
                       0.5 * surface.sheetThickness[std::size_t(surface.triangleSheet[std::size_t(t)])],
                       s.triangleLow.col(t), s.triangleHigh.col(t));
        }
    for (int e = 0; e < edges; ++e)
        if (s.edgeActive[std::size_t(e)] && touches(&surface.edgeEnds[std::size_t(2 * e)], 2)) {
            s.looseEdge[std::size_t(e)] = 1;
            s.freshEdge[std::size_t(e)] = 1;
            featureBox(&surface.edgeEnds[std::size_t(2 * e)], 2,
                       0.5 * surface.sheetThickness[std::size_t(surface.edgeSheet[std::size_t(e)])], s.edgeLow.col(e),
                       s.edgeHigh.col(e));
        }
    s.looseCount = loose;
    // the grids of the loose items and of the fresh ones, in the main grids' cells
    Cells cells;
    cells.size = s.cellSize;
    for (int t = 0; t < triangles; ++t) {
        s.looseTriangleActive[std::size_t(t)] = s.looseTriangle[std::size_t(t)] && s.triangleActive[std::size_t(t)];
        s.freshTriangle[std::size_t(t)] = s.freshTriangle[std::size_t(t)] && s.triangleActive[std::size_t(t)];
    }
    for (int e = 0; e < edges; ++e) {
        s.looseEdgeActive[std::size_t(e)] = s.looseEdge[std::size_t(e)] && s.edgeActive[std::size_t(e)];
        s.freshEdge[std::size_t(e)] = s.freshEdge[std::size_t(e)] && s.edgeActive[std::size_t(e)];
    }
    fillGrid(cells, s.triangleLow, s.triangleHigh, s.looseTriangleActive, s.looseTriangleGrid);
    fillGrid(cells, s.edgeLow, s.edgeHigh, s.looseEdgeActive, s.looseEdgeGrid);
    fillGrid(cells, s.triangleLow, s.triangleHigh, s.freshTriangle, s.freshTriangleGrid);

    // the kept pairs: neither a moved particle nor a fresh item in them (a pair of a loose item
    // found since the grids were filled holds while its particles stay within their bounds)
    std::size_t kept = 0;
    for (std::size_t c = 0; c < s.candidates.size(); ++c) {
        const TrianglePair &pair = s.candidates[c];
        const bool redo = pair.edges ? s.freshEdge[std::size_t(pair.a)] || s.freshEdge[std::size_t(pair.b)]
                                     : s.isMoved[std::size_t(pair.a)] || s.freshTriangle[std::size_t(pair.b)];
        if (redo)
            continue;
        s.candidates[kept] = pair;
        s.builtDistance[kept] = s.builtDistance[c];
        ++kept;
    }
    s.candidates.resize(kept);
    s.builtDistance.resize(kept);

    // the pairs found again, pruned by their features' reach now
    measureReach(x0, x1, s);
    std::vector<TrianglePair> &found = s.shareCandidates[0];
    found.clear();
    auto keep = [&](const TrianglePair &pair) {
        const PairView v = view(surface, s, pair);
        const auto [first, second] = featureBounds(v, s.reach);
        const double d = pairDistance(s.built, v);
        if (!(d - std::max(first, bound) - std::max(second, bound) > v.distance))
            found.push_back(pair);
    };
    std::vector<int> &visits = s.shareVisits[0];
    for (int i = 0; i < n; ++i) {
        if (!s.finite[std::size_t(i)])
            continue;
        visits.clear();
        auto visit = [&](int t) {
            if (pointTriangleAllowed(model, surface, i, t))
                visits.push_back(t);
        };
        if (s.isMoved[std::size_t(i)]) {  // every triangle: those in the main grid, the loose ones
            query(cells, s.pointLow.col(i), s.pointHigh.col(i), s.triangleGrid, s.triangleLow, s.triangleHigh,
                  s.triangleActive, -1, [&](int t) {
                      if (!s.looseTriangle[std::size_t(t)])
                          visit(t);
                  });
            query(cells, s.pointLow.col(i), s.pointHigh.col(i), s.looseTriangleGrid, s.triangleLow, s.triangleHigh,
                  s.looseTriangleActive, -1, visit);
        } else {  // the fresh triangles alone
            query(cells, s.pointLow.col(i), s.pointHigh.col(i), s.freshTriangleGrid, s.triangleLow, s.triangleHigh,
                  s.freshTriangle, -1, visit);
        }
        std::sort(visits.begin(), visits.end());
        visits.erase(std::unique(visits.begin(), visits.end()), visits.end());
        for (const int t : visits)
            keep({false, i, t});
    }
    for (int e = 0; e < edges; ++e) {
        if (!s.freshEdge[std::size_t(e)] || !s.edgeLow.col(e).allFinite() || !s.edgeHigh.col(e).allFinite())
            continue;
        visits.clear();
        // the edges in the main grid, either side of e; the loose ones, fresh ones after e only (a
        // pair of two fresh edges is found from its first)
        query(cells, s.edgeLow.col(e), s.edgeHigh.col(e), s.edgeGrid, s.edgeLow, s.edgeHigh, s.edgeActive, -1, [&](int f) {
            if (!s.looseEdge[std::size_t(f)] && edgeEdgeAllowed(model, surface, e, f))
                visits.push_back(f);
        });
        query(cells, s.edgeLow.col(e), s.edgeHigh.col(e), s.looseEdgeGrid, s.edgeLow, s.edgeHigh, s.looseEdgeActive, -1,
              [&](int f) {
                  if ((!s.freshEdge[std::size_t(f)] || f > e) && edgeEdgeAllowed(model, surface, e, f))
                      visits.push_back(f);
              });
        std::sort(visits.begin(), visits.end());
        visits.erase(std::unique(visits.begin(), visits.end()), visits.end());
        for (const int f : visits)
            keep({true, std::min(e, f), std::max(e, f)});
    }
    std::sort(found.begin(), found.end(), pairBefore);
    // merged into the kept ones, in the one order
    std::vector<TrianglePair> &merged = s.mergedCandidates;
    std::vector<double> &distances = s.mergedDistances;
    merged.clear();
    distances.clear();
    std::size_t a = 0, b = 0;
    while (a < s.candidates.size() || b < found.size()) {
        if (b == found.size() || (a < s.candidates.size() && pairBefore(s.candidates[a], found[b]))) {
            merged.push_back(s.candidates[a]);
            distances.push_back(s.builtDistance[a]);
            ++a;
        } else {
            merged.push_back(found[b]);
            distances.push_back(pairDistance(s.built, view(surface, s, found[b])));
            ++b;
        }
    }
    std::swap(s.candidates, merged);
    std::swap(s.builtDistance, distances);
    found.clear();
    return true;
}

// the free particles' mean move over the sub-step (the finite ones'): the common shift of a sheet that
// falls or swings as a whole, which changes no distance between two features
Vec meanMove(const Model &model, const Eigen::Matrix3Xd &x0, const Eigen::Matrix3Xd &x1)
{
    Vec sum = Vec::Zero();
    int count = 0;
    for (const int i : model.freeParticles) {
        const Vec d = x1.col(i) - x0.col(i);
        if (d.allFinite()) {
            sum += d;
            ++count;
        }
    }
    return count > 0 ? Vec(sum / count) : Vec::Zero();
}

// whether candidate c is certainly farther apart than its distance all through the sub-step: its
// distance where it was found, less how far each of its features can have come since (a feature's
// closest point moves no farther than its farthest corner). Only for pairs no answer has moved in
// this sub-step
bool surelyApart(const TriangleScratch &s, std::size_t c, const PairView &pair)
{
    const auto [first, second] = featureBounds(pair, s.reach);
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

// With spin (the plan's), the point of a point–triangle pair, when it is a ball rather than a
// sheet's particle, touches the sheet at −r n from its centre (n towards it): its surface there
// slides over the sheet at the relative velocity less r ω × n, and friction's impulse −F on it turns
// it by a r n × F (contact_spin.h; the sheet's corners do not turn). Stopping that slip costs
// F (Σ c² w + a r²), so a ball struck across a sheet turns to rolling on it as on a floor, and a
// sheet pulled from under a ball turns it
struct PointSpin {
    int particle = -1;  // -1: the pair does not turn anything
    ContactLevers levers;
};

PointSpin pointSpin(const Model &model, const ClothSurface &surface, const PairView &pair)
{
    if (!model.plan.spin || pair.kind != PairKind::PointTriangle)
        return {};
    const int p = pair.v[0];
    if (surface.vertexSheet[std::size_t(p)] >= 0 || !(model.invInertia[p] > 0.0) || !(model.radius[p] > 0.0))
        return {};
    PointSpin spin;
    spin.particle = p;
    spin.levers.ri = model.radius[p];
    spin.levers.ai = model.invInertia[p];
    return spin;
}

// the sliding of the pair along the surface, ut, and the inverse mass that stops it, with the
// point's spin where it turns
Vec slideWithSpin(const State &state, const PointSpin &spin, const Vec &ut, const Vec &n, double &weight)
{
    if (spin.particle < 0)
        return ut;
    weight += spin.levers.turning();
    return ut + spinSlip(spin.levers, state.angularVelocity.col(spin.particle), Vec::Zero(), n);
}

// the end velocity after a contact along n that closed at `closing` (< 0, m/s): separating at the
// restitution's share of that speed at least, with friction
void answerVelocity(const Model &model, State &state, const std::array<int, 4> &v, const Weights4 &k, const Vec &n,
                    double closing, const PointSpin &spin)
{
    const Vec u = relative(state.velocity, v, k.c);
    const double un = u.dot(n);
    const double target = -contactRestitution(model, closing) * closing;
    if (un >= target)
        return;
    const double j = (target - un) / k.sum;
    double weight = k.sum;
    const Vec slide = slideWithSpin(state, spin, u - un * n, n, weight);
    const Vec friction = frictionImpulse(model, slide, j, weight);
    applyVelocity(state.velocity, v, k, j * n - friction);
    if (spin.particle >= 0) {
        Vec unused = Vec::Zero();
        turnBy(spin.levers, n, -friction, state.angularVelocity.col(spin.particle), unused);
    }
}

// a pair closer than its distance at the sub-step's end: pushed apart to it along the line between
// its closest points, its closing velocity taken away (restitution as a contact's)
bool answerProximity(const Model &model, const ClothSurface &surface, State &state, const Eigen::Matrix3Xd &x0,
                     const PairView &pair, std::vector<int> &changedAt, int stamp, double h)
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
    // (with spin, the slide of the point of contact: a ball rolling along the sheet does not slide;
    // found only for the pairs that are answered, most candidates being clear)
    const PointSpin spin = pointSpin(model, surface, pair);
    double weight = k.sum;
    const Vec slide = slideWithSpin(state, spin, (moved - moved.dot(n) * n) / h, n, weight);
    const Vec push = ((pair.distance - d) / (h * k.sum)) * n - frictionImpulse(model, slide, -closing / k.sum, weight);
    applyMove(state.position, pair.v, k, push, h, changedAt, stamp);
    answerVelocity(model, state, pair.v, k, n, closing, spin);
    return true;
}

// an impact found at fraction t of the motion: the pair's closing motion along the line between its
// closest points there is stopped for the whole sub-step, its end velocity bounces
bool answerImpact(const Model &model, State &state, const Eigen::Matrix3Xd &x0, const PairView &pair, double t,
                  const PointSpin &spin, std::vector<int> &changedAt, int stamp, double h)
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
    double weight = k.sum;
    const Vec slide = slideWithSpin(state, spin, u - un * n, n, weight);
    applyMove(state.position, pair.v, k, j * n - frictionImpulse(model, slide, j, weight), h, changedAt, stamp);
    answerVelocity(model, state, pair.v, k, n, un, spin);
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

// the particles (every one, or those an answer moved since `stamp`) that left their bound about
// where the candidates were found, into s.moved
void collectMoved(TriangleScratch &s, const Eigen::Matrix3Xd &x1, int stamp, bool every)
{
    s.moved.clear();
    for (int i = 0; i < x1.cols(); ++i) {
        if (!every && s.changedAt[std::size_t(i)] < stamp)
            continue;
        const double reach = every ? s.reach[std::size_t(i)] : (x1.col(i) - s.shiftEnd - s.built.col(i)).norm();
        if (!(reach <= s.bound[std::size_t(i)]))
            s.moved.push_back(i);
    }
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
    // every particle within its bound once the common shift is taken away (distances between
    // features do not change with it, so a sheet falling as a whole keeps its candidates); those
    // of the particles that left it found again, or all of them when many did
    const bool rebuild = s.builtFor != &surface || s.built.cols() != n || s.builtActive != s.triangleActive;
    const Vec common = meanMove(model, x0, state.position);
    s.shiftStart = s.shiftCarried;
    s.shiftEnd = s.shiftStart + common;
    if (!rebuild) {
        measureReach(x0, state.position, s);
        collectMoved(s, state.position, 0, true);
    }
    // more candidates than a sheet that is not flying apart has: the run stops as blown up (the
    // candidates, incomplete, are found afresh next time)
    auto overwhelmed = [&] {
        s.builtFor = nullptr;
        s.candidates.clear();
        s.builtDistance.clear();
        work.blowup = Blowup{-1, Blowup::Quantity::SheetPairs, double(mostCandidates(n, surface.edgeCount())), 0, 0.0};
    };
    if (rebuild || (!s.moved.empty() && !updateCandidates(model, surface, x0, state.position, s))) {
        s.shiftStart = -common;
        s.shiftEnd.setZero();
        if (!findCandidates(model, surface, x0, state.position, s))
            return overwhelmed();
        measureReach(x0, state.position, s);
        ++s.builds;
    } else if (!s.moved.empty()) {
        ++s.updates;
    }
    s.shiftCarried = s.shiftEnd;

    // 1. proximity at the thickness (stamp 0)
    for (std::size_t c = 0; c < s.candidates.size(); ++c) {
        const PairView pair = view(surface, s, s.candidates[c]);
        if (!whole(s, s.candidates[c]) || (!movedSince(s.changedAt, pair.v, 0) && surelyApart(s, c, pair)))
            continue;
        answerProximity(model, surface, state, x0, pair, s.changedAt, 0, h);
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
            if (answer && answerImpact(model, state, x0, pair, t, pointSpin(model, surface, pair), s.changedAt, stamp, h))
                ++s.impacts;
            else
                pending[c] = 1;
        }
        searchAll = false;
    };
    auto refresh = [&](int since) {
        collectMoved(s, state.position, since, false);
        if (s.moved.empty())
            return true;
        if (!updateCandidates(model, surface, x0, state.position, s)) {
            s.shiftStart -= s.shiftEnd;
            s.shiftEnd.setZero();
            s.shiftCarried.setZero();
            if (!findCandidates(model, surface, x0, state.position, s)) {
                overwhelmed();
                return false;
            }
        }
        measureReach(x0, state.position, s);
        pending.assign(s.candidates.size(), 0);
        searchAll = true;
        ++s.rebuilds;
        return true;
    };
    for (int pass = 0; pass < kPasses; ++pass) {
        stamp = pass + 1;
        if (!refresh(stamp - 1))
            return;
        search(stamp - 1, true);
        if (s.impacted.empty())
            return;
    }
    // what the last pass's answers left meeting
    ++stamp;
    if (!refresh(stamp - 1))
        return;
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
        if (!refresh(stamp - 1))
            return;
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
