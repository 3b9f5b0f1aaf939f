#pragma once
// Small things every benchmark mode needs: the machine it ran on, process CPU time, and an
// integrator's name as scene files spell it.

#include "core/integrator.h"

#include <QString>

namespace bench {

// "AMD EPYC, 2 logical cores": the CPU model from /proc/cpuinfo and the cores Qt sees
QString machineDescription();
// the process's CPU time, s (all threads)
double cpuSeconds();
// an integrator's name as scene files spell it
QString nameOf(core::Integrator integrator);

}  // namespace bench
