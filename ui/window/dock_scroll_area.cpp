#include "dock_scroll_area.h"

#include <QEvent>
#include <QScrollBar>

#include <algorithm>

namespace ui {

DockScrollArea::DockScrollArea(QWidget *content, QWidget *parent) : QScrollArea(parent)
{
    setWidget(content);
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    content->installEventFilter(this);
}

QSize DockScrollArea::minimumSizeHint() const
{
    const QWidget *content = widget();
    if (!content)
        return QScrollArea::minimumSizeHint();
    // room for the bar whether or not it shows now, so that its coming never narrows the content
    const int bar = verticalScrollBar()->sizeHint().width();
    const int frame = 2 * frameWidth();
    // (and the content's own minimum width where it sets one: a panel whose parts come and go keeps
    // the width of its widest, so that the view beside it does not change size)
    const int width = std::max(content->minimumSizeHint().width(), content->minimumWidth());
    return {width + bar + frame, QScrollArea::minimumSizeHint().height()};
}

bool DockScrollArea::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == widget() && event->type() == QEvent::LayoutRequest)
        updateGeometry();
    return QScrollArea::eventFilter(watched, event);
}

}  // namespace ui
