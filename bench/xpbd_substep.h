#pragma once
// `springlab-bench xpbd-substep`: the cost of one xpbd sub-step on the stiff cloth, the pass the core
// runs (core/integrators/xpbd.cpp) beside the colour-by-colour pass it replaced (colour_xpbd.h) and symplectic
// Euler's fused lattice sub-step, on 1 and 2 threads, and the stretch each ordering leaves.

#include <QTextStream>

namespace bench {

struct XpbdSubStepOptions {
    int size = 128;           // particles a side
    double stiffness = 1e7;   // N/m, structural
    int substeps = 200;       // a 0.01 s step
    int runs = 5;             // timed runs of each variant, the median counts
    int subStepsARun = 1000;  // sub-steps a timed run
    double drape = 0.2;       // s of draping over which the stretch is read (0: none)
};

int runXpbdSubStep(const XpbdSubStepOptions &options, QTextStream &out);

}  // namespace bench
