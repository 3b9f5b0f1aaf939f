#include "timeline_bar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QToolButton>
#include <algorithm>
#include <limits>

namespace ui {

namespace {

constexpr std::size_t kMiB = std::size_t(1) << 20;
// the budget the spin box offers, MB: from a little to most of a large machine's memory
constexpr int kLeastBudgetMb = 1;
constexpr int kMostBudgetMb = 65536;

int sliderValue(std::uint64_t step)
{
    return static_cast<int>(std::min<std::uint64_t>(step, std::numeric_limits<int>::max()));
}

QString megabytes(std::size_t bytes)
{
    return QString::number(static_cast<double>(bytes) / static_cast<double>(kMiB), 'f', 1);
}

}  // namespace

TimelineSlider::TimelineSlider(QWidget *parent) : QSlider(Qt::Horizontal, parent)
{
    setObjectName(QStringLiteral("timelineSlider"));
}

void TimelineSlider::setBreaks(std::vector<std::uint64_t> steps)
{
    if (steps == m_breaks)
        return;
    m_breaks = std::move(steps);
    update();
}

void TimelineSlider::paintEvent(QPaintEvent *event)
{
    QSlider::paintEvent(event);
    if (m_breaks.empty() || maximum() <= minimum())
        return;
    // a red tick over the groove where each break happened, placed as the style places the handle
    QStyleOptionSlider option;
    initStyleOption(&option);
    const QRect groove = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, this);
    const QRect handle = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, this);
    const int span = groove.width() - handle.width();
    QPainter painter(this);
    painter.setPen(QPen(QColor(220, 40, 40), 2));
    for (std::uint64_t step : m_breaks) {
        const int value = sliderValue(step);
        if (value < minimum() || value > maximum())
            continue;
        const int x = groove.left() + handle.width() / 2 +
                      QStyle::sliderPositionFromValue(minimum(), maximum(), value, span);
        painter.drawLine(x, rect().top(), x, groove.top() + 1);
    }
}

TimelineBar::TimelineBar(QWidget *parent)
    : QWidget(parent), m_slider(new TimelineSlider(this)), m_back(new QToolButton(this)),
      m_forward(new QToolButton(this)), m_time(new QLabel(this)), m_memory(new QLabel(this)),
      m_budget(new QSpinBox(this))
{
    setObjectName(QStringLiteral("timelineBar"));
    m_back->setObjectName(QStringLiteral("timelineStepBack"));
    m_back->setIcon(style()->standardIcon(QStyle::SP_MediaSeekBackward));
    m_back->setToolTip(tr("One step back through the recording (Shift+F6)"));
    m_forward->setObjectName(QStringLiteral("timelineStepForward"));
    m_forward->setIcon(style()->standardIcon(QStyle::SP_MediaSeekForward));
    m_forward->setToolTip(tr("One step forward: through the recording, then a new step (F6)"));
    m_slider->setRange(0, 0);
    m_time->setObjectName(QStringLiteral("timelineTime"));
    m_time->setMinimumWidth(m_time->fontMetrics().horizontalAdvance(QStringLiteral("t = 0000.000 s, step 0000000")));
    m_memory->setObjectName(QStringLiteral("timelineMemory"));
    m_memory->setToolTip(tr("Memory the recording uses, of its budget; past the budget the oldest steps go"));
    m_budget->setObjectName(QStringLiteral("timelineBudget"));
    m_budget->setRange(kLeastBudgetMb, kMostBudgetMb);
    m_budget->setValue(512);
    m_budget->setSuffix(tr(" MB"));
    m_budget->setToolTip(tr("Memory budget of the recording"));

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->addWidget(m_back);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_forward);
    layout->addWidget(m_time);
    layout->addWidget(m_memory);
    layout->addWidget(m_budget);

    connect(m_slider, &QSlider::valueChanged, this, &TimelineBar::sliderMovedTo);
    connect(m_back, &QToolButton::clicked, this, &TimelineBar::stepBackRequested);
    connect(m_forward, &QToolButton::clicked, this, &TimelineBar::stepForwardRequested);
    connect(m_budget, &QSpinBox::valueChanged, this, [this] { emit budgetChanged(budgetBytes()); });
    showTimeline(TimelineInfo{}, 0, 0.0);
}

void TimelineBar::showTimeline(const TimelineInfo &info, std::uint64_t shownStep, double shownTime)
{
    m_info = info;
    m_shownStep = shownStep;
    m_shownTime = shownTime;
    {
        // the frames move the slider; only the user's moves ask for a scrub
        const QSignalBlocker blocker(m_slider);
        m_slider->setRange(sliderValue(info.firstStep), sliderValue(info.lastStep));
        if (!m_slider->isSliderDown())
            m_slider->setValue(sliderValue(shownStep));
    }
    m_slider->setBreaks(info.breakSteps);
    const bool usable = !info.empty && !info.locked;
    m_slider->setEnabled(usable);
    m_back->setEnabled(usable && shownStep > info.firstStep);
    const QString tooLarge =
        info.empty && info.keyframeOverBudget > 0
            ? tr("Nothing is recorded: one step of this scene (its model and state) needs %1 MB, more than the "
                 "budget of %2 MB. Raise the budget to scrub")
                  .arg(megabytes(info.keyframeOverBudget), megabytes(info.budgetBytes))
            : QString();
    m_slider->setToolTip(info.locked            ? tr("No scrubbing while a session is recorded (Simulation › Record Session)")
                         : !tooLarge.isEmpty() ? tooLarge
                                               : tr("Scrub through the recorded run; Play goes on from the step shown and "
                                                    "drops what was recorded after it. Red ticks: springs broke"));
    m_time->setText(timeText());
    m_memory->setText(memoryText());
    m_memory->setToolTip(tooLarge.isEmpty() ? tr("Memory the recording uses, of its budget; past the budget the "
                                                 "oldest steps go")
                                            : tooLarge);
}

QString TimelineBar::timeText() const
{
    return tr("t = %1 s, step %2").arg(m_shownTime, 0, 'f', 3).arg(m_shownStep);
}

QString TimelineBar::memoryText() const
{
    if (m_info.empty && m_info.keyframeOverBudget > 0)
        return tr("off: a step needs %1 MB").arg(megabytes(m_info.keyframeOverBudget));
    return tr("%1 / %2 MB").arg(megabytes(m_info.usedBytes), megabytes(m_info.budgetBytes));
}

std::size_t TimelineBar::budgetBytes() const
{
    return static_cast<std::size_t>(m_budget->value()) * kMiB;
}

void TimelineBar::setBudgetBytes(std::size_t bytes)
{
    m_budget->setValue(static_cast<int>(std::clamp<std::size_t>(bytes / kMiB, kLeastBudgetMb, kMostBudgetMb)));
}

void TimelineBar::sliderMovedTo(int value)
{
    emit scrubRequested(static_cast<std::uint64_t>(std::max(0, value)));
}

}  // namespace ui
