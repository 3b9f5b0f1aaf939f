#pragma once
// Chooses how many threads the core's loops use from the run's own step times, so that a run
// never waits on a thread that has no core (a 2-core machine with one core busy made two threads
// 7-10 times slower than one: every parallel loop ends at a barrier that waits for the thread the
// other program holds off its core). Results do not depend on the count (core/threads.h), so the
// choice may change at any step.
//
// A round of trials steps with 1 thread, then 2, 4, ... up to the most, and keeps the fastest
// (more threads only where they are clearly faster). A count whose first step is already far
// slower than the best is dropped after that step, and counts the other programs leave no cores
// for (what /proc/stat says they used since the last look) are not tried at all. Rounds come again
// after a while (each time the choice stands, twice as long a while), and at once when the kept
// count's steps slow down (the machine got busier). Wall time is what is measured: a thread kept
// waiting for a core shows there, not in CPU time.

#include <functional>
#include <vector>

namespace core {

class ThreadChooser {
public:
    // the cores the machine's other programs left free since the last call (NaN: not known)
    using FreeCores = std::function<double()>;

    // most: the largest count tried (default: core::maxThreadCount(), the machine's hardware
    // threads; core::setThreadCount holds any count to that). Where the user set
    // OMP_NUM_THREADS, that count stands and nothing is tried. freeCores: by default
    // core::freeCoresFromProcStat (Linux), for tests a model machine's.
    explicit ThreadChooser(int most = 0, FreeCores freeCores = {});
    static bool userSetThreads();

    // the thread count to take the next step with; set it with core::setThreadCount before stepping
    int threads() const { return m_threads; }
    // the wall time, in seconds, the step just taken at threads() took
    void stepped(double seconds);
    // a new scene or a new Play: what was measured says nothing of what comes next
    void startOver();

    bool trying() const { return m_trial >= 0; }
    // the count last chosen (0 until a first choice), and how many rounds have chosen
    int chosen() const { return m_chosen; }
    int choices() const { return m_choices; }
    // s of stepping the current choice stands before the next round
    double keepSeconds() const { return m_keepSeconds; }

    // a count's trial lasts at least kTrialSteps steps and kTrialSeconds, or one step past
    // kLongTrialSeconds, or one step that took kSlowerBy times the best count's step; a choice
    // stands kKeepSeconds of stepping, twice that each time a round confirms it (up to
    // kLongestKeepSeconds), or until its steps take kSlowerBy times as long as in its trial
    static constexpr int kTrialSteps = 3;
    static constexpr double kTrialSeconds = 0.03;
    static constexpr double kProbeSeconds = 0.1;  // one thread's trial, the other programs' measure
    static constexpr double kLongTrialSeconds = 0.5;
    static constexpr double kKeepSeconds = 3.0;
    static constexpr double kLongestKeepSeconds = 48.0;
    static constexpr double kSlowerBy = 1.5;
    // more threads are kept only where they are this much faster (their cost is more power and
    // cores taken from the rest of the desktop)
    static constexpr double kMoreThreadsGain = 1.1;

private:
    void beginRound();
    void endTrial();
    // the next count to try after m_trial, or -1 when the round is over
    int nextTrial() const;

    std::vector<int> m_ladder;      // the counts tried: 1, 2, 4, ..., most
    std::vector<double> m_perStep;  // the mean step time of each count in this round (0: not tried)
    FreeCores m_freeCores;
    int m_threads = 1;
    int m_trial = -1;               // index in m_ladder of the count on trial, -1 between rounds
    int m_most = 0;                 // index of the largest count this round may try
    int m_chosen = 0;
    int m_choices = 0;
    int m_steps = 0;                // steps and seconds of the current trial or of the choice
    double m_seconds = 0.0;
    double m_recent = 0.0;          // a moving mean of the chosen count's step time
    double m_chosenPerStep = 0.0;
    double m_keepSeconds = kKeepSeconds;
};

// the cores the other programs left free since the previous call, from /proc/stat and this
// process's own /proc/self/stat; NaN on the first call and where they cannot be read
double freeCoresFromProcStat();

}  // namespace core
