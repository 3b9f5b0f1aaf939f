#pragma once
// The stability map, drawn with QPainter into an image: for every cell of the sweep, the measured
// largest stable step over the theoretical one, against the theoretical step on a log axis; one
// colour per integrator, filled markers for the shortest chain and hollow ones for the longest.
// Needs a QGuiApplication for the text (the offscreen platform will do).

#include "core/integrators/integrator.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <vector>

namespace bench {

inline constexpr QSize kStabilityPlotSize{1000, 700};  // pixels

struct StabilityPoint {
    core::Integrator integrator = core::Integrator::SymplecticEuler;
    int particles = 2;
    double theoryStep = 0.0;    // s
    double measuredStep = 0.0;  // s
};

// `note` is printed under the legend (implicit Euler's result)
QImage drawStabilityMap(const QString &title, const std::vector<StabilityPoint> &points, const QString &note,
                        const QSize &size = kStabilityPlotSize);

}  // namespace bench
