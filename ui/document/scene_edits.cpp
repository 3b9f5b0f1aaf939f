#include "scene_edits.h"

#include "core/contacts/cloth_surface.h"
#include "core/contacts/contact_impulses.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace ui {

namespace {

bool contains(const std::vector<int> &sorted, int i)
{
    return std::binary_search(sorted.begin(), sorted.end(), i);
}

void toggle(std::vector<int> &sorted, int i)
{
    const auto at = std::lower_bound(sorted.begin(), sorted.end(), i);
    if (at != sorted.end() && *at == i)
        sorted.erase(at);
    else
        sorted.insert(at, i);
}

bool inRange(const core::SceneDesc &scene, int i)
{
    return i >= 0 && i < static_cast<int>(scene.particles.size());
}

}  // namespace

void normalise(std::vector<int> &indices)
{
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
}

bool Selection::hasParticle(int i) const { return contains(particles, i); }
bool Selection::hasSpring(int i) const { return contains(springs, i); }
void Selection::toggleParticle(int i) { toggle(particles, i); }
void Selection::toggleSpring(int i) { toggle(springs, i); }

void Selection::clamp(const core::SceneDesc &scene)
{
    const auto drop = [](std::vector<int> &v, std::size_t size) {
        v.erase(std::remove_if(v.begin(), v.end(), [size](int i) { return i < 0 || std::size_t(i) >= size; }),
                v.end());
    };
    drop(particles, scene.particles.size());
    drop(springs, scene.springs.size());
}

std::optional<core::SceneProblem> changedParticleProblem(const core::SceneDesc &before, const core::SceneDesc &after)
{
    for (std::size_t i = 0; i < after.particles.size(); ++i)
        if (i >= before.particles.size() || !(after.particles[i] == before.particles[i]))
            if (std::optional<core::SceneProblem> problem = core::findParticleProblem(after, i))
                return problem;
    return std::nullopt;
}

std::optional<std::size_t> particlesPastLimit(const core::SceneDesc &scene, std::size_t added)
{
    const std::size_t total = scene.particles.size() + added;
    if (total > kMaxSceneParticles)
        return total;
    return std::nullopt;
}

int addParticle(core::SceneDesc &scene, const core::ParticleDesc &particle)
{
    scene.particles.push_back(particle);
    return static_cast<int>(scene.particles.size()) - 1;
}

int addSpring(core::SceneDesc &scene, int a, int b, double stiffness, double damping)
{
    if (a == b || !inRange(scene, a) || !inRange(scene, b))
        return -1;
    for (const core::SpringDesc &s : scene.springs)
        if ((s.a == a && s.b == b) || (s.a == b && s.b == a))
            return -1;
    const double length =
        (scene.particles[std::size_t(a)].position - scene.particles[std::size_t(b)].position).norm();
    scene.springs.push_back({a, b, stiffness, damping, length});
    return static_cast<int>(scene.springs.size()) - 1;
}

void setPinned(core::SceneDesc &scene, const std::vector<int> &particles, bool pinned)
{
    for (int i : particles) {
        if (!inRange(scene, i))
            continue;
        core::ParticleDesc &p = scene.particles[std::size_t(i)];
        p.pinned = pinned;
        if (pinned)
            p.velocity.setZero();
    }
}

void togglePinned(core::SceneDesc &scene, const std::vector<int> &particles)
{
    for (int i : particles)
        if (inRange(scene, i))
            setPinned(scene, {i}, !scene.particles[std::size_t(i)].pinned);
}

void removeItems(core::SceneDesc &scene, const Selection &selection)
{
    const std::size_t n = scene.particles.size();
    std::vector<char> goes(n, 0);
    for (int i : selection.particles)
        if (inRange(scene, i))
            goes[std::size_t(i)] = 1;

    // old index -> new index, -1 for removed
    std::vector<int> remap(n, -1);
    std::vector<core::ParticleDesc> kept;
    kept.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (goes[i])
            continue;
        remap[i] = static_cast<int>(kept.size());
        kept.push_back(scene.particles[i]);
    }

    std::vector<core::SpringDesc> springs;
    for (std::size_t s = 0; s < scene.springs.size(); ++s) {
        core::SpringDesc spring = scene.springs[s];
        if (selection.hasSpring(static_cast<int>(s)) || !inRange(scene, spring.a) || !inRange(scene, spring.b))
            continue;
        spring.a = remap[std::size_t(spring.a)];
        spring.b = remap[std::size_t(spring.b)];
        if (spring.a >= 0 && spring.b >= 0)
            springs.push_back(spring);
    }

    // the listed triangles of the particles that stay
    std::vector<std::array<int, 3>> triangles;
    for (std::array<int, 3> t : scene.triangles) {
        bool whole = true;
        for (int &corner : t) {
            corner = inRange(scene, corner) ? remap[std::size_t(corner)] : -1;
            whole = whole && corner >= 0;
        }
        if (whole)
            triangles.push_back(t);
    }
    scene.triangles = std::move(triangles);

    // an imported mesh stays whole or goes: its vertices are the file's, which an export must keep
    std::vector<core::MeshDesc> meshes;
    for (core::MeshDesc mesh : scene.meshes) {
        bool whole = true;
        for (int &p : mesh.particles) {
            p = inRange(scene, p) ? remap[std::size_t(p)] : -1;
            whole = whole && p >= 0;
        }
        if (whole)
            meshes.push_back(std::move(mesh));
    }
    scene.meshes = std::move(meshes);

    if (scene.steerable >= 0)
        scene.steerable = inRange(scene, scene.steerable) ? remap[std::size_t(scene.steerable)] : -1;
    scene.particles = std::move(kept);
    scene.springs = std::move(springs);
    core::renumberContactImpulses(scene.contactImpulses, remap);
}

std::vector<int> selectedParticles(const core::SceneDesc &scene, const Selection &selection)
{
    std::vector<int> particles = selection.particles;
    for (int s : selection.springs)
        if (s >= 0 && std::size_t(s) < scene.springs.size()) {
            particles.push_back(scene.springs[std::size_t(s)].a);
            particles.push_back(scene.springs[std::size_t(s)].b);
        }
    particles.erase(std::remove_if(particles.begin(), particles.end(), [&](int i) { return !inRange(scene, i); }),
                    particles.end());
    normalise(particles);
    return particles;
}

Fragment copyItems(const core::SceneDesc &scene, const Selection &selection)
{
    Fragment fragment;
    std::vector<int> remap(scene.particles.size(), -1);
    for (int i : selectedParticles(scene, selection)) {
        remap[std::size_t(i)] = static_cast<int>(fragment.particles.size());
        fragment.particles.push_back(scene.particles[std::size_t(i)]);
    }
    for (const core::SpringDesc &s : scene.springs) {
        if (!inRange(scene, s.a) || !inRange(scene, s.b))
            continue;
        const int a = remap[std::size_t(s.a)];
        const int b = remap[std::size_t(s.b)];
        if (a >= 0 && b >= 0)
            fragment.springs.push_back({a, b, s.stiffness, s.damping, s.restLength});
    }
    // the listed triangles all of whose corners are copied
    for (const std::array<int, 3> &t : scene.triangles) {
        std::array<int, 3> copied{};
        bool whole = true;
        for (std::size_t c = 0; c < 3; ++c) {
            copied[c] = inRange(scene, t[c]) ? remap[std::size_t(t[c])] : -1;
            whole = whole && copied[c] >= 0;
        }
        if (whole)
            fragment.triangles.push_back(copied);
    }
    return fragment;
}

Selection pasteFragment(core::SceneDesc &scene, const Fragment &fragment, const Eigen::Vector3d &offset)
{
    Selection added;
    const int base = static_cast<int>(scene.particles.size());
    // a scene that lists triangles keeps listing all of them: the scene's own (those its springs
    // make, when it listed none) and the fragment's
    if (core::listsTriangles(scene) || !fragment.triangles.empty()) {
        if (!core::listsTriangles(scene))
            scene.triangles = core::listedTriangles(scene);
        std::vector<std::array<int, 3>> added = fragment.triangles;
        if (added.empty()) {
            core::SceneDesc part;
            part.particles = fragment.particles;
            part.springs = fragment.springs;
            added = core::listedTriangles(part);
        }
        for (std::array<int, 3> t : added)
            scene.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    for (core::ParticleDesc p : fragment.particles) {
        p.position += offset;
        added.particles.push_back(addParticle(scene, p));
    }
    for (core::SpringDesc s : fragment.springs) {
        s.a += base;
        s.b += base;
        added.springs.push_back(static_cast<int>(scene.springs.size()));
        scene.springs.push_back(s);
    }
    return added;
}

Selection addGenerated(core::SceneDesc &scene, const core::SceneDesc &generated, const Eigen::Vector3d &centre)
{
    if (generated.particles.empty())
        return {};
    Eigen::Vector3d low = generated.particles.front().position;
    Eigen::Vector3d high = low;
    for (const core::ParticleDesc &p : generated.particles) {
        low = low.cwiseMin(p.position);
        high = high.cwiseMax(p.position);
    }
    scene.settings.substeps = std::max(scene.settings.substeps, generated.settings.substeps);
    // a generated sheet's thickness and self-collision (Generate › Cloth) become the scene's; a
    // soft ball's triangles are its drawn surface, and leave the scene's collisions as they are
    if (!generated.triangles.empty() && generated.settings.triangleCollisions) {
        if (generated.settings.thickness > 0.0)
            scene.settings.thickness = generated.settings.thickness;
        scene.settings.selfCollision = generated.settings.selfCollision;
        scene.settings.triangleCollisions = true;
    }
    return pasteFragment(scene, Fragment{generated.particles, generated.springs, generated.triangles}, centre - 0.5 * (low + high));
}

void moveParticles(core::SceneDesc &scene, const std::vector<int> &particles, const std::vector<Eigen::Vector3d> &from,
                   const Eigen::Vector3d &delta)
{
    for (std::size_t k = 0; k < particles.size() && k < from.size(); ++k)
        if (inRange(scene, particles[k]))
            scene.particles[std::size_t(particles[k])].position = from[k] + delta;
}

bool SelectionTransform::isIdentity() const
{
    return translation.isZero(0.0) && angleDegrees == 0.0 && scale == Eigen::Vector3d::Ones();
}

Eigen::Vector3d centroid(const core::SceneDesc &scene, const std::vector<int> &particles)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i : particles)
        sum += scene.particles[std::size_t(i)].position;
    return particles.empty() ? sum : Eigen::Vector3d(sum / double(particles.size()));
}

void transformParticles(core::SceneDesc &scene, const std::vector<int> &particles, const SelectionTransform &transform)
{
    assert(transform.axis.norm() > 0.0 && (transform.scale.array() != 0.0).all());
    const Eigen::Vector3d centre = centroid(scene, particles);
    std::vector<char> moved(scene.particles.size(), 0);
    for (int i : particles)
        moved[std::size_t(i)] = 1;
    // whole turns exactly: 360° gives back the same bits rather than a rounding of them
    const double degrees = std::fmod(transform.angleDegrees, 360.0);
    const Eigen::Matrix3d turn =
        degrees == 0.0
            ? Eigen::Matrix3d::Identity()
            : Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, transform.axis.normalized()).toRotationMatrix();
    const Eigen::Matrix3d linear = turn * transform.scale.asDiagonal();
    const Eigen::Matrix3d velocityTurn = turn * transform.scale.cwiseSign().asDiagonal();

    // the springs within first, measured before the particles move
    if (transform.scaleRestLengths && transform.scale != Eigen::Vector3d::Ones()) {
        // a spring whose ends coincide has no direction: it takes the factors' geometric mean
        const double meanFactor = std::cbrt(std::abs(transform.scale.prod()));
        for (core::SpringDesc &spring : scene.springs) {
            if (!inRange(scene, spring.a) || !inRange(scene, spring.b) || !moved[std::size_t(spring.a)] ||
                !moved[std::size_t(spring.b)])
                continue;
            const Eigen::Vector3d d =
                scene.particles[std::size_t(spring.b)].position - scene.particles[std::size_t(spring.a)].position;
            const double length = d.norm();
            spring.restLength *= length > 0.0 ? transform.scale.cwiseProduct(d).norm() / length : meanFactor;
        }
    }

    for (int i : particles) {
        core::ParticleDesc &p = scene.particles[std::size_t(i)];
        p.position = centre + transform.translation + linear * (p.position - centre);
        p.velocity = velocityTurn * p.velocity;
    }

    // the saved contacts of what moved held where it was, not where it is
    std::erase_if(scene.contactImpulses, [&](const core::ContactImpulse &c) {
        const auto movedOne = [&](int k) { return k >= 0 && std::size_t(k) < moved.size() && moved[std::size_t(k)]; };
        return movedOne(c.i) || (!c.withPlane() && movedOne(c.j));
    });
}

Eigen::Vector3d snapToGrid(const Eigen::Vector3d &point, double step)
{
    if (!(step > 0.0))
        return point;
    return (point / step).array().round().matrix() * step;
}

}  // namespace ui
