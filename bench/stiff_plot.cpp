#include "stiff_plot.h"

#include "bench_common.h"
#include "plot_frame.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace bench {

namespace {

// a dot for the smallest cloth, a square for the others; hollow for an estimate
void drawMarker(QPainter &painter, QColor colour, bool square, bool hollow, QPointF c)
{
    constexpr double r = 4.5;
    painter.setPen(QPen(colour.darker(120), 1.6));
    painter.setBrush(hollow ? QBrush(Qt::white) : QBrush(colour));
    if (square)
        painter.drawRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
    else
        painter.drawEllipse(c, r, r);
}

}  // namespace

QImage drawStiff(const QString &title, const std::vector<StiffPoint> &points, const QString &note, const QSize &size)
{
    QImage image = blankPlot(size);
    QPainter painter(&image);
    const QFont font = preparePlotPainter(painter);

    // the lines: one per integrator and size, in stiffness order
    std::map<std::pair<int, int>, std::vector<StiffPoint>> lines;
    double kLo = std::numeric_limits<double>::infinity(), kHi = 0.0;
    double costLo = std::numeric_limits<double>::infinity(), costHi = 0.0;
    int smallest = std::numeric_limits<int>::max();
    for (const StiffPoint &p : points) {
        lines[{static_cast<int>(p.integrator), p.size}].push_back(p);
        kLo = std::min(kLo, p.stiffness);
        kHi = std::max(kHi, p.stiffness);
        costLo = std::min(costLo, p.cost);
        costHi = std::max(costHi, p.cost);
        smallest = std::min(smallest, p.size);
    }
    for (auto &[key, line] : lines)
        std::sort(line.begin(), line.end(),
                  [](const StiffPoint &a, const StiffPoint &b) { return a.stiffness < b.stiffness; });
    const bool empty = points.empty();
    const QRectF plot(QPointF(110.0, 70.0), QPointF(size.width() - 300.0, size.height() - 90.0));
    const LogAxes axes{plot, empty ? Decades{3, 8} : decadesAround(kLo, kHi),
                       empty ? Decades{-2, 2} : decadesAround(costLo, costHi)};

    drawPlotTitle(painter, size, font, title);
    drawLogGrid(painter, axes);

    // real time: one second of CPU per simulated second
    const QPen realTimePen(QColor(0x44, 0x44, 0x44), 1.4, Qt::DashDotLine);
    if (axes.y.lo <= 0 && axes.y.hi >= 0) {
        painter.setPen(realTimePen);
        painter.drawLine(QPointF(plot.left(), axes.toY(1.0)), QPointF(plot.right(), axes.toY(1.0)));
    }
    drawPlotFrame(painter, plot, QStringLiteral("structural stiffness k (N/m)"),
                  QStringLiteral("CPU seconds per simulated second, stretch < 1%"), 28.0);

    // each line: solid between measured points, dashed into an estimate
    painter.setClipRect(plot.adjusted(-8.0, -8.0, 8.0, 8.0));
    for (const auto &[key, line] : lines) {
        const QColor colour = integratorColour(static_cast<core::Integrator>(key.first));
        for (std::size_t i = 1; i < line.size(); ++i) {
            const bool dashed = line[i - 1].estimated || line[i].estimated;
            painter.setPen(QPen(colour, 2.0, dashed ? Qt::DashLine : Qt::SolidLine));
            painter.drawLine(QPointF(axes.toX(line[i - 1].stiffness), axes.toY(line[i - 1].cost)),
                             QPointF(axes.toX(line[i].stiffness), axes.toY(line[i].cost)));
        }
        for (const StiffPoint &p : line)
            drawMarker(painter, colour, p.size != smallest, p.estimated,
                       QPointF(axes.toX(p.stiffness), axes.toY(p.cost)));
    }
    painter.setClipping(false);
    if (empty)
        painter.drawText(plot, Qt::AlignCenter, QStringLiteral("no row met the criterion"));

    // legend: a sample of each line, then the markers, the real-time line and the note
    double y = plot.top() + 6.0;
    const double x = plot.right() + 22.0;
    for (const auto &[key, line] : lines) {
        const QColor colour = integratorColour(static_cast<core::Integrator>(key.first));
        painter.setPen(QPen(colour, 2.0));
        painter.drawLine(QPointF(x, y + 9.0), QPointF(x + 30.0, y + 9.0));
        drawMarker(painter, colour, key.second != smallest, false, QPointF(x + 15.0, y + 9.0));
        painter.setPen(Qt::black);
        painter.drawText(QPointF(x + 40.0, y + 14.0),
                         QStringLiteral("%1, %2\u00D7%2").arg(nameOf(static_cast<core::Integrator>(key.first))).arg(key.second));
        y += 24.0;
    }
    y += 8.0;
    QFont noteFont = font;
    noteFont.setPointSizeF(9.5);
    painter.setFont(noteFont);
    drawMarker(painter, Qt::gray, false, true, QPointF(x + 15.0, y + 9.0));
    painter.setPen(Qt::black);
    painter.drawText(QPointF(x + 40.0, y + 13.0), QStringLiteral("estimate (capped run)"));
    y += 22.0;
    drawLegendLine(painter, realTimePen, QPointF(x, y), 30.0, 10.0, QStringLiteral("real time"));
    y += 32.0;
    painter.drawText(QRectF(x, y, size.width() - x - 12.0, size.height() - y - 20.0), Qt::TextWordWrap, note);
    return image;
}

}  // namespace bench
