#include "core/thread_chooser.h"

#include "core/threads.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <unistd.h>

namespace core {

ThreadChooser::ThreadChooser(int most, FreeCores freeCores)
    : m_freeCores(freeCores ? std::move(freeCores) : FreeCores(freeCoresFromProcStat))
{
    const int top = std::max(1, most > 0 ? most : maxThreadCount());
    if (userSetThreads()) {
        m_ladder.push_back(threadCount());  // the user's choice stands
    } else {
        for (int count = 1; count < top; count *= 2)
            m_ladder.push_back(count);
        m_ladder.push_back(top);
    }
    m_perStep.assign(m_ladder.size(), 0.0);
    startOver();
}

bool ThreadChooser::userSetThreads()
{
    const char *set = std::getenv("OMP_NUM_THREADS");
    return set != nullptr && *set != '\0';
}

void ThreadChooser::startOver()
{
    m_chosen = 0;
    m_keepSeconds = kKeepSeconds;
    beginRound();
}

void ThreadChooser::beginRound()
{
    m_freeCores();  // the look the round's first trial is measured from
    std::fill(m_perStep.begin(), m_perStep.end(), 0.0);
    m_most = int(m_ladder.size()) - 1;
    m_trial = 0;
    m_threads = m_ladder.front();
    m_steps = 0;
    m_seconds = 0.0;
    if (m_ladder.size() == 1)
        endTrial();  // nothing to choose between: chosen at once, by its first step's time
}

int ThreadChooser::nextTrial() const
{
    return m_trial + 1 <= m_most ? m_trial + 1 : -1;
}

void ThreadChooser::stepped(double seconds)
{
    if (m_ladder.size() == 1)
        return;  // nothing to choose
    seconds = std::max(0.0, seconds);
    ++m_steps;
    m_seconds += seconds;
    if (trying()) {
        double best = std::numeric_limits<double>::infinity();
        for (double perStep : m_perStep)
            if (perStep > 0.0)
                best = std::min(best, perStep);
        // one thread's trial is also the other programs' measure: long enough for /proc/stat's
        // hundredths of a second to say how busy they kept the cores
        const double least = m_trial == 0 ? kProbeSeconds : kTrialSeconds;
        const bool enough = (m_steps >= kTrialSteps && m_seconds >= least) || m_seconds >= kLongTrialSeconds ||
                            seconds > kSlowerBy * best;
        if (enough)
            endTrial();
        return;
    }
    // settled: watch whether the choice stops paying, and try again after a while anyway
    m_recent = m_steps == 1 ? seconds : 0.8 * m_recent + 0.2 * seconds;
    const bool slower = m_steps >= kTrialSteps && m_recent > kSlowerBy * m_chosenPerStep;
    if (slower)
        m_keepSeconds = kKeepSeconds;
    if (slower || m_seconds >= m_keepSeconds)
        beginRound();
}

void ThreadChooser::endTrial()
{
    if (m_steps > 0)
        m_perStep[std::size_t(m_trial)] = m_seconds / double(m_steps);
    if (m_trial == 0 && m_ladder.size() > 1) {
        // the other programs' share while one thread ran: counts they leave no cores for are
        // not tried (a second thread there waits for a core at every loop's end)
        const double free = m_freeCores();
        if (std::isfinite(free))
            while (m_most > 0 && double(m_ladder[std::size_t(m_most)]) > std::max(1.0, free) + 0.25)
                --m_most;
    }
    m_steps = 0;
    m_seconds = 0.0;
    if (const int next = nextTrial(); next >= 0) {
        m_trial = next;
        m_threads = m_ladder[std::size_t(m_trial)];
        return;
    }
    // every count tried: the fewest threads unless more are clearly faster
    std::size_t best = 0;
    for (std::size_t i = 1; i < m_ladder.size(); ++i)
        if (m_perStep[i] > 0.0 && m_perStep[i] * kMoreThreadsGain < m_perStep[best])
            best = i;
    const int previous = m_chosen;
    m_trial = -1;
    m_threads = m_chosen = m_ladder[best];
    m_chosenPerStep = m_perStep[best];
    m_recent = m_chosenPerStep;
    // a choice a round confirms stands twice as long; a new one, the shortest while
    m_keepSeconds = m_chosen == previous ? std::min(2.0 * m_keepSeconds, kLongestKeepSeconds) : kKeepSeconds;
    ++m_choices;
}

namespace {

// jiffies the whole machine spent busy, and this process
bool readBusy(double &machine, double &self)
{
    std::ifstream stat("/proc/stat");
    std::string cpu;
    double user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
    if (!(stat >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal) || cpu != "cpu")
        return false;
    machine = user + nice + system + irq + softirq + steal;
    std::ifstream own("/proc/self/stat");
    std::string line;
    if (!std::getline(own, line))
        return false;
    // fields 14 and 15 (utime, stime) come after the command name, which ends at the last ')'
    const std::size_t end = line.rfind(')');
    if (end == std::string::npos)
        return false;
    std::istringstream fields(line.substr(end + 2));
    std::string field;
    double utime = 0, stime = 0;
    for (int i = 3; i <= 15 && fields >> field; ++i) {
        if (i == 14)
            utime = std::strtod(field.c_str(), nullptr);
        if (i == 15)
            stime = std::strtod(field.c_str(), nullptr);
    }
    self = utime + stime;
    return true;
}

}  // namespace

double freeCoresFromProcStat()
{
    static thread_local double lastMachine = -1.0, lastSelf = 0.0;
    static thread_local std::chrono::steady_clock::time_point lastAt;
    double machine = 0.0, self = 0.0;
    const auto now = std::chrono::steady_clock::now();
    if (!readBusy(machine, self))
        return std::numeric_limits<double>::quiet_NaN();
    const double ticksPerSecond = double(sysconf(_SC_CLK_TCK));
    const double seconds = std::chrono::duration<double>(now - lastAt).count();
    const bool known = lastMachine >= 0.0 && seconds >= 0.02 && ticksPerSecond > 0.0;
    const double others = known ? ((machine - lastMachine) - (self - lastSelf)) / ticksPerSecond / seconds : 0.0;
    lastMachine = machine;
    lastSelf = self;
    lastAt = now;
    if (!known)
        return std::numeric_limits<double>::quiet_NaN();
    return std::max(0.0, double(maxThreadCount()) - std::max(0.0, others));
}

}  // namespace core
