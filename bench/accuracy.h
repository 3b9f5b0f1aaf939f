#pragma once
// `springlab-bench accuracy`: error against run time for every integrator on the five reference
// problems (see accuracy.cpp and docs/benchmarks.md).

#include <QString>
#include <QTextStream>

namespace bench {

struct AccuracyOptions {
    QString outDir = QStringLiteral(".");  // where the CSVs and plots go
    bool quick = false;                    // a tiny sweep, one timing per run: a smoke test only
};

// runs the sweeps, writes accuracy-<problem>.csv and .png, prints the summary; returns the exit
// code (0 done, 1 a file could not be written)
int runAccuracy(const AccuracyOptions &options, QTextStream &out);

}  // namespace bench
