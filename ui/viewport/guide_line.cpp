#include "guide_line.h"

#include "render_data.h"

#include <QEvent>
#include <QPainter>

#include <algorithm>

namespace ui {

GuideLine::GuideLine(QWidget *view) : QWidget(view)
{
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setGeometry(view->rect());
    view->installEventFilter(this);
    hide();
}

void GuideLine::showLine(const QLineF &line, const QString &label)
{
    m_source = nullptr;
    m_shape = {line, label};
    show();
    update();
}

void GuideLine::follow(Source source)
{
    m_source = std::move(source);
    show();
    update();
}

void GuideLine::setDashed(bool dashed)
{
    m_dashed = dashed;
    update();
}

std::optional<GuideLine::Shape> GuideLine::shape() const
{
    if (m_source)
        return m_source();
    return m_shape;
}

QLineF GuideLine::line() const
{
    const std::optional<Shape> now = shape();
    return now ? now->line : QLineF();
}

QString GuideLine::label() const
{
    const std::optional<Shape> now = shape();
    return now ? now->label : QString();
}

bool GuideLine::eventFilter(QObject *watched, QEvent *event)
{
    // as large as the view, whatever it is resized to
    if (watched == parentWidget() && event->type() == QEvent::Resize)
        setGeometry(parentWidget()->rect());
    return QWidget::eventFilter(watched, event);
}

void GuideLine::paintEvent(QPaintEvent *)
{
    ++m_paints;
    m_painted = shape();
    if (!m_painted)
        return;
    const QLineF &line = m_painted->line;

    // the selection's colour over a dark line, so that it reads on any background
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(0, 0, 0, 160), 4.0, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(line);
    const QColor colour = QColor::fromRgbF(kSelectedColour[0], kSelectedColour[1], kSelectedColour[2]);
    painter.setPen(QPen(colour, 2.0, m_dashed ? Qt::DashLine : Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(line);
    if (m_painted->label.isEmpty())
        return;

    // the label on a dark box beside the middle of the line, off it so that it hides neither end
    const QFontMetrics metrics = painter.fontMetrics();
    const QSizeF size(metrics.horizontalAdvance(m_painted->label) + 8.0, metrics.height() + 4.0);
    QPointF side = line.length() > 0.0 ? QPointF(-line.dy(), line.dx()) / line.length() : QPointF(0.0, -1.0);
    if (side.y() > 0.0)
        side = -side;  // above the line, where the eye looks for a label
    const QPointF centre = line.center() + side * (0.5 * size.height() + 4.0);
    QRectF box(QPointF(), size);
    box.moveCenter(centre);
    box.moveLeft(std::clamp(box.left(), 0.0, std::max(0.0, width() - box.width())));
    box.moveTop(std::clamp(box.top(), 0.0, std::max(0.0, height() - box.height())));
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 180));
    painter.drawRoundedRect(box, 3.0, 3.0);
    painter.setPen(colour);
    painter.drawText(box, Qt::AlignCenter, m_painted->label);
}

}  // namespace ui
