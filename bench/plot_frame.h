#pragma once
// What every benchmark plot draws the same way: a white image and the painter's font, the title
// across the top, and the frame of the
// plot area with the axis labels below it and, turned, left of it. The plots themselves
// (accuracy, stability, throughput) draw their own grids, lines and legends.

#include <QFont>
#include <QImage>
#include <QRectF>
#include <QSize>
#include <QString>

class QPainter;

namespace bench {

// a white image of `size` to draw a plot on
QImage blankPlot(const QSize &size);

// the painter made ready for a plot: antialiased, in the plots' 11-point font, which it returns
QFont preparePlotPainter(QPainter &painter);

// the title, bold and larger than `font`, centred across the top of an image of `size`; leaves
// the painter's font at `font`
void drawPlotTitle(QPainter &painter, const QSize &size, const QFont &font, const QString &title);

// the frame of `plot` and its axis labels: x centred below, y turned and centred at yLabelX
void drawPlotFrame(QPainter &painter, const QRectF &plot, const QString &xLabel, const QString &yLabel,
                   double yLabelX = 26.0);

}  // namespace bench
