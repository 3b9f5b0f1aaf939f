#pragma once
// PlotCanvas: draws one PlotSeries with QPainter: a legend with one colour per curve, axes with
// ticks at round values and their labels, and the curves against time. It reads the series when
// it paints and owns nothing; whoever adds samples calls update().

#include <QColor>
#include <QString>
#include <QWidget>

namespace ui {

class PlotSeries;

class PlotCanvas : public QWidget {
    Q_OBJECT

public:
    explicit PlotCanvas(QWidget *parent = nullptr);

    // the series drawn (null: only the empty text); it must outlive the canvas or be replaced
    void setSeries(const PlotSeries *series);
    const PlotSeries *series() const { return m_series; }
    // the line above the legend, the vertical axis's label ("energy [J]"), and what the canvas says
    // while the series has no samples
    void setTitle(const QString &title);
    void setValueLabel(const QString &label);
    void setEmptyText(const QString &text);
    QString title() const { return m_title; }
    QString emptyText() const { return m_emptyText; }

    // the colour of curve i in every plot
    static QColor curveColour(int curve);

    QSize sizeHint() const override { return {520, 260}; }
    QSize minimumSizeHint() const override { return {240, 140}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    const PlotSeries *m_series = nullptr;
    QString m_title;
    QString m_valueLabel;
    QString m_emptyText;
};

}  // namespace ui
