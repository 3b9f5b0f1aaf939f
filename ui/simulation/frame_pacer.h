#pragma once
// FramePacer: how often the window shows a frame of a playing run, and the frames per second it
// reached. Where OpenGL is drawn on the CPU (Mesa's software renderer), a frame of a large scene
// costs about as much computing as a step, on the cores the worker steps on. So while the run
// falls behind real time, frames are spaced so that drawing them takes at most kDrawShare of the
// wall time and the worker keeps the rest; a run that keeps up gets up to kMostFramesPerSecond,
// since drawing then uses time the worker leaves idle. The cost of a frame is measured as it is
// drawn (from its arrival to the screen), averaged over the latest few, and starts over with each
// scene and each Play: a cost measured on a scene of 10⁶ particles must not space the frames of
// the next small one. However costly the frames, a playing run shows one at least every
// kMostSecondsBetweenFrames, so that it never looks hung. The frame rate is counted over windows of
// at least kRateWindowSeconds that hold a frame, so a slow rate never reads 0.
// Qt-free: times are seconds on any steady clock, given by the caller.

namespace ui {

class FramePacer {
public:
    static constexpr double kMostFramesPerSecond = 60.0;
    static constexpr double kDrawShare = 0.1;
    static constexpr double kRateWindowSeconds = 1.0;
    static constexpr double kMostSecondsBetweenFrames = 1.0;

    // a frame reached the screen at `now`, `cost` seconds after it arrived
    void drawn(double cost, double now);
    // the expected cost of a frame (s): the latest frames' average, 0 before the first
    double frameCost() const { return m_cost; }
    // the shortest time between two frames (s), for a run that falls behind real time or not
    double interval(bool behind) const;

    // the frame rate starts over (a run starts) at `now`
    void restartRate(double now);
    // the cost and the rate start over (another scene, or Play) at `now`: nothing measured yet
    void startOver(double now);
    // frames per second over the latest window; 0 before the first window closed
    double framesPerSecond() const { return m_framesPerSecond; }

private:
    double m_cost = 0.0;
    bool m_measured = false;
    double m_windowStart = 0.0;
    int m_windowFrames = 0;
    double m_framesPerSecond = 0.0;
};

}  // namespace ui
