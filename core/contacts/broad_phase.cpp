// Design note. The grid's cells are as wide as the largest diameter among the particles it holds,
// so two overlapping particles lie in the same or in neighbouring cells. Cells are numbered
// densely over the bounding box when that takes at most 4 cells a particle, else hashed into a
// table of about 2n buckets (a scene may be spread over any volume); either way a row of cells
// along x lands in consecutive buckets. The particles are counting-sorted by bucket into copies
// of what the test reads. The pairs are found in grid order, where neighbours in space
// are neighbours in memory, each pair of cells once (a cell and the 13 of its neighbours ahead of
// it), then counting-sorted by i, so the list comes out in lexicographic order exactly as the
// brute force makes it. A few particles much larger than the rest would make every cell huge:
// those above twice the 90th percentile of the radii stay out of the grid and are tested against
// every particle. A particle keeps at most kMaxGridPartners pairs of the grid: a crowd of
// coincident particles would otherwise need memory quadratic in its size (the cap is far above
// the 12 that equal spheres can touch, so only such a crowd meets it).

#include "core/contacts/broad_phase.h"
#include "core/parallel.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace core {

namespace {

constexpr int kAxisBits = 21;                               // bits of one packed cell coordinate
constexpr double kAxisCells = double(1 << (kAxisBits - 1));  // cells an axis may span
constexpr int kSamples = 1024;                               // radii sampled for the cell size
constexpr int kNotFinite = -1;                               // slotOf: in no pair
constexpr int kBig = -2;                                     // slotOf: tested against every particle

// the one overlap test of both broad phases, so that they agree to the last bit
inline bool overlapping(double xi, double yi, double zi, double ri, double xj, double yj, double zj, double rj)
{
    const double dx = xi - xj;
    const double dy = yi - yj;
    const double dz = zi - zj;
    const double contact = ri + rj;
    return dx * dx + dy * dy + dz * dz < contact * contact;  // false for NaN
}

bool overlapping(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius, int i, int j)
{
    if (model.invMass[i] == 0.0 && model.invMass[j] == 0.0)
        return false;  // two pinned particles: nothing to resolve
    return overlapping(position(0, i), position(1, i), position(2, i), radius[i], position(0, j),
                       position(1, j), position(2, j), radius[j]);
}

std::uint64_t packCell(std::uint64_t x, std::uint64_t y, std::uint64_t z)
{
    return (x << (2 * kAxisBits)) | (y << kAxisBits) | z;
}

// the bucket of a row of cells (y, z), to which the cell's x is added: neighbours along x get
// consecutive buckets (Fibonacci hashing: the top bits of the product)
std::uint64_t rowHash(std::uint64_t y, std::uint64_t z, int shift)
{
    return ((y << kAxisBits) | z) * 0x9E3779B97F4A7C15ull >> shift;
}

// the cell coordinate of u (cells from the grid's corner), offset by 1 so that a neighbour's is
// never negative; clamped so that no value can overflow the packing
std::uint64_t cellCoordinate(double u)
{
    const double clamped = u >= 0.0 ? std::min(u, kAxisCells) : 0.0;
    return static_cast<std::uint64_t>(clamped) + 1;
}

// the grid's geometry for this pass: cells are numbered densely over the bounding box when that
// takes few enough of them, else hashed into a table
struct Layout {
    double inverseCell = 0.0;     // 1/m
    bool dense = false;
    std::uint64_t buckets = 0;    // the table's size
    std::uint64_t mask = ~0ull;   // hashed: buckets - 1 (a power of two)
    int shift = 63;               // hashed: 64 - log2(buckets)
    std::uint64_t nx = 0, ny = 0; // dense: cells along x and y
};

constexpr std::uint64_t kAxisMask = (std::uint64_t(1) << kAxisBits) - 1;

// the bucket of the cell at x in row (y, z): consecutive along x
std::uint64_t bucketAt(const Layout &layout, std::uint64_t x, std::uint64_t y, std::uint64_t z)
{
    if (layout.dense)
        return (z * layout.ny + y) * layout.nx + x;
    return (rowHash(y, z, layout.shift) + x) & layout.mask;
}

std::uint64_t bucketOf(const Layout &layout, std::uint64_t cell)
{
    return bucketAt(layout, cell >> (2 * kAxisBits), (cell >> kAxisBits) & kAxisMask, cell & kAxisMask);
}

// radii above this stay out of the grid: twice the 90th percentile of a sample of the radii
double bigRadius(const Model &model, const Eigen::VectorXd &radius, ContactGrid &grid)
{
    const int n = model.particleCount();
    const int stride = std::max(1, n / kSamples);
    grid.radiusSample.clear();
    for (int i = 0; i < n; i += stride)
        grid.radiusSample.push_back(radius[i]);
    const auto percentile = grid.radiusSample.begin() + std::ptrdiff_t(grid.radiusSample.size() * 9 / 10);
    std::nth_element(grid.radiusSample.begin(), percentile, grid.radiusSample.end());
    return 2.0 * *percentile;
}

// room in a per-bucket array for the most buckets either layout may take for `count` particles (4
// a particle dense, under 4 hashed, and one past the end), reserved so that a box that grows never
// reallocates it
void reserveForBuckets(std::vector<int> &perBucket, int count)
{
    const std::size_t most = 4 * std::size_t(count) + 2;
    if (perBucket.capacity() < most)
        perBucket.reserve(most);
}

// particle i's cell
std::uint64_t cellOfParticle(const Eigen::Matrix3Xd &position, int i, const Eigen::Vector3d &lo, const Layout &layout)
{
    const Eigen::Vector3d u = (position.col(i) - lo) * layout.inverseCell;
    return packCell(cellCoordinate(u.x()), cellCoordinate(u.y()), cellCoordinate(u.z()));
}

// particle i into grid slot `slot`
void putInSlot(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius, ContactGrid &grid,
               int i, int slot)
{
    GridSlot &s = grid.sorted[std::size_t(slot)];
    s.x = position(0, i);
    s.y = position(1, i);
    s.z = position(2, i);
    s.radius = radius[i];
    s.cell = grid.cellOf[std::size_t(i)];
    s.particle = i;
    s.pinned = model.invMass[i] == 0.0;
    grid.slotOf[std::size_t(i)] = slot;
}

// The counting sort of the grid's `count` particles by bucket, on one thread: each particle's cell
// (in parallel), the particles of each bucket counted, the starts summed, then each bucket filled
// from its end in descending index order, so that each bucket ends up ascending
void sortInTurn(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius, ContactGrid &grid,
                const Layout &layout, const Eigen::Vector3d &lo, int count)
{
    const int n = model.particleCount();
    grid.bucketStart.assign(std::size_t(layout.buckets) + 1, 0);
    parallelFor(n, [&](int i) {
        if (grid.slotOf[std::size_t(i)] == 0)
            grid.cellOf[std::size_t(i)] = cellOfParticle(position, i, lo, layout);
    });
    for (int i = 0; i < n; ++i)
        if (grid.slotOf[std::size_t(i)] == 0)
            grid.bucketStart[std::size_t(bucketOf(layout, grid.cellOf[std::size_t(i)]))] += 1;
    int end = 0;
    for (int &b : grid.bucketStart) {
        end += b;
        b = end;
    }
    grid.sorted.resize(std::size_t(count));
    for (int i = n - 1; i >= 0; --i) {
        if (grid.slotOf[std::size_t(i)] != 0)
            continue;
        putInSlot(model, position, radius, grid, i, --grid.bucketStart[std::size_t(bucketOf(layout, grid.cellOf[std::size_t(i)]))]);
    }
}

// The same sort in parallel shares, to the same slots. Each share of the particles counts its own
// per bucket; the starts are summed over ranges of buckets in parallel (each range's total, the
// ranges' offsets in turn, then each range's starts), where bucket b's share s starts after every
// particle of a lower bucket and of b's lower shares; then each share fills its particles in, in
// ascending order, from its own starts. Share 0's particles of a bucket come before share 1's, so
// each bucket is ascending as one thread makes it. (On one thread the counting and the filling
// were a seventh of a 10⁶-particle box's step, which a second thread could not share.)
void sortInShares(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius,
                  ContactGrid &grid, const Layout &layout, const Eigen::Vector3d &lo, int count)
{
    const int n = model.particleCount();
    const int shares = twoPhaseShares(n);
    const std::size_t buckets = std::size_t(layout.buckets);
    if (int(grid.shareStarts.size()) < shares)
        grid.shareStarts.resize(std::size_t(shares));
    grid.bucketStart.resize(buckets + 1);
    parallelShares(n, [&](int share, int begin, int end) {
        std::vector<int> &counts = grid.shareStarts[std::size_t(share)];
        reserveForBuckets(counts, count);
        counts.assign(buckets, 0);
        for (int i = begin; i < end; ++i) {
            if (grid.slotOf[std::size_t(i)] != 0)
                continue;
            const std::uint64_t cell = cellOfParticle(position, i, lo, layout);
            grid.cellOf[std::size_t(i)] = cell;
            counts[std::size_t(bucketOf(layout, cell))] += 1;
        }
    });
    const int ranges = twoPhaseShares(int(buckets));
    grid.rangeStarts.assign(std::size_t(ranges), 0);
    parallelShares(int(buckets), [&](int range, int begin, int end) {
        int total = 0;
        for (int b = begin; b < end; ++b)
            for (int s = 0; s < shares; ++s)
                total += grid.shareStarts[std::size_t(s)][std::size_t(b)];
        grid.rangeStarts[std::size_t(range)] = total;
    });
    int offset = 0;
    for (int &start : grid.rangeStarts) {
        const int total = start;
        start = offset;
        offset += total;
    }
    parallelShares(int(buckets), [&](int range, int begin, int end) {
        int running = grid.rangeStarts[std::size_t(range)];
        for (int b = begin; b < end; ++b) {
            grid.bucketStart[std::size_t(b)] = running;
            for (int s = 0; s < shares; ++s) {
                int &start = grid.shareStarts[std::size_t(s)][std::size_t(b)];
                const int counted = start;
                start = running;
                running += counted;
            }
        }
    });
    grid.bucketStart[buckets] = count;
    grid.sorted.resize(std::size_t(count));
    parallelShares(n, [&](int share, int begin, int end) {
        std::vector<int> &next = grid.shareStarts[std::size_t(share)];
        for (int i = begin; i < end; ++i)
            if (grid.slotOf[std::size_t(i)] == 0)
                putInSlot(model, position, radius, grid, i, next[std::size_t(bucketOf(layout, grid.cellOf[std::size_t(i)]))]++);
    });
}

// sorts the particles into the grid: which are in it, which are big, the layout; false when the
// grid holds no particle
bool sortIntoGrid(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius, ContactGrid &grid,
                  Layout &layout)
{
    const int n = model.particleCount();
    grid.slotOf.resize(std::size_t(n));
    grid.cellOf.resize(std::size_t(n));
    grid.big.clear();

    // classify: not finite (in no pair), big (against all), or in the grid; the grid's extent. In
    // parallel shares, each with its own extent and big particles, joined in share order
    const double big = bigRadius(model, radius, grid);
    const int shares = twoPhaseShares(n);
    if (int(grid.shareExtents.size()) < shares) {
        grid.shareExtents.resize(std::size_t(shares));
        grid.bigShares.resize(std::size_t(shares));
    }
    parallelShares(n, [&](int share, int begin, int end) {
        GridExtent &extent = grid.shareExtents[std::size_t(share)];
        extent = GridExtent{};
        std::vector<int> &bigOnes = grid.bigShares[std::size_t(share)];
        bigOnes.clear();
        for (int i = begin; i < end; ++i) {
            const auto x = position.col(i);
            if (!x.allFinite()) {
                grid.slotOf[std::size_t(i)] = kNotFinite;
            } else if (radius[i] > big) {
                grid.slotOf[std::size_t(i)] = kBig;
                bigOnes.push_back(i);
            } else {
                grid.slotOf[std::size_t(i)] = 0;
                extent.lo = extent.lo.cwiseMin(x);
                extent.hi = extent.hi.cwiseMax(x);
                extent.largest = std::max(extent.largest, radius[i]);
                extent.count += 1;
            }
        }
    });
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
    double largest = 0.0;
    int count = 0;
    for (int share = 0; share < shares; ++share) {
        const GridExtent &extent = grid.shareExtents[std::size_t(share)];
        lo = lo.cwiseMin(extent.lo);
        hi = hi.cwiseMax(extent.hi);
        largest = std::max(largest, extent.largest);
        count += extent.count;
        grid.big.insert(grid.big.end(), grid.bigShares[std::size_t(share)].begin(), grid.bigShares[std::size_t(share)].end());
    }
    if (count == 0)
        return false;

    // the cell: the largest diameter with a margin for rounding (so that an overlapping pair can
    // never land two cells apart), widened if the scene spans more cells than the packing holds
    const double spread = (hi - lo).maxCoeff();
    double cell = std::max(2.0 * largest * (1.0 + 1e-6), spread / (kAxisCells - 4.0));
    if (!(cell > 0.0 && std::isfinite(cell))) {
        if (!std::isfinite(spread)) {
            // positions near the largest double: every particle is tested against every other
            for (int i = 0; i < n; ++i)
                if (grid.slotOf[std::size_t(i)] == 0) {
                    grid.slotOf[std::size_t(i)] = kBig;
                    grid.big.push_back(i);
                }
            std::sort(grid.big.begin(), grid.big.end());
            return false;
        }
        cell = 1.0;  // all radii zero at one point
    }
    layout.inverseCell = 1.0 / cell;

    // dense over the bounding box (with a cell of margin on each side) if that takes at most 4
    // cells a particle, else hashed into at least 2 buckets a particle
    const Eigen::Vector3d extent = (hi - lo) * layout.inverseCell;
    const std::uint64_t nx = cellCoordinate(extent.x()) + 2;
    const std::uint64_t ny = cellCoordinate(extent.y()) + 2;
    const std::uint64_t nz = cellCoordinate(extent.z()) + 2;
    layout.dense = double(nx) * double(ny) * double(nz) <= 4.0 * double(count);
    if (layout.dense) {
        layout.nx = nx;
        layout.ny = ny;
        layout.buckets = nx * ny * nz;
    } else {
        layout.buckets = 2;
        layout.shift = 63;
        while (layout.buckets < 2 * std::uint64_t(count)) {
            layout.buckets *= 2;
            layout.shift -= 1;
        }
        layout.mask = layout.buckets - 1;
    }
    grid.hashed = !layout.dense;
    reserveForBuckets(grid.bucketStart, count);

    if (twoPhaseShares(n) > 1 && layout.buckets < std::uint64_t(std::numeric_limits<int>::max()))
        sortInShares(model, position, radius, grid, layout, lo, count);
    else
        sortInTurn(model, position, radius, grid, layout, lo, count);
    return true;
}

// the pairs of grid slot a with the slots [begin, end) that lie in one of `cells` cells along x
// from `first`, as (a, b), into `out`; a scan that has found kMaxGridPartners (`found`) stops
void scanRow(const ContactGrid &grid, const GridSlot &a, std::uint64_t first, std::uint64_t cells, int begin, int end,
             int &found, std::vector<ContactPair> &out)
{
    constexpr std::uint64_t kStepX = std::uint64_t(1) << (2 * kAxisBits);
    for (int k = begin; k < end && found < kMaxGridPartners; ++k) {
        const GridSlot &b = grid.sorted[std::size_t(k)];
        const std::uint64_t offset = b.cell - first;  // wraps to a huge value below `first`
        if (offset % kStepX == 0 && offset / kStepX < cells && !(a.pinned && b.pinned) &&
            overlapping(a.x, a.y, a.z, a.radius, b.x, b.y, b.z, b.radius)) {
            out.push_back({a.particle, b.particle});
            ++found;
        }
    }
}

// the pairs of the slots [begin, end) with those after them: each particle with those after it in
// its own cell and with all of those in the 13 neighbouring cells ahead of it, so each pair of
// cells is visited once. Those 13 cells are five rows along x, each in consecutive buckets, so each
// row is one run of memory
void scanSlots(const Layout &layout, const ContactGrid &grid, int begin, int end, std::vector<ContactPair> &out)
{
    const auto start = [&](std::uint64_t bucket) { return grid.bucketStart[std::size_t(bucket)]; };
    for (int slot = begin; slot < end; ++slot) {
        const GridSlot &a = grid.sorted[std::size_t(slot)];
        const std::uint64_t cx = a.cell >> (2 * kAxisBits);
        const std::uint64_t cy = (a.cell >> kAxisBits) & kAxisMask;
        const std::uint64_t cz = a.cell & kAxisMask;
        const std::uint64_t own = bucketOf(layout, a.cell);
        int found = 0;
        scanRow(grid, a, a.cell, 1, slot + 1, start(own + 1), found, out);
        for (std::uint64_t z = cz; z <= cz + 1; ++z) {
            for (std::uint64_t y = z == cz ? cy : cy - 1; y <= cy + 1; ++y) {
                // the row's cells: x - 1 .. x + 1, or only x + 1 in the particle's own row
                const std::uint64_t x = z == cz && y == cy ? cx + 1 : cx - 1;
                const std::uint64_t cells = cx + 2 - x;
                const std::uint64_t bucket = bucketAt(layout, x, y, z);
                if (bucket + cells <= layout.buckets) {
                    scanRow(grid, a, packCell(x, y, z), cells, start(bucket), start(bucket + cells), found, out);
                } else {
                    // the row wraps around the end of the table
                    for (std::uint64_t c = 0; c < cells; ++c) {
                        const std::uint64_t b = bucketAt(layout, x + c, y, z);
                        scanRow(grid, a, packCell(x + c, y, z), 1, start(b), start(b + 1), found, out);
                    }
                }
            }
        }
    }
}

// every overlapping pair of the grid, once, in grid order (neighbours in memory are neighbours in
// space). The slots are scanned in contiguous shares, one a thread, each into its own list; the
// lists joined in share order are the pairs in the order one thread finds them, whatever the
// thread count. A particle then keeps its pairs in that order until it has kMaxGridPartners (each
// scan stops at that many of its own, so a crowd's lists stay linear in its size)
void pairsInGrid(const Layout &layout, ContactGrid &grid)
{
    const int count = int(grid.sorted.size());
    const int shares = twoPhaseShares(count);
    if (int(grid.foundShares.size()) < shares)
        grid.foundShares.resize(std::size_t(shares));
    parallelShares(count, [&](int share, int begin, int end) {
        std::vector<ContactPair> &out = grid.foundShares[std::size_t(share)];
        out.clear();
        scanSlots(layout, grid, begin, end, out);
    });
    for (int share = 0; share < shares; ++share)
        for (const ContactPair &p : grid.foundShares[std::size_t(share)]) {
            std::uint16_t &partnersOfA = grid.partners[std::size_t(p.i)];
            std::uint16_t &partnersOfB = grid.partners[std::size_t(p.j)];
            if (partnersOfA >= kMaxGridPartners || partnersOfB >= kMaxGridPartners) {
                grid.crowded = true;
                continue;
            }
            ++partnersOfA;
            ++partnersOfB;
            grid.crowded = grid.crowded || partnersOfA >= kMaxGridPartners || partnersOfB >= kMaxGridPartners;
            grid.found.push_back({std::min(p.i, p.j), std::max(p.i, p.j)});
        }
}

// the pairs of each big particle with every other particle (with another big one only once)
void pairsOfBig(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius, ContactGrid &grid)
{
    const int n = model.particleCount();
    for (int b : grid.big)
        for (int j = 0; j < n; ++j) {
            const int slot = grid.slotOf[std::size_t(j)];
            if (j == b || slot == kNotFinite || (slot == kBig && j < b))
                continue;
            const int i = std::min(b, j);
            const int k = std::max(b, j);
            if (overlapping(model, position, radius, i, k))
                grid.found.push_back({i, k});
        }
}

// the found pairs in lexicographic order: a counting sort by i, then each i's few partners sorted
void sortPairs(int n, ContactGrid &grid)
{
    grid.pairStart.assign(std::size_t(n) + 1, 0);
    for (const ContactPair &p : grid.found)
        grid.pairStart[std::size_t(p.i)] += 1;
    int end = 0;
    for (int &start : grid.pairStart) {
        end += start;
        start = end;
    }
    grid.pairs.resize(grid.found.size());
    for (auto p = grid.found.rbegin(); p != grid.found.rend(); ++p)
        grid.pairs[std::size_t(--grid.pairStart[std::size_t(p->i)])] = *p;
    for (int i = 0; i < n; ++i) {
        const auto first = grid.pairs.begin() + grid.pairStart[std::size_t(i)];
        const auto last = grid.pairs.begin() + grid.pairStart[std::size_t(i) + 1];
        if (last - first > 1)
            std::sort(first, last, [](const ContactPair &a, const ContactPair &b) { return a.j < b.j; });
    }
}

}  // namespace

void findContactsBruteForce(const Model &model, const Eigen::Matrix3Xd &position, std::vector<ContactPair> &pairs)
{
    findContactsBruteForce(model, position, model.radius, pairs);
}

void findContactsBruteForce(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius,
                            std::vector<ContactPair> &pairs)
{
    pairs.clear();
    const int n = model.particleCount();
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (overlapping(model, position, radius, i, j))
                pairs.push_back({i, j});
}

void findContacts(const Model &model, const Eigen::Matrix3Xd &position, ContactGrid &grid)
{
    findContacts(model, position, model.radius, grid);
}

void findContacts(const Model &model, const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius, ContactGrid &grid)
{
    grid.pairs.clear();
    grid.found.clear();
    grid.crowded = false;
    const int n = model.particleCount();
    if (n < 2)
        return;
    grid.partners.assign(std::size_t(n), 0);
    // room for the pairs of a dense packing, so that later passes rarely grow it
    if (grid.found.capacity() < 2 * std::size_t(n)) {
        grid.found.reserve(2 * std::size_t(n));
        grid.pairs.reserve(2 * std::size_t(n));
    }

    Layout layout;
    if (sortIntoGrid(model, position, radius, grid, layout))
        pairsInGrid(layout, grid);
    pairsOfBig(model, position, radius, grid);
    sortPairs(n, grid);
}

}  // namespace core
