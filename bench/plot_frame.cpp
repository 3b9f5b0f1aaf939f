#include "plot_frame.h"

#include <QFontMetricsF>
#include <QPainter>

#include <cmath>

namespace bench {

QImage blankPlot(const QSize &size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    return image;
}

QColor integratorColour(core::Integrator integrator)
{
    switch (integrator) {
    case core::Integrator::SymplecticEuler: return QColor(0x00, 0x72, 0xB2);
    case core::Integrator::ExplicitEuler: return QColor(0xD5, 0x5E, 0x00);
    case core::Integrator::VelocityVerlet: return QColor(0x00, 0x9E, 0x73);
    case core::Integrator::Rk4: return QColor(0xCC, 0x79, 0xA7);
    case core::Integrator::ImplicitEuler: return QColor(0xE6, 0x9F, 0x00);
    case core::Integrator::AdaptiveRk45: return QColor(0x00, 0x00, 0x00);
    case core::Integrator::Xpbd: return QColor(0x56, 0xB4, 0xE9);
    case core::Integrator::Projective: return QColor(0x88, 0x22, 0x55);
    case core::Integrator::Vbd: return QColor(0x11, 0x77, 0x33);
    }
    return Qt::gray;
}

QFont preparePlotPainter(QPainter &painter)
{
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = painter.font();
    font.setPointSizeF(11.0);
    painter.setFont(font);
    return font;
}

void drawPlotTitle(QPainter &painter, const QSize &size, const QFont &font, const QString &title)
{
    QFont titleFont = font;
    titleFont.setPointSizeF(15.0);
    titleFont.setBold(true);
    painter.setFont(titleFont);
    painter.setPen(Qt::black);
    painter.drawText(QRectF(0.0, 12.0, size.width(), 36.0), Qt::AlignCenter, title);
    painter.setFont(font);
}

void drawPlotFrame(QPainter &painter, const QRectF &plot, const QString &xLabel, const QString &yLabel,
                   double yLabelX)
{
    painter.setPen(QPen(Qt::black, 1.2));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(plot);
    painter.drawText(QRectF(plot.left(), plot.bottom() + 38.0, plot.width(), 24.0), Qt::AlignCenter, xLabel);
    painter.save();
    painter.translate(yLabelX, plot.center().y());
    painter.rotate(-90.0);
    painter.drawText(QRectF(-plot.height() / 2.0, -12.0, plot.height(), 24.0), Qt::AlignCenter, yLabel);
    painter.restore();
}

Decades decadesAround(double smallest, double largest)
{
    constexpr double kMargin = 0.1;  // decades
    Decades d{static_cast<int>(std::floor(std::log10(smallest) - kMargin)),
              static_cast<int>(std::ceil(std::log10(largest) + kMargin))};
    if (d.hi <= d.lo)
        d.hi = d.lo + 1;
    return d;
}

double LogAxes::toX(double value) const
{
    return plot.left() + (std::log10(value) - x.lo) / (x.hi - x.lo) * plot.width();
}

double LogAxes::toY(double value) const
{
    return plot.bottom() - (std::log10(value) - y.lo) / (y.hi - y.lo) * plot.height();
}

namespace {

// "10" with the exponent as a superscript, placed by its right edge (y axis) or its centre (x axis)
void drawPowerOfTen(QPainter &painter, int exponent, QPointF anchor, bool rightAligned)
{
    const QFont base = painter.font();
    QFont small = base;
    small.setPointSizeF(base.pointSizeF() * 0.72);
    const QString mantissa = QStringLiteral("10");
    const QString power = QString::number(exponent).replace(u'-', QChar(0x2212));
    const double baseWidth = QFontMetricsF(base).horizontalAdvance(mantissa);
    const double powerWidth = QFontMetricsF(small).horizontalAdvance(power);
    const double width = baseWidth + powerWidth;
    const double ascent = QFontMetricsF(base).ascent();
    const double left = rightAligned ? anchor.x() - width : anchor.x() - 0.5 * width;
    const double baseline = rightAligned ? anchor.y() + 0.35 * ascent : anchor.y() + ascent;
    painter.drawText(QPointF(left, baseline), mantissa);
    painter.setFont(small);
    painter.drawText(QPointF(left + baseWidth, baseline - 0.45 * ascent), power);
    painter.setFont(base);
}

}  // namespace

void drawLogGridX(QPainter &painter, const LogAxes &axes)
{
    const QRectF &plot = axes.plot;
    const QPen gridPen(QColor(0xDD, 0xDD, 0xDD), 1.0);
    const QPen tickPen(QColor(0x55, 0x55, 0x55), 1.0);
    for (int k = axes.x.lo; k <= axes.x.hi; ++k) {
        const double x = axes.toX(std::pow(10.0, k));
        painter.setPen(gridPen);
        painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        painter.setPen(tickPen);
        painter.drawLine(QPointF(x, plot.bottom()), QPointF(x, plot.bottom() + 7.0));
        drawPowerOfTen(painter, k, QPointF(x, plot.bottom() + 10.0), false);
        for (int m = 2; m <= 9 && k < axes.x.hi; ++m) {
            const double xm = axes.toX(m * std::pow(10.0, k));
            painter.drawLine(QPointF(xm, plot.bottom()), QPointF(xm, plot.bottom() + 4.0));
        }
    }
}

void drawLogGridY(QPainter &painter, const LogAxes &axes)
{
    const QRectF &plot = axes.plot;
    const QPen gridPen(QColor(0xDD, 0xDD, 0xDD), 1.0);
    const QPen tickPen(QColor(0x55, 0x55, 0x55), 1.0);
    for (int k = axes.y.lo; k <= axes.y.hi; ++k) {
        const double y = axes.toY(std::pow(10.0, k));
        painter.setPen(gridPen);
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.setPen(tickPen);
        painter.drawLine(QPointF(plot.left() - 7.0, y), QPointF(plot.left(), y));
        drawPowerOfTen(painter, k, QPointF(plot.left() - 11.0, y), true);
        for (int m = 2; m <= 9 && k < axes.y.hi; ++m) {
            const double ym = axes.toY(m * std::pow(10.0, k));
            painter.drawLine(QPointF(plot.left() - 4.0, ym), QPointF(plot.left(), ym));
        }
    }
}

void drawLogGrid(QPainter &painter, const LogAxes &axes)
{
    drawLogGridX(painter, axes);
    drawLogGridY(painter, axes);
}

void drawLegendLine(QPainter &painter, const QPen &pen, QPointF at, double length, double textGap,
                    const QString &text)
{
    painter.setPen(pen);
    painter.drawLine(QPointF(at.x(), at.y() + 9.0), QPointF(at.x() + length, at.y() + 9.0));
    painter.setPen(Qt::black);
    painter.drawText(QPointF(at.x() + length + textGap, at.y() + 13.0), text);
}

}  // namespace bench
