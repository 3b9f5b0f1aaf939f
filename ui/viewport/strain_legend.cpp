#include "strain_legend.h"

#include "render_data.h"

#include <QEvent>
#include <QLinearGradient>
#include <QPainter>

namespace ui {

namespace {

constexpr int kMargin = 10;   // px from the view's bottom-left corner
constexpr int kPadding = 6;   // px inside the box
constexpr int kBarWidth = 150;
constexpr int kBarHeight = 8;

QColor toColour(const Rgb &c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

}  // namespace

StrainLegend::StrainLegend(QWidget *view) : QWidget(view), m_fullStrain(kFullStrain)
{
    setObjectName(QStringLiteral("strainLegend"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setToolTip(tr("Spring colours: compressed blue, at rest grey, stretched red"));
    resize(sizeHint());
    view->installEventFilter(this);
    place();
}

QSize StrainLegend::sizeHint() const
{
    const int line = fontMetrics().height();
    return {kBarWidth + 2 * kPadding, 2 * line + kBarHeight + 2 * kPadding + 2};
}

bool StrainLegend::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == parentWidget() && event->type() == QEvent::Resize)
        place();
    return QWidget::eventFilter(watched, event);
}

void StrainLegend::place()
{
    // the bottom-left corner, where the axes and the status bar's figures are not
    resize(sizeHint());
    if (QWidget *view = parentWidget())
        move(kMargin, view->height() - height() - kMargin);
}

void StrainLegend::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);

    // a dark box, so that it reads over the grid and the sheet
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 150));
    painter.drawRoundedRect(rect(), 4, 4);

    // the caption, the bar and the strains under it
    const int line = fontMetrics().height();
    const QRect caption(kPadding, kPadding, kBarWidth, line);
    const QRect bar(kPadding, caption.bottom() + 2, kBarWidth, kBarHeight);
    const QRect labels(kPadding, bar.bottom() + 1, kBarWidth, line);
    painter.setPen(QColor(230, 230, 230));
    painter.drawText(caption, Qt::AlignLeft | Qt::AlignVCenter, tr("Spring strain"));
    QLinearGradient gradient(bar.topLeft(), bar.topRight());
    gradient.setColorAt(0.0, toColour(strainColour(-m_fullStrain, m_fullStrain)));
    gradient.setColorAt(0.5, toColour(strainColour(0.0f, m_fullStrain)));
    gradient.setColorAt(1.0, toColour(strainColour(m_fullStrain, m_fullStrain)));
    painter.fillRect(bar, gradient);
    const QString percent = QString::number(double(m_fullStrain) * 100.0, 'g', 3);
    painter.drawText(labels, Qt::AlignLeft | Qt::AlignVCenter, tr("−%1 %").arg(percent));
    painter.drawText(labels, Qt::AlignHCenter | Qt::AlignVCenter, tr("rest"));
    painter.drawText(labels, Qt::AlignRight | Qt::AlignVCenter, tr("+%1 %").arg(percent));
}

}  // namespace ui
