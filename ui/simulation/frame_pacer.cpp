#include "frame_pacer.h"

#include <algorithm>

namespace ui {

namespace {

// the weight of the newest frame in the average cost: about the latest four count
constexpr double kNewestWeight = 0.25;

}  // namespace

void FramePacer::drawn(double cost, double now)
{
    cost = std::max(0.0, cost);
    m_cost = m_measured ? (1.0 - kNewestWeight) * m_cost + kNewestWeight * cost : cost;
    m_measured = true;

    // the rate: a window closes once it is long enough and holds a frame
    ++m_windowFrames;
    const double window = now - m_windowStart;
    if (window >= kRateWindowSeconds) {
        m_framesPerSecond = m_windowFrames / window;
        m_windowStart = now;
        m_windowFrames = 0;
    }
}

double FramePacer::interval(bool behind) const
{
    const double least = 1.0 / kMostFramesPerSecond;
    return behind ? std::clamp(m_cost / kDrawShare, least, kMostSecondsBetweenFrames) : least;
}

void FramePacer::startOver(double now)
{
    m_cost = 0.0;
    m_measured = false;
    restartRate(now);
}

void FramePacer::restartRate(double now)
{
    m_windowStart = now;
    m_windowFrames = 0;
    m_framesPerSecond = 0.0;
}

}  // namespace ui
