#include "plot_frame.h"

#include <QPainter>

namespace bench {

QImage blankPlot(const QSize &size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    return image;
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

}  // namespace bench
