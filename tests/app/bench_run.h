#pragma once
// What the springlab-bench tests share: running the benchmark program (SPRINGLAB_BENCH, its path,
// set by each test's target) and reading a number from one of its CSV fields.

#include "program_run.h"

#include <QByteArray>
#include <QStringList>
#include <cmath>

namespace test {

inline ProgramRun runBench(const QStringList &arguments)
{
    return runProgram(QStringLiteral(SPRINGLAB_BENCH), arguments);
}

// a CSV field as a number; NaN when it is not one (an empty field, "n/a")
inline double number(const QByteArray &text)
{
    bool ok = false;
    const double value = text.toDouble(&ok);
    return ok ? value : std::nan("");
}

}  // namespace test
