#pragma once
// One table of parameter metadata: name, unit, range, scale, default, tooltip. The parameters
// panel builds its sliders from it and the scene validation checks against it, so every range is
// written once.

#include <optional>
#include <span>
#include <string_view>

namespace core {

// the largest position component (m) and velocity component (m/s) a scene may hold: the file's
// range, and the bound past which a run counts as blown up (step.h), so that any state a run
// reaches can be saved and loaded again
inline constexpr double kStateLimit = 1.0e9;

enum class Parameter {
    TimeStep,
    Substeps,
    Viscosity,
    Restitution,
    Gravity,  // one component of the gravity vector
    Mass,
    Radius,
    Stiffness,
    Damping,
    RestLength,
    Coordinate,  // a position component or a plane offset
    Speed,       // a velocity component
    Tolerance,   // adaptive-rk45's local error target
    BreakStrain,  // (l - l0) / l0 at which a spring breaks; 0: never
    Friction,     // a Coulomb coefficient, static or kinetic
    Extent,       // a side of a rectangle
    XpbdIterations,  // xpbd's passes over the springs a sub-step
    Thickness,       // how far apart sheets stay; 0: each sheet's own
    AngularSpeed,    // a spin component
    SolverIterations,  // projective's and vbd's iterations a sub-step
};
inline constexpr int kParameterCount = static_cast<int>(Parameter::SolverIterations) + 1;

enum class Scale { Linear, Log };

struct ParameterInfo {
    Parameter parameter;
    std::string_view key;    // as in scene files: "timeStep"
    std::string_view label;  // as in the panel: "Time step"
    std::string_view unit;   // "s", "kg", "N/m", "" for none
    double minimum;          // inclusive
    double maximum;          // inclusive
    bool minimumExclusive;   // true: the value must be strictly greater than minimum
    Scale scale;             // how a slider maps onto the range
    double defaultValue;
    std::string_view tooltip;
    // the part of the range a slider spans: a gravity of ±1e4 m/s² is safe, but a slider over it
    // could not set 9.81 (the spin box beside it still takes the whole range)
    double sliderMinimum;
    double sliderMaximum;
};

std::span<const ParameterInfo> parameterTable();
const ParameterInfo &parameterInfo(Parameter parameter);

// nullopt when value is finite and inside the parameter's range; else the reason, e.g.
// "must be greater than 0 (got -1 kg)"
std::optional<std::string> checkParameter(Parameter parameter, double value);

// the shortest text that reads back as the same value, with its unit after a space when it has one
std::string formatValue(double value, std::string_view unit = {});

}  // namespace core
