#include "plot_canvas.h"

#include "plot_axis.h"
#include "plot_series.h"

#include <QPaintEvent>
#include <QPainter>
#include <QPolygonF>

#include <cmath>
#include <vector>

namespace ui {

namespace {

// one colour per curve, told apart on white: red, blue, green, near black, orange, purple
constexpr QRgb kCurveColours[] = {0xd62728, 0x1f77b4, 0x2ca02c, 0x202020, 0xff7f0e, 0x9467bd};

constexpr int kGap = 6;       // px between a label and what it labels
constexpr int kSwatch = 18;   // px, the legend's sample of a line
constexpr int kTickSize = 4;  // px

// data to pixels inside the plot's rectangle
struct Mapping {
    QRectF rect;
    AxisRange time;
    AxisRange value;
    double x(double t) const { return rect.left() + (t - time.low) / time.span() * rect.width(); }
    double y(double v) const { return rect.bottom() - (v - value.low) / value.span() * rect.height(); }
};

// a curve as polylines, broken where a value is not finite; where samples crowd more than two to
// a pixel column, each column keeps only its lowest and highest point, in the order they came, so
// that the shape and every spike survive at a fraction of the points
std::vector<QPolygonF> curvePolylines(const PlotSeries &series, std::size_t curve, const Mapping &map)
{
    std::vector<QPolygonF> lines(1);
    const bool crowded = static_cast<double>(series.size()) > 2.0 * map.rect.width();
    long column = 0;
    double columnX = 0.0, low = 0.0, high = 0.0;
    bool highFirst = false;  // the column's highest point came before its lowest
    bool open = false;       // a crowded column is being gathered
    auto flush = [&] {
        if (!open)
            return;
        lines.back() << QPointF(columnX, highFirst ? high : low);
        if (high != low)
            lines.back() << QPointF(columnX, highFirst ? low : high);
        open = false;
    };
    for (std::size_t i = 0; i < series.size(); ++i) {
        const double v = series.value(curve, i);
        if (!std::isfinite(v)) {
            flush();
            if (!lines.back().isEmpty())
                lines.emplace_back();
            continue;
        }
        const double x = map.x(series.time(i));
        const double y = map.y(v);
        if (!crowded) {
            lines.back() << QPointF(x, y);
            continue;
        }
        // pixels grow downwards: the highest value has the smallest y
        const long at = std::lround(std::floor(x));
        if (open && at == column) {
            if (y < high) {
                high = y;
                highFirst = false;
            }
            if (y > low) {
                low = y;
                highFirst = true;
            }
            continue;
        }
        flush();
        open = true;
        column = at;
        columnX = x;
        low = high = y;
        highFirst = false;
    }
    flush();
    return lines;
}

}  // namespace

PlotCanvas::PlotCanvas(QWidget *parent) : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void PlotCanvas::setSeries(const PlotSeries *series)
{
    m_series = series;
    update();
}

void PlotCanvas::setTitle(const QString &title)
{
    m_title = title;
    update();
}

void PlotCanvas::setValueLabel(const QString &label)
{
    m_valueLabel = label;
    update();
}

void PlotCanvas::setEmptyText(const QString &text)
{
    m_emptyText = text;
    update();
}

QColor PlotCanvas::curveColour(int curve)
{
    const int count = static_cast<int>(std::size(kCurveColours));
    return QColor(kCurveColours[((curve % count) + count) % count]);
}

void PlotCanvas::paintEvent(QPaintEvent *)
{
    // white paper, dark ink: the same on screen and in an exported image
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    const QFontMetrics metrics = painter.fontMetrics();
    const int line = metrics.height();
    const QColor ink(0x30, 0x30, 0x30);
    painter.setPen(ink);

    // the title on top
    int top = kGap;
    if (!m_title.isEmpty()) {
        painter.drawText(QRect(kGap, top, width() - 2 * kGap, line), Qt::AlignLeft | Qt::AlignVCenter, m_title);
        top += line + kGap / 2;
    }

    // with no samples, only what to do to get some
    if (!m_series || m_series->empty()) {
        painter.drawText(rect().adjusted(kGap, top, -kGap, -kGap), Qt::AlignCenter | Qt::TextWordWrap, m_emptyText);
        return;
    }
    const PlotSeries &series = *m_series;

    // the legend below it: a sample of each line and its name, wrapped to the width
    int x = kGap;
    for (std::size_t c = 0; c < series.curveCount(); ++c) {
        const QString name = QString::fromStdString(series.curves()[c].name);
        const int entry = kSwatch + kGap / 2 + metrics.horizontalAdvance(name);
        if (x > kGap && x + entry > width() - kGap) {
            x = kGap;
            top += line;
        }
        painter.setPen(QPen(curveColour(static_cast<int>(c)), 2.0));
        painter.drawLine(QPointF(x, top + line / 2.0), QPointF(x + kSwatch, top + line / 2.0));
        painter.setPen(ink);
        painter.drawText(QRect(x + kSwatch + kGap / 2, top, entry, line), Qt::AlignLeft | Qt::AlignVCenter, name);
        x += entry + 2 * kGap;
    }
    top += line + kGap;

    // the ranges: all the time kept, all the values with some room
    const double firstTime = series.time(0);
    const double lastTime = series.time(series.size() - 1);
    const AxisRange time = timeRange(firstTime, lastTime);
    const auto values = series.valueRange();
    const AxisRange value = values ? paddedRange(values->first, values->second) : AxisRange{};
    const AxisTicks valueTicks = niceTicks(value, 5);
    const AxisTicks timeTicks = niceTicks(time, 6);
    auto label = [](double tick, const AxisTicks &ticks) {
        return QString::fromStdString(tickLabel(tick, ticks.step));
    };

    // room for the labels: the value ticks' width and the axis label on the left, the time ticks
    // and "time [s]" below
    int labelWidth = 0;
    for (double tick : valueTicks.values)
        labelWidth = std::max(labelWidth, metrics.horizontalAdvance(label(tick, valueTicks)));
    const int left = kGap + (m_valueLabel.isEmpty() ? 0 : line + kGap) + labelWidth + kGap + kTickSize;
    const int right = kGap + metrics.horizontalAdvance(label(time.high, timeTicks)) / 2;
    const int bottom = kTickSize + kGap / 2 + 2 * line + kGap;
    const QRectF plot(left, top, std::max(1, width() - left - right), std::max(1, height() - top - bottom));
    const Mapping map{plot, time, value};

    // the grid and the ticks with their labels
    const QPen grid(QColor(0xe0, 0xe0, 0xe0), 1.0);
    for (double tick : valueTicks.values) {
        const double y = map.y(tick);
        painter.setPen(grid);
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.setPen(ink);
        painter.drawLine(QPointF(plot.left() - kTickSize, y), QPointF(plot.left(), y));
        painter.drawText(QRectF(plot.left() - kTickSize - kGap - labelWidth, y - line / 2.0, labelWidth, line),
                         Qt::AlignRight | Qt::AlignVCenter, label(tick, valueTicks));
    }
    for (double tick : timeTicks.values) {
        const double tx = map.x(tick);
        painter.setPen(grid);
        painter.drawLine(QPointF(tx, plot.top()), QPointF(tx, plot.bottom()));
        painter.setPen(ink);
        painter.drawLine(QPointF(tx, plot.bottom()), QPointF(tx, plot.bottom() + kTickSize));
        painter.drawText(QRectF(tx - 50.0, plot.bottom() + kTickSize + kGap / 2.0, 100.0, line), Qt::AlignCenter,
                         label(tick, timeTicks));
    }
    painter.drawRect(plot);

    // the axes' labels
    painter.drawText(QRectF(plot.left(), plot.bottom() + kTickSize + kGap / 2.0 + line, plot.width(), line),
                     Qt::AlignCenter, tr("time [s]"));
    if (!m_valueLabel.isEmpty()) {
        painter.save();
        painter.translate(kGap, plot.center().y());
        painter.rotate(-90.0);
        painter.drawText(QRectF(-plot.height() / 2.0, 0.0, plot.height(), line), Qt::AlignCenter, m_valueLabel);
        painter.restore();
    }

    // the curves, inside the frame, in one-pixel lines: a wider pen is stroked as a path, some 30
    // times slower for a curve of thousands of points
    painter.setClipRect(plot.adjusted(-1.0, -1.0, 1.0, 1.0));
    for (std::size_t c = 0; c < series.curveCount(); ++c) {
        QPen pen(curveColour(static_cast<int>(c)), 1.0);
        pen.setCosmetic(true);
        painter.setPen(pen);
        for (const QPolygonF &polyline : curvePolylines(series, c, map)) {
            if (polyline.size() == 1)
                painter.drawEllipse(polyline.front(), 1.5, 1.5);
            else
                painter.drawPolyline(polyline);
        }
    }
}

}  // namespace ui
