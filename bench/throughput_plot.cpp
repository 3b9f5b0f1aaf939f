#include "throughput_plot.h"

#include "plot_frame.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace bench {

namespace {

// a line of the plot: a variant at a thread count on one kind of scene, or (variant empty) the bound
struct SeriesKey {
    SceneKind kind;
    QString variant;
    int threads;
    bool operator<(const SeriesKey &other) const
    {
        return std::tie(kind, variant, threads) < std::tie(other.kind, other.variant, other.threads);
    }
};

// the Okabe and Ito colours the other plots use; the core's lines in blues, the references apart
QColor colourOf(const QString &variant, int threads)
{
    if (variant.isEmpty())
        return threads > 1 ? QColor(0x99, 0x99, 0x99) : QColor(0x55, 0x55, 0x55);
    if (variant == QLatin1String("springlab"))
        return threads > 1 ? QColor(0x56, 0xB4, 0xE9) : QColor(0x00, 0x72, 0xB2);
    if (variant == QLatin1String("plain"))
        return QColor(0x00, 0x9E, 0x73);
    if (variant == QLatin1String("naive"))
        return QColor(0xD5, 0x5E, 0x00);
    return QColor(0xCC, 0x79, 0xA7);
}

QPen penOf(const SeriesKey &key)
{
    QPen pen(colourOf(key.variant, key.threads), key.variant.isEmpty() ? 1.6 : 2.2);
    if (key.variant.isEmpty())
        pen.setStyle(key.kind == SceneKind::Cloth ? Qt::DashLine : Qt::DotLine);
    else if (key.kind == SceneKind::Box)
        pen.setStyle(Qt::DashDotLine);
    return pen;
}

void drawMarker(QPainter &painter, const SeriesKey &key, QPointF c)
{
    const QColor colour = colourOf(key.variant, key.threads);
    painter.setPen(QPen(colour.darker(120), 1.4));
    painter.setBrush(key.variant.isEmpty() ? QBrush(Qt::white) : QBrush(colour));
    constexpr double r = 4.5;
    if (key.kind == SceneKind::Box)
        painter.drawRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
    else
        painter.drawEllipse(c, r, r);
}

QString labelOf(const SeriesKey &key)
{
    const QString kind = key.kind == SceneKind::Cloth ? QStringLiteral("cloth") : QStringLiteral("box");
    const QString threads =
        key.threads == 1 ? QStringLiteral("1 thread") : QStringLiteral("%1 threads").arg(key.threads);
    if (key.variant.isEmpty())
        return QStringLiteral("%1 bandwidth bound, %2").arg(kind, threads);
    return QStringLiteral("%1 %2, %3").arg(kind, key.variant, threads);
}

}  // namespace

QImage drawThroughput(const QString &title, const std::vector<ThroughputRow> &rows, const QString &note,
                      const QSize &size)
{
    QImage image = blankPlot(size);
    QPainter painter(&image);
    const QFont font = preparePlotPainter(painter);

    // the lines: each variant and thread count, and the bound at each thread count, per kind of scene
    std::map<SeriesKey, std::map<long long, double>> series;
    for (const ThroughputRow &row : rows) {
        series[{row.kind, row.variant, row.threads}][row.particles] = row.msPerStep;
        series[{row.kind, QString(), row.threads}][row.particles] = row.boundMs;
    }

    // the ranges, in whole decades
    double xMin = std::numeric_limits<double>::infinity(), xMax = 0.0;
    double yMin = std::numeric_limits<double>::infinity(), yMax = 0.0;
    for (const auto &[key, points] : series)
        for (const auto &[particles, ms] : points) {
            xMin = std::min(xMin, static_cast<double>(particles));
            xMax = std::max(xMax, static_cast<double>(particles));
            yMin = std::min(yMin, ms);
            yMax = std::max(yMax, ms);
        }
    const bool empty = series.empty();
    const int xLo = empty ? 3 : static_cast<int>(std::floor(std::log10(xMin)));
    const int xHi = empty ? 6 : std::max(xLo + 1, static_cast<int>(std::ceil(std::log10(xMax))));
    const int yLo = empty ? -3 : static_cast<int>(std::floor(std::log10(yMin)));
    const int yHi = empty ? 3 : std::max(yLo + 1, static_cast<int>(std::ceil(std::log10(yMax))));

    const QRectF plot(QPointF(100.0, 70.0), QPointF(size.width() - 330.0, size.height() - 90.0));
    const LogAxes axes{plot, Decades{xLo, xHi}, Decades{yLo, yHi}};
    const auto toX = [&](double x) { return axes.toX(x); };
    const auto toY = [&](double y) { return axes.toY(y); };

    drawPlotTitle(painter, size, font, title);

    // grid: decades both ways
    drawLogGrid(painter, axes);

    // the frame and the axis labels, with units
    drawPlotFrame(painter, plot, QStringLiteral("particles"),
                  QStringLiteral("run time per step (ms), one sub-step"));

    // the lines, bounds first so the measurements lie on top
    painter.setClipRect(plot.adjusted(-8.0, -8.0, 8.0, 8.0));
    for (bool bounds : {true, false})
        for (const auto &[key, points] : series) {
            if (key.variant.isEmpty() != bounds)
                continue;
            QPainterPath path;
            for (const auto &[particles, ms] : points) {
                const QPointF p(toX(static_cast<double>(particles)), toY(ms));
                if (path.elementCount() == 0)
                    path.moveTo(p);
                else
                    path.lineTo(p);
            }
            painter.setPen(penOf(key));
            painter.setBrush(Qt::NoBrush);
            painter.drawPath(path);
            for (const auto &[particles, ms] : points)
                drawMarker(painter, key, QPointF(toX(static_cast<double>(particles)), toY(ms)));
        }
    painter.setClipping(false);
    if (empty)
        painter.drawText(plot, Qt::AlignCenter, QStringLiteral("nothing measured"));

    // legend: the measured lines, the bounds, then the note
    QFont legendFont = font;
    legendFont.setPointSizeF(9.5);
    painter.setFont(legendFont);
    const double x = plot.right() + 20.0;
    double y = plot.top() + 4.0;
    for (bool bounds : {false, true})
        for (const auto &[key, points] : series) {
            if (key.variant.isEmpty() != bounds)
                continue;
            painter.setPen(penOf(key));
            painter.drawLine(QPointF(x, y + 8.0), QPointF(x + 30.0, y + 8.0));
            drawMarker(painter, key, QPointF(x + 15.0, y + 8.0));
            painter.setPen(Qt::black);
            painter.drawText(QPointF(x + 40.0, y + 12.0), labelOf(key));
            y += 22.0;
        }
    y += 12.0;
    painter.setPen(Qt::black);
    painter.drawText(QRectF(x, y, size.width() - x - 12.0, size.height() - y - 20.0), Qt::TextWordWrap, note);
    return image;
}

}  // namespace bench
