#include "core/model/validate.h"

#include "core/model/parameters.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace core {

namespace {

std::string indexed(const char *array, std::size_t index, const char *key)
{
    return std::string(array) + "[" + std::to_string(index) + "]." + key;
}

// checks one value; fills problem and returns false at the first failure
bool check(Parameter parameter, double value, std::string path, std::optional<SceneProblem> &problem)
{
    if (auto reason = checkParameter(parameter, value)) {
        problem = SceneProblem{std::move(path), std::move(*reason)};
        return false;
    }
    return true;
}

bool checkVector(Parameter parameter, const Eigen::Vector3d &value, const std::string &path,
                 std::optional<SceneProblem> &problem)
{
    for (int axis = 0; axis < 3; ++axis)
        if (!check(parameter, value[axis], path + "[" + std::to_string(axis) + "]", problem))
            return false;
    return true;
}

}  // namespace

Eigen::Vector3d unitNormal(const Eigen::Vector3d &normal)
{
    const double squared = normal.squaredNorm();
    if (std::abs(squared - 1.0) <= 4.0 * std::numeric_limits<double>::epsilon())
        return normal;
    if (squared >= std::numeric_limits<double>::min())
        return normal / std::sqrt(squared);
    // so short that its square underflows (1e-200): scaled up first, it still has a direction
    const Eigen::Vector3d scaled = normal / normal.cwiseAbs().maxCoeff();
    return scaled / scaled.norm();
}

std::optional<SceneProblem> findParticleProblem(const SceneDesc &scene, std::size_t i)
{
    std::optional<SceneProblem> problem;
    const ParticleDesc &p = scene.particles[i];
    if (!checkVector(Parameter::Coordinate, p.position, indexed("particles", i, "position"), problem) ||
        !checkVector(Parameter::Speed, p.velocity, indexed("particles", i, "velocity"), problem) ||
        !check(Parameter::Mass, p.mass, indexed("particles", i, "mass"), problem) ||
        !check(Parameter::Radius, p.radius, indexed("particles", i, "radius"), problem) ||
        !checkVector(Parameter::AngularSpeed, p.angularVelocity, indexed("particles", i, "angularVelocity"), problem))
        return problem;
    // an orientation is a rotation: any finite quaternion but zero (it is normalised when loaded)
    if (!p.orientation.allFinite() || !(p.orientation.squaredNorm() > 1e-200) ||
        !(p.orientation.cwiseAbs().maxCoeff() <= kStateLimit))
        return SceneProblem{indexed("particles", i, "orientation"),
                            "must be a rotation, a quaternion [w, x, y, z] of finite numbers, not all 0"};
    return std::nullopt;
}

std::optional<SceneProblem> findProblem(const SceneDesc &scene)
{
    std::optional<SceneProblem> problem;
    const Settings &s = scene.settings;

    // settings
    if (!check(Parameter::TimeStep, s.timeStep, "settings.timeStep", problem) ||
        !check(Parameter::Substeps, s.substeps, "settings.substeps", problem) ||
        !check(Parameter::XpbdIterations, s.xpbdIterations, "settings.xpbdIterations", problem) ||
        !check(Parameter::SolverIterations, s.solverIterations, "settings.solverIterations", problem) ||
        !check(Parameter::Tolerance, s.tolerance, "settings.tolerance", problem) ||
        (s.adaptiveStep && !check(Parameter::TimeStep, *s.adaptiveStep, "settings.adaptiveStep", problem)) ||
        !checkVector(Parameter::Gravity, s.gravity, "settings.gravity", problem) ||
        !check(Parameter::Viscosity, s.viscosity, "settings.viscosity", problem) ||
        !check(Parameter::Restitution, s.restitution, "settings.restitution", problem) ||
        !check(Parameter::Friction, s.friction, "settings.friction", problem) ||
        !check(Parameter::Thickness, s.thickness, "settings.thickness", problem) ||
        !check(Parameter::Friction, s.rollingFriction, "settings.rollingFriction", problem) ||
        !check(Parameter::Friction, s.spinningFriction, "settings.spinningFriction", problem) ||
        (s.staticFriction && !check(Parameter::Friction, *s.staticFriction, "settings.staticFriction", problem)))
        return problem;

    // particles
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        if (auto found = findParticleProblem(scene, i))
            return found;

    // springs
    const auto count = static_cast<long long>(scene.particles.size());
    for (std::size_t i = 0; i < scene.springs.size(); ++i) {
        const SpringDesc &spring = scene.springs[i];
        for (int end = 0; end < 2; ++end) {
            const long long index = end == 0 ? spring.a : spring.b;
            if (index < 0 || index >= count)
                return SceneProblem{indexed("springs", i, "particles") + "[" + std::to_string(end) + "]",
                                    "particle index " + std::to_string(index) + " is out of range (the scene has " +
                                        std::to_string(count) + " particles)"};
        }
        if (spring.a == spring.b)
            return SceneProblem{indexed("springs", i, "particles"),
                                "joins particle " + std::to_string(spring.a) + " to itself"};
        if (!check(Parameter::Stiffness, spring.stiffness, indexed("springs", i, "stiffness"), problem) ||
            !check(Parameter::Damping, spring.damping, indexed("springs", i, "damping"), problem) ||
            !check(Parameter::RestLength, spring.restLength, indexed("springs", i, "restLength"), problem) ||
            !check(Parameter::BreakStrain, spring.breakStrain, indexed("springs", i, "breakStrain"), problem))
            return problem;
        // a strain is measured against the rest length
        if (spring.breakStrain > 0.0 && !(spring.restLength > 0.0))
            return SceneProblem{indexed("springs", i, "breakStrain"),
                                "needs a rest length greater than 0 m: a strain is a share of the rest length"};
    }

    // planes
    for (std::size_t i = 0; i < scene.planes.size(); ++i) {
        const PlaneDesc &plane = scene.planes[i];
        if (!checkVector(Parameter::Coordinate, plane.normal, indexed("planes", i, "normal"), problem) ||
            !check(Parameter::Coordinate, plane.offset, indexed("planes", i, "offset"), problem))
            return problem;
        if (!(plane.normal.cwiseAbs().maxCoeff() > 0.0))
            return SceneProblem{indexed("planes", i, "normal"), "is zero: a plane needs a direction"};
        if ((plane.friction && !check(Parameter::Friction, *plane.friction, indexed("planes", i, "friction"), problem)) ||
            (plane.rollingFriction &&
             !check(Parameter::Friction, *plane.rollingFriction, indexed("planes", i, "rollingFriction"), problem)) ||
            (plane.spinningFriction &&
             !check(Parameter::Friction, *plane.spinningFriction, indexed("planes", i, "spinningFriction"), problem)) ||
            !check(Parameter::Extent, plane.size[0], indexed("planes", i, "size") + "[0]", problem) ||
            !check(Parameter::Extent, plane.size[1], indexed("planes", i, "size") + "[1]", problem) ||
            !checkVector(Parameter::Coordinate, plane.centre, indexed("planes", i, "centre"), problem) ||
            !checkVector(Parameter::Coordinate, plane.axis, indexed("planes", i, "axis"), problem))
            return problem;
        if ((plane.size[0] > 0.0) != (plane.size[1] > 0.0))
            return SceneProblem{indexed("planes", i, "size"),
                                "needs both sides greater than 0 m for a rectangle, or both 0 for the whole plane"};
    }
    // the sheets' triangles: three different particles each
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const std::array<int, 3> &t = scene.triangles[i];
        for (std::size_t corner = 0; corner < 3; ++corner)
            if (t[corner] < 0 || t[corner] >= count)
                return SceneProblem{"triangles[" + std::to_string(i) + "][" + std::to_string(corner) + "]",
                                    "particle index " + std::to_string(t[corner]) +
                                        " is out of range (the scene has " + std::to_string(count) + " particles)"};
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            return SceneProblem{"triangles[" + std::to_string(i) + "]",
                                "names a particle twice: a triangle needs three different particles"};
    }
    // the imported surfaces: each vertex a weighted sum of existing particles, faces of its vertices
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        if (auto meshProblem = findMeshProblem(scene.meshes[m], scene.particles.size()); meshProblem) {
            meshProblem->path = "meshes[" + std::to_string(m) + "]" + (meshProblem->path.empty() ? "" : "." + meshProblem->path);
            return meshProblem;
        }
    // the particle the arrow keys push
    if (scene.steerable < -1 || scene.steerable >= count)
        return SceneProblem{"steerable", "particle index " + std::to_string(scene.steerable) +
                                             " is out of range (the scene has " + std::to_string(count) +
                                             " particles)"};

    // the contact impulses a saved run starts from
    return findContactImpulseProblem(scene.contactImpulses, scene.particles.size(), scene.planes.size());
}

std::optional<SceneProblem> findMeshProblem(const MeshDesc &mesh, std::size_t particles)
{
    const auto count = static_cast<long long>(particles);
    const std::size_t bindings = mesh.particles.size();
    if (mesh.offsets.empty() || mesh.offsets.front() != 0 || mesh.weights.size() != bindings ||
        std::size_t(mesh.offsets.back()) != bindings)
        return SceneProblem{"vertices", "the vertices' particles and weights do not match (a damaged mesh)"};
    const int vertices = mesh.vertexCount();
    for (int v = 0; v < vertices; ++v) {
        const std::string path = "vertices[" + std::to_string(v) + "]";
        const int first = mesh.offsets[std::size_t(v)], last = mesh.offsets[std::size_t(v) + 1];
        if (last - first < 1 || last - first > kMostMeshBindings)
            return SceneProblem{path, "needs 1 to " + std::to_string(kMostMeshBindings) + " particles (got " +
                                          std::to_string(std::max(0, last - first)) + ")"};
        double sum = 0.0;
        for (int k = first; k < last; ++k) {
            const int p = mesh.particles[std::size_t(k)];
            const double w = mesh.weights[std::size_t(k)];
            if (p < 0 || p >= count)
                return SceneProblem{path, "particle index " + std::to_string(p) + " is out of range (the scene has " +
                                              std::to_string(count) + " particles)"};
            if (!std::isfinite(w))
                return SceneProblem{path, "a weight is not a finite number"};
            sum += w;
        }
        // the weights sum to 1, so that the vertex moves with its particles when they all move alike
        if (!(std::abs(sum - 1.0) <= 1e-6))
            return SceneProblem{path, "its weights must sum to 1 (got " + std::to_string(sum) + ")"};
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const std::array<int, 3> &t = mesh.faces[f];
        for (std::size_t corner = 0; corner < 3; ++corner)
            if (t[corner] < 0 || t[corner] >= vertices)
                return SceneProblem{"faces[" + std::to_string(f) + "][" + std::to_string(corner) + "]",
                                    "vertex index " + std::to_string(t[corner]) + " is out of range (the mesh has " +
                                        std::to_string(vertices) + " vertices)"};
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            return SceneProblem{"faces[" + std::to_string(f) + "]",
                                "names a vertex twice: a face needs three different vertices"};
    }
    return std::nullopt;
}

std::optional<SceneProblem> findContactImpulseProblem(const std::vector<ContactImpulse> &impulses, std::size_t particles,
                                                      std::size_t planes)
{
    const auto count = static_cast<long long>(particles);
    const auto planeCount = static_cast<long long>(planes);
    for (std::size_t k = 0; k < impulses.size(); ++k) {
        const ContactImpulse &c = impulses[k];
        if (c.i < 0 || c.i >= count)
            return SceneProblem{indexed("contactImpulses", k, "particle"), "particle index " + std::to_string(c.i) +
                                                                              " is out of range (the scene has " +
                                                                              std::to_string(count) + " particles)"};
        if (c.withPlane() && c.plane() >= planeCount)
            return SceneProblem{indexed("contactImpulses", k, "plane"), "plane index " + std::to_string(c.plane()) +
                                                                           " is out of range (the scene has " +
                                                                           std::to_string(planeCount) + " planes)"};
        if (!c.withPlane() && (c.j >= count || c.j == c.i))
            return SceneProblem{indexed("contactImpulses", k, "other"),
                                c.j == c.i ? "is the particle itself: a contact joins two particles"
                                           : "particle index " + std::to_string(c.j) + " is out of range (the scene has " +
                                                 std::to_string(count) + " particles)"};
        if (!(c.normal >= 0.0 && c.normal <= kStateLimit))
            return SceneProblem{indexed("contactImpulses", k, "normal"),
                                "must be from 0 to 1e9 N·s (a contact pushes, never pulls) (got " + formatValue(c.normal, "N·s") + ")"};
        for (int axis = 0; axis < 3; ++axis)
            if (!(std::abs(c.friction[axis]) <= kStateLimit))
                return SceneProblem{indexed("contactImpulses", k, "friction") + "[" + std::to_string(axis) + "]",
                                    "must be from -1e9 to 1e9 N·s (got " + formatValue(c.friction[axis], "N·s") + ")"};
    }
    return std::nullopt;
}

}  // namespace core
