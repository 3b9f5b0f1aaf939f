#pragma once
// RunRates: how fast a playing run goes, for the status bar: steps per second of wall time, and
// simulated seconds per second (the real-time factor). Both are averaged over a window of wall
// time that closes once it is kWindowSeconds long and holds at least one step, so that a run of
// slow steps reads its true rate ("0.2 steps/s", "×0.002") and never 0 while it steps. Qt-free:
// the caller times the window.

#include <cstdint>

namespace ui {

class RunRates {
public:
    static constexpr double kWindowSeconds = 0.5;

    // a run starts: nothing measured yet (both rates 0) and a window opens
    void start();
    // a tick took `steps` steps, keeping up with `creditedSeconds` of wall time; `windowSeconds`
    // is the wall time since the window opened. True if that closed the window: the caller opens
    // the next one (its clock starts again)
    bool add(int steps, double creditedSeconds, double windowSeconds);

    double stepsPerSecond() const { return m_stepsPerSecond; }
    double realTimeFactor() const { return m_realTimeFactor; }

private:
    std::uint64_t m_steps = 0;
    double m_credited = 0.0;  // s
    double m_stepsPerSecond = 0.0;
    double m_realTimeFactor = 0.0;
};

}  // namespace ui
