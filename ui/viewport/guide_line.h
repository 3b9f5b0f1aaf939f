#pragma once
// GuideLine: a line over the viewport from one pixel to another, with an optional label at its
// middle, such as the Spring tool's rubber band from the particle it starts at to the cursor, or
// the Measure tool's line between two particles with their distance. A child widget as large as
// the view that lets the mouse through, like the Select tool's QRubberBand box. A line that joins
// moving things follows a source instead of fixed pixels: the source is asked again at each
// paint, and the widget is painted whenever the view under it is, so the line is always drawn
// with the frame and the camera it lies on.

#include <QLineF>
#include <QString>
#include <QWidget>

#include <functional>
#include <optional>

namespace ui {

class GuideLine : public QWidget {
    Q_OBJECT

public:
    // a line between two logical pixels of the view, and what its label says (empty: no label)
    struct Shape {
        QLineF line;
        QString label;
    };
    // the shape to draw now, or nullopt to draw nothing (an end behind the camera)
    using Source = std::function<std::optional<Shape>()>;

    explicit GuideLine(QWidget *view);

    // shows a fixed line, with a label
    void showLine(const QLineF &line, const QString &label = {});
    // shows what the source says at each paint
    void follow(Source source);
    // dashed (a line on its way, the default) or solid (a finished one)
    void setDashed(bool dashed);

    // the shape shown now: the fixed line, or the source's answer now
    std::optional<Shape> shape() const;
    QLineF line() const;
    QString label() const;
    // how many times it was painted, and the shape the last paint drew (nullopt: nothing)
    int paintCount() const { return m_paints; }
    const std::optional<Shape> &painted() const { return m_painted; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;

private:
    Shape m_shape;
    Source m_source;
    bool m_dashed = true;
    int m_paints = 0;
    std::optional<Shape> m_painted;
};

}  // namespace ui
