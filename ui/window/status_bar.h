#pragma once
// StatusBar: the main window's status bar, in which every text stays readable at any window width
// the window allows (1200 × 800 by default). QStatusBar draws a passing message (a menu's status
// tip, "Screenshot saved to …") itself, cut wherever its first permanent widget starts, and a
// label holding a long warning would widen the bar past the window and push the figures over
// each other. Here the message and the latest warning share one label on the left that takes the
// room the figures leave and elides what does not fit, the whole text in its tooltip; the
// passing message shows while there is one, the warning otherwise. The figures of the run keep
// their own labels on the right (addFigure), each as wide as its text.

#include <QLabel>
#include <QStatusBar>
#include <QString>

namespace ui {

// a one-line label that shows as much of its text as its width holds, ending in "…", with the
// whole text as its tooltip when cut; it may be narrowed to a few characters
class ElidedLabel : public QLabel {
    Q_OBJECT

public:
    explicit ElidedLabel(QWidget *parent = nullptr);

    void setFullText(const QString &text);
    const QString &fullText() const { return m_fullText; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void elide();

    QString m_fullText;
};

class StatusBar : public QStatusBar {
    Q_OBJECT

public:
    explicit StatusBar(QWidget *parent = nullptr);

    // the latest warning: shown whenever no passing message is
    void setWarning(const QString &text);
    const QString &warning() const { return m_warning; }
    // the label that shows the passing message or the warning
    ElidedLabel *messageLabel() const { return m_message; }

    // a figure of the run on the right, after those added before it: at least as wide as
    // `typical` (so that it does not jitter as its figures change), wider when its text is
    QLabel *addFigure(const char *objectName, const QString &typical, const QString &toolTip);

protected:
    // the passing message is shown by the label, not drawn over the figures
    void paintEvent(QPaintEvent *event) override;

private:
    void showCurrent();

    ElidedLabel *m_message = nullptr;
    QString m_warning;
};

}  // namespace ui
