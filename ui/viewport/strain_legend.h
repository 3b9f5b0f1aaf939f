#pragma once
// StrainLegend: the key to the springs' colours, in a corner of the view while springs are drawn:
// a bar from compressed (blue) through the rest length (grey) to stretched (red), with the strains
// at its ends and middle. A child widget over the viewport rather than part of the GL picture, so
// that it stays the same size on screen and is never in an exported image of the scene; it lets
// the mouse through to the view.

#include <QWidget>

namespace ui {

class StrainLegend : public QWidget {
    Q_OBJECT

public:
    explicit StrainLegend(QWidget *view);

    QSize sizeHint() const override;

    // the strain at the ends of the bar (the colours' full scale)
    float fullStrain() const { return m_fullStrain; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;

private:
    void place();

    float m_fullStrain;
};

}  // namespace ui
