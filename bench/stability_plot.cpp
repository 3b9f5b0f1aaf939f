#include "stability_plot.h"

#include "bench_common.h"

#include "plot_frame.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bench {

namespace {

// a marker shape per integrator, so the plot reads in grey too
QPainterPath markerOf(core::Integrator integrator, QPointF c, double r)
{
    QPainterPath path;
    switch (integrator) {
    case core::Integrator::ExplicitEuler: path.addRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r)); break;
    case core::Integrator::VelocityVerlet:
        path.moveTo(c.x(), c.y() - 1.2 * r);
        path.lineTo(c.x() + 1.15 * r, c.y() + 0.85 * r);
        path.lineTo(c.x() - 1.15 * r, c.y() + 0.85 * r);
        path.closeSubpath();
        break;
    case core::Integrator::Rk4:
        path.moveTo(c.x(), c.y() - 1.3 * r);
        path.lineTo(c.x() + 1.3 * r, c.y());
        path.lineTo(c.x(), c.y() + 1.3 * r);
        path.lineTo(c.x() - 1.3 * r, c.y());
        path.closeSubpath();
        break;
    default: path.addEllipse(c, r, r); break;
    }
    return path;
}

// filled for the shortest chain, hollow (white inside) for the others
void drawMarker(QPainter &painter, core::Integrator integrator, bool filled, QPointF centre)
{
    const QColor colour = integratorColour(integrator);
    painter.setPen(QPen(colour.darker(120), 1.6));
    painter.setBrush(filled ? QBrush(colour) : QBrush(Qt::white));
    painter.drawPath(markerOf(integrator, centre, 5.0));
}

}  // namespace

QImage drawStabilityMap(const QString &title, const std::vector<StabilityPoint> &points, const QString &note,
                        const QSize &size)
{
    QImage image = blankPlot(size);
    QPainter painter(&image);
    const QFont font = preparePlotPainter(painter);

    // the ranges: whole decades of the theoretical step; ratios in tenths, always showing 1
    double stepLo = std::numeric_limits<double>::infinity(), stepHi = 0.0;
    double ratioLo = 1.0, ratioHi = 1.0;
    int fewest = std::numeric_limits<int>::max();
    for (const StabilityPoint &p : points) {
        stepLo = std::min(stepLo, p.theoryStep);
        stepHi = std::max(stepHi, p.theoryStep);
        ratioLo = std::min(ratioLo, p.measuredStep / p.theoryStep);
        ratioHi = std::max(ratioHi, p.measuredStep / p.theoryStep);
        fewest = std::min(fewest, p.particles);
    }
    const bool empty = points.empty();
    const int xLo = empty ? -5 : static_cast<int>(std::floor(std::log10(stepLo) - 0.1));
    const int xHi = empty ? 0 : std::max(xLo + 1, static_cast<int>(std::ceil(std::log10(stepHi) + 0.1)));
    const double yLo = std::floor(ratioLo * 10.0 - 0.5) / 10.0;
    const double yHi = std::ceil(ratioHi * 10.0 + 0.5) / 10.0;

    const QRectF plot(QPointF(100.0, 70.0), QPointF(size.width() - 270.0, size.height() - 90.0));
    const LogAxes xAxis{plot, Decades{xLo, xHi}, Decades{}};
    const auto toX = [&](double step) { return xAxis.toX(step); };
    const auto toY = [&](double ratio) { return plot.bottom() - (ratio - yLo) / (yHi - yLo) * plot.height(); };

    drawPlotTitle(painter, size, font, title);

    // grid: decades across, tenths up
    const QPen gridPen(QColor(0xDD, 0xDD, 0xDD), 1.0);
    const QPen tickPen(QColor(0x55, 0x55, 0x55), 1.0);
    const QFontMetricsF metrics(font);
    drawLogGridX(painter, xAxis);
    // a line every 0.02 on a narrow range, every 0.1 or 0.2 on wider ones
    const double spacing = yHi - yLo <= 0.3 ? 0.02 : (yHi - yLo <= 1.2 ? 0.1 : 0.2);
    const int lines = static_cast<int>(std::lround((yHi - yLo) / spacing));
    for (int t = 0; t <= lines; ++t) {
        const double ratio = yLo + spacing * t;
        const double y = toY(ratio);
        painter.setPen(gridPen);
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.setPen(tickPen);
        painter.drawLine(QPointF(plot.left() - 6.0, y), QPointF(plot.left(), y));
        const QString label = QString::number(ratio, 'f', spacing < 0.1 ? 2 : 1);
        painter.drawText(QPointF(plot.left() - 10.0 - metrics.horizontalAdvance(label), y + 0.35 * metrics.ascent()),
                         label);
    }

    // the theory: measured = predicted
    const QPen theoryPen(QColor(0x44, 0x44, 0x44), 1.4, Qt::DashLine);
    painter.setPen(theoryPen);
    painter.drawLine(QPointF(plot.left(), toY(1.0)), QPointF(plot.right(), toY(1.0)));

    // the frame and the axis labels, with units
    drawPlotFrame(painter, plot, QStringLiteral("theoretical stability limit (s), core/integrators/stability.h"),
                  QStringLiteral("measured largest stable step / theoretical limit"));

    // the cells, hollow ones first so the filled ones stay visible where they coincide
    painter.setClipRect(plot.adjusted(-8.0, -8.0, 8.0, 8.0));
    for (bool filled : {false, true})
        for (const StabilityPoint &p : points)
            if ((p.particles == fewest) == filled)
                drawMarker(painter, p.integrator, filled,
                           QPointF(toX(p.theoryStep), toY(p.measuredStep / p.theoryStep)));
    painter.setClipping(false);
    if (empty)
        painter.drawText(plot, Qt::AlignCenter, QStringLiteral("no cell measured"));

    // legend: the integrators present, what filled and hollow mean, the dashed line, the note
    double y = plot.top() + 6.0;
    const double x = plot.right() + 24.0;
    std::vector<core::Integrator> shown;
    for (const StabilityPoint &p : points)
        if (std::find(shown.begin(), shown.end(), p.integrator) == shown.end())
            shown.push_back(p.integrator);
    for (core::Integrator integrator : shown) {
        drawMarker(painter, integrator, true, QPointF(x + 8.0, y + 9.0));
        painter.setPen(Qt::black);
        painter.drawText(QPointF(x + 24.0, y + 14.0), nameOf(integrator));
        y += 24.0;
    }
    y += 10.0;
    QFont noteFont = font;
    noteFont.setPointSizeF(9.5);
    painter.setFont(noteFont);
    int most = 0;
    for (const StabilityPoint &p : points)
        most = std::max(most, p.particles);
    if (!empty) {
        drawMarker(painter, core::Integrator::SymplecticEuler, true, QPointF(x + 8.0, y + 9.0));
        painter.setPen(Qt::black);
        painter.drawText(QPointF(x + 24.0, y + 13.0), QStringLiteral("chain of %1 particles").arg(fewest));
        y += 22.0;
        if (most != fewest) {
            drawMarker(painter, core::Integrator::SymplecticEuler, false, QPointF(x + 8.0, y + 9.0));
            painter.setPen(Qt::black);
            painter.drawText(QPointF(x + 24.0, y + 13.0), QStringLiteral("chain of %1 particles").arg(most));
            y += 22.0;
        }
    }
    drawLegendLine(painter, theoryPen, QPointF(x, y), 18.0, 6.0, QStringLiteral("measured = theory"));
    y += 34.0;
    painter.drawText(QRectF(x, y, size.width() - x - 12.0, size.height() - y - 20.0), Qt::TextWordWrap, note);
    return image;
}

}  // namespace bench
