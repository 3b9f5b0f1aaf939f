#include "status_bar.h"

#include <QPainter>
#include <QStyle>
#include <QStyleOption>
#include <algorithm>

namespace ui {

namespace {

// what an elided text keeps at the least: a few characters and the ellipsis
constexpr int kMinimumCharacters = 6;

}  // namespace

ElidedLabel::ElidedLabel(QWidget *parent) : QLabel(parent)
{
    setTextFormat(Qt::PlainText);
    setWordWrap(false);
}

void ElidedLabel::setFullText(const QString &text)
{
    if (text == m_fullText)
        return;
    m_fullText = text;
    updateGeometry();
    elide();
}

QSize ElidedLabel::sizeHint() const
{
    // as wide as the whole text
    const QMargins margins = contentsMargins();
    return {fontMetrics().horizontalAdvance(m_fullText) + margins.left() + margins.right() + 2 * margin(),
            QLabel::sizeHint().height()};
}

QSize ElidedLabel::minimumSizeHint() const
{
    const int least = fontMetrics().averageCharWidth() * kMinimumCharacters;
    return {std::min(least, sizeHint().width()), QLabel::minimumSizeHint().height()};
}

void ElidedLabel::resizeEvent(QResizeEvent *event)
{
    QLabel::resizeEvent(event);
    elide();
}

void ElidedLabel::elide()
{
    // the text as it fits the label's contents; the whole of it in the tooltip when it does not
    const QString shown = fontMetrics().elidedText(m_fullText, Qt::ElideRight, contentsRect().width() - 2 * margin());
    setText(shown);
    setToolTip(shown == m_fullText ? QString() : m_fullText);
}

StatusBar::StatusBar(QWidget *parent) : QStatusBar(parent), m_message(new ElidedLabel(this))
{
    // the message on the left takes what room the figures leave
    m_message->setObjectName(QStringLiteral("statusMessage"));
    addPermanentWidget(m_message, 1);
    connect(this, &QStatusBar::messageChanged, this, &StatusBar::showCurrent);
}

void StatusBar::setWarning(const QString &text)
{
    m_warning = text;
    showCurrent();
}

QLabel *StatusBar::addFigure(const char *objectName, const QString &typical, const QString &toolTip)
{
    auto *figure = new QLabel(this);
    figure->setObjectName(QString::fromLatin1(objectName));
    figure->setMinimumWidth(figure->fontMetrics().horizontalAdvance(typical));
    figure->setToolTip(toolTip);
    addPermanentWidget(figure);
    return figure;
}

void StatusBar::paintEvent(QPaintEvent *)
{
    // the frame of each shown field, as QStatusBar draws them, and no text of its own
    QPainter painter(this);
    QStyleOption option;
    for (const QLabel *field : findChildren<QLabel *>(Qt::FindDirectChildrenOnly)) {
        if (!field->isVisible())
            continue;
        option.initFrom(this);
        option.rect = field->geometry().adjusted(-1, -1, 1, 1);
        style()->drawPrimitive(QStyle::PE_FrameStatusBarItem, &option, &painter, field);
    }
}

void StatusBar::showCurrent()
{
    const QString message = currentMessage();
    m_message->setFullText(message.isEmpty() ? m_warning : message);
}

}  // namespace ui
