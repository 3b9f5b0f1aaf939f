#pragma once
// Small things every benchmark mode needs: the machine it ran on and how busy it was, process CPU
// time, and an integrator's name as scene files spell it.

#include "core/integrators/integrator.h"

#include <QDir>
#include <QElapsedTimer>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <atomic>
#include <optional>
#include <thread>
#include <vector>

namespace bench {

// "AMD EPYC, 2 logical cores": the CPU model from /proc/cpuinfo and the cores Qt sees
QString machineDescription();
// the process's CPU time, s (all threads)
double cpuSeconds();
// the wall clock and the process's CPU time since a run began, for the line that ends its output
class RunClock {
public:
    RunClock();
    // "412 s wall, 380 s CPU"
    QString text() const;

private:
    QElapsedTimer m_wall;
    double m_cpuStart = 0.0;
};
// the median of the samples (the mean of the middle two when there is an even number)
double median(std::vector<double> values);
// an integrator's name as scene files spell it
QString nameOf(core::Integrator integrator);
// the load average over the last minute (/proc/loadavg), or -1 where it cannot be read: other work
// on the machine slows every figure, so a run records it at its start and its end
double loadAverage();
// the load average as a run prints it, with a warning when the machine is busy
QString loadText();
// the folder a mode writes its CSV and PNG to, made if missing; nullopt (and a line on out) if it
// cannot be made
std::optional<QDir> outputFolder(const QString &path, QTextStream &out);
// writes the lines (a CSV's) to dir/name whole or not at all, and says which on out
bool writeLines(const QDir &dir, const QString &name, const QStringList &lines, QTextStream &out);

// a loop that keeps one core busy while it lives (the other program of a busy desktop: a browser,
// a build)
class BusyCore {
public:
    BusyCore();
    ~BusyCore();
    BusyCore(const BusyCore &) = delete;
    BusyCore &operator=(const BusyCore &) = delete;

private:
    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

}  // namespace bench
