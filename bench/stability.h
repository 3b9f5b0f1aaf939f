#pragma once
// `springlab-bench stability`: for each explicit integrator, the largest stable time step measured
// on spring chains across stiffness and mass, against the limit core/integrators/stability.h predicts; and
// implicit Euler run at 100 times that limit (see stability.cpp and docs/benchmarks.md).

#include <QString>
#include <QTextStream>

namespace bench {

struct StabilityOptions {
    QString outDir = QStringLiteral(".");  // where stability.csv and stability.png go
    bool quick = false;                    // a small grid and short trials: a smoke test only
};

// runs the sweep, writes stability.csv and stability.png, prints the summary; returns the exit
// code (0 done, 1 a file could not be written)
int runStability(const StabilityOptions &options, QTextStream &out);

}  // namespace bench
