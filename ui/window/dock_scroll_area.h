#pragma once
// DockScrollArea: a dock's content that scrolls up and down but is never cut at its side. A plain
// QScrollArea lets a dock be narrower than its content, and when its vertical scroll bar appears
// the bar takes its width from the content, so the right end of a row (the inspector's distance,
// a plane's size field) went behind the bar or past a horizontal one. This one asks for the
// content's minimum width plus the vertical bar's, and asks again whenever the content's layout
// changes (the inspector's groups come and go with the selection).

#include <QScrollArea>

namespace ui {

class DockScrollArea : public QScrollArea {
    Q_OBJECT

public:
    explicit DockScrollArea(QWidget *content, QWidget *parent = nullptr);

    QSize minimumSizeHint() const override;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
};

}  // namespace ui
