#include "work_precision_plot.h"

#include "plot_frame.h"

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bench {

namespace {

// the targets the summary table reads costs at, drawn as dashed lines
constexpr double kTargets[] = {1e-2, 1e-4, 1e-6};

enum class Marker { Circle, Square, TriangleUp, Diamond, TriangleDown, Cross, Plus };

struct CurveStyle {
    QColor colour;
    Marker marker;
};

// the integrator's colour (plot_frame.h) and a distinct marker per integrator
CurveStyle styleOf(core::Integrator integrator)
{
    const QColor colour = integratorColour(integrator);
    switch (integrator) {
    case core::Integrator::SymplecticEuler: return {colour, Marker::Circle};
    case core::Integrator::ExplicitEuler: return {colour, Marker::Square};
    case core::Integrator::VelocityVerlet: return {colour, Marker::TriangleUp};
    case core::Integrator::Rk4: return {colour, Marker::Diamond};
    case core::Integrator::ImplicitEuler: return {colour, Marker::TriangleDown};
    case core::Integrator::AdaptiveRk45: return {colour, Marker::Cross};
    case core::Integrator::Xpbd: return {colour, Marker::Plus};
    case core::Integrator::Projective: return {colour, Marker::Square};
    case core::Integrator::Vbd: return {colour, Marker::Diamond};
    }
    return {colour, Marker::Circle};
}

void drawMarker(QPainter &painter, Marker marker, QPointF centre, double size)
{
    const double r = 0.5 * size;
    QPainterPath path;
    switch (marker) {
    case Marker::Circle: path.addEllipse(centre, r, r); break;
    case Marker::Square: path.addRect(QRectF(centre.x() - r, centre.y() - r, size, size)); break;
    case Marker::TriangleUp:
        path.moveTo(centre.x(), centre.y() - 1.15 * r);
        path.lineTo(centre.x() + 1.1 * r, centre.y() + 0.8 * r);
        path.lineTo(centre.x() - 1.1 * r, centre.y() + 0.8 * r);
        path.closeSubpath();
        break;
    case Marker::Diamond:
        path.moveTo(centre.x(), centre.y() - 1.25 * r);
        path.lineTo(centre.x() + 1.25 * r, centre.y());
        path.lineTo(centre.x(), centre.y() + 1.25 * r);
        path.lineTo(centre.x() - 1.25 * r, centre.y());
        path.closeSubpath();
        break;
    case Marker::TriangleDown:
        path.moveTo(centre.x(), centre.y() + 1.15 * r);
        path.lineTo(centre.x() + 1.1 * r, centre.y() - 0.8 * r);
        path.lineTo(centre.x() - 1.1 * r, centre.y() - 0.8 * r);
        path.closeSubpath();
        break;
    case Marker::Cross:
    case Marker::Plus: {
        // an X or a + drawn with the line pen, thicker so it reads as a marker
        const QPen pen = painter.pen();
        painter.setPen(QPen(pen.color(), 2.2));
        const double a = marker == Marker::Cross ? r : 0.0;
        const double b = marker == Marker::Cross ? r : 1.3 * r;
        painter.drawLine(centre + QPointF(-a, -b), centre + QPointF(a, b));
        painter.drawLine(centre + QPointF(-b, a), centre + QPointF(b, -a));
        painter.setPen(pen);
        return;
    }
    }
    painter.drawPath(path);
}

// whether a run has a place on the log-log axes
bool plottable(const WorkPrecisionPoint &point)
{
    return !point.blewUp() && point.error > 0.0 && point.error <= kPlotErrorCeiling && point.cost > 0.0;
}

}  // namespace

QImage drawWorkPrecision(const QString &title, const std::vector<WorkPrecisionCurve> &curves, const QSize &size)
{
    QImage image = blankPlot(size);
    QPainter painter(&image);
    const QFont font = preparePlotPainter(painter);

    // the data's range, in whole decades
    double costLo = std::numeric_limits<double>::infinity(), costHi = 0.0;
    double errorLo = std::numeric_limits<double>::infinity(), errorHi = 0.0;
    for (const WorkPrecisionCurve &curve : curves)
        for (const WorkPrecisionPoint &point : curve.points)
            if (plottable(point)) {
                costLo = std::min(costLo, point.cost);
                costHi = std::max(costHi, point.cost);
                errorLo = std::min(errorLo, point.error);
                errorHi = std::max(errorHi, point.error);
            }
    const bool empty = costHi == 0.0;
    const Decades xs = empty ? Decades{-3, 0} : decadesAround(costLo, costHi);
    const Decades ys = empty ? Decades{-6, 0} : decadesAround(errorLo, errorHi);

    // the frame: title on top, legend on the right, axis labels left and below
    const QRectF plot(QPointF(110.0, 70.0), QPointF(size.width() - 250.0, size.height() - 90.0));
    const LogAxes axes{plot, xs, ys};

    drawPlotTitle(painter, size, font, title);
    drawLogGrid(painter, axes);

    // the errors the summary table reads costs at
    QPen targetPen(QColor(0x88, 0x88, 0x88), 1.2, Qt::DashLine);
    painter.setPen(targetPen);
    for (double target : kTargets)
        if (target > std::pow(10.0, ys.lo) && target < std::pow(10.0, ys.hi))
            painter.drawLine(QPointF(plot.left(), axes.toY(target)), QPointF(plot.right(), axes.toY(target)));

    // the frame and the axis labels, with units
    drawPlotFrame(painter, plot, QStringLiteral("cost: CPU seconds per simulated second"),
                  QStringLiteral("error: RMS position error at the end time (m)"), 28.0);

    // one line with markers per integrator, in sweep order, clipped to the frame
    painter.setClipRect(plot.adjusted(-8.0, -8.0, 8.0, 8.0));
    for (const WorkPrecisionCurve &curve : curves) {
        const CurveStyle style = styleOf(curve.integrator);
        QPolygonF line;
        for (const WorkPrecisionPoint &point : curve.points)
            if (plottable(point))
                line << QPointF(axes.toX(point.cost), axes.toY(point.error));
        painter.setPen(QPen(style.colour, 2.0));
        painter.setBrush(Qt::NoBrush);
        painter.drawPolyline(line);
        painter.setBrush(style.colour);
        painter.setPen(QPen(style.colour.darker(130), 1.0));
        if (style.marker == Marker::Cross || style.marker == Marker::Plus)
            painter.setPen(QPen(style.colour, 1.0));
        for (const QPointF &p : line)
            drawMarker(painter, style.marker, p, 8.0);
    }
    painter.setClipping(false);
    if (empty)
        painter.drawText(plot, Qt::AlignCenter, QStringLiteral("no run to show"));

    // legend: a sample of each line, the name, and what was left out
    double y = plot.top() + 8.0;
    const double x = plot.right() + 22.0;
    QFont noteFont = font;
    noteFont.setPointSizeF(9.0);
    for (const WorkPrecisionCurve &curve : curves) {
        const CurveStyle style = styleOf(curve.integrator);
        int shown = 0, blowups = 0, offScale = 0;
        for (const WorkPrecisionPoint &point : curve.points) {
            if (plottable(point))
                ++shown;
            else if (point.blewUp())
                ++blowups;
            else
                ++offScale;
        }
        painter.setPen(QPen(style.colour, 2.0));
        painter.drawLine(QPointF(x, y + 9.0), QPointF(x + 34.0, y + 9.0));
        painter.setBrush(style.colour);
        painter.setPen(style.marker == Marker::Cross || style.marker == Marker::Plus ? QPen(style.colour, 1.0)
                                                                                   : QPen(style.colour.darker(130), 1.0));
        drawMarker(painter, style.marker, QPointF(x + 17.0, y + 9.0), 8.0);
        painter.setPen(Qt::black);
        const std::string_view name = core::integratorName(curve.integrator);
        painter.drawText(QPointF(x + 44.0, y + 14.0),
                         QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size())));
        y += 22.0;
        QStringList notes;
        if (blowups > 0)
            notes << QStringLiteral("%1 of %2 runs blew up").arg(blowups).arg(curve.points.size());
        if (offScale > 0)
            notes << QStringLiteral("%1 with error > %2 m").arg(offScale).arg(kPlotErrorCeiling);
        if (shown == 0 && notes.isEmpty())
            notes << QStringLiteral("no runs");
        painter.setFont(noteFont);
        painter.setPen(QColor(0x55, 0x55, 0x55));
        for (const QString &note : notes) {
            painter.drawText(QPointF(x + 44.0, y + 8.0), note);
            y += 16.0;
        }
        painter.setFont(font);
        y += 8.0;
    }

    // what the dashed lines are
    painter.setPen(targetPen);
    painter.drawLine(QPointF(x, y + 9.0), QPointF(x + 34.0, y + 9.0));
    painter.setPen(Qt::black);
    painter.setFont(noteFont);
    painter.drawText(QRectF(x + 44.0, y, size.width() - x - 50.0, 40.0), Qt::TextWordWrap,
                     QStringLiteral("errors the summary table reads costs at"));
    painter.setFont(font);
    return image;
}

}  // namespace bench
