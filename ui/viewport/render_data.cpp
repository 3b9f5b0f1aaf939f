#include "render_data.h"

#include "core/contacts/colliders.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <utility>

namespace ui {

namespace {

// appends one vertex of position and colour
void pushVertex(std::vector<float> &out, const QVector3D &p, const Rgb &c, float alpha = 1.0f)
{
    const std::size_t at = out.size();
    out.resize(at + kVertexFloats);
    float *v = out.data() + at;
    v[0] = p.x();
    v[1] = p.y();
    v[2] = p.z();
    v[3] = c[0];
    v[4] = c[1];
    v[5] = c[2];
    v[6] = alpha;
}

Rgb mix(const Rgb &a, const Rgb &b, float t)
{
    return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

QVector3D toVector(const Eigen::Vector3d &v) { return QVector3D(float(v.x()), float(v.y()), float(v.z())); }

// a grid's lines at most this many steps either side of its middle
constexpr int kMaxHalfCells = 100;

// lines across the rectangle centre ± halfU u ± halfV v, at whole steps from its centre, both ways
void pushGridLines(std::vector<float> &out, const QVector3D &centre, const QVector3D &u, const QVector3D &v,
                   float halfU, float halfV, float step)
{
    // a step's share is allowed for rounding, so that a grid of whole steps keeps its outer lines
    const int cellsU = std::min(kMaxHalfCells, int(std::floor(halfU / step + 1.0e-3f)));
    const int cellsV = std::min(kMaxHalfCells, int(std::floor(halfV / step + 1.0e-3f)));
    for (int i = -cellsU; i <= cellsU; ++i) {
        pushVertex(out, centre + u * (float(i) * step) - v * halfV, kGridColour);
        pushVertex(out, centre + u * (float(i) * step) + v * halfV, kGridColour);
    }
    for (int i = -cellsV; i <= cellsV; ++i) {
        pushVertex(out, centre + v * (float(i) * step) - u * halfU, kGridColour);
        pushVertex(out, centre + v * (float(i) * step) + u * halfU, kGridColour);
    }
}

// about ten cells across the scene
float gridStep(const Sphere &scene) { return niceStep(std::max(scene.radius, 0.5f) / 4.0f); }

// the square grid about the scene on the plane through origin with the unit normal n, snapped to
// whole steps from origin so that it does not crawl as the scene moves
void pushPlaneGrid(std::vector<float> &out, const QVector3D &origin, const QVector3D &n, const Sphere &scene)
{
    const float step = gridStep(scene);
    const int halfCells = std::min(kMaxHalfCells, int(std::ceil(2.5f * std::max(scene.radius, 0.5f) / step)));
    const float half = float(halfCells) * step;
    // the plane's own directions: x along it, and the normal × that
    const QVector3D u = (QVector3D(1.0f, 0.0f, 0.0f) - n.x() * n).normalized();
    const QVector3D v = QVector3D::crossProduct(n, u);
    const QVector3D fromOrigin = scene.centre - origin;
    const float a = std::round(QVector3D::dotProduct(fromOrigin, u) / step) * step;
    const float b = std::round(QVector3D::dotProduct(fromOrigin, v) / step) * step;
    pushGridLines(out, origin + a * u + b * v, u, v, half, half, step);
}

}  // namespace

Rgb strainColour(float strain, float fullStrain)
{
    // linear in the strain up to the full scale, then saturated; not-a-number shows as rest
    if (!(fullStrain > 0.0f) || !std::isfinite(strain))
        return kRestColour;
    const float t = std::clamp(strain / fullStrain, -1.0f, 1.0f);
    return t < 0.0f ? mix(kRestColour, kCompressedColour, -t) : mix(kRestColour, kStretchedColour, t);
}

Rgb ParticleStyle::colour(int i) const
{
    const float *v = values.data() + std::size_t(i) * kStyleFloats;
    return {v[1], v[2], v[3]};
}

ParticleStyle packParticleStyle(const core::Snapshot &snapshot, const std::vector<int> &selection, int hover,
                                const std::vector<std::uint8_t> &hidden)
{
    const int n = snapshot.particleCount();
    std::vector<std::uint8_t> selected(std::size_t(n), 0);
    for (int i : selection)
        if (i >= 0 && i < n)
            selected[std::size_t(i)] = 1;

    // selection wins over pinned for the colour, pinned over free; the marks keep both
    ParticleStyle style;
    style.values.resize(std::size_t(n) * kStyleFloats);
    for (int i = 0; i < n; ++i) {
        const bool pinned = i < int(snapshot.pinned.size()) && snapshot.pinned[std::size_t(i)] != 0;
        const bool isSelected = selected[std::size_t(i)] != 0;
        const Rgb &c = i == hover ? kHoverColour : isSelected ? kSelectedColour : pinned ? kPinnedColour : kFreeColour;
        float *v = style.values.data() + std::size_t(i) * kStyleFloats;
        const bool shown = i == hover || isSelected || i >= int(hidden.size()) || hidden[std::size_t(i)] == 0;
        v[0] = shown ? snapshot.radii[std::size_t(i)] : 0.0f;
        v[1] = c[0];
        v[2] = c[1];
        v[3] = c[2];
        v[4] = pinned ? 1.0f : 0.0f;
        v[5] = isSelected ? 1.0f : 0.0f;
    }
    return style;
}

DrawnParticles drawnParticles(const ParticleStyle &style)
{
    DrawnParticles drawn;
    const int n = style.count();
    int first = 0;
    while (first < n && style.radius(first) != 0.0f)
        ++first;
    if (first == n)
        return drawn;
    drawn.all = false;
    drawn.rows.reserve(std::size_t(first));
    for (int i = 0; i < n; ++i)
        if (style.radius(i) != 0.0f)
            drawn.rows.push_back(std::uint32_t(i));
    return drawn;
}

void gatherRows(const float *from, int width, const std::vector<std::uint32_t> &rows, std::vector<float> &to)
{
    const std::size_t w = std::size_t(width);
    to.resize(rows.size() * w);
    for (std::size_t k = 0; k < rows.size(); ++k)
        std::copy_n(from + rows[k] * w, w, to.data() + k * w);
}

bool StyleKey::matches(const core::Snapshot &snapshot) const
{
    // bitwise, so that a radius that became NaN still counts as a change
    return m_valid && m_radii.size() == snapshot.radii.size() && m_pinned == snapshot.pinned &&
           std::memcmp(m_radii.data(), snapshot.radii.data(), m_radii.size() * sizeof(float)) == 0;
}

void StyleKey::remember(const core::Snapshot &snapshot)
{
    m_radii = snapshot.radii;
    m_pinned = snapshot.pinned;
    m_valid = true;
}

void StyleKey::clear()
{
    m_valid = false;
    m_radii.clear();
    m_pinned.clear();
}

int packSpringLines(const core::Snapshot &snapshot, std::vector<float> &vertices, float fullStrain,
                    const SpringHighlight &highlight, const std::vector<std::uint8_t> &hidden)
{
    // end a then end b of each spring, both in the spring's colour
    const int springs = snapshot.springCount();
    vertices.clear();
    if (snapshot.springEnds.size() < std::size_t(springs) * 6)
        return 0;
    std::vector<std::uint8_t> selected(std::size_t(springs), 0);
    for (int s : highlight.selected)
        if (s >= 0 && s < springs)
            selected[std::size_t(s)] = 1;
    auto highlighted = [&](int s) { return s == highlight.hover || selected[std::size_t(s)] != 0; };
    auto push = [&](int s, const Rgb &c) {
        const float *e = snapshot.springEnds.data() + std::size_t(s) * 6;
        pushVertex(vertices, QVector3D(e[0], e[1], e[2]), c);
        pushVertex(vertices, QVector3D(e[3], e[4], e[5]), c);
    };
    vertices.reserve(std::size_t(springs) * 2 * kVertexFloats);

    // a broken spring is gone from the picture; a hidden one is left out unless highlighted
    for (int s = 0; s < springs; ++s)
        if (!snapshot.isBroken(s) && !highlighted(s) && (s >= int(hidden.size()) || hidden[std::size_t(s)] == 0))
            push(s, strainColour(snapshot.springStrain[s], fullStrain));
    int last = 0;
    for (int s = 0; s < springs; ++s)
        if (!snapshot.isBroken(s) && highlighted(s)) {
            push(s, s == highlight.hover ? kHoverColour : kSelectedColour);
            ++last;
        }
    return last;
}

Sphere particleBounds(const core::Snapshot &snapshot)
{
    // particles whose position or radius is not finite (a blown-up run) are left out
    const int n = std::min<int>(snapshot.particleCount(), int(snapshot.positions.size() / 3));
    auto position = [&](int i) {
        const float *p = snapshot.positions.data() + 3 * i;
        return QVector3D(p[0], p[1], p[2]);
    };
    auto usable = [&](int i) {
        const QVector3D p = position(i);
        return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()) && std::isfinite(snapshot.radii[i]);
    };

    // the centre of the bounding box
    bool any = false;
    QVector3D lo, hi;
    for (int i = 0; i < n; ++i) {
        if (!usable(i))
            continue;
        const QVector3D p = position(i);
        lo = any ? QVector3D(std::min(lo.x(), p.x()), std::min(lo.y(), p.y()), std::min(lo.z(), p.z())) : p;
        hi = any ? QVector3D(std::max(hi.x(), p.x()), std::max(hi.y(), p.y()), std::max(hi.z(), p.z())) : p;
        any = true;
    }
    if (!any)
        return {};

    // then the farthest surface from it
    Sphere sphere{(lo + hi) * 0.5f, 0.0f};
    for (int i = 0; i < n; ++i)
        if (usable(i))
            sphere.radius =
                std::max(sphere.radius, (position(i) - sphere.centre).length() + std::max(snapshot.radii[i], 0.0f));
    return sphere;
}

float niceStep(float length)
{
    // 1, 2 or 5 times the power of ten at or below the length
    if (!(length > 0.0f) || !std::isfinite(length))
        return 1.0f;
    const float power = std::pow(10.0f, std::floor(std::log10(length)));
    const float mantissa = length / power;
    return power * (mantissa < 2.0f ? 1.0f : mantissa < 5.0f ? 2.0f : 5.0f);
}

std::vector<float> packGrid(const Sphere &scene, float height)
{
    std::vector<float> vertices;
    pushPlaneGrid(vertices, QVector3D(0.0f, height, 0.0f), QVector3D(0.0f, 1.0f, 0.0f), scene);
    return vertices;
}

bool isFloor(const core::PlaneDesc &plane)
{
    const QVector3D n = toVector(plane.normal).normalized();
    return n.y() >= kFloorNormalY;
}

namespace {

// an unbounded one-sided plane with the scene's centre on its inner side: a wall of the room the
// scene is in, which cuts the other planes' squares
bool enclosesScene(const core::PlaneDesc &plane, const QVector3D &n, const Sphere &scene)
{
    return !plane.bounded() && !plane.twoSided && !n.isNull() &&
           QVector3D::dotProduct(n, scene.centre) >= float(plane.offset);
}

// the part of a convex polygon on the inner side of the plane n·x = offset (n·x ≥ offset)
std::vector<QVector3D> clipToInside(const std::vector<QVector3D> &polygon, const QVector3D &n, float offset)
{
    std::vector<QVector3D> kept;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const QVector3D &a = polygon[k];
        const QVector3D &b = polygon[(k + 1) % polygon.size()];
        const float da = QVector3D::dotProduct(n, a) - offset;
        const float db = QVector3D::dotProduct(n, b) - offset;
        if (da >= 0.0f)
            kept.push_back(a);
        if ((da >= 0.0f) != (db >= 0.0f))
            kept.push_back(a + (b - a) * (da / (da - db)));
    }
    return kept;
}

// keeps the part of each line (a pair of vertices from `first` on) inside the walls around the scene
// other than `skip`: a pool's grid ends at its walls
void clipLinesToWalls(std::vector<float> &vertices, std::size_t first, const std::vector<core::PlaneDesc> &planes,
                      std::size_t skip, const Sphere &scene)
{
    std::vector<float> kept(vertices.begin(), vertices.begin() + std::ptrdiff_t(first));
    for (std::size_t at = first; at + 2 * kVertexFloats <= vertices.size(); at += 2 * kVertexFloats) {
        const QVector3D a(vertices[at], vertices[at + 1], vertices[at + 2]);
        const QVector3D b(vertices[at + kVertexFloats], vertices[at + kVertexFloats + 1], vertices[at + kVertexFloats + 2]);
        float from = 0.0f, to = 1.0f;
        for (std::size_t q = 0; q < planes.size() && from <= to; ++q) {
            const QVector3D n = toVector(planes[q].normal).normalized();
            if (q == skip || !enclosesScene(planes[q], n, scene))
                continue;
            const float da = QVector3D::dotProduct(n, a) - float(planes[q].offset);
            const float db = QVector3D::dotProduct(n, b) - float(planes[q].offset);
            if (da < 0.0f && db < 0.0f)
                to = -1.0f;
            else if (da < 0.0f)
                from = std::max(from, da / (da - db));
            else if (db < 0.0f)
                to = std::min(to, da / (da - db));
        }
        if (!(from < to))
            continue;
        // each end keeps its own colour
        const float ends[2] = {from, to};
        for (int e = 0; e < 2; ++e) {
            const QVector3D x = a + (b - a) * ends[e];
            const std::size_t source = at + std::size_t(e) * kVertexFloats;
            kept.insert(kept.end(), {x.x(), x.y(), x.z()});
            kept.insert(kept.end(), vertices.begin() + std::ptrdiff_t(source + 3),
                        vertices.begin() + std::ptrdiff_t(source + kVertexFloats));
        }
    }
    vertices = std::move(kept);
}

}  // namespace

std::vector<float> packFloorGrids(const std::vector<core::PlaneDesc> &planes, const Sphere &scene)
{
    std::vector<float> vertices;
    for (std::size_t p = 0; p < planes.size(); ++p) {
        const core::PlaneDesc &plane = planes[p];
        if (!isFloor(plane))
            continue;
        // a hair above the floor, so that the floor's translucent square does not hide it
        const QVector3D n = toVector(plane.normal).normalized();
        const QVector3D lift = n * (1.0e-4f * std::max(scene.radius, 0.5f));
        if (!plane.bounded()) {
            const std::size_t first = vertices.size();
            pushPlaneGrid(vertices, n * float(plane.offset) + lift, n, scene);
            clipLinesToWalls(vertices, first, planes, p, scene);
            continue;
        }
        // a rectangle (a table top): lines across it, from its middle out to its edges, with no
        // more of them than a whole plane's grid has
        const core::Collider quad = core::makeCollider(plane, core::Settings{});
        const float halfU = float(quad.halfWidth);
        const float halfV = float(quad.halfHeight);
        float step = gridStep(scene);
        while (std::max(halfU, halfV) / step > float(kMaxHalfCells))
            step = niceStep(2.5f * step);
        pushGridLines(vertices, toVector(quad.centre) + lift, toVector(quad.axisU), toVector(quad.axisV), halfU, halfV,
                      step);
    }
    return vertices;
}

SphereMesh icosphere(int subdivisions)
{
    // the icosahedron: three golden rectangles, in the planes x = 0, y = 0 and z = 0
    const float phi = (1.0f + std::sqrt(5.0f)) * 0.5f;
    std::vector<QVector3D> points = {
        {-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
        {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1},
    };
    std::vector<std::array<std::uint32_t, 3>> faces = {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
        {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1},
    };
    for (QVector3D &p : points)
        p.normalize();

    // each split adds one vertex per edge, shared by the edge's two faces
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const std::pair<std::uint32_t, std::uint32_t> key = std::minmax(a, b);
            const auto found = midpoints.find(key);
            if (found != midpoints.end())
                return found->second;
            points.push_back((points[a] + points[b]).normalized());
            const auto index = std::uint32_t(points.size() - 1);
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        finer.reserve(faces.size() * 4);
        for (const auto &[a, b, c] : faces) {
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({b, bc, ab});
            finer.push_back({c, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }

    // flat arrays, every triangle turned to face outwards
    SphereMesh mesh;
    mesh.vertices.reserve(points.size() * 3);
    for (const QVector3D &p : points) {
        mesh.vertices.push_back(p.x());
        mesh.vertices.push_back(p.y());
        mesh.vertices.push_back(p.z());
    }
    for (auto [a, b, c] : faces) {
        const QVector3D normal = QVector3D::crossProduct(points[b] - points[a], points[c] - points[a]);
        if (QVector3D::dotProduct(normal, points[a] + points[b] + points[c]) < 0.0f)
            std::swap(b, c);
        mesh.indices.push_back(a);
        mesh.indices.push_back(b);
        mesh.indices.push_back(c);
    }
    return mesh;
}

std::vector<float> packAxes(float length)
{
    std::vector<float> vertices;
    const QVector3D origin(0.0f, 0.0f, 0.0f);
    pushVertex(vertices, origin, {0.90f, 0.25f, 0.25f});
    pushVertex(vertices, QVector3D(length, 0.0f, 0.0f), {0.90f, 0.25f, 0.25f});
    pushVertex(vertices, origin, {0.30f, 0.85f, 0.30f});
    pushVertex(vertices, QVector3D(0.0f, length, 0.0f), {0.30f, 0.85f, 0.30f});
    pushVertex(vertices, origin, {0.30f, 0.45f, 0.95f});
    pushVertex(vertices, QVector3D(0.0f, 0.0f, length), {0.30f, 0.45f, 0.95f});
    return vertices;
}

Sphere withEnclosedFloors(const std::vector<core::PlaneDesc> &planes, const Sphere &scene)
{
    // each floor as a square far wider than any room, cut by the walls: closed in, when every
    // corner of it was cut away
    constexpr float kFarther = 1.0e4f;
    QVector3D lo = scene.centre - QVector3D(1, 1, 1) * scene.radius;
    QVector3D hi = scene.centre + QVector3D(1, 1, 1) * scene.radius;
    bool grown = false;
    for (std::size_t p = 0; p < planes.size(); ++p) {
        if (planes[p].bounded() || !isFloor(planes[p]))
            continue;
        const QVector3D n = toVector(planes[p].normal).normalized();
        const QVector3D foot = scene.centre - (QVector3D::dotProduct(n, scene.centre) - float(planes[p].offset)) * n;
        const QVector3D u = QVector3D::crossProduct(n, QVector3D(1, 0, 0)).normalized() * kFarther;
        const QVector3D v = QVector3D::crossProduct(n, u).normalized() * kFarther;
        std::vector<QVector3D> polygon{foot - u - v, foot + u - v, foot + u + v, foot - u + v};
        for (std::size_t q = 0; q < planes.size() && polygon.size() >= 3; ++q) {
            const QVector3D wall = toVector(planes[q].normal).normalized();
            if (q != p && enclosesScene(planes[q], wall, scene))
                polygon = clipToInside(polygon, wall, float(planes[q].offset));
        }
        const bool closed = polygon.size() >= 3 && std::all_of(polygon.begin(), polygon.end(), [&](const QVector3D &x) {
                                return (x - foot).length() < 0.5f * kFarther;
                            });
        if (!closed)
            continue;
        for (const QVector3D &x : polygon) {
            lo = QVector3D(std::min(lo.x(), x.x()), std::min(lo.y(), x.y()), std::min(lo.z(), x.z()));
            hi = QVector3D(std::max(hi.x(), x.x()), std::max(hi.y(), x.y()), std::max(hi.z(), x.z()));
        }
        grown = true;
    }
    if (!grown)
        return scene;
    return Sphere{(lo + hi) * 0.5f, 0.5f * (hi - lo).length()};
}

std::vector<float> packPlaneQuads(const std::vector<core::PlaneDesc> &planes, const Sphere &scene)
{
    // the normals, and how far the walls around the scene are: a square must reach them
    std::vector<QVector3D> normals;
    float reach = 1.5f * std::max(scene.radius, 0.5f);
    for (const core::PlaneDesc &plane : planes) {
        normals.push_back(toVector(plane.normal).normalized());
        if (enclosesScene(plane, normals.back(), scene))
            reach = std::max(reach, QVector3D::dotProduct(normals.back(), scene.centre) - float(plane.offset));
    }
    const float half = reach;
    std::vector<float> vertices;
    vertices.reserve(planes.size() * 6 * kVertexFloats);
    for (std::size_t p = 0; p < planes.size(); ++p) {
        const core::PlaneDesc &plane = planes[p];
        const QVector3D n = normals[p];
        if (n.isNull())
            continue;

        // a rectangle is drawn as exactly the quad that collides: its corners from the collider
        // the core compiles it to (the settings only lend it friction, which is not drawn)
        if (plane.bounded()) {
            const core::Collider quad = core::makeCollider(plane, core::Settings{});
            const QVector3D centre = toVector(quad.centre);
            const QVector3D u = toVector(quad.axisU * quad.halfWidth);
            const QVector3D v = toVector(quad.axisV * quad.halfHeight);
            const QVector3D a = centre - u - v, b = centre + u - v, c = centre + u + v, d = centre - u + v;
            for (const QVector3D &corner : {a, b, c, a, c, d})
                pushVertex(vertices, corner, kPlaneColour, kPlaneAlpha);
            continue;
        }

        // the point of the plane nearest the scene's centre, and two directions along the plane
        const QVector3D foot = scene.centre - (QVector3D::dotProduct(n, scene.centre) - float(plane.offset)) * n;
        const QVector3D helper = std::abs(n.y()) < 0.9f ? QVector3D(0.0f, 1.0f, 0.0f) : QVector3D(1.0f, 0.0f, 0.0f);
        const QVector3D u = QVector3D::crossProduct(n, helper).normalized() * half;
        const QVector3D v = QVector3D::crossProduct(n, u).normalized() * half;

        // the square, cut by the walls around the scene, as a fan of triangles
        std::vector<QVector3D> polygon{foot - u - v, foot + u - v, foot + u + v, foot - u + v};
        for (std::size_t q = 0; q < planes.size() && polygon.size() >= 3; ++q)
            if (q != p && enclosesScene(planes[q], normals[q], scene))
                polygon = clipToInside(polygon, normals[q], float(planes[q].offset));
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
            for (const QVector3D &corner : {polygon[0], polygon[k], polygon[k + 1]})
                pushVertex(vertices, corner, kPlaneColour, kPlaneAlpha);
    }
    return vertices;
}

}  // namespace ui
