#pragma once
// What the springlab-bench tests share: running the benchmark program (SPRINGLAB_BENCH, its path,
// set by each test's target), reading a number from one of its CSV fields, and telling a drawn
// plot from an empty one.

#include "program_run.h"

#include <QByteArray>
#include <QImage>
#include <QSet>
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

// how many colours a plot shows, every third pixel sampled both ways: a drawn plot has text,
// grid lines and data in several colours, an empty or failed one has one or two
inline qsizetype coloursIn(const QImage &plot)
{
    QSet<QRgb> colours;
    for (int y = 0; y < plot.height(); y += 3)
        for (int x = 0; x < plot.width(); x += 3)
            colours.insert(plot.pixel(x, y));
    return colours.size();
}

}  // namespace test
