// Each variant runs options.runs times from the same flat cloth, options.subStepsARun sub-steps of
// 0.01 s / options.substeps each, timed by the wall clock (the 2-thread runs would count both
// threads' CPU); the median per sub-step is printed, with the load average, since other work on the
// machine slows every figure. Then, for the orderings' convergence, each xpbd variant drapes the
// cloth for options.drape s in whole steps and prints the largest structural stretch at a step's end.
#include "xpbd_substep.h"

#include "bench_common.h"
#include "colour_xpbd.h"
#include "stiff_scene.h"

#include "core/model/model.h"
#include "core/passes.h"
#include "core/model/state.h"
#include "core/threads.h"

#include <QElapsedTimer>

#include <algorithm>
#include <functional>

namespace bench {

namespace {

enum class Variant { Colours, Layout, Layout2, Euler };

QString variantName(Variant variant)
{
    switch (variant) {
    case Variant::Colours: return QStringLiteral("xpbd, former colour-by-colour pass");
    case Variant::Layout: return QStringLiteral("xpbd, layout pass (the core's)");
    case Variant::Layout2: return QStringLiteral("xpbd, layout pass, 2 iterations");
    case Variant::Euler: return QStringLiteral("symplectic Euler, fused lattice sub-step");
    }
    return {};
}

struct Run {
    std::shared_ptr<const core::Model> model;
    core::State state;
    core::Workspace work;
    ColourXpbd colours;
    std::function<void(Run &, double)> subStep;
};

Run makeRun(const XpbdSubStepOptions &o, Variant variant)
{
    const bool euler = variant == Variant::Euler;
    core::SceneDesc scene =
        stiffCloth(o.size, o.stiffness, euler ? core::Integrator::SymplecticEuler : core::Integrator::Xpbd, o.substeps);
    scene.settings.xpbdIterations = variant == Variant::Layout2 ? 2 : 1;
    Run run;
    run.model = core::compileModel(scene);
    run.state = core::makeState(*run.model, scene);
    run.work.force.setZero(3, run.model->particleCount());
    if (variant == Variant::Colours) {
        run.colours = colourXpbd(*run.model);
        run.subStep = [](Run &r, double h) { colourXpbdSubStep(*r.model, r.colours, r.state, r.work, h); };
    } else if (euler) {
        run.subStep = [](Run &r, double h) { core::stepSpringBlocks(*r.model, r.state, r.work, h); };
    } else {
        run.subStep = [](Run &r, double h) { core::xpbd(*r.model, r.state, r.work, h); };
    }
    return run;
}

double largestStretch(const core::Model &model, const core::State &state, int n)
{
    double worst = 0.0;
    for (int k = 0; k < structuralSpringCount(n); ++k) {
        const double length = (state.position.col(model.springA[std::size_t(k)]) -
                               state.position.col(model.springB[std::size_t(k)])).norm();
        worst = std::max(worst, (length - model.restLength[k]) / model.restLength[k]);
    }
    return worst;
}

}  // namespace

int runXpbdSubStep(const XpbdSubStepOptions &o, QTextStream &out)
{
    out << "xpbd-substep: " << o.size << " x " << o.size << " cloth, k = " << o.stiffness << " N/m, " << o.substeps
        << " sub-steps a 0.01 s step; " << machineDescription() << "; " << loadText() << '\n';
    const double h = kStiffTimeStep / o.substeps;
    for (Variant variant : {Variant::Colours, Variant::Layout, Variant::Layout2, Variant::Euler}) {
        for (int threads : {1, 2}) {
            core::setThreadCount(threads);
            std::vector<double> perSubStep;
            for (int r = 0; r < o.runs; ++r) {
                Run run = makeRun(o, variant);
                run.subStep(run, h);  // first use: scratch made
                QElapsedTimer clock;
                clock.start();
                for (int s = 0; s < o.subStepsARun; ++s)
                    run.subStep(run, h);
                perSubStep.push_back(double(clock.nsecsElapsed()) * 1e-6 / o.subStepsARun);
            }
            const auto [low, high] = std::minmax_element(perSubStep.begin(), perSubStep.end());
            out << QStringLiteral("%1, %2 thread(s): %3 ms a sub-step (median of %4, range %5-%6)\n")
                       .arg(variantName(variant))
                       .arg(threads)
                       .arg(median(perSubStep), 0, 'f', 3)
                       .arg(o.runs)
                       .arg(*low, 0, 'f', 3)
                       .arg(*high, 0, 'f', 3);
            out.flush();
        }
    }
    core::setThreadCount(1);
    if (o.drape > 0.0) {
        const int steps = int(std::lround(o.drape / kStiffTimeStep));
        for (Variant variant : {Variant::Colours, Variant::Layout, Variant::Layout2}) {
            Run run = makeRun(o, variant);
            double worst = 0.0;
            for (int step = 0; step < steps; ++step) {
                for (int s = 0; s < o.substeps; ++s)
                    run.subStep(run, h);
                worst = std::max(worst, largestStretch(*run.model, run.state, o.size));
            }
            out << QStringLiteral("%1: largest structural stretch over %2 s: %3%\n")
                       .arg(variantName(variant))
                       .arg(o.drape)
                       .arg(100.0 * worst, 0, 'f', 3);
            out.flush();
        }
    }
    core::setThreadCount(0);
    out << "end: " << loadText() << '\n';
    return 0;
}

}  // namespace bench
