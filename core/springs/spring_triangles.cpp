#include "core/springs/spring_triangles.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <utility>

namespace core {

namespace {

// twice a triangle's area over its longest side squared below which its corners count as a line
// (a right triangle of a grid cell has 0.5; a row and its bend spring 0)
constexpr double kThin = 0.02;
// far corners whose directions from a common side are within 30° of each other: folded onto each
// other, the two triangles overlap
constexpr double kFoldedCosine = 0.866;

struct Candidate {
    double doubleArea = 0.0;
    std::array<int, 3> corners{};
    std::array<int, 3> sides{};  // side s joins corners s and (s + 1) % 3
};

// the part of (x - p) across the line through p along the unit direction e
Eigen::Vector3d across(const Eigen::Vector3d &x, const Eigen::Vector3d &p, const Eigen::Vector3d &e)
{
    const Eigen::Vector3d d = x - p;
    return d - d.dot(e) * e;
}

}  // namespace

SpringTriangles findSpringTriangles(const SceneDesc &scene)
{
    const int n = static_cast<int>(scene.particles.size());
    const int springs = static_cast<int>(scene.springs.size());
    auto position = [&](int i) -> const Eigen::Vector3d & { return scene.particles[static_cast<std::size_t>(i)].position; };

    // each particle's neighbours, ascending, each with the first spring that joins the two
    std::vector<int> offsets(static_cast<std::size_t>(n) + 1, 0);
    for (const SpringDesc &s : scene.springs)
        if (s.a != s.b && s.a >= 0 && s.b >= 0 && s.a < n && s.b < n) {
            ++offsets[static_cast<std::size_t>(s.a) + 1];
            ++offsets[static_cast<std::size_t>(s.b) + 1];
        }
    for (std::size_t i = 1; i < offsets.size(); ++i)
        offsets[i] += offsets[i - 1];
    std::vector<std::pair<int, int>> neighbours(static_cast<std::size_t>(offsets.back()));
    {
        std::vector<int> filled(offsets.begin(), offsets.end() - 1);
        for (int k = 0; k < springs; ++k) {
            const SpringDesc &s = scene.springs[static_cast<std::size_t>(k)];
            if (s.a == s.b || s.a < 0 || s.b < 0 || s.a >= n || s.b >= n)
                continue;
            neighbours[static_cast<std::size_t>(filled[static_cast<std::size_t>(s.a)]++)] = {s.b, k};
            neighbours[static_cast<std::size_t>(filled[static_cast<std::size_t>(s.b)]++)] = {s.a, k};
        }
    }
    std::vector<int> ends(static_cast<std::size_t>(n));  // one past each particle's last neighbour
    for (int i = 0; i < n; ++i) {
        const auto first = neighbours.begin() + offsets[static_cast<std::size_t>(i)];
        const auto last = neighbours.begin() + offsets[static_cast<std::size_t>(i) + 1];
        std::sort(first, last);
        const auto kept = std::unique(first, last, [](const auto &x, const auto &y) { return x.first == y.first; });
        ends[static_cast<std::size_t>(i)] = static_cast<int>(kept - neighbours.begin());
    }

    // every triple u < v < w joined pairwise, unless its corners lie on a line
    std::vector<Candidate> candidates;
    for (int u = 0; u < n; ++u) {
        const int uFirst = offsets[static_cast<std::size_t>(u)], uEnd = ends[static_cast<std::size_t>(u)];
        for (int a = uFirst; a < uEnd; ++a) {
            const auto [v, uv] = neighbours[static_cast<std::size_t>(a)];
            if (v < u)
                continue;
            // the neighbours w > v that u and v share
            int i = a + 1;
            int j = offsets[static_cast<std::size_t>(v)];
            const int vEnd = ends[static_cast<std::size_t>(v)];
            while (i < uEnd && j < vEnd) {
                // u's neighbours from a + 1 on are all past v
                const auto [wu, uw] = neighbours[static_cast<std::size_t>(i)];
                const auto [wv, vw] = neighbours[static_cast<std::size_t>(j)];
                if (wv <= v || wv < wu) {
                    ++j;
                    continue;
                }
                if (wu < wv) {
                    ++i;
                    continue;
                }
                ++i;
                ++j;
                const int w = wu;
                const Eigen::Vector3d pu = position(u), pv = position(v), pw = position(w);
                const double doubleArea = (pv - pu).cross(pw - pu).norm();
                const double longest =
                    std::max({(pv - pu).squaredNorm(), (pw - pv).squaredNorm(), (pu - pw).squaredNorm()});
                if (!(doubleArea > kThin * longest))
                    continue;
                candidates.push_back({doubleArea, {u, v, w}, {uv, vw, uw}});
            }
        }
    }

    // smallest first, by a counting sort on the area's logarithm in steps of 1/64 of a doubling (a
    // global sort took most of the time on a large cloth); within a step in the order found, which
    // is by corners, so that the choice depends on nothing else
    constexpr double kStepsPerDoubling = 64.0;
    std::vector<int> key(candidates.size());
    int lowest = 0, highest = 0;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
        key[c] = static_cast<int>(std::floor(std::log2(candidates[c].doubleArea) * kStepsPerDoubling));
        lowest = c == 0 ? key[c] : std::min(lowest, key[c]);
        highest = c == 0 ? key[c] : std::max(highest, key[c]);
    }
    std::vector<int> bucketStart(static_cast<std::size_t>(highest - lowest) + 2, 0);
    for (const int k : key)
        ++bucketStart[static_cast<std::size_t>(k - lowest) + 1];
    for (std::size_t b = 1; b < bucketStart.size(); ++b)
        bucketStart[b] += bucketStart[b - 1];
    std::vector<int> order(candidates.size());
    for (std::size_t c = 0; c < candidates.size(); ++c)
        order[static_cast<std::size_t>(bucketStart[static_cast<std::size_t>(key[c] - lowest)]++)] = static_cast<int>(c);

    // taken unless a side of it is a side of a taken triangle folded onto it; the taken triangles
    // on each spring as a list through their sides (entry 3 t + s)
    std::vector<Candidate> taken;
    std::vector<int> firstOn(static_cast<std::size_t>(springs), -1);
    std::vector<int> nextOn;
    for (const int index : order) {
        const Candidate &c = candidates[static_cast<std::size_t>(index)];
        bool overlaps = false;
        for (int s = 0; s < 3 && !overlaps; ++s) {
            const int p = c.corners[static_cast<std::size_t>(s)];
            const int q = c.corners[static_cast<std::size_t>((s + 1) % 3)];
            const int apex = c.corners[static_cast<std::size_t>((s + 2) % 3)];
            const Eigen::Vector3d e = (position(q) - position(p)).normalized();
            const Eigen::Vector3d mine = across(position(apex), position(p), e);
            for (int entry = firstOn[static_cast<std::size_t>(c.sides[static_cast<std::size_t>(s)])]; entry >= 0;
                 entry = nextOn[static_cast<std::size_t>(entry)]) {
                const Candidate &other = taken[static_cast<std::size_t>(entry / 3)];
                const int otherApex = other.corners[static_cast<std::size_t>((entry % 3 + 2) % 3)];
                const Eigen::Vector3d theirs = across(position(otherApex), position(p), e);
                const double dot = mine.dot(theirs);
                if (dot > 0.0 && dot * dot > kFoldedCosine * kFoldedCosine * mine.squaredNorm() * theirs.squaredNorm()) {
                    overlaps = true;
                    break;
                }
            }
        }
        if (overlaps)
            continue;
        const int t = static_cast<int>(taken.size());
        taken.push_back(c);
        nextOn.resize(nextOn.size() + 3);
        for (int s = 0; s < 3; ++s) {
            int &first = firstOn[static_cast<std::size_t>(c.sides[static_cast<std::size_t>(s)])];
            nextOn[static_cast<std::size_t>(3 * t + s)] = first;
            first = 3 * t + s;
        }
    }

    // turned alike across each side shared by exactly two triangles, walking outwards from the
    // first triangle of each piece, which faces up (+y, else +z, else +x)
    const int count = static_cast<int>(taken.size());
    auto flip = [](Candidate &c) {
        std::swap(c.corners[1], c.corners[2]);
        std::swap(c.sides[0], c.sides[2]);
    };
    auto normal = [&](const Candidate &c) {
        return Eigen::Vector3d((position(c.corners[1]) - position(c.corners[0]))
                                   .cross(position(c.corners[2]) - position(c.corners[0])));
    };
    std::vector<char> turned(static_cast<std::size_t>(count), 0);
    std::deque<int> queue;
    for (int start = 0; start < count; ++start) {
        if (turned[static_cast<std::size_t>(start)])
            continue;
        Candidate &first = taken[static_cast<std::size_t>(start)];
        const Eigen::Vector3d up = normal(first);
        const double lead = std::abs(up.y()) > 1e-9 * up.norm() ? up.y() : std::abs(up.z()) > 1e-9 * up.norm() ? up.z() : up.x();
        if (lead < 0.0)
            flip(first);
        turned[static_cast<std::size_t>(start)] = 1;
        queue.push_back(start);
        while (!queue.empty()) {
            const int t = queue.front();
            queue.pop_front();
            const Candidate &c = taken[static_cast<std::size_t>(t)];
            for (int s = 0; s < 3; ++s) {
                // the other triangle on this side, if it is the only other
                const int entry = firstOn[static_cast<std::size_t>(c.sides[static_cast<std::size_t>(s)])];
                const int second = nextOn[static_cast<std::size_t>(entry)];
                if (second < 0 || nextOn[static_cast<std::size_t>(second)] >= 0)
                    continue;
                const int u = (entry / 3 == t ? second : entry) / 3;
                if (turned[static_cast<std::size_t>(u)])
                    continue;
                // a neighbour turned alike runs along the common side the other way
                Candidate &other = taken[static_cast<std::size_t>(u)];
                const int from = c.corners[static_cast<std::size_t>(s)];
                for (int r = 0; r < 3; ++r)
                    if (other.sides[static_cast<std::size_t>(r)] == c.sides[static_cast<std::size_t>(s)] &&
                        other.corners[static_cast<std::size_t>(r)] == from) {
                        flip(other);
                        break;
                    }
                turned[static_cast<std::size_t>(u)] = 1;
                queue.push_back(u);
            }
        }
    }

    SpringTriangles triangles;
    triangles.springEnds.reserve(2 * scene.springs.size());
    for (const SpringDesc &s : scene.springs)
        triangles.springEnds.insert(triangles.springEnds.end(), {s.a, s.b});
    triangles.corners.reserve(3 * taken.size());
    triangles.sides.reserve(3 * taken.size());
    for (const Candidate &c : taken) {
        triangles.corners.insert(triangles.corners.end(), c.corners.begin(), c.corners.end());
        triangles.sides.insert(triangles.sides.end(), c.sides.begin(), c.sides.end());
    }
    return triangles;
}

}  // namespace core
