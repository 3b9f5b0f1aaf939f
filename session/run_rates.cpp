#include "run_rates.h"

namespace ui {

void RunRates::start()
{
    m_steps = 0;
    m_credited = 0.0;
    m_stepsPerSecond = 0.0;
    m_realTimeFactor = 0.0;
}

bool RunRates::add(int steps, double creditedSeconds, double windowSeconds)
{
    m_steps += static_cast<std::uint64_t>(steps > 0 ? steps : 0);
    m_credited += creditedSeconds;
    // a window without a step stays open: its rate would read 0 while the run steps
    if (windowSeconds < kWindowSeconds || m_steps == 0)
        return false;
    m_stepsPerSecond = static_cast<double>(m_steps) / windowSeconds;
    m_realTimeFactor = m_credited / windowSeconds;
    m_steps = 0;
    m_credited = 0.0;
    return true;
}

}  // namespace ui
