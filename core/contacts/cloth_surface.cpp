#include "core/contacts/cloth_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace core {

namespace {

std::uint64_t edgeKey(int a, int b)
{
    if (a > b)
        std::swap(a, b);
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

int pieceRoot(std::vector<int> &parent, int i)
{
    while (parent[std::size_t(i)] != i) {
        parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
        i = parent[std::size_t(i)];
    }
    return i;
}

}  // namespace

double automaticThickness(double meanRadius, double shortestSide)
{
    return std::min(2.0 * meanRadius, 0.3 * shortestSide);
}

bool listsTriangles(const SceneDesc &scene)
{
    return !scene.triangles.empty() || !scene.meshes.empty();
}

SpringTriangles sceneTriangles(const SceneDesc &scene)
{
    if (!listsTriangles(scene))
        return findSpringTriangles(scene);
    SpringTriangles triangles;
    std::unordered_map<std::uint64_t, int> springOf;
    springOf.reserve(scene.springs.size());
    triangles.springEnds.reserve(2 * scene.springs.size());
    for (std::size_t k = 0; k < scene.springs.size(); ++k) {
        const SpringDesc &s = scene.springs[k];
        triangles.springEnds.insert(triangles.springEnds.end(), {s.a, s.b});
        springOf.emplace(edgeKey(s.a, s.b), static_cast<int>(k));  // the first spring of a pair
    }
    triangles.corners.reserve(3 * scene.triangles.size());
    triangles.sides.reserve(3 * scene.triangles.size());
    for (const std::array<int, 3> &t : scene.triangles)
        for (int s = 0; s < 3; ++s) {
            triangles.corners.push_back(t[std::size_t(s)]);
            const auto found = springOf.find(edgeKey(t[std::size_t(s)], t[std::size_t((s + 1) % 3)]));
            triangles.sides.push_back(found == springOf.end() ? -1 : found->second);
        }
    return triangles;
}

std::vector<std::array<int, 3>> listedTriangles(const SceneDesc &scene)
{
    if (listsTriangles(scene))
        return scene.triangles;
    const SpringTriangles found = findSpringTriangles(scene);
    std::vector<std::array<int, 3>> corners(std::size_t(found.count()));
    for (std::size_t t = 0; t < corners.size(); ++t)
        corners[t] = {found.corners[3 * t], found.corners[3 * t + 1], found.corners[3 * t + 2]};
    return corners;
}

ClothSurface makeClothSurface(const SceneDesc &scene, const SpringTriangles &triangles)
{
    ClothSurface surface;
    const int n = static_cast<int>(scene.particles.size());
    const int count = triangles.count();
    surface.selfCollision = scene.settings.selfCollision;
    surface.vertexSheet.assign(std::size_t(n), -1);
    surface.contactRadius.resize(std::size_t(n));
    for (int i = 0; i < n; ++i)
        surface.contactRadius[std::size_t(i)] = scene.particles[std::size_t(i)].radius;
    if (count == 0)
        return surface;

    // the mesh's edges, each with the triangles on it
    std::unordered_map<std::uint64_t, int> edgeOf;
    edgeOf.reserve(std::size_t(3 * count));
    std::vector<int> edgeEnds, trianglesOn;  // trianglesOn: how many triangles border each edge
    std::vector<int> edgeTriangles;
    std::vector<int> triangleEdges(std::size_t(3 * count));
    for (int t = 0; t < count; ++t)
        for (int s = 0; s < 3; ++s) {
            const int a = triangles.corners[std::size_t(3 * t + s)];
            const int b = triangles.corners[std::size_t(3 * t + (s + 1) % 3)];
            const auto [it, added] = edgeOf.emplace(edgeKey(a, b), static_cast<int>(trianglesOn.size()));
            if (added) {
                edgeEnds.insert(edgeEnds.end(), {std::min(a, b), std::max(a, b)});
                trianglesOn.push_back(0);
                edgeTriangles.insert(edgeTriangles.end(), {-1, -1});
            }
            const int e = it->second;
            if (trianglesOn[std::size_t(e)] < 2)
                edgeTriangles[std::size_t(2 * e + trianglesOn[std::size_t(e)])] = t;
            ++trianglesOn[std::size_t(e)];
            triangleEdges[std::size_t(3 * t + s)] = e;
        }

    // pieces: particles joined through triangles; a piece with an edge of three or more triangles
    // is a lattice's, not a sheet, where the springs made the triangles (a listed mesh's are a
    // surface, a non-manifold one too: a chair's seat where its legs meet it)
    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    for (int t = 0; t < count; ++t)
        for (int s = 1; s < 3; ++s) {
            const int a = pieceRoot(parent, triangles.corners[std::size_t(3 * t)]);
            const int b = pieceRoot(parent, triangles.corners[std::size_t(3 * t + s)]);
            if (a != b)
                parent[std::size_t(std::max(a, b))] = std::min(a, b);
        }
    std::vector<std::uint8_t> lattice(std::size_t(n), 0);
    for (std::size_t e = 0; e < trianglesOn.size(); ++e)
        if (trianglesOn[e] > 2 && !listsTriangles(scene))
            lattice[std::size_t(pieceRoot(parent, edgeEnds[2 * e]))] = 1;

    // sheets numbered in the order of their lowest particle
    std::vector<int> sheetOfRoot(std::size_t(n), -1);
    int sheets = 0;
    for (int i = 0; i < n; ++i)
        if (pieceRoot(parent, i) == i && !lattice[std::size_t(i)])
            sheetOfRoot[std::size_t(i)] = -2;  // a candidate; numbered once it has a triangle
    std::vector<int> triangleIndex(std::size_t(count), -1);
    for (int t = 0; t < count; ++t) {
        const int r = pieceRoot(parent, triangles.corners[std::size_t(3 * t)]);
        if (sheetOfRoot[std::size_t(r)] == -1)
            continue;
        if (sheetOfRoot[std::size_t(r)] == -2)
            sheetOfRoot[std::size_t(r)] = sheets++;
        triangleIndex[std::size_t(t)] = surface.triangleCount();
        surface.triangleSheet.push_back(sheetOfRoot[std::size_t(r)]);
        for (int s = 0; s < 3; ++s) {
            surface.corners.push_back(triangles.corners[std::size_t(3 * t + s)]);
            surface.sides.push_back(triangles.sides[std::size_t(3 * t + s)]);
        }
    }
    // the edges in the order of their particles, so that a sheet that lost triangles (a torn sheet
    // stored and loaded again) keeps its edges in the same order
    std::vector<int> edgeOrder(trianglesOn.size());
    std::iota(edgeOrder.begin(), edgeOrder.end(), 0);
    std::sort(edgeOrder.begin(), edgeOrder.end(), [&](int x, int y) {
        return std::pair(edgeEnds[std::size_t(2 * x)], edgeEnds[std::size_t(2 * x + 1)]) <
               std::pair(edgeEnds[std::size_t(2 * y)], edgeEnds[std::size_t(2 * y + 1)]);
    });
    for (const int edge : edgeOrder) {
        const std::size_t e = std::size_t(edge);
        const int first = triangleIndex[std::size_t(edgeTriangles[2 * e])];
        if (first < 0)
            continue;
        const int second = edgeTriangles[2 * e + 1] < 0 ? -1 : triangleIndex[std::size_t(edgeTriangles[2 * e + 1])];
        surface.edgeEnds.insert(surface.edgeEnds.end(), {edgeEnds[2 * e], edgeEnds[2 * e + 1]});
        surface.edgeTriangles.insert(surface.edgeTriangles.end(), {first, second});
        surface.edgeSheet.push_back(surface.triangleSheet[std::size_t(first)]);
    }

    // each sheet's thickness: the setting's, or its own from its corners' radii and shortest side
    std::vector<double> radiusSum(std::size_t(sheets), 0.0), shortest(std::size_t(sheets),
                                                                      std::numeric_limits<double>::infinity());
    std::vector<int> cornerCount(std::size_t(sheets), 0);
    for (int t = 0; t < surface.triangleCount(); ++t) {
        const int sheet = surface.triangleSheet[std::size_t(t)];
        for (int s = 0; s < 3; ++s) {
            const int a = surface.corners[std::size_t(3 * t + s)];
            const int b = surface.corners[std::size_t(3 * t + (s + 1) % 3)];
            // a side's rest length where a spring joins its corners (which a run does not change, so
            // that a run resumed from a stored state has the same thickness), else its length
            const int spring = surface.sides[std::size_t(3 * t + s)];
            const double side = spring >= 0 && scene.springs[std::size_t(spring)].restLength > 0.0
                                    ? scene.springs[std::size_t(spring)].restLength
                                    : (scene.particles[std::size_t(a)].position - scene.particles[std::size_t(b)].position).norm();
            if (side > 0.0)
                shortest[std::size_t(sheet)] = std::min(shortest[std::size_t(sheet)], side);
            if (surface.vertexSheet[std::size_t(a)] < 0) {
                surface.vertexSheet[std::size_t(a)] = sheet;
                radiusSum[std::size_t(sheet)] += scene.particles[std::size_t(a)].radius;
                ++cornerCount[std::size_t(sheet)];
            }
        }
    }
    surface.sheetThickness.resize(std::size_t(sheets));
    for (int s = 0; s < sheets; ++s) {
        const double own = automaticThickness(radiusSum[std::size_t(s)] / std::max(1, cornerCount[std::size_t(s)]),
                                              std::isfinite(shortest[std::size_t(s)]) ? shortest[std::size_t(s)] : 0.0);
        surface.sheetThickness[std::size_t(s)] = scene.settings.thickness > 0.0 ? scene.settings.thickness : own;
    }
    for (int i = 0; i < n; ++i)
        if (surface.vertexSheet[std::size_t(i)] >= 0)
            surface.contactRadius[std::size_t(i)] = 0.5 * surface.sheetThickness[std::size_t(surface.vertexSheet[std::size_t(i)])];
    return surface;
}

}  // namespace core
