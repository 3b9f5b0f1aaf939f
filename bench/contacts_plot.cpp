#include "contacts_plot.h"

#include "plot_frame.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bench {

namespace {

// the Okabe and Ito colours the other plots use: the core in blue, Bullet in the peer's pink, Bullet
// with its rotation locked in orange
QColor colourOf(const QString &engine)
{
    if (engine == QLatin1String("springlab"))
        return QColor(0x00, 0x72, 0xB2);
    if (engine == QLatin1String("bullet"))
        return QColor(0xCC, 0x79, 0xA7);
    return QColor(0xE6, 0x9F, 0x00);
}

// the names in the order they first appear
std::vector<QString> inOrder(const std::vector<ContactRow> &rows, QString ContactRow::*field)
{
    std::vector<QString> names;
    for (const ContactRow &row : rows)
        if (std::find(names.begin(), names.end(), row.*field) == names.end())
            names.push_back(row.*field);
    return names;
}

// the table's cells for one row
QStringList cellsOf(const ContactRow &row)
{
    QString stands = QStringLiteral("—");
    if (row.stands)
        stands = QStringLiteral("%1, %2 mm")
                     .arg(*row.stands ? QStringLiteral("stands") : QStringLiteral("no"))
                     .arg(*row.movedMm, 0, 'g', 2);
    QString settled = row.settled ? QStringLiteral("at %1 s").arg(*row.settleSeconds, 0, 'f', 2)
                                  : QStringLiteral("no: %1 J").arg(row.kineticPeak, 0, 'g', 2);
    if (row.blewUp)
        settled = QStringLiteral("blew up");
    QString repose = QStringLiteral("—");
    if (row.reposeConeDegrees)
        repose = QStringLiteral("%1 / %2°")
                     .arg(row.reposeFitDegrees ? QString::number(*row.reposeFitDegrees, 'f', 1) + QStringLiteral("°")
                                               : QStringLiteral("–"))
                     .arg(*row.reposeConeDegrees, 0, 'f', 1);
    return {row.scene,
            row.engine,
            QString::number(row.balls),
            QString::number(row.substeps),
            stands,
            settled,
            QStringLiteral("%1 mm").arg(row.overlapMm, 0, 'f', 2),
            repose,
            QString::number(row.msPerStep, 'g', 3)};
}

}  // namespace

QImage drawContacts(const QString &title, const std::vector<ContactRow> &rows, const QString &note, const QSize &size)
{
    QImage image = blankPlot(size);
    QPainter painter(&image);
    const QFont font = preparePlotPainter(painter);
    const QFontMetricsF metrics(font);
    drawPlotTitle(painter, size, font, title);

    const std::vector<QString> scenes = inOrder(rows, &ContactRow::scene);
    const std::vector<QString> engines = inOrder(rows, &ContactRow::engine);

    // the bars' range, in whole decades
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (const ContactRow &row : rows)
        if (row.msPerStep > 0.0) {
            lo = std::min(lo, row.msPerStep);
            hi = std::max(hi, row.msPerStep);
        }
    const bool empty = !(hi > 0.0);
    const int yLo = empty ? -2 : static_cast<int>(std::floor(std::log10(lo)));
    const int yHi = empty ? 1 : std::max(yLo + 1, static_cast<int>(std::ceil(std::log10(hi))));
    const QRectF plot(QPointF(100.0, 70.0), QPointF(size.width() - 40.0, 370.0));
    const auto toY = [&](double y) { return plot.bottom() - (std::log10(y) - yLo) / (yHi - yLo) * plot.height(); };

    // grid: decades
    for (int k = yLo; k <= yHi; ++k) {
        const double y = toY(std::pow(10.0, k));
        painter.setPen(QPen(QColor(0xDD, 0xDD, 0xDD), 1.0));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.setPen(QPen(QColor(0x55, 0x55, 0x55), 1.0));
        painter.drawLine(QPointF(plot.left() - 6.0, y), QPointF(plot.left(), y));
        const QString label = QStringLiteral("1e%1").arg(k);
        painter.drawText(QPointF(plot.left() - 10.0 - metrics.horizontalAdvance(label), y + 0.35 * metrics.ascent()),
                         label);
    }

    // the bars: a group per scene, a bar per engine, its figure above it
    const double group = scenes.empty() ? plot.width() : plot.width() / static_cast<double>(scenes.size());
    const double barWidth = std::min(70.0, 0.7 * group / std::max<std::size_t>(1, engines.size()));
    QFont small = font;
    small.setPointSizeF(9.5);
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        const double centre = plot.left() + (static_cast<double>(s) + 0.5) * group;
        painter.setFont(font);
        painter.setPen(Qt::black);
        painter.drawText(QRectF(centre - 0.5 * group, plot.bottom() + 6.0, group, 22.0), Qt::AlignCenter, scenes[s]);
        painter.setFont(small);
        for (std::size_t e = 0; e < engines.size(); ++e) {
            const auto found = std::find_if(rows.begin(), rows.end(), [&](const ContactRow &row) {
                return row.scene == scenes[s] && row.engine == engines[e];
            });
            if (found == rows.end() || !(found->msPerStep > 0.0))
                continue;
            const double left = centre + (static_cast<double>(e) - 0.5 * static_cast<double>(engines.size())) * barWidth;
            const double top = toY(found->msPerStep);
            painter.setPen(QPen(colourOf(engines[e]).darker(130), 1.0));
            painter.setBrush(colourOf(engines[e]));
            painter.drawRect(QRectF(left, top, barWidth, plot.bottom() - top));
            painter.setPen(Qt::black);
            painter.drawText(QRectF(left - 10.0, top - 20.0, barWidth + 20.0, 18.0), Qt::AlignCenter,
                             QString::number(found->msPerStep, 'g', 3));
        }
    }
    painter.setFont(font);
    drawPlotFrame(painter, plot, QString(), QStringLiteral("CPU time per step of h (ms)"));
    if (empty)
        painter.drawText(plot, Qt::AlignCenter, QStringLiteral("nothing measured"));

    // legend, top left inside the plot
    double legendY = plot.top() + 10.0;
    for (const QString &engine : engines) {
        painter.setPen(QPen(colourOf(engine).darker(130), 1.0));
        painter.setBrush(colourOf(engine));
        painter.drawRect(QRectF(plot.left() + 12.0, legendY, 22.0, 14.0));
        painter.setPen(Qt::black);
        painter.drawText(QPointF(plot.left() + 42.0, legendY + 12.0), engine);
        legendY += 22.0;
    }

    // the table: one line per scene and engine
    const QStringList header{QStringLiteral("scene"),   QStringLiteral("engine"),  QStringLiteral("balls"),
                             QStringLiteral("sub-steps"), QStringLiteral("stack (moved)"), QStringLiteral("settled"),
                             QStringLiteral("overlap"), QStringLiteral("repose fit / cone"),
                             QStringLiteral("ms / step")};
    const std::vector<double> widths{110, 130, 70, 90, 170, 150, 110, 170, 100};
    const double tableLeft = 60.0;
    double y = plot.bottom() + 56.0;
    constexpr double rowHeight = 24.0;
    const auto drawCells = [&](const QStringList &cells) {
        double x = tableLeft;
        for (qsizetype c = 0; c < cells.size(); ++c) {
            painter.drawText(QRectF(x + 4.0, y, widths[static_cast<std::size_t>(c)] - 8.0, rowHeight),
                             Qt::AlignVCenter | (c < 2 ? Qt::AlignLeft : Qt::AlignRight), cells[c]);
            x += widths[static_cast<std::size_t>(c)];
        }
        y += rowHeight;
    };
    QFont bold = font;
    bold.setBold(true);
    painter.setFont(bold);
    painter.setPen(Qt::black);
    drawCells(header);
    double tableWidth = 0.0;
    for (double w : widths)
        tableWidth += w;
    painter.drawLine(QPointF(tableLeft, y), QPointF(tableLeft + tableWidth, y));
    painter.setFont(font);
    for (std::size_t r = 0; r < rows.size(); ++r) {
        if (r % 2 == 1)
            painter.fillRect(QRectF(tableLeft, y, tableWidth, rowHeight), QColor(0xF2, 0xF2, 0xF2));
        painter.setPen(colourOf(rows[r].engine).darker(120));
        drawCells(cellsOf(rows[r]));
    }

    // the note
    y += 16.0;
    painter.setPen(Qt::black);
    painter.setFont(small);
    painter.drawText(QRectF(tableLeft, y, size.width() - 2.0 * tableLeft, size.height() - y - 10.0), Qt::TextWordWrap,
                     note);
    return image;
}

}  // namespace bench
