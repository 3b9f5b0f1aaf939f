#pragma once
// `springlab-bench stiff`: a stiff cloth draping for 1 s, from 1e3 to 1e8 N/m, run by symplectic
// Euler, implicit Euler and xpbd side by side; for each, the fewest sub-steps that keep every
// structural spring within 1% of its rest length (and the energy under its start), what they cost,
// and how much motion they leave against a fine reference (see stiff.cpp and docs/benchmarks.md).

#include <QString>
#include <QTextStream>

#include <vector>

namespace bench {

struct StiffOptions {
    QString outDir = QStringLiteral(".");  // where stiff.csv, stiff.txt and stiff.png go
    bool quick = false;                    // a tiny cloth, two stiffnesses: a smoke test only
    // only these cloth sizes and structural stiffnesses of the full plan (empty: all of them), to
    // rerun some rows where the whole sweep does not fit
    std::vector<int> sizes;
    std::vector<double> stiffness;
};

// runs the sweep, writes stiff.csv, stiff.txt and stiff.png, prints the rows and the issue's
// targets; returns the exit code (0 done, 1 a file could not be written)
int runStiff(const StiffOptions &options, QTextStream &out);

}  // namespace bench
