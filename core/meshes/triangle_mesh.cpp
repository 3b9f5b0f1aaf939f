#include "core/meshes/triangle_mesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace core {

namespace {

std::uint64_t meshEdgeKey(int a, int b)
{
    return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
}

// a grid cell of the welding hash: the position over the tolerance, rounded down
struct WeldCell {
    std::int64_t x, y, z;
    bool operator==(const WeldCell &) const = default;
};
struct WeldCellHash {
    std::size_t operator()(const WeldCell &c) const
    {
        return std::size_t(c.x * 73856093LL ^ c.y * 19349663LL ^ c.z * 83492791LL);
    }
};

}  // namespace

WeldedMesh weldVertices(const TriangleMesh &mesh, double tolerance)
{
    WeldedMesh welded;
    const std::size_t n = mesh.vertices.size();
    std::vector<char> used(n, 0);
    for (const std::array<int, 3> &f : mesh.faces)
        for (int v : f)
            used[std::size_t(v)] = 1;

    // cells of the tolerance's size: two vertices within it share a cell or are neighbours
    const double cell = tolerance > 0.0 ? tolerance : 1.0;
    const auto cellOf = [&](const Eigen::Vector3d &p) {
        return WeldCell{std::int64_t(std::floor(p.x() / cell)), std::int64_t(std::floor(p.y() / cell)),
                        std::int64_t(std::floor(p.z() / cell))};
    };
    std::unordered_map<WeldCell, std::vector<int>, WeldCellHash> points;
    points.reserve(n);
    welded.pointOf.assign(n, -1);
    for (std::size_t v = 0; v < n; ++v) {
        if (!used[v])
            continue;
        const Eigen::Vector3d &p = mesh.vertices[v];
        const WeldCell c = cellOf(p);
        int found = -1;
        for (std::int64_t dx = -1; dx <= 1 && found < 0; ++dx)
            for (std::int64_t dy = -1; dy <= 1 && found < 0; ++dy)
                for (std::int64_t dz = -1; dz <= 1 && found < 0; ++dz) {
                    const auto it = points.find({c.x + dx, c.y + dy, c.z + dz});
                    if (it == points.end())
                        continue;
                    for (int q : it->second)
                        if ((welded.points[std::size_t(q)] - p).cwiseAbs().maxCoeff() <= tolerance) {
                            found = q;
                            break;
                        }
                }
        if (found < 0) {
            found = static_cast<int>(welded.points.size());
            welded.points.push_back(p);
            points[c].push_back(found);
        }
        welded.pointOf[v] = found;
    }
    welded.faces.reserve(mesh.faces.size());
    for (const std::array<int, 3> &f : mesh.faces) {
        const std::array<int, 3> t{welded.pointOf[std::size_t(f[0])], welded.pointOf[std::size_t(f[1])],
                                   welded.pointOf[std::size_t(f[2])]};
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            ++welded.droppedFaces;
        else
            welded.faces.push_back(t);
    }
    return welded;
}

MeshEdges meshEdges(const std::vector<std::array<int, 3>> &faces, int pointCount)
{
    (void)pointCount;
    MeshEdges edges;
    std::unordered_map<std::uint64_t, int> edgeOf;
    edgeOf.reserve(faces.size() * 3 / 2 + 1);
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (int s = 0; s < 3; ++s) {
            const int a = faces[f][std::size_t(s)], b = faces[f][std::size_t((s + 1) % 3)];
            const auto [it, added] = edgeOf.emplace(meshEdgeKey(a, b), static_cast<int>(edges.ends.size()));
            if (added) {
                edges.ends.push_back({std::min(a, b), std::max(a, b)});
                edges.faces.push_back({-1, -1});
                edges.faceCount.push_back(0);
            }
            const std::size_t e = std::size_t(it->second);
            if (edges.faceCount[e] < 2)
                edges.faces[e][std::size_t(edges.faceCount[e])] = static_cast<int>(f);
            ++edges.faceCount[e];
        }
    for (int count : edges.faceCount) {
        edges.boundary += count == 1;
        edges.nonManifold += count > 2;
    }
    return edges;
}

double surfaceArea(const std::vector<Eigen::Vector3d> &points, const std::vector<std::array<int, 3>> &faces,
                   std::vector<double> *pointShare)
{
    if (pointShare)
        pointShare->assign(points.size(), 0.0);
    double total = 0.0;
    for (const std::array<int, 3> &f : faces) {
        const Eigen::Vector3d &a = points[std::size_t(f[0])], &b = points[std::size_t(f[1])],
                              &c = points[std::size_t(f[2])];
        const double area = 0.5 * (b - a).cross(c - a).norm();
        total += area;
        if (pointShare)
            for (int v : f)
                (*pointShare)[std::size_t(v)] += area / 3.0;
    }
    return total;
}

double enclosedVolume(const std::vector<Eigen::Vector3d> &points, const std::vector<std::array<int, 3>> &faces)
{
    // the divergence theorem: the signed volumes of the tetrahedra each face makes with a point
    // inside its box (the origin would lose digits far from it)
    const Eigen::Vector3d centre = 0.5 * (boundingBox(points).low + boundingBox(points).high);
    double six = 0.0;
    for (const std::array<int, 3> &f : faces)
        six += (points[std::size_t(f[0])] - centre)
                   .dot((points[std::size_t(f[1])] - centre).cross(points[std::size_t(f[2])] - centre));
    return six / 6.0;
}

void triangulatePolygon(const std::vector<Eigen::Vector3d> &corners, std::vector<std::array<int, 3>> &out)
{
    const int n = int(corners.size());
    if (n < 3)
        return;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // Newell's: twice the area, along the turn
    for (int i = 0; i < n; ++i)
        normal += corners[std::size_t(i)].cross(corners[std::size_t((i + 1) % n)]);
    const double twiceArea = normal.norm();
    std::vector<int> left(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        left[std::size_t(i)] = i;
    const auto fan = [&] {
        for (std::size_t i = 1; i + 1 < left.size(); ++i)
            out.push_back({left[0], left[i], left[i + 1]});
    };
    if (!(twiceArea > 0.0) || n == 3) {
        fan();
        return;
    }
    normal /= twiceArea;
    // 2D coordinates in the plane, turning counter-clockwise about the normal
    const Eigen::Vector3d u = normal.unitOrthogonal();
    const Eigen::Vector3d v = normal.cross(u);
    std::vector<Eigen::Vector2d> flat(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        flat[std::size_t(i)] = {corners[std::size_t(i)].dot(u), corners[std::size_t(i)].dot(v)};
    const auto turn = [&](int a, int b, int c) {
        const Eigen::Vector2d ab = flat[std::size_t(b)] - flat[std::size_t(a)];
        const Eigen::Vector2d ac = flat[std::size_t(c)] - flat[std::size_t(a)];
        return ab.x() * ac.y() - ab.y() * ac.x();
    };
    const double tiny = 1e-12 * twiceArea;
    while (left.size() > 3) {
        const std::size_t m = left.size();
        bool clipped = false;
        for (std::size_t i = 0; i < m && !clipped; ++i) {
            const int a = left[(i + m - 1) % m], b = left[i], c = left[(i + 1) % m];
            if (turn(a, b, c) <= tiny)
                continue;  // a reflex (or flat) corner is no ear
            bool empty = true;
            for (std::size_t j = 0; j < m && empty; ++j) {
                const int p = left[j];
                if (p == a || p == b || p == c || flat[std::size_t(p)] == flat[std::size_t(a)] ||
                    flat[std::size_t(p)] == flat[std::size_t(b)] || flat[std::size_t(p)] == flat[std::size_t(c)])
                    continue;
                empty = !(turn(a, b, p) >= 0.0 && turn(b, c, p) >= 0.0 && turn(c, a, p) >= 0.0);
            }
            if (!empty)
                continue;
            out.push_back({a, b, c});
            left.erase(left.begin() + std::ptrdiff_t(i));
            clipped = true;
        }
        if (!clipped)
            break;  // a self-crossing outline: what is left goes as a fan
    }
    fan();
}

Box boundingBox(const std::vector<Eigen::Vector3d> &points)
{
    Box box;
    if (points.empty())
        return box;
    box.low = box.high = points.front();
    for (const Eigen::Vector3d &p : points) {
        box.low = box.low.cwiseMin(p);
        box.high = box.high.cwiseMax(p);
    }
    return box;
}

}  // namespace core
