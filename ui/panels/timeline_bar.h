#pragma once
// TimelineBar: the strip under the viewport that scrubs through the recorded run. A slider over
// the recorded steps (a tick above it for each step in which springs broke), step back and step
// forward buttons, the time shown, and the memory the recording uses of its budget, which the
// user sets. It only shows frames and asks for edits: the worker owns the recording.

#include "session/simulation_frame.h"

#include <QSlider>
#include <QWidget>
#include <cstdint>
#include <vector>

class QLabel;
class QSpinBox;
class QToolButton;

namespace ui {

// the slider, with the steps springs broke in drawn as ticks over its groove
class TimelineSlider : public QSlider {
    Q_OBJECT

public:
    explicit TimelineSlider(QWidget *parent = nullptr);
    void setBreaks(std::vector<std::uint64_t> steps);
    const std::vector<std::uint64_t> &breaks() const { return m_breaks; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    std::vector<std::uint64_t> m_breaks;
};

class TimelineBar : public QWidget {
    Q_OBJECT

public:
    explicit TimelineBar(QWidget *parent = nullptr);

    // shows a frame's timeline and the step the frame shows; the slider follows that step unless
    // the user holds it
    void showTimeline(const TimelineInfo &info, std::uint64_t shownStep, double shownTime);

    TimelineSlider *slider() const { return m_slider; }
    QToolButton *stepBackButton() const { return m_back; }
    QToolButton *stepForwardButton() const { return m_forward; }
    QSpinBox *budgetBox() const { return m_budget; }
    QString timeText() const;
    QString memoryText() const;

    // the budget spin box's value, in bytes
    std::size_t budgetBytes() const;
    void setBudgetBytes(std::size_t bytes);

signals:
    void scrubRequested(std::uint64_t step);
    void stepBackRequested();
    void stepForwardRequested();
    void budgetChanged(std::size_t bytes);

private:
    void sliderMovedTo(int value);

    TimelineSlider *m_slider = nullptr;
    QToolButton *m_back = nullptr;
    QToolButton *m_forward = nullptr;
    QLabel *m_time = nullptr;
    QLabel *m_memory = nullptr;
    QSpinBox *m_budget = nullptr;
    TimelineInfo m_info;
    std::uint64_t m_shownStep = 0;
    double m_shownTime = 0.0;
};

}  // namespace ui
