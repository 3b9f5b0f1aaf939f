#pragma once
// GuideLine: a dashed line over the viewport from one pixel to another, such as the Spring tool's
// rubber band from the particle it starts at to the cursor. A child widget as large as the view
// that lets the mouse through, like the Select tool's QRubberBand box.

#include <QLineF>
#include <QWidget>

namespace ui {

class GuideLine : public QWidget {
    Q_OBJECT

public:
    explicit GuideLine(QWidget *view);

    // shows the line between two logical pixels of the view
    void showLine(const QLineF &line);
    QLineF line() const { return m_line; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;

private:
    QLineF m_line;
};

}  // namespace ui
