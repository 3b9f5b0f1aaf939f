// Design note. A file's mesh keeps its own vertices (the export writes them, in its order) while
// the bodies are made of its welded points: a cloth's and a collider's vertex rides on its point's
// particle; a soft body's on the eight corners of the lattice cell its point lies in, by trilinear
// weights. A vertex no face uses rides with the point nearest it.

#include "core/meshes/mesh_import.h"

#include "core/meshes/mesh_surface.h"
#include "core/model/generators.h"
#include "core/model/parameters.h"
#include "core/model/validate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace core {

namespace {

constexpr std::array<ClothMaterialValues, 4> kClothMaterials{{
    // a cotton shirt: 150 g/m²
    {ClothMaterial::Cotton, "cotton", 0.15, 2000.0, 400.0, 40.0, 0.02},
    // silk: light and limp
    {ClothMaterial::Silk, "silk", 0.06, 800.0, 100.0, 4.0, 0.005},
    // denim: heavy and stiff to fold
    {ClothMaterial::Denim, "denim", 0.40, 5000.0, 1500.0, 250.0, 0.05},
    // a 1 mm rubber sheet: stretches, resists shear as much as stretch
    {ClothMaterial::RubberSheet, "rubber-sheet", 1.1, 300.0, 300.0, 30.0, 0.05},
}};

constexpr std::array<std::pair<PinSide, std::string_view>, 7> kPinSides{{{PinSide::None, "none"},
                                                                         {PinSide::Top, "top"},
                                                                         {PinSide::Bottom, "bottom"},
                                                                         {PinSide::Left, "left"},
                                                                         {PinSide::Right, "right"},
                                                                         {PinSide::Front, "front"},
                                                                         {PinSide::Back, "back"}}};

// vertices closer than this share of the box's diagonal are one point (a file writes a split
// vertex's position twice with the same digits, so a tight tolerance finds them all)
constexpr double kWeldShare = 1e-7;
// an across spring longer than this many times the edge it crosses folds the sheet (a bend
// spring); a shorter one is the other diagonal of a quad (a shear spring)
constexpr double kBendAcross = 1.5;

std::uint64_t pairKey(int a, int b)
{
    return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
}

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

// the welded mesh and what is wrong with it for any kind of body
struct Prepared {
    TriangleMesh placed;
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    WeldedMesh welded;
    MeshEdges edges;
    Box box;
    std::vector<int> nearestPoint;  // per vertex: its point, or for a vertex no face uses the nearest
    std::vector<std::array<int, 3>> vertexFaces;  // the file's faces, those with three different vertices
};

std::string prepare(const TriangleMesh &mesh, const MeshImportOptions &options, Prepared &p)
{
    if (mesh.vertices.empty())
        return "the mesh has no vertices";
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        if (!mesh.vertices[v].allFinite())
            return "vertex " + std::to_string(v) + " has a coordinate that is not a finite number";
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (int v : mesh.faces[f])
            if (v < 0 || std::size_t(v) >= mesh.vertices.size())
                return "face " + std::to_string(f) + " names vertex " + std::to_string(v) + ", which the mesh has not";
    if (mesh.faces.empty())
        return "the mesh has no triangles (only points or lines?)";
    if (!(options.placement.scale > 0.0) || !std::isfinite(options.placement.scale))
        return "the scale must be a number greater than 0 (got " + number(options.placement.scale) + ")";
    p.placed = placedMesh(mesh, options.placement, &p.offset);
    for (const Eigen::Vector3d &v : p.placed.vertices)
        if (!v.allFinite() || v.cwiseAbs().maxCoeff() > 1e6)
            return "the mesh placed and scaled reaches past 10^6 m from the origin: choose a smaller scale";
    p.box = boundingBox(p.placed.vertices);
    const double diagonal = p.box.size().norm();
    p.welded = weldVertices(p.placed, kWeldShare * std::max(diagonal, 1e-300));
    if (p.welded.faces.empty())
        return "every face of the mesh has no area (its corners are at one place or on a line)";
    if (!(surfaceArea(p.welded.points, p.welded.faces) > 0.0))
        return "every face of the mesh has no area (its corners are on a line)";
    p.edges = meshEdges(p.welded.faces, int(p.welded.points.size()));
    for (const std::array<int, 3> &f : p.placed.faces)
        if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2])
            p.vertexFaces.push_back(f);

    // a vertex no face uses rides with the nearest point
    p.nearestPoint = p.welded.pointOf;
    for (std::size_t v = 0; v < p.nearestPoint.size(); ++v) {
        if (p.nearestPoint[v] >= 0)
            continue;
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t q = 0; q < p.welded.points.size(); ++q) {
            const double d = (p.welded.points[q] - p.placed.vertices[v]).squaredNorm();
            if (d < best) {
                best = d;
                p.nearestPoint[v] = int(q);
            }
        }
    }
    return {};
}

// each point's shortest edge, and the mean edge
void edgeLengths(const Prepared &p, std::vector<double> &shortest, double &mean)
{
    shortest.assign(p.welded.points.size(), std::numeric_limits<double>::infinity());
    double sum = 0.0;
    for (const std::array<int, 2> &e : p.edges.ends) {
        const double l = (p.welded.points[std::size_t(e[0])] - p.welded.points[std::size_t(e[1])]).norm();
        sum += l;
        for (int end : e)
            shortest[std::size_t(end)] = std::min(shortest[std::size_t(end)], l);
    }
    mean = sum / double(std::max<std::size_t>(1, p.edges.ends.size()));
}

bool pinned(const Prepared &p, PinSide side, const Eigen::Vector3d &x)
{
    const double band = 1e-3 * p.box.size().maxCoeff();
    switch (side) {
    case PinSide::None: return false;
    case PinSide::Top: return x.y() >= p.box.high.y() - band;
    case PinSide::Bottom: return x.y() <= p.box.low.y() + band;
    case PinSide::Left: return x.x() <= p.box.low.x() + band;
    case PinSide::Right: return x.x() >= p.box.high.x() - band;
    case PinSide::Front: return x.z() >= p.box.high.z() - band;
    case PinSide::Back: return x.z() <= p.box.low.z() + band;
    }
    return false;
}

void recordMesh(SceneDesc &scene, const Prepared &p, const MeshImportOptions &options, MeshDesc mesh)
{
    mesh.name = options.name.empty() ? "mesh" : options.name;
    mesh.source = options.source;
    mesh.kind = options.kind;
    mesh.scale = options.placement.scale;
    mesh.zUp = options.placement.zUp;
    mesh.offset = p.offset;
    scene.meshes.push_back(std::move(mesh));
}

// a particle per point (pinned ones for a collider), the triangles listed, the mesh on its points
void addPointParticles(SceneDesc &scene, const Prepared &p, const MeshImportOptions &options, bool collider,
                       MeshImportResult &result)
{
    const int base = int(scene.particles.size());
    std::vector<double> share;
    result.area = surfaceArea(p.welded.points, p.welded.faces, &share);
    const double density = options.density.value_or(clothMaterial(options.material).density);
    std::vector<double> shortest;
    double mean = 0.0;
    edgeLengths(p, shortest, mean);
    // a point of faces without area still weighs something: a hundredth of the mean
    const double floorMass = 0.01 * density * result.area / double(p.welded.points.size());
    for (std::size_t q = 0; q < p.welded.points.size(); ++q) {
        ParticleDesc particle;
        particle.position = p.welded.points[q];
        particle.pinned = collider || pinned(p, options.pin, particle.position);
        particle.mass = collider ? 1.0 : std::max(density * share[q], floorMass);
        // spheres that keep clear of their neighbours: under half the shortest edge. A collider's
        // are thin beside the whole body (its sheet is twice as thick), not beside its triangles,
        // which may be a metre across on a table: a cloth laid over it rests on its surface
        const double size = collider ? 0.005 * p.box.size().norm() : 0.35 * mean;
        particle.radius = std::min(size, 0.45 * shortest[q]);
        if (!particle.pinned)
            result.mass += particle.mass;
        scene.particles.push_back(particle);
    }
    for (const std::array<int, 3> &f : p.welded.faces)
        scene.triangles.push_back({f[0] + base, f[1] + base, f[2] + base});
    std::vector<int> particleOf(p.nearestPoint.size());
    for (std::size_t v = 0; v < particleOf.size(); ++v)
        particleOf[v] = p.nearestPoint[v] + base;
    recordMesh(scene, p, options, meshOnParticles(particleOf, p.vertexFaces));
    result.particles = int(p.welded.points.size());
    result.triangles = int(p.welded.faces.size());
    scene.settings.triangleCollisions = true;
}

void addClothSprings(SceneDesc &scene, const Prepared &p, const MeshImportOptions &options, int base,
                     MeshImportResult &result)
{
    const ClothMaterialValues &material = clothMaterial(options.material);
    const double scale = options.stiffness ? *options.stiffness / material.stretch : 1.0;
    const double damping = options.damping.value_or(material.damping);
    std::unordered_set<std::uint64_t> joined;
    joined.reserve(p.edges.ends.size() * 2);
    for (const std::array<int, 2> &e : p.edges.ends) {
        addSpring(scene, e[0] + base, e[1] + base, material.stretch * scale, damping);
        joined.insert(pairKey(e[0], e[1]));
    }
    int shear = 0, bend = 0;
    for (std::size_t e = 0; e < p.edges.ends.size(); ++e) {
        if (p.edges.faceCount[e] != 2)
            continue;
        const std::array<int, 2> &ends = p.edges.ends[e];
        const auto farCorner = [&](int face) {
            for (int v : p.welded.faces[std::size_t(face)])
                if (v != ends[0] && v != ends[1])
                    return v;
            return -1;
        };
        const int c = farCorner(p.edges.faces[e][0]), d = farCorner(p.edges.faces[e][1]);
        if (c < 0 || d < 0 || c == d || !joined.insert(pairKey(c, d)).second)
            continue;
        const double across = (p.welded.points[std::size_t(c)] - p.welded.points[std::size_t(d)]).norm();
        const double edge = (p.welded.points[std::size_t(ends[0])] - p.welded.points[std::size_t(ends[1])]).norm();
        const bool folds = across > kBendAcross * edge;
        addSpring(scene, c + base, d + base, (folds ? material.bend : material.shear) * scale, damping);
        ++(folds ? bend : shear);
    }
    result.springs = int(p.edges.ends.size()) + shear + bend;
    result.notes.push_back(std::to_string(p.edges.ends.size()) + " edge springs, " + std::to_string(shear) +
                           " shear and " + std::to_string(bend) + " bend springs across pairs of faces");
}

// a soft body: the lattice of cells that hold the inside, its surface carried by them
std::string addSoftBody(SceneDesc &scene, const Prepared &p, const MeshImportOptions &options, MeshImportResult &result)
{
    if (!p.edges.closed())
        return "the mesh is not closed (" + std::to_string(p.edges.boundary) + " edges border one face only, " +
               std::to_string(p.edges.nonManifold) +
               " three or more): a soft body fills the inside of a closed surface, and this one has no inside. "
               "Import it as cloth or as a collider, or close its holes in a modeller";
    const double volume = enclosedVolume(p.welded.points, p.welded.faces);
    const double size = p.box.size().maxCoeff();
    if (!(std::abs(volume) > 1e-9 * size * size * size))
        return "the mesh encloses no volume";
    if (volume < 0.0)
        result.notes.push_back("its faces turn inward (clockwise seen from outside); the inside is found all the same");
    result.volume = std::abs(volume);
    result.area = surfaceArea(p.welded.points, p.welded.faces);
    const double h = options.spacing > 0.0 ? options.spacing : 0.1 * size;
    if (!(h > 0.0) || !std::isfinite(h))
        return "the lattice spacing must be a number greater than 0 m";

    // the lattice: cells of h over the box, with half a cell to spare on every side
    std::array<int, 3> cells{};
    Eigen::Vector3d origin;
    const Eigen::Vector3d centre = 0.5 * (p.box.low + p.box.high);
    double nodes = 1.0;
    for (int a = 0; a < 3; ++a) {
        const double n = std::ceil(p.box.size()[a] / h) + 1.0;
        if (n > 1e5)
            return "the lattice spacing " + number(h) + " m is too fine for a mesh " + number(size) + " m across";
        cells[std::size_t(a)] = int(n);
        origin[a] = centre[a] - 0.5 * n * h;
        nodes *= n + 1.0;
    }
    if (nodes > 8.0 * kMaxImportedParticles)
        return "a lattice of spacing " + number(h) + " m would have about " + number(nodes) +
               " nodes, past the limit of " + std::to_string(kMaxImportedParticles) + " particles: choose a larger spacing";
    const int nx = cells[0] + 1, ny = cells[1] + 1, nz = cells[2] + 1;
    const auto node = [&](int i, int j, int k) { return (std::size_t(k) * std::size_t(ny) + std::size_t(j)) * std::size_t(nx) + std::size_t(i); };

    // which nodes are inside: along each row of nodes in x, the faces it crosses (the row is moved
    // by a small odd fraction of h so that it never runs exactly through an edge or a corner)
    std::vector<std::vector<double>> crossings(std::size_t(ny) * std::size_t(nz));
    const double dy = 1.234567e-4 * h, dz = 2.345678e-4 * h;
    for (const std::array<int, 3> &f : p.welded.faces) {
        const Eigen::Vector3d &a = p.welded.points[std::size_t(f[0])], &b = p.welded.points[std::size_t(f[1])],
                              &c = p.welded.points[std::size_t(f[2])];
        const double ylo = std::min({a.y(), b.y(), c.y()}), yhi = std::max({a.y(), b.y(), c.y()});
        const double zlo = std::min({a.z(), b.z(), c.z()}), zhi = std::max({a.z(), b.z(), c.z()});
        const int j0 = std::max(0, int(std::ceil((ylo - origin.y() - dy) / h))), j1 = std::min(ny - 1, int(std::floor((yhi - origin.y() - dy) / h)));
        const int k0 = std::max(0, int(std::ceil((zlo - origin.z() - dz) / h))), k1 = std::min(nz - 1, int(std::floor((zhi - origin.z() - dz) / h)));
        const double det = (b.y() - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (b.z() - a.z());
        if (det == 0.0)
            continue;  // edge-on to the rows
        for (int k = k0; k <= k1; ++k)
            for (int j = j0; j <= j1; ++j) {
                const double y = origin.y() + j * h + dy, z = origin.z() + k * h + dz;
                // barycentric coordinates of (y, z) in the face's projection
                const double u = ((y - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (z - a.z())) / det;
                const double v = ((b.y() - a.y()) * (z - a.z()) - (y - a.y()) * (b.z() - a.z())) / det;
                if (u < 0.0 || v < 0.0 || u + v > 1.0)
                    continue;
                crossings[std::size_t(k) * std::size_t(ny) + std::size_t(j)].push_back(a.x() + u * (b.x() - a.x()) +
                                                                                         v * (c.x() - a.x()));
            }
    }
    std::vector<char> inside(std::size_t(nx) * std::size_t(ny) * std::size_t(nz), 0);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j) {
            std::vector<double> &xs = crossings[std::size_t(k) * std::size_t(ny) + std::size_t(j)];
            std::sort(xs.begin(), xs.end());
            std::size_t passed = 0;
            for (int i = 0; i < nx; ++i) {
                const double x = origin.x() + i * h;
                while (passed < xs.size() && xs[passed] < x)
                    ++passed;
                inside[node(i, j, k)] = passed % 2 == 1;
            }
        }

    // the cells kept: those with a corner inside or a point of the surface in them
    const auto cellIndex = [&](int i, int j, int k) {
        return (std::size_t(k) * std::size_t(cells[1]) + std::size_t(j)) * std::size_t(cells[0]) + std::size_t(i);
    };
    const std::size_t cellCount = std::size_t(cells[0]) * std::size_t(cells[1]) * std::size_t(cells[2]);
    std::vector<char> kept(cellCount, 0);
    const auto cellOf = [&](const Eigen::Vector3d &x, std::array<int, 3> &c, Eigen::Vector3d &t) {
        for (int a = 0; a < 3; ++a) {
            const double s = (x[a] - origin[a]) / h;
            c[std::size_t(a)] = std::clamp(int(std::floor(s)), 0, cells[std::size_t(a)] - 1);
            t[a] = s - c[std::size_t(a)];
        }
    };
    for (const Eigen::Vector3d &x : p.welded.points) {
        std::array<int, 3> c{};
        Eigen::Vector3d t;
        cellOf(x, c, t);
        kept[cellIndex(c[0], c[1], c[2])] = 1;
    }
    for (int k = 0; k < cells[2]; ++k)
        for (int j = 0; j < cells[1]; ++j)
            for (int i = 0; i < cells[0]; ++i)
                for (int corner = 0; corner < 8 && !kept[cellIndex(i, j, k)]; ++corner)
                    if (inside[node(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1))])
                        kept[cellIndex(i, j, k)] = 1;

    // a particle at every corner of a kept cell
    const int base = int(scene.particles.size());
    std::vector<int> particleOfNode(inside.size(), -1);
    std::vector<int> cornersOfKept;
    int count = 0;
    for (int k = 0; k < cells[2]; ++k)
        for (int j = 0; j < cells[1]; ++j)
            for (int i = 0; i < cells[0]; ++i) {
                if (!kept[cellIndex(i, j, k)])
                    continue;
                for (int corner = 0; corner < 8; ++corner) {
                    int &particle = particleOfNode[node(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1))];
                    if (particle < 0)
                        particle = base + count++;
                    cornersOfKept.push_back(particle);
                }
            }
    if (count > kMaxImportedParticles)
        return "a lattice of spacing " + number(h) + " m makes " + std::to_string(count) + " particles, past the limit of " +
               std::to_string(kMaxImportedParticles) + ": choose a larger spacing";
    const double density = options.density.value_or(kDefaultSoftDensity);
    const double mass = density * result.volume / count;
    scene.particles.resize(std::size_t(base + count));
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                if (const int particle = particleOfNode[node(i, j, k)]; particle >= 0) {
                    ParticleDesc &d = scene.particles[std::size_t(particle)];
                    d.position = origin + h * Eigen::Vector3d(i, j, k);
                    d.mass = mass;
                    d.radius = 0.25 * h;
                    d.pinned = false;
                }
    std::vector<ParticleDesc> added(scene.particles.begin() + base, scene.particles.end());
    for (ParticleDesc &d : added)
        d.pinned = pinned(p, options.pin, d.position);
    std::copy(added.begin(), added.end(), scene.particles.begin() + base);
    result.mass = 0.0;
    for (const ParticleDesc &d : added)
        result.mass += d.pinned ? 0.0 : d.mass;

    // springs between every two corners of a kept cell: its edges, its faces' and its own diagonals
    const double stiffness = options.stiffness.value_or(kDefaultSoftStiffness * h / 0.1);
    const double damping = options.damping.value_or(0.5);
    std::unordered_set<std::uint64_t> joined;
    for (std::size_t cell = 0; cell < cornersOfKept.size(); cell += 8)
        for (int a = 0; a < 8; ++a)
            for (int b = a + 1; b < 8; ++b) {
                const int pa = cornersOfKept[cell + std::size_t(a)], pb = cornersOfKept[cell + std::size_t(b)];
                if (joined.insert(pairKey(pa, pb)).second)
                    addSpring(scene, pa, pb, stiffness, damping);
            }
    result.particles = count;
    result.springs = int(joined.size());

    // the surface: each point by the trilinear weights of its cell's corners
    MeshDesc mesh;
    mesh.offsets.assign(1, 0);
    std::vector<std::array<std::pair<int, double>, 8>> bindings(p.welded.points.size());
    for (std::size_t q = 0; q < p.welded.points.size(); ++q) {
        std::array<int, 3> c{};
        Eigen::Vector3d t;
        cellOf(p.welded.points[q], c, t);
        for (int corner = 0; corner < 8; ++corner) {
            const int ox = corner & 1, oy = (corner >> 1) & 1, oz = (corner >> 2) & 1;
            const double w = (ox ? t.x() : 1.0 - t.x()) * (oy ? t.y() : 1.0 - t.y()) * (oz ? t.z() : 1.0 - t.z());
            bindings[q][std::size_t(corner)] = {particleOfNode[node(c[0] + ox, c[1] + oy, c[2] + oz)], w};
        }
    }
    for (int point : p.nearestPoint) {
        for (const auto &[particle, w] : bindings[std::size_t(point)])
            if (w != 0.0) {
                mesh.particles.push_back(particle);
                mesh.weights.push_back(w);
            }
        mesh.offsets.push_back(int(mesh.particles.size()));
    }
    mesh.faces = p.vertexFaces;
    recordMesh(scene, p, options, std::move(mesh));
    result.notes.push_back("a lattice of " + number(h) + " m: " + std::to_string(count) + " particles, " +
                           std::to_string(result.springs) + " springs");
    return {};
}

// sub-steps enough that symplectic Euler keeps ω h within 1.5 (its limit is 2) on the body's springs,
// with ω from Gershgorin's bound (an over-estimate: the power iteration of automatic substeps
// found 1 sub-step for a soft cube that gained energy at it, and 4 that lost it)
int gershgorinSubsteps(const SceneDesc &scene, std::size_t firstSpring)
{
    std::vector<double> rows(scene.particles.size(), 0.0);
    for (std::size_t k = firstSpring; k < scene.springs.size(); ++k) {
        const SpringDesc &s = scene.springs[k];
        const ParticleDesc &a = scene.particles[std::size_t(s.a)], &b = scene.particles[std::size_t(s.b)];
        const double wa = a.pinned ? 0.0 : 1.0 / a.mass, wb = b.pinned ? 0.0 : 1.0 / b.mass;
        rows[std::size_t(s.a)] += s.stiffness * (wa + std::sqrt(wa * wb));
        rows[std::size_t(s.b)] += s.stiffness * (wb + std::sqrt(wa * wb));
    }
    const double omega = std::sqrt(*std::max_element(rows.begin(), rows.end()));
    const double wanted = std::ceil(omega * scene.settings.timeStep / 1.5);
    return int(std::clamp(wanted, 1.0, double(parameterInfo(Parameter::Substeps).maximum)));
}

}  // namespace

const ClothMaterialValues &clothMaterial(ClothMaterial material)
{
    for (const ClothMaterialValues &values : kClothMaterials)
        if (values.material == material)
            return values;
    return kClothMaterials.front();
}

std::optional<ClothMaterial> clothMaterialNamed(std::string_view name)
{
    for (const ClothMaterialValues &values : kClothMaterials)
        if (values.name == name)
            return values.material;
    return std::nullopt;
}

std::string_view knownClothMaterials()
{
    return "cotton, silk, denim, rubber-sheet";
}

std::optional<PinSide> pinSideNamed(std::string_view name)
{
    for (const auto &[side, known] : kPinSides)
        if (known == name)
            return side;
    return std::nullopt;
}

std::string_view knownPinSides()
{
    return "none, top, bottom, left, right, front, back";
}

TriangleMesh placedMesh(const TriangleMesh &mesh, const MeshPlacement &placement, Eigen::Vector3d *offset)
{
    TriangleMesh placed = mesh;
    for (Eigen::Vector3d &v : placed.vertices) {
        v *= placement.scale;
        if (placement.zUp)
            v = Eigen::Vector3d(v.x(), v.z(), -v.y());
    }
    Eigen::Vector3d move = Eigen::Vector3d::Zero();
    if (placement.at && !placed.vertices.empty()) {
        const Box box = boundingBox(placed.vertices);
        const Eigen::Vector3d bottom(0.5 * (box.low.x() + box.high.x()), box.low.y(), 0.5 * (box.low.z() + box.high.z()));
        move = *placement.at - bottom;
        for (Eigen::Vector3d &v : placed.vertices)
            v += move;
    }
    if (offset)
        *offset = move;
    return placed;
}

MeshImportResult addMeshToScene(SceneDesc &scene, const TriangleMesh &mesh, const MeshImportOptions &options)
{
    MeshImportResult result;
    Prepared p;
    if (std::string problem = prepare(mesh, options, p); !problem.empty()) {
        result.error = std::move(problem);
        return result;
    }
    result.weldedVertices = int(std::count_if(p.welded.pointOf.begin(), p.welded.pointOf.end(), [](int q) { return q >= 0; })) -
                            int(p.welded.points.size());
    if (options.kind != MeshKind::Soft && int(p.welded.points.size()) > kMaxImportedParticles) {
        result.error = "the mesh has " + std::to_string(p.welded.points.size()) + " vertices, past the limit of " +
                       std::to_string(kMaxImportedParticles) + " particles";
        return result;
    }
    SceneDesc changed = scene;
    const std::size_t firstSpring = changed.springs.size();
    switch (options.kind) {
    case MeshKind::Cloth: {
        const int base = int(changed.particles.size());
        addPointParticles(changed, p, options, false, result);
        addClothSprings(changed, p, options, base, result);
        changed.settings.autoSubsteps = true;
        if (p.edges.nonManifold > 0)
            result.notes.push_back(std::to_string(p.edges.nonManifold) +
                                   " edges border three or more faces: springs join them all the same");
        break;
    }
    case MeshKind::Collider:
        addPointParticles(changed, p, options, true, result);
        break;
    case MeshKind::Soft:
        if (std::string problem = addSoftBody(changed, p, options, result); !problem.empty()) {
            result.error = std::move(problem);
            return result;
        }
        changed.settings.autoSubsteps = true;
        break;
    }
    if (changed.springs.size() > firstSpring)
        changed.settings.substeps = std::max(changed.settings.substeps, gershgorinSubsteps(changed, firstSpring));
    if (result.weldedVertices > 0)
        result.notes.insert(result.notes.begin(), std::to_string(result.weldedVertices) +
                                                      " vertices welded to others at the same place");
    if (p.welded.droppedFaces > 0)
        result.notes.push_back(std::to_string(p.welded.droppedFaces) + " faces without area left out of the body");
    if (const auto problem = findProblem(changed)) {
        result.error = "the body made of the mesh is not valid: " + problem->path + ": " + problem->message;
        return result;
    }
    scene = std::move(changed);
    return result;
}

MeshImportResult sceneFromMesh(SceneDesc &scene, const TriangleMesh &mesh, const MeshImportOptions &options)
{
    SceneDesc made;
    made.name = options.name.empty() ? "imported mesh" : options.name;
    // a body that lands and settles, as cloth and foam do, rather than bouncing elastically, and
    // grips what it lands on (cloth on wood or on a floor: μ about 0.5), so that a sheet laid over a
    // table stays on it
    made.settings.restitution = 0.3;
    made.settings.friction = 0.5;
    MeshImportResult result = addMeshToScene(made, mesh, options);
    if (!result.ok())
        return result;
    double lowest = 0.0;
    for (const ParticleDesc &d : made.particles)
        lowest = std::min(lowest, d.position.y() - d.radius);
    made.planes.push_back(floorPlane(lowest));
    scene = std::move(made);
    return result;
}

}  // namespace core
