#include "guide_line.h"

#include "render_data.h"

#include <QEvent>
#include <QPainter>

namespace ui {

GuideLine::GuideLine(QWidget *view) : QWidget(view)
{
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setGeometry(view->rect());
    view->installEventFilter(this);
    hide();
}

void GuideLine::showLine(const QLineF &line)
{
    m_line = line;
    show();
    update();
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
    // the selection's colour, dashed over a dark line so that it reads on any background
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(0, 0, 0, 160), 4.0, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(m_line);
    QPen dashes(QColor::fromRgbF(kSelectedColour[0], kSelectedColour[1], kSelectedColour[2]), 2.0, Qt::DashLine,
                Qt::RoundCap);
    painter.setPen(dashes);
    painter.drawLine(m_line);
}

}  // namespace ui
