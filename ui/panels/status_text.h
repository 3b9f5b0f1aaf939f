#pragma once
// The status bar's words for the figures of a run, kept apart from the window so that the unit
// tests can check them: "t = 1.250 s", "×1.00", "×0.35 — slower than real time", "850 steps/s",
// "0.19 steps/s", "12 frames/s", "E = 12.5 J", "local error ≈ 3.2e-6 m/step", "ΔE = +0.4 %", and
// what the accuracy planner picked.

#include "core/integrators/accuracy_planner.h"
#include "core/model/diagnostics.h"

#include <Eigen/Core>
#include <QString>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace ui {

// a real-time factor below this is called slower than real time (rounding shows ×1.00 above it)
inline constexpr double kRealTimeTolerance = 0.995;

QString timeText(double seconds);
// where the cue meets the ball, in tenths of its radius: "0.3 r below the centre", or briefly
// "−0.3r", "centre"
QString cueHeightText(int tenths, bool brief = false);
// the steering figure: the push and the cue, "push 3 N 45°; cue 4 m/s −0.3r"
QString steerText(double pushNewtons, double degrees, double cueSpeed, int cueTenths);
// factor 0 while running means "not measured yet" ("×…"); below 0.1 it has two significant
// digits ("×0.0021"), never "×0.00". speed is the one chosen (playback_speed.h): a run slower than
// it says so ("slower than real time" at ×1, "slower than the ×4 asked"), and one as fast as it
// goes says that instead
QString rateText(bool running, double realTimeFactor, double speed = 1.0);
// rates while running, empty while paused; 0 means "not measured yet" ("… steps/s"), and a slow
// rate keeps two significant digits ("0.19 steps/s"), never "0 steps/s"; paused with steps that
// Step asked for still owed, "taking a step…"
QString stepsText(bool running, double stepsPerSecond, std::uint64_t owed = 0);
QString framesText(bool running, double framesPerSecond);
QString energyText(double joules);
// the total of the energies, shown as 0 where it is round-off: nothing beside its parts (they
// cancel to a billionth), or below kRoundOffJoules whatever they are (a scene at rest, 1e-27 J)
inline constexpr double kRoundOffJoules = 1e-20;
QString energyText(const core::Energies &energies);

// a number in short scientific notation with at most `digits` significant digits: "3.2e-6", "1e-6"
QString scientificText(double value, int digits = 2);
// a computing time with its unit: "12 µs", "0.8 ms", "1.3 s"
QString durationText(double seconds);

// "local error ≈ 3.2e-6 m/step" (a step of the integrator: one sub-step); "local error ≈ ?" before
// the first estimate or when its trial blew up
QString localErrorText(std::optional<double> metres);

// below this share of the sizes of its parts, the total energy at reset counts as zero, and the
// drift is given in joules instead of relative to it
inline constexpr double kZeroEnergyShare = 1e-3;
// "ΔE = +0.4 %" since the energies at reset, or "ΔE = -0.012 J" when their total is about zero
QString driftText(const core::Energies &initial, double current);

// "121 particles and 220 springs selected", "1 particle selected", "Nothing selected"
QString selectionText(std::size_t particles, std::size_t springs);

// a measured length for the view's label, four significant digits: "1.234 m", "0.0005 m"
QString lengthText(double metres);
// a measured distance from one point to another, six significant digits with its parts:
// "1.22474 m (Δx 1, Δy 0.5, Δz -0.5)"
QString distanceText(const Eigen::Vector3d &delta);
// the same as two lines, the distance over its parts, for the inspector (a label that wraps by
// itself in a form is given one line's height and overlaps the row below)
QString distanceLines(const Eigen::Vector3d &delta);

// why an edit that would add particles past the editor's limit was refused: "Not duplicated: the
// scene would have 400000 particles, more than the 200000 the editor allows; nothing was changed"
QString particleLimitText(const QString &notDone, std::size_t total);

// what the planner picked and why: "rk4 with 3 substeps: ≈ 2.1e-7 m/step at 0.8 ms per simulated
// second, the cheapest of 4 integrators that meet 1e-6 m/step"; or why nothing was picked
QString planText(const core::AccuracyPlan &plan);

// how a sub-step stands against the explicit integrators' stability limit
enum class StabilityLevel { Safe, Near, Past };
// from this share of the limit on, a sub-step is near it
inline constexpr double kNearStabilityShare = 0.8;
struct StabilityNote {
    QString text;
    StabilityLevel level = StabilityLevel::Safe;
};
// "Stable sub-step ≤ 3.1 ms; each is 10 ms, 3.2× over: use ≥ 4 substeps or implicit-euler", for a
// limit maxSubStep (s; infinite when any step is stable, 0 when none is) and the sub-step taken
StabilityNote stabilityNote(double maxSubStep, double subStep, double timeStep, core::Integrator integrator);

}  // namespace ui
