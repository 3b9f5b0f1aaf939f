// The generators' option checks (generators.h): each names the first option that is wrong and why,
// in the words of the parameter table (parameters.h) where the option is a scene value, so that the
// editor's Generate dialog can say it and refuse to generate.
#include "core/model/generators.h"

#include "core/model/parameters.h"

#include <cmath>
#include <numbers>
#include <sstream>

namespace core {

namespace {

// "0.1 m": the shortest text of a value that reads back the same, with its unit
std::string withUnit(double value, const char *unit)
{
    std::ostringstream out;
    out << value << ' ' << unit;
    return out.str();
}

// the widest a generated object may be: its springs stay in the rest length's range
constexpr double kMaxExtent = 1e6;  // m

// collects the first problem; every check after it is skipped
class Checker {
public:
    // a count from least to most
    Checker &count(const char *name, long long value, long long least, long long most)
    {
        if (m_problem)
            return *this;
        if (value < least)
            m_problem = std::string(name) + " must be at least " + std::to_string(least) + " (got " +
                        std::to_string(value) + ")";
        else if (value > most)
            m_problem = std::string(name) + " must be at most " + std::to_string(most) + " (got " +
                        std::to_string(value) + ")";
        return *this;
    }

    // a value in the range of a parameter of the scene
    Checker &value(const char *name, Parameter parameter, double value)
    {
        if (!m_problem)
            if (std::optional<std::string> reason = checkParameter(parameter, value))
                m_problem = std::string(name) + " " + *reason;
        return *this;
    }

    // a length that must be more than 0 (and in the rest length's range)
    Checker &length(const char *name, double value)
    {
        if (!m_problem && !(value > 0.0))
            m_problem = std::string(name) + " must be greater than 0 m (got " + withUnit(value, "m") + ")";
        return this->value(name, Parameter::RestLength, value);
    }

    // any other condition, with its message
    Checker &require(bool holds, const std::string &message)
    {
        if (!m_problem && !holds)
            m_problem = message;
        return *this;
    }

    // the particles a generator would make, against the cap
    Checker &particles(double count)
    {
        if (!m_problem && count > kMaxGeneratedParticles) {
            std::ostringstream out;
            out << "makes " << std::llround(count) << " particles, more than the " << kMaxGeneratedParticles
                << " a generator may make";
            m_problem = out.str();
        }
        return *this;
    }

    // how far apart the two furthest particles can be: it bounds every spring's rest length too
    Checker &extent(double across)
    {
        if (!m_problem && !(across <= kMaxExtent))
            m_problem = "it would be " + withUnit(across, "m") + " across, more than the " + withUnit(kMaxExtent, "m") +
                        " a generator may span";
        return *this;
    }

    bool failed() const { return m_problem.has_value(); }
    std::optional<std::string> result() const { return m_problem; }

private:
    std::optional<std::string> m_problem;
};

// the limit a radius keeps to so that particles `spacing` apart do not overlap
std::string overlapMessage(double radius, double most, const char *why)
{
    return "radius " + withUnit(radius, "m") + " is too large: at most " + withUnit(most, "m") + " " + why;
}

// a lattice's granular options: the particles, and a jitter that keeps them apart
void checkGrains(Checker &check, double spacing, double mass, double radius, double jitter)
{
    check.length("spacing", spacing).value("mass", Parameter::Mass, mass).value("radius", Parameter::Radius, radius);
    check.require(jitter >= 0.0, "jitter must be at least 0 m (got " + withUnit(jitter, "m") + ")");
    check.require(radius + jitter <= 0.5 * spacing,
                  overlapMessage(radius, 0.5 * spacing - jitter,
                                 "(half the spacing less the jitter), or neighbours would overlap"));
}

}  // namespace

std::optional<std::string> checkOptions(const ClothOptions &o)
{
    Checker check;
    check.count("rows", o.rows, 2, kMaxGeneratedParticles).count("columns", o.cols, 2, kMaxGeneratedParticles);
    check.particles(double(o.rows) * double(o.cols));
    check.length("spacing", o.spacing).value("mass", Parameter::Mass, o.mass).value("radius", Parameter::Radius, o.radius);
    check.require(2.0 * o.radius <= o.spacing,
                  overlapMessage(o.radius, 0.5 * o.spacing, "(half the spacing), or neighbours would overlap"));
    check.value("structural stiffness", Parameter::Stiffness, o.structuralStiffness)
        .value("shear stiffness", Parameter::Stiffness, o.shearStiffness)
        .value("bend stiffness", Parameter::Stiffness, o.bendStiffness)
        .value("damping", Parameter::Damping, o.damping)
        .value("substeps", Parameter::Substeps, o.substeps)
        .value("height", Parameter::Coordinate, o.height)
        .value("thickness", Parameter::Thickness, o.thickness)
        .extent(o.spacing * std::hypot(o.rows - 1, o.cols - 1));
    return check.result();
}

std::optional<std::string> checkOptions(const ChainOptions &o)
{
    Checker check;
    check.count("links", o.links, 1, kMaxGeneratedParticles - 1);
    check.length("link length", o.linkLength).value("mass", Parameter::Mass, o.mass).value("radius", Parameter::Radius, o.radius);
    check.require(2.0 * o.radius <= o.linkLength,
                  overlapMessage(o.radius, 0.5 * o.linkLength, "(half a link), or neighbours would overlap"));
    check.value("stiffness", Parameter::Stiffness, o.stiffness).value("damping", Parameter::Damping, o.damping);
    check.value("height", Parameter::Coordinate, o.height).extent(o.linkLength * o.links);
    return check.result();
}

std::optional<std::string> checkOptions(const RopeOptions &o)
{
    Checker check;
    check.count("segments", o.segments, 1, kMaxGeneratedParticles - 1);
    check.length("length", o.length).value("mass", Parameter::Mass, o.mass);
    check.value("height", Parameter::Coordinate, o.height).extent(o.length);
    check.value("stiffness", Parameter::Stiffness, o.stiffness).value("damping", Parameter::Damping, o.damping);
    return check.result();
}

std::optional<std::string> checkOptions(const BlockOptions &o)
{
    Checker check;
    check.count("nx", o.nx, 1, kMaxGeneratedParticles).count("ny", o.ny, 1, kMaxGeneratedParticles);
    check.count("nz", o.nz, 1, kMaxGeneratedParticles);
    check.particles(double(o.nx) * double(o.ny) * double(o.nz));
    checkGrains(check, o.spacing, o.mass, o.radius, o.jitter);
    check.value("height", Parameter::Coordinate, o.height);
    check.extent(o.spacing * std::sqrt(double(o.nx - 1) * (o.nx - 1) + double(o.ny - 1) * (o.ny - 1) +
                                       double(o.nz - 1) * (o.nz - 1)));
    return check.result();
}

std::optional<std::string> checkOptions(const BallOptions &o)
{
    Checker check;
    check.length("ball radius", o.ballRadius);
    checkGrains(check, o.spacing, o.mass, o.radius, o.jitter);
    check.value("height", Parameter::Coordinate, o.height).extent(2.0 * o.ballRadius);
    if (check.failed())
        return check.result();
    // the lattice points inside the ball: about its volume over a cell's, or exactly, by counting
    // them, when that is near the cap
    const double estimate = 4.0 / 3.0 * std::numbers::pi * std::pow(o.ballRadius / o.spacing, 3.0);
    if (estimate > 2.0 * kMaxGeneratedParticles)
        return check.particles(estimate).result();
    return check.particles(double(makeBall(o).particles.size())).result();
}

std::optional<std::string> checkOptions(const SoftBallOptions &o)
{
    Checker check;
    check.count("points", o.points, 4, kMaxSoftBallPoints);
    check.length("ball radius", o.ballRadius).value("mass", Parameter::Mass, o.mass).value("radius", Parameter::Radius, o.radius);
    if (check.failed())
        return check.result();
    // points of a Fibonacci lattice are never closer than 0.849 × the mean spacing (measured for
    // every count from 4 to 20000)
    const double spacing = o.ballRadius * std::sqrt(4.0 * std::numbers::pi / o.points);
    check.require(o.radius <= 0.42 * spacing,
                  overlapMessage(o.radius, 0.42 * spacing, "for this many points on this ball, or neighbours would overlap"));
    check.require(!o.centre || 2.0 * o.radius <= o.ballRadius,
                  overlapMessage(o.radius, 0.5 * o.ballRadius, "(half the ball's radius), or the centre would overlap the surface"));
    check.value("stiffness", Parameter::Stiffness, o.stiffness).value("damping", Parameter::Damping, o.damping);
    if (o.centre)
        check.value("centre stiffness", Parameter::Stiffness, o.centreStiffness);
    check.value("height", Parameter::Coordinate, o.height).extent(2.0 * o.ballRadius);
    return check.result();
}

}  // namespace core
