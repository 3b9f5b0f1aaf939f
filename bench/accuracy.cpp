// The accuracy benchmark: for each reference problem, each integrator runs a sweep of sub-step
// counts (adaptive-rk45: of tolerances) from the problem's initial state to its end time.
//
// - error: RMS over the free particles of the position error at the end time (pinned particles
//   never move and would only dilute it), against the closed form for problems 1 to 3 and
//   against RK4 at a step 1000 times finer than the finest swept step for problems 4 and 5. That
//   reference is itself checked against RK4 at half its step, and its error estimate printed next
//   to the smallest error the sweep reports.
// - cost: CPU seconds of the stepping loop alone (process CPU time, so that other work on a
//   shared machine is not counted) per simulated second, the median of at least three runs; runs
//   shorter than kMinSample are repeated in batches until one batch is measurable.
// - the scene's time step (0.01 s) stays the frame; the swept quantity is the number of sub-steps
//   per frame, so the integration step is timeStep / substeps. adaptive-rk45 runs one sub-step
//   per frame, the frame being the largest step it may take.
// - a sweep stops refining once its error is below kErrorFloor, below which rounding, not the
//   integrator, decides the error, or below 100 times the reference's error estimate; a run whose
//   error is under 10 times that estimate is not reported at all (the reference cannot tell it).
#include "accuracy.h"

#include "bench_common.h"

#include "reference_problems.h"
#include "work_precision.h"
#include "work_precision_plot.h"

#include "core/model/model.h"
#include "core/model/state.h"
#include "core/step.h"

#include <QDir>
#include <QFile>
#include <QSaveFile>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>

namespace bench {

namespace {

constexpr double kErrorFloor = 1e-10;      // m
constexpr double kStopAbove = 100.0;       // × the reference's error estimate: refine no further
constexpr double kTrustAbove = 10.0;       // × the reference's error estimate: report no error below
constexpr double kMinSample = 0.02;        // s of CPU time: shorter runs are timed in batches
constexpr double kLongRun = 0.5;           // s of CPU time: three samples are enough from here on
constexpr double kTargetErrors[] = {1e-2, 1e-4, 1e-6};  // m, the errors the summary reads costs at
constexpr int kReferenceFactor = 1000;     // the reference step is the finest swept step over this
constexpr int kQuickReferenceFactor = 10;  // --quick: cheap, and not to be trusted



// what each problem's sweep covers
struct Sweep {
    std::vector<int> substeps;       // per frame, coarse to fine
    std::vector<double> tolerances;  // adaptive-rk45's, loose to tight
};

// the finest sub-step count per problem: fine enough for the first-order schemes to show their
// slope over three or four decades where that is cheap (one particle), and no finer than the
// reference run (1000 times finer again) allows for the chain and the cloth
int finestSubsteps(const std::string &problem)
{
    if (problem == "chain")
        return 100;
    if (problem == "cloth")
        return 32;
    if (problem == "oscillator")
        return 21544;  // 10^(26/6): where symplectic Euler gets to 1e-6 m
    return 10000;
}

// six sub-step counts per decade, 10^(k/6) rounded, up to the problem's finest; tolerances two per
// decade from 1e-2 to 1e-10
Sweep sweepFor(const std::string &problem, bool quick)
{
    Sweep sweep;
    if (quick)
        return {{10, 22}, {1e-3, 1e-5}};
    const int finest = finestSubsteps(problem);
    for (int k = 0;; ++k) {
        const int substeps = static_cast<int>(std::lround(std::pow(10.0, k / 6.0)));
        if (substeps > finest)
            break;
        if (sweep.substeps.empty() || substeps != sweep.substeps.back())
            sweep.substeps.push_back(substeps);
    }
    for (int k = 4; k <= 20; ++k)
        sweep.tolerances.push_back(std::pow(10.0, -k / 2.0));
    return sweep;
}

// one run from the initial state to the end time
struct Outcome {
    bool ok = true;  // false: the run blew up
    Eigen::Matrix3Xd position;
    double seconds = 0.0;  // CPU time of the stepping loop
};

Outcome simulate(const core::Model &model, const core::State &initial, int steps)
{
    core::State state = initial;
    core::Workspace work;
    Outcome outcome;
    const double start = cpuSeconds();
    for (int i = 0; i < steps && outcome.ok; ++i)
        outcome.ok = core::step(model, state, work);
    outcome.seconds = cpuSeconds() - start;
    outcome.position = std::move(state.position);
    return outcome;
}

// RMS over the free particles of the distance between two sets of positions
double rmsError(const core::Model &model, const Eigen::Matrix3Xd &a, const Eigen::Matrix3Xd &b)
{
    double sum = 0.0;
    for (int i : model.freeParticles)
        sum += (a.col(i) - b.col(i)).squaredNorm();
    return std::sqrt(sum / static_cast<double>(std::max<std::size_t>(1, model.freeParticles.size())));
}

// the scene of one run of the sweep
core::SceneDesc sceneFor(const ReferenceProblem &problem, core::Integrator integrator, int substeps,
                         double tolerance)
{
    core::SceneDesc scene = problem.scene;
    scene.settings.integrator = integrator;
    scene.settings.substeps = substeps;
    if (integrator == core::Integrator::AdaptiveRk45)
        scene.settings.tolerance = tolerance;
    return scene;
}

int frameCount(const ReferenceProblem &problem)
{
    return static_cast<int>(std::lround(problem.duration / problem.scene.settings.timeStep));
}

// the positions every run is measured against, and an estimate of their own error (m; 0 for a
// closed form)
struct Reference {
    Eigen::Matrix3Xd position;
    double errorEstimate = 0.0;
    QString description;
};

Reference referenceFor(const ReferenceProblem &problem, const Sweep &sweep, bool quick)
{
    if (problem.exact)
        return {*problem.exact, 0.0, QStringLiteral("closed form")};

    // RK4 at the finest swept step over the factor, and at half that step; the reference error is
    // taken as twice their RMS difference (exact for a first-order error, generous for fourth)
    const int substeps = sweep.substeps.back() * (quick ? kQuickReferenceFactor : kReferenceFactor);
    const int frames = frameCount(problem);
    Eigen::Matrix3Xd positions[2];
    double seconds = 0.0;
    for (int half = 0; half < 2; ++half) {
        const core::SceneDesc scene = sceneFor(problem, core::Integrator::Rk4, substeps * (half + 1), 0.0);
        const std::shared_ptr<const core::Model> model = core::compileModel(scene);
        const Outcome outcome = simulate(*model, core::makeState(*model, scene), frames);
        seconds += outcome.seconds;
        if (!outcome.ok)
            return {{}, std::numeric_limits<double>::infinity(), QStringLiteral("RK4 reference blew up")};
        positions[half] = outcome.position;
    }
    const std::shared_ptr<const core::Model> model = core::compileModel(problem.scene);
    const double estimate = 2.0 * rmsError(*model, positions[0], positions[1]);
    const double step = problem.scene.settings.timeStep / substeps;
    return {positions[0], estimate,
            QStringLiteral("RK4 at h = %1 s (%2 sub-steps per frame), checked against h/2: error estimate %3 m "
                           "(%4 s CPU)")
                .arg(step, 0, 'g', 3)
                .arg(substeps)
                .arg(estimate, 0, 'g', 2)
                .arg(seconds, 0, 'f', 1)};
}

// the median CPU time of one run, s: the first run counts as a sample when it is long; short runs
// are timed in batches of at least kMinSample
double medianSeconds(const core::Model &model, const core::State &initial, int frames, double firstRun, bool quick)
{
    if (quick)
        return firstRun;
    std::vector<double> samples;
    if (firstRun >= kLongRun) {
        samples.push_back(firstRun);
        while (samples.size() < 3)
            samples.push_back(simulate(model, initial, frames).seconds);
    } else {
        const int batch = std::max(1, static_cast<int>(std::ceil(kMinSample / std::max(firstRun, 1e-9))));
        while (samples.size() < 5) {
            double total = 0.0;
            for (int run = 0; run < batch; ++run)
                total += simulate(model, initial, frames).seconds;
            samples.push_back(total / batch);
        }
    }
    std::sort(samples.begin(), samples.end());
    return samples[samples.size() / 2];
}

// one integrator's sweep on one problem; `untrusted` counts the runs left out for being closer to
// the reference than it can tell (never in a quick run, whose reference is coarse anyway)
WorkPrecisionCurve sweepIntegrator(const ReferenceProblem &problem, const Sweep &sweep, const Reference &reference,
                                   core::Integrator integrator, bool quick, int &untrusted)
{
    const double stopBelow = std::max(kErrorFloor, kStopAbove * reference.errorEstimate);
    const double trustBelow = quick ? 0.0 : kTrustAbove * reference.errorEstimate;
    WorkPrecisionCurve curve{integrator, {}};
    const bool adaptive = integrator == core::Integrator::AdaptiveRk45;
    const std::size_t count = adaptive ? sweep.tolerances.size() : sweep.substeps.size();
    const int frames = frameCount(problem);
    for (std::size_t k = 0; k < count; ++k) {
        const int substeps = adaptive ? 1 : sweep.substeps[k];
        const double tolerance = adaptive ? sweep.tolerances[k] : 0.0;
        const core::SceneDesc scene = sceneFor(problem, integrator, substeps, tolerance);
        const std::shared_ptr<const core::Model> model = core::compileModel(scene);
        const core::State initial = core::makeState(*model, scene);

        // the error from a first run, then its cost from as many more as it takes
        WorkPrecisionPoint point{scene.settings.timeStep, substeps, tolerance, 0.0, 0.0};
        const Outcome first = simulate(*model, initial, frames);
        if (!first.ok) {
            point.error = std::numeric_limits<double>::infinity();
            point.cost = std::numeric_limits<double>::quiet_NaN();
        } else {
            point.error = rmsError(*model, first.position, reference.position);
            point.cost = medianSeconds(*model, initial, frames, first.seconds, quick) / problem.duration;
        }
        if (point.error < trustBelow)
            untrusted += 1;
        else
            curve.points.push_back(point);
        if (point.error < stopBelow)
            break;
    }
    return curve;
}

// "1e-4": a power of ten as the table writes it
QString powerOfTen(double value)
{
    return QStringLiteral("1e%1").arg(std::lround(std::log10(value)));
}

// "0.01", "1e-05": short and exact enough to redo the run
QString number(double value, int digits)
{
    return QString::number(value, 'g', digits);
}

bool writeCsv(const QString &path, const ReferenceProblem &problem, const std::vector<WorkPrecisionCurve> &curves,
              QTextStream &out)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        out << "springlab-bench: cannot write " << path << ": " << file.errorString() << '\n';
        return false;
    }
    QTextStream csv(&file);
    csv << "problem,integrator,time_step,substeps,tolerance,error,seconds_per_simulated_second\n";
    for (const WorkPrecisionCurve &curve : curves)
        for (const WorkPrecisionPoint &point : curve.points) {
            // the tolerance only for adaptive-rk45, the cost only for a run that did not blow up
            const bool adaptive = curve.integrator == core::Integrator::AdaptiveRk45;
            csv << QString::fromStdString(problem.name) << ',' << nameOf(curve.integrator)
                << ',' << number(point.timeStep, 10) << ',' << point.substeps << ','
                << (adaptive ? number(point.tolerance, 6) : QString()) << ','
                << (point.blewUp() ? QStringLiteral("inf") : number(point.error, 6)) << ','
                << (point.blewUp() ? QString() : number(point.cost, 6)) << '\n';
        }
    csv.flush();
    if (!file.commit()) {
        out << "springlab-bench: cannot write " << path << ": " << file.errorString() << '\n';
        return false;
    }
    return true;
}

// a table cell: "2.3e-05 (0.41x)", "<=2.3e-05 (1.00x)" when the sweep's first usable run already
// got there, "not reached"
QString cell(const std::optional<CostAtError> &cost, const std::optional<CostAtError> &baseline)
{
    if (!cost)
        return QStringLiteral("not reached");
    QString text = (cost->atMost ? QStringLiteral("<=") : QString()) + QString::number(cost->cost, 'e', 1);
    if (baseline)
        text += QStringLiteral(" (%1x)").arg(cost->cost / baseline->cost, 0, 'g', 2);
    return text;
}

// for each target error, every integrator's cost and the cheapest, relative to symplectic Euler
void printSummary(const std::vector<WorkPrecisionCurve> &curves, QTextStream &out)
{
    const auto baselineCurve = std::find_if(curves.begin(), curves.end(), [](const WorkPrecisionCurve &c) {
        return c.integrator == core::Integrator::SymplecticEuler;
    });
    std::optional<CostAtError> baseline[std::size(kTargetErrors)];
    for (std::size_t t = 0; t < std::size(kTargetErrors); ++t)
        if (baselineCurve != curves.end())
            baseline[t] = costToReach(*baselineCurve, kTargetErrors[t]);

    out << "  cost to reach an error, CPU s per simulated s (relative to symplectic-euler):\n";
    out << QStringLiteral("  %1").arg(QStringLiteral("error"), -18);
    for (double target : kTargetErrors)
        out << QStringLiteral("%1").arg(powerOfTen(target) + QStringLiteral(" m"), -22);
    out << '\n';
    for (const WorkPrecisionCurve &curve : curves) {
        out << QStringLiteral("  %1").arg(nameOf(curve.integrator), -18);
        for (std::size_t t = 0; t < std::size(kTargetErrors); ++t)
            out << QStringLiteral("%1").arg(cell(costToReach(curve, kTargetErrors[t]), baseline[t]), -22);
        out << '\n';
    }
    for (std::size_t t = 0; t < std::size(kTargetErrors); ++t) {
        const WorkPrecisionCurve *cheapest = nullptr;
        std::optional<CostAtError> best;
        for (const WorkPrecisionCurve &curve : curves) {
            const std::optional<CostAtError> cost = costToReach(curve, kTargetErrors[t]);
            if (cost && (!best || cost->cost < best->cost)) {
                best = cost;
                cheapest = &curve;
            }
        }
        out << QStringLiteral("  cheapest at %1 m: ").arg(powerOfTen(kTargetErrors[t]));
        if (!cheapest)
            out << "no integrator reached it\n";
        else if (!baseline[t])
            out << nameOf(cheapest->integrator) << ", " << cell(best, {})
                << " (symplectic-euler did not reach it)\n";
        else
            out << nameOf(cheapest->integrator) << ", "
                << QStringLiteral("%1x symplectic-euler's cost").arg(best->cost / baseline[t]->cost, 0, 'g', 2) << '\n';
    }
}

// the smallest error a sweep reports, to hold the reference's own error against
double smallestError(const std::vector<WorkPrecisionCurve> &curves)
{
    double smallest = std::numeric_limits<double>::infinity();
    for (const WorkPrecisionCurve &curve : curves)
        for (const WorkPrecisionPoint &point : curve.points)
            if (point.error > 0.0)
                smallest = std::min(smallest, point.error);
    return smallest;
}


}  // namespace

int runAccuracy(const AccuracyOptions &options, QTextStream &out)
{
    const std::optional<QDir> folder = outputFolder(options.outDir, out);
    if (!folder)
        return 1;
    const QDir &dir = *folder;
    out << "machine: " << machineDescription() << '\n';
    if (options.quick)
        out << "accuracy --quick: a smoke test; the figures are not to be trusted\n";

    for (const ReferenceProblem &problem : referenceProblems()) {
        const double start = cpuSeconds();
        const QString title = QStringLiteral("%1 (end time %2 s)")
                                  .arg(QString::fromStdString(problem.title))
                                  .arg(problem.duration);
        out << '\n' << title << '\n';
        const Sweep sweep = sweepFor(problem.name, options.quick);
        const Reference reference = referenceFor(problem, sweep, options.quick);
        out << "  reference: " << reference.description << '\n';
        out.flush();
        if (!std::isfinite(reference.errorEstimate))
            return 1;

        // every integrator's sweep
        std::vector<WorkPrecisionCurve> curves;
        for (core::Integrator integrator : core::kIntegrators) {
            int untrusted = 0;
            curves.push_back(sweepIntegrator(problem, sweep, reference, integrator, options.quick, untrusted));
            int blowups = 0;
            for (const WorkPrecisionPoint &point : curves.back().points)
                blowups += point.blewUp() ? 1 : 0;
            out << QStringLiteral("  %1 %2 runs, %3 blew up")
                       .arg(nameOf(integrator), -18)
                       .arg(curves.back().points.size(), 2)
                       .arg(blowups);
            if (untrusted > 0)
                out << QStringLiteral(", %1 more below %2x the reference's error estimate left out")
                           .arg(untrusted)
                           .arg(kTrustAbove);
            out << '\n';
            out.flush();
        }

        // the reference must be well inside the errors it measures
        if (reference.errorEstimate > 0.0) {
            const double smallest = smallestError(curves);
            out << QStringLiteral("  smallest error reported %1 m, %2 times the reference's error estimate%3\n")
                       .arg(smallest, 0, 'g', 2)
                       .arg(smallest / reference.errorEstimate, 0, 'g', 2)
                       .arg(smallest < 10.0 * reference.errorEstimate ? QStringLiteral(": TOO CLOSE, do not trust it")
                                                                       : QString());
        }

        // the files, then the table
        const QString stem = dir.filePath(QStringLiteral("accuracy-%1").arg(QString::fromStdString(problem.name)));
        if (!writeCsv(stem + QStringLiteral(".csv"), problem, curves, out))
            return 1;
        const QImage plot = drawWorkPrecision(title, curves);
        if (!plot.save(stem + QStringLiteral(".png"))) {
            out << "springlab-bench: cannot write " << stem << ".png\n";
            return 1;
        }
        printSummary(curves, out);
        out << QStringLiteral("  (%1 s CPU for this problem)\n").arg(cpuSeconds() - start, 0, 'f', 0);
        out.flush();
    }
    return 0;
}

}  // namespace bench
