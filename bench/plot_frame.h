#pragma once
// What every benchmark plot draws the same way: a white image and the painter's font, the title
// across the top, and the frame of the
// plot area with the axis labels below it and, turned, left of it; for the log-log plots (accuracy,
// stiff) their decades and grid, and for every plot of integrators their colours. The plots
// themselves draw their own lines and legends.

#include "core/integrators/integrator.h"

#include <QColor>
#include <QFont>
#include <QImage>
#include <QPen>
#include <QPointF>
#include <QRectF>
#include <QSize>
#include <QString>

class QPainter;

namespace bench {

// a white image of `size` to draw a plot on
QImage blankPlot(const QSize &size);

// an integrator's colour, the same in every plot: a colour-blind-safe palette (Okabe and Ito)
QColor integratorColour(core::Integrator integrator);

// the painter made ready for a plot: antialiased, in the plots' 11-point font, which it returns
QFont preparePlotPainter(QPainter &painter);

// the title, bold and larger than `font`, centred across the top of an image of `size`; leaves
// the painter's font at `font`
void drawPlotTitle(QPainter &painter, const QSize &size, const QFont &font, const QString &title);

// the frame of `plot` and its axis labels: x centred below, y turned and centred at yLabelX
void drawPlotFrame(QPainter &painter, const QRectF &plot, const QString &xLabel, const QString &yLabel,
                   double yLabelX = 26.0);

// whole decades around the values, [10^lo, 10^hi], at least one decade wide and leaving a tenth of
// a decade between the data and the frame
struct Decades {
    int lo = 0;
    int hi = 1;
};
Decades decadesAround(double smallest, double largest);

// log-log axes over a plot area: where a value falls, in pixels
struct LogAxes {
    QRectF plot;
    Decades x;
    Decades y;
    double toX(double value) const;
    double toY(double value) const;
};

// the grid of log-log axes: a grey line at each decade with its label (10 with the exponent
// raised), short ticks at 2..9 times it
void drawLogGrid(QPainter &painter, const LogAxes &axes);
// the same for one axis alone, for a plot whose other axis is linear (its y decades unused)
void drawLogGridX(QPainter &painter, const LogAxes &axes);
void drawLogGridY(QPainter &painter, const LogAxes &axes);

// a legend entry at `at` (its top left): a line of `pen`, `length` long, then `text` in black,
// `textGap` after the line's end
void drawLegendLine(QPainter &painter, const QPen &pen, QPointF at, double length, double textGap,
                    const QString &text);

}  // namespace bench
