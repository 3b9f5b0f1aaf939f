#include "core/contacts/surface_crossings.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace core {

namespace {

// six times the signed volume of tetrahedron p a b c
double orientation(const Eigen::Vector3d &p, const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &c)
{
    return (a - p).dot((b - p).cross(c - p));
}

std::uint64_t crossingCell(long long x, long long y, long long z)
{
    return std::uint64_t(x) * 0x9E3779B97F4A7C15ull ^ std::uint64_t(y) * 0xC2B2AE3D27D4EB4Full ^
           std::uint64_t(z) * 0x165667B19E3779F9ull;
}

}  // namespace

bool segmentCrossesTriangle(const Eigen::Vector3d &p, const Eigen::Vector3d &q, const Eigen::Vector3d &a,
                            const Eigen::Vector3d &b, const Eigen::Vector3d &c)
{
    const double sp = orientation(p, a, b, c), sq = orientation(q, a, b, c);
    if (!((sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0)))
        return false;
    // the line p q passes inside a b c when it turns the same way about each side
    const double u = orientation(p, q, a, b), v = orientation(p, q, b, c), w = orientation(p, q, c, a);
    return (u > 0.0 && v > 0.0 && w > 0.0) || (u < 0.0 && v < 0.0 && w < 0.0);
}

int countCrossings(const ClothSurface &surface, const Eigen::Matrix3Xd &x, const std::vector<std::uint8_t> &springBroken)
{
    const int triangles = surface.triangleCount();
    if (triangles == 0)
        return 0;
    auto broken = [&](int spring) {
        return spring >= 0 && !springBroken.empty() && springBroken[std::size_t(spring)] != 0;
    };
    std::vector<std::uint8_t> whole(std::size_t(triangles), 1);
    double extent = 0.0;
    for (int t = 0; t < triangles; ++t) {
        const int *c = &surface.corners[std::size_t(3 * t)];
        for (int s = 0; s < 3; ++s)
            if (broken(surface.sides[std::size_t(3 * t + s)]))
                whole[std::size_t(t)] = 0;
        extent += (x.col(c[0]).cwiseMax(x.col(c[1])).cwiseMax(x.col(c[2])) -
                   x.col(c[0]).cwiseMin(x.col(c[1])).cwiseMin(x.col(c[2])))
                      .maxCoeff();
    }
    const double size = extent > 0.0 && std::isfinite(extent) ? extent / triangles : 1.0;
    auto cell = [&](double v) { return static_cast<long long>(std::clamp(std::floor(v / size), -1e15, 1e15)); };

    // the whole triangles by the grid cells their boxes cover
    std::unordered_map<std::uint64_t, std::vector<int>> grid;
    for (int t = 0; t < triangles; ++t) {
        if (!whole[std::size_t(t)])
            continue;
        const int *c = &surface.corners[std::size_t(3 * t)];
        const Eigen::Vector3d low = x.col(c[0]).cwiseMin(x.col(c[1])).cwiseMin(x.col(c[2]));
        const Eigen::Vector3d high = x.col(c[0]).cwiseMax(x.col(c[1])).cwiseMax(x.col(c[2]));
        if (!low.allFinite() || !high.allFinite())
            continue;
        for (long long i = cell(low.x()); i <= cell(high.x()); ++i)
            for (long long j = cell(low.y()); j <= cell(high.y()); ++j)
                for (long long k = cell(low.z()); k <= cell(high.z()); ++k)
                    grid[crossingCell(i, j, k)].push_back(t);
    }

    int crossings = 0;
    std::vector<int> seen;
    for (int e = 0; e < surface.edgeCount(); ++e) {
        const int first = surface.edgeTriangles[std::size_t(2 * e)], second = surface.edgeTriangles[std::size_t(2 * e + 1)];
        if (!whole[std::size_t(first)] && (second < 0 || !whole[std::size_t(second)]))
            continue;  // torn free
        const int a = surface.edgeEnds[std::size_t(2 * e)], b = surface.edgeEnds[std::size_t(2 * e + 1)];
        const Eigen::Vector3d low = x.col(a).cwiseMin(x.col(b)), high = x.col(a).cwiseMax(x.col(b));
        if (!low.allFinite() || !high.allFinite())
            continue;
        seen.clear();
        for (long long i = cell(low.x()); i <= cell(high.x()); ++i)
            for (long long j = cell(low.y()); j <= cell(high.y()); ++j)
                for (long long k = cell(low.z()); k <= cell(high.z()); ++k) {
                    const auto found = grid.find(crossingCell(i, j, k));
                    if (found != grid.end())
                        seen.insert(seen.end(), found->second.begin(), found->second.end());
                }
        std::sort(seen.begin(), seen.end());
        seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
        for (const int t : seen) {
            const int *c = &surface.corners[std::size_t(3 * t)];
            if (c[0] == a || c[1] == a || c[2] == a || c[0] == b || c[1] == b || c[2] == b)
                continue;
            if (segmentCrossesTriangle(x.col(a), x.col(b), x.col(c[0]), x.col(c[1]), x.col(c[2])))
                ++crossings;
        }
    }
    return crossings;
}

}  // namespace core
