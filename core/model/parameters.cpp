#include "core/model/parameters.h"

#include <cassert>
#include <cmath>
#include <charconv>
#include <sstream>
#include <string>

namespace core {

namespace {

// the ranges: wide enough for any sensible scene, narrow enough that a typo (a time step of 5 s,
// a mass of 1e300) is caught at the boundary instead of blowing up the simulation
constexpr ParameterInfo kTable[] = {
    {Parameter::TimeStep, "timeStep", "Time step", "s", 0.0, 1.0, true, Scale::Log, 0.01,
     "Simulated time advanced by one step", 1e-5, 0.1},
    {Parameter::Substeps, "substeps", "Substeps", "", 1.0, 10000.0, false, Scale::Log, 1.0,
     "Each step is split into this many equal sub-steps; more is slower but more stable", 1.0, 100.0},
    {Parameter::Viscosity, "viscosity", "Viscosity", "kg/s", 0.0, 1.0e6, false, Scale::Linear, 0.0,
     "Drag of the medium: a force -c v on every particle", 0.0, 20.0},
    {Parameter::Restitution, "restitution", "Restitution", "", 0.0, 1.0, false, Scale::Linear, 1.0,
     "Share of the approach speed kept after a contact: 1 elastic, 0 fully inelastic", 0.0, 1.0},
    {Parameter::Gravity, "gravity", "Gravity", "m/s²", -1.0e4, 1.0e4, false, Scale::Linear, -9.81,
     "Acceleration of gravity, one component (y is up)", -20.0, 20.0},
    {Parameter::Mass, "mass", "Mass", "kg", 0.0, 1.0e9, true, Scale::Log, 1.0, "Mass of a particle", 1e-3, 1e3},
    {Parameter::Radius, "radius", "Radius", "m", 0.0, 1.0e6, true, Scale::Log, 0.1,
     "Radius of a particle, used for contacts and drawing", 1e-3, 10.0},
    {Parameter::Stiffness, "stiffness", "Stiffness", "N/m", 0.0, 1.0e9, false, Scale::Log, 1000.0,
     "Spring constant k of Hooke's law", 1.0, 1e6},
    {Parameter::Damping, "damping", "Damping", "N·s/m", 0.0, 1.0e7, false, Scale::Log, 0.0,
     "Damper coefficient kc along the spring", 1e-2, 1e4},
    {Parameter::RestLength, "restLength", "Rest length", "m", 0.0, 1.0e6, false, Scale::Linear, 0.0,
     "Length at which the spring exerts no force", 0.0, 10.0},
    {Parameter::Coordinate, "position", "Position", "m", -kStateLimit, kStateLimit, false, Scale::Linear, 0.0,
     "A coordinate in space", -100.0, 100.0},
    {Parameter::Speed, "velocity", "Velocity", "m/s", -kStateLimit, kStateLimit, false, Scale::Linear, 0.0,
     "A velocity component", -100.0, 100.0},
    {Parameter::Tolerance, "tolerance", "Tolerance", "", 1e-12, 1.0, false, Scale::Log, 1e-6,
     "Local error per step (m, m/s) the adaptive integrator keeps under", 1e-10, 1e-2},
    {Parameter::BreakStrain, "breakStrain", "Breaking strain", "", 0.0, 1.0e6, false, Scale::Linear, 0.0,
     "Stretch (l - l0) / l0 at which the spring breaks, live; 0 never breaks", 0.0, 2.0},
    {Parameter::Friction, "friction", "Friction", "", 0.0, 10.0, false, Scale::Linear, 0.0,
     "Coulomb coefficient: the friction a contact can hold, as a share of the force pressing it", 0.0, 2.0},
    {Parameter::Extent, "size", "Size", "m", 0.0, 1.0e6, false, Scale::Linear, 0.0,
     "A side of a rectangle; 0 makes the plane unbounded", 0.0, 20.0},
    {Parameter::XpbdIterations, "xpbdIterations", "Iterations", "", 1.0, 100.0, false, Scale::Linear, 1.0,
     "xpbd's passes over the springs in each sub-step: more hold stiff springs closer to their rest length, "
     "at that many times the cost of the pass",
     1.0, 20.0},
    {Parameter::Thickness, "thickness", "Thickness", "m", 0.0, 1.0e3, false, Scale::Linear, 0.0,
     "How far apart a sheet keeps from itself, other sheets and particles in a triangle collision; "
     "0: each sheet's own, from its particles' radii and its shortest side",
     0.0, 0.1},
    {Parameter::AngularSpeed, "angularVelocity", "Spin", "rad/s", -kStateLimit, kStateLimit, false, Scale::Linear,
     0.0, "A component of the particle's angular velocity", -100.0, 100.0},
    {Parameter::SolverIterations, "solverIterations", "Solver iterations", "", 1.0, 200.0, false, Scale::Linear, 10.0,
     "projective's and vbd's iterations of the implicit Euler solve in each sub-step: more hold stiff springs "
     "closer to their rest length, at that many times the cost of an iteration",
     1.0, 50.0},
};

}  // namespace

std::string formatValue(double value, std::string_view unit)
{
    // the shortest text that reads back as the same value: 2147483647 (not 2.14748e+09), 1e+09, 0.1
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    std::ostringstream out;
    out << std::string_view(text, std::size_t(end - text));
    if (!unit.empty())
        out << ' ' << unit;
    return out.str();
}

std::span<const ParameterInfo> parameterTable()
{
    return kTable;
}

const ParameterInfo &parameterInfo(Parameter parameter)
{
    const ParameterInfo &info = kTable[static_cast<int>(parameter)];
    assert(info.parameter == parameter);  // the table is in enum order
    return info;
}

std::optional<std::string> checkParameter(Parameter parameter, double value)
{
    const ParameterInfo &info = parameterInfo(parameter);
    if (std::isnan(value))
        return std::string("is not a number (NaN)");
    if (!std::isfinite(value))
        return std::string("must be finite (got ") + (value > 0 ? "infinity)" : "-infinity)");
    if (info.minimumExclusive && value <= info.minimum)
        return "must be greater than " + formatValue(info.minimum, info.unit) + " (got " +
               formatValue(value, info.unit) + ")";
    if (value < info.minimum)
        return "must be at least " + formatValue(info.minimum, info.unit) + " (got " +
               formatValue(value, info.unit) + ")";
    if (value > info.maximum)
        return "must be at most " + formatValue(info.maximum, info.unit) + " (got " +
               formatValue(value, info.unit) + ")";
    // a mass so small that 1 / m overflows would make the particle's acceleration infinite
    if (parameter == Parameter::Mass && !std::isfinite(1.0 / value))
        return "is too small: 1 / mass is infinite (got " + formatValue(value, info.unit) + ")";
    return std::nullopt;
}

}  // namespace core
