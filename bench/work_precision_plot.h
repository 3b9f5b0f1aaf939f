#pragma once
// The work-precision diagram of one reference problem, drawn with QPainter into an image:
// error against cost on log-log axes, one coloured line with markers per integrator.
// Needs a QGuiApplication for the text (the offscreen platform will do).

#include "work_precision.h"

#include <QImage>
#include <QSize>
#include <QString>

namespace bench {

inline constexpr QSize kPlotSize{1000, 700};  // pixels

// runs that blew up, and errors above this (m), are left out: such a run says nothing about accuracy
inline constexpr double kPlotErrorCeiling = 10.0;

QImage drawWorkPrecision(const QString &title, const std::vector<WorkPrecisionCurve> &curves,
                         const QSize &size = kPlotSize);

}  // namespace bench
