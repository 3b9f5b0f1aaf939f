#pragma once
// The status bar's words for the figures of a run, kept apart from the window so that the unit
// tests can check them: "t = 1.250 s", "×1.00", "×0.35 — slower than real time", "850 steps/s",
// "E = 12.5 J".

#include <QString>

namespace ui {

// a real-time factor below this is called slower than real time (rounding shows ×1.00 above it)
inline constexpr double kRealTimeTolerance = 0.995;

QString timeText(double seconds);
// factor 0 while running means "not measured yet"
QString rateText(bool running, double realTimeFactor);
QString stepsText(bool running, double stepsPerSecond);
QString energyText(double joules);

}  // namespace ui
