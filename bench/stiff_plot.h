#pragma once
// The stiff-cloth plot, drawn with QPainter into an image: the cost per simulated second that keeps
// a draping cloth within 1% stretch, against the structural stiffness, on log-log axes; one line
// per integrator (its colour) and cloth size (dots for the smallest, squares for the others),
// estimates hollow and joined by a dashed line. Needs a QGuiApplication for the text (the
// offscreen platform will do).

#include "core/integrators/integrator.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <vector>

namespace bench {

inline constexpr QSize kStiffPlotSize{1100, 720};  // pixels

struct StiffPoint {
    core::Integrator integrator = core::Integrator::Xpbd;
    int size = 0;            // particles a side
    double stiffness = 0.0;  // N/m
    double cost = 0.0;       // s per simulated s
    bool estimated = false;  // predicted from the first steps of a capped run
};

// `note` is written under the legend (the machine, the load, what the figures are)
QImage drawStiff(const QString &title, const std::vector<StiffPoint> &points, const QString &note,
                 const QSize &size = kStiffPlotSize);

}  // namespace bench
