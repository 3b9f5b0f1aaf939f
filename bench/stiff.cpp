// The stiff-cloth benchmark (issue 24). A cloth of n × n particles (stiff_scene.h) drapes for 1 s
// from flat, pinned at two corners, at structural stiffness k from 1e3 to 1e8 N/m. For each cell
// (n, k) and each of symplectic Euler, implicit Euler, xpbd, projective and vbd (at the scene's default
// solver iterations), the sub-step count is searched
// upward over a ladder until a run meets a criterion:
//
// - stretch: the largest (l - l0) / l0 of any structural spring, read at the end of every step of
//   0.01 s, stays under 1%;
// - stretch+energy: that, and the total energy (core::energies) never rises above its start (by
//   more than 1e-9 of it, rounding), read at the same times.
//
// Symplectic Euler starts at the fewest sub-steps its stability limit allows
// (core::stableSubsteps: 90% of StabilityLimit::maxSubStep) and climbs the ladder from there; the
// other two start at one sub-step. A run that has already failed what is still being searched for
// stops there, so failing runs are cheap.
//
// Budget: a run is predicted from its first two steps; one predicted to take more CPU time than
// the plan's cap is stopped there and reported "capped", with the predicted cost marked as an
// estimate (for symplectic Euler that is its cost per sub-step times the count its stability limit
// demands). The ladder's top is the other bound ("none up to N").
//
// Reference, per cell: RK4 at as many sub-steps as the plan's reference budget affords (at least its
// own stability count), else symplectic Euler at its stability count, else none. If the reference
// itself stretches past 1%, the cloth is too soft for the criterion: no integrator is searched
// ("soft"), since meeting it would take being wrong. The reference's kinetic energy at 1 s is what
// each row's is compared with (the visual damping).
//
// Timing: CPU time of the process in the calls that step, on one thread (core::setThreadCount(1)),
// per simulated second; the median of 3 runs where a run takes under the plan's threshold, one run
// above it. Every repetition must end on the same positions to the bit. The xpbd, projective and
// vbd rows of the largest cloth are also timed on 2 threads, by the wall clock (process CPU time would count both
// threads).
#include "stiff.h"

#include "bench_common.h"
#include "stiff_plot.h"
#include "stiff_scene.h"

#include "core/model/diagnostics.h"
#include "core/model/model.h"
#include "core/integrators/stability.h"
#include "core/model/state.h"
#include "core/step.h"
#include "core/threads.h"

#include <QElapsedTimer>
#include <QSaveFile>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <vector>

namespace bench {

namespace {

constexpr core::Integrator kCompared[] = {core::Integrator::SymplecticEuler, core::Integrator::ImplicitEuler,
                                          core::Integrator::Xpbd, core::Integrator::Projective,
                                          core::Integrator::Vbd};
// the integrators with no stability limit, whose rows on the largest cloth are also timed on 2 threads
bool unconditionallyStable(core::Integrator integrator)
{
    return integrator == core::Integrator::Xpbd || core::isVariational(integrator);
}
constexpr int kProbeSteps = 2;  // steps a run's cost is predicted from
constexpr int kMostSubsteps = 1000000;

// what a run must meet
enum class Criterion { Stretch, StretchAndEnergy };
constexpr Criterion kCriteria[] = {Criterion::Stretch, Criterion::StretchAndEnergy};

QString criterionName(Criterion criterion)
{
    return criterion == Criterion::Stretch ? QStringLiteral("stretch") : QStringLiteral("stretch+energy");
}

struct Plan {
    std::vector<int> sizes;         // particles a side
    std::vector<double> stiffness;  // N/m, structural
    std::vector<int> ladder;        // sub-step counts searched, ascending
    double runCap = 0.0;            // CPU s: a run predicted to cost more is stopped ("capped")
    double referenceBudget = 0.0;   // CPU s the RK4 reference may take
    double repeatBelow = 0.0;       // CPU s: shorter runs are timed 3 times, the median counts
    int twoThreadSize = 0;          // the cloth whose xpbd rows are timed on 2 threads too
};

Plan planFor(bool quick)
{
    Plan plan;
    plan.ladder = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000};
    if (quick) {
        plan.sizes = {8};
        plan.stiffness = {1e3, 1e6};
        plan.runCap = 5.0;
        plan.referenceBudget = 0.5;
        plan.repeatBelow = 1.0;
        plan.twoThreadSize = 8;
        return plan;
    }
    plan.sizes = {64, 128, 256};
    plan.stiffness = {1e4, 1e5, 1e6, 1e7, 1e8};
    plan.runCap = 60.0;
    plan.referenceBudget = 10.0;
    plan.repeatBelow = 10.0;
    plan.twoThreadSize = 128;
    return plan;
}

// when a run stops before its end
enum class Stop {
    Never,             // runs to the end: a reference, a timing
    OnStretch,         // once the stretch passes 1%
    OnStretchOrEnergy  // once either criterion has failed
};

// one run of the cloth by one integrator at one sub-step count
struct Trial {
    core::Integrator integrator = core::Integrator::SymplecticEuler;
    int substeps = 0;
    bool complete = false;  // ran the whole second
    bool blewUp = false;
    bool capped = false;           // stopped after the probe: predicted past the plan's cap
    double predictedSeconds = 0.0;  // CPU s for the whole run, from its first steps
    double simulated = 0.0;         // s simulated
    double maxStretch = 0.0;        // the largest structural (l - l0) / l0 at the ends of steps
    double startEnergy = 0.0;       // J
    double energyRise = -std::numeric_limits<double>::infinity();  // J, the largest E - E(0)
    double kineticEnd = 0.0;        // J, at the last step run
    double cpuSeconds = 0.0;        // in the step calls
    double wallSeconds = 0.0;       // in the step calls
    Eigen::Matrix3Xd endPosition;

    bool stretchHeld() const { return !blewUp && maxStretch < kStretchLimit; }
    bool energyHeld() const { return !blewUp && energyRise <= kEnergyRounding * std::abs(startEnergy); }
    bool meets(Criterion criterion) const
    {
        return complete && stretchHeld() && (criterion == Criterion::Stretch || energyHeld());
    }
};

// the largest (l - l0) / l0 of the structural springs (the model's first `structural`)
double largestStretch(const core::Model &model, const core::State &state, int structural)
{
    double largest = 0.0;
    for (int k = 0; k < structural; ++k) {
        const double length =
            (state.position.col(model.springA[std::size_t(k)]) - state.position.col(model.springB[std::size_t(k)])).norm();
        largest = std::max(largest, (length - model.restLength[k]) / model.restLength[k]);
    }
    return largest;
}

Trial simulate(int n, double stiffness, core::Integrator integrator, int substeps, Stop stop, double cap)
{
    const core::SceneDesc scene = stiffCloth(n, stiffness, integrator, substeps);
    const std::shared_ptr<const core::Model> model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    core::Workspace work;
    const int structural = structuralSpringCount(n);
    const int steps = static_cast<int>(std::lround(kStiffDuration / kStiffTimeStep));

    Trial trial;
    trial.integrator = integrator;
    trial.substeps = substeps;
    trial.startEnergy = core::energies(*model, state).total();
    bool stretchFailed = false, energyFailed = false;
    for (int s = 0; s < steps; ++s) {
        const double cpuBefore = cpuSeconds();
        const auto wallBefore = std::chrono::steady_clock::now();
        const bool ok = core::step(*model, state, work);
        trial.wallSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - wallBefore).count();
        trial.cpuSeconds += cpuSeconds() - cpuBefore;
        trial.simulated = (s + 1) * kStiffTimeStep;
        if (!ok) {
            trial.blewUp = true;
            break;
        }
        trial.maxStretch = std::max(trial.maxStretch, largestStretch(*model, state, structural));
        const core::Energies energy = core::energies(*model, state);
        trial.energyRise = std::max(trial.energyRise, energy.total() - trial.startEnergy);
        trial.kineticEnd = energy.kinetic;
        stretchFailed = stretchFailed || !trial.stretchHeld();
        energyFailed = energyFailed || !trial.energyHeld();
        if ((stop != Stop::Never && stretchFailed) || (stop == Stop::OnStretchOrEnergy && energyFailed))
            break;
        if (s + 1 == kProbeSteps && steps > kProbeSteps) {
            trial.predictedSeconds = trial.cpuSeconds / kProbeSteps * steps;
            if (trial.predictedSeconds > cap) {
                trial.capped = true;
                break;
            }
        }
    }
    trial.complete = !trial.blewUp && !trial.capped && trial.simulated >= kStiffDuration - 0.5 * kStiffTimeStep;
    trial.endPosition = std::move(state.position);
    return trial;
}

// what the search found for one integrator and criterion in one cell
enum class Status { Met, None, Capped, Soft };

QString statusName(Status status)
{
    switch (status) {
    case Status::Met: return QStringLiteral("met");
    case Status::None: return QStringLiteral("none");
    case Status::Capped: return QStringLiteral("capped");
    case Status::Soft: return QStringLiteral("soft");
    }
    return {};
}

struct Row {
    int size = 0;
    int particles = 0;
    int springs = 0;
    double stiffness = 0.0;  // N/m
    core::Integrator integrator = core::Integrator::SymplecticEuler;
    Criterion criterion = Criterion::Stretch;
    Status status = Status::None;
    int substeps = 0;                // met: the count chosen; none: the last tried; capped: the one capped
    std::optional<int> below;        // the count tried before it, which failed
    std::optional<double> cost;      // CPU s per simulated s, median (met)
    std::optional<double> estimate;  // CPU s per simulated s, predicted from the first steps (capped)
    std::optional<double> twoThreads;  // wall s per simulated s on 2 threads (xpbd, largest cloth, met)
    int runs = 0;                    // timed runs behind cost
    std::optional<Trial> trial;      // the run the figures come from (none when soft)
    std::optional<double> kineticRatio;  // the trial's kinetic energy at 1 s over the reference's
    QString reference;
};

// the runs of one cell, each (integrator, sub-steps) at most once: the reference's symplectic
// Euler run is the first that integrator's search tries
class Cell {
public:
    Cell(int n, double stiffness, const Plan &plan) : m_n(n), m_stiffness(stiffness), m_plan(plan) {}

    // a run, from the cache when one that went as far is there
    const Trial &run(core::Integrator integrator, int substeps, Stop stop)
    {
        const auto key = std::make_pair(static_cast<int>(integrator), substeps);
        const auto found = m_trials.find(key);
        if (found != m_trials.end() && (found->second.complete || found->second.capped || found->second.blewUp ||
                                        stop != Stop::Never))
            return found->second;
        return m_trials[key] = simulate(m_n, m_stiffness, integrator, substeps, stop, m_plan.runCap);
    }

    int n() const { return m_n; }
    double stiffness() const { return m_stiffness; }
    const Plan &plan() const { return m_plan; }

private:
    int m_n;
    double m_stiffness;
    const Plan &m_plan;
    std::map<std::pair<int, int>, Trial> m_trials;
};

// the cost of a met row: the search's run as the first sample, and two more when it was short;
// false if a repetition ended elsewhere
bool timeRow(Row &row, const Plan &plan)
{
    std::vector<double> samples{row.trial->cpuSeconds};
    bool same = true;
    if (row.trial->cpuSeconds < plan.repeatBelow)
        for (int r = 0; r < 2; ++r) {
            const Trial again = simulate(row.size, row.stiffness, row.integrator, row.substeps, Stop::Never,
                                         std::numeric_limits<double>::infinity());
            samples.push_back(again.cpuSeconds);
            same = same && again.endPosition == row.trial->endPosition;
        }
    row.cost = median(samples) / kStiffDuration;
    row.runs = static_cast<int>(samples.size());
    return same;
}

// the row's wall time on 2 threads, median of 3 when short
void timeTwoThreads(Row &row, const Plan &plan)
{
    const int restore = core::threadCount();
    core::setThreadCount(2);
    std::vector<double> samples;
    for (int r = 0; r < 3; ++r) {
        const Trial run = simulate(row.size, row.stiffness, row.integrator, row.substeps, Stop::Never,
                                   std::numeric_limits<double>::infinity());
        samples.push_back(run.wallSeconds);
        if (run.wallSeconds >= plan.repeatBelow)
            break;
    }
    core::setThreadCount(restore);
    row.twoThreads = median(samples) / kStiffDuration;
}

// the sub-step counts an integrator's search tries, in order
std::vector<int> countsFor(core::Integrator integrator, int stableCount, const Plan &plan)
{
    if (integrator != core::Integrator::SymplecticEuler)
        return plan.ladder;
    std::vector<int> counts{stableCount};
    for (int c : plan.ladder)
        if (c > stableCount)
            counts.push_back(c);
    return counts;
}

// searches one integrator in one cell for both criteria at once; the rows come back untimed
std::vector<Row> search(Cell &cell, core::Integrator integrator, int stableCount, const Row &blank)
{
    std::vector<Row> rows;
    for (Criterion criterion : kCriteria) {
        Row row = blank;
        row.integrator = integrator;
        row.criterion = criterion;
        rows.push_back(row);
    }
    Row &stretch = rows[0];
    Row &both = rows[1];
    bool stretchFound = false;
    std::optional<int> previous;
    const Trial *last = nullptr;
    for (int count : countsFor(integrator, stableCount, cell.plan())) {
        const Trial &trial = cell.run(integrator, count, stretchFound ? Stop::OnStretchOrEnergy : Stop::OnStretch);
        last = &trial;
        if (trial.capped) {
            for (Row *row : {&stretch, &both})
                if (row->status == Status::None) {
                    row->status = Status::Capped;
                    row->substeps = count;
                    row->below = previous;
                    row->estimate = trial.predictedSeconds / kStiffDuration;
                    row->trial = trial;
                }
            return rows;
        }
        if (!stretchFound && trial.meets(Criterion::Stretch)) {
            stretchFound = true;
            stretch.status = Status::Met;
            stretch.substeps = count;
            stretch.below = previous;
            stretch.trial = trial;
        }
        if (trial.meets(Criterion::StretchAndEnergy)) {
            both.status = Status::Met;
            both.substeps = count;
            both.below = previous;
            both.trial = trial;
            return rows;
        }
        previous = count;
    }
    // nothing up to the ladder's top: the figures of the last run tried
    for (Row *row : {&stretch, &both})
        if (row->status == Status::None && last != nullptr) {
            row->substeps = last->substeps;
            row->trial = *last;
        }
    return rows;
}

QString percent(double strain)
{
    return QString::number(100.0 * strain, 'g', 3) + QLatin1Char('%');
}

QString costText(const Row &row)
{
    if (row.cost)
        return QString::number(*row.cost, 'g', 3);
    if (row.estimate)
        return QStringLiteral("~%1 (est.)").arg(*row.estimate, 0, 'g', 3);
    return QStringLiteral("-");
}

QString substepsText(const Row &row, const Plan &plan)
{
    switch (row.status) {
    case Status::Met: return QString::number(row.substeps);
    case Status::Soft: return QStringLiteral("soft");
    case Status::Capped: return QStringLiteral("capped at %1").arg(row.substeps);
    case Status::None:
        return QStringLiteral("none up to %1").arg(std::max(row.substeps, plan.ladder.back()));
    }
    return {};
}

// one line of the table
QString tableLine(const Row &row, const Plan &plan)
{
    QString figures;
    if (row.trial) {
        const Trial &t = *row.trial;
        figures = QStringLiteral("%1 %2")
                      .arg(t.blewUp ? QStringLiteral("blew up") : percent(t.maxStretch), 8)
                      .arg(QString::number(t.energyRise, 'g', 3), 11);
        figures += QStringLiteral(" %1").arg(row.kineticRatio ? QString::number(*row.kineticRatio, 'f', 3)
                                                              : QStringLiteral("-"),
                                             8);
        if (!t.complete)
            figures += QStringLiteral("  (first %1 s)").arg(t.simulated, 0, 'f', 2);
    }
    QString line = QStringLiteral("  %1 %2 %3 %4 %5 %6")
                       .arg(QStringLiteral("%1x%1").arg(row.size), -7)
                       .arg(QString::number(row.stiffness, 'g', 2), -6)
                       .arg(nameOf(row.integrator), -17)
                       .arg(criterionName(row.criterion), -15)
                       .arg(substepsText(row, plan), -17)
                       .arg(costText(row), 16);
    line += QStringLiteral(" %1 ").arg(row.twoThreads ? QString::number(*row.twoThreads, 'g', 3) : QStringLiteral("-"), 8);
    return line + figures;
}

QString tableHeader()
{
    return QStringLiteral("  %1 %2 %3 %4 %5 %6 %7 %8 %9 %10\n")
        .arg(QStringLiteral("size"), -7)
        .arg(QStringLiteral("k N/m"), -6)
        .arg(QStringLiteral("integrator"), -17)
        .arg(QStringLiteral("criterion"), -15)
        .arg(QStringLiteral("sub-steps"), -17)
        .arg(QStringLiteral("CPU s/sim s"), 16)
        .arg(QStringLiteral("2 thr"), 8)
        .arg(QStringLiteral("stretch"), 8)
        .arg(QStringLiteral("E rise J"), 11)
        .arg(QStringLiteral("KE/ref"), 8);
}

bool writeCsv(const QString &path, const std::vector<Row> &rows, QTextStream &out)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        out << "springlab-bench: cannot write " << path << '\n';
        return false;
    }
    const auto optional = [](const std::optional<double> &value) {
        return value ? QString::number(*value, 'g', 6) : QString();
    };
    QTextStream csv(&file);
    csv << "size,particles,springs,stiffness,integrator,criterion,status,substeps,substeps_below,"
           "cost_s_per_s,cost_estimated_s_per_s,cost_2threads_wall_s_per_s,runs,simulated_s,max_stretch,"
           "energy_rise_J,kinetic_end_J,kinetic_ratio,reference\n";
    for (const Row &row : rows) {
        csv << row.size << ',' << row.particles << ',' << row.springs << ',' << QString::number(row.stiffness, 'g', 6)
            << ',' << nameOf(row.integrator) << ',' << criterionName(row.criterion) << ',' << statusName(row.status) << ','
            << (row.status == Status::Soft ? QString() : QString::number(row.substeps)) << ','
            << (row.below ? QString::number(*row.below) : QString()) << ',' << optional(row.cost) << ','
            << optional(row.estimate) << ',' << optional(row.twoThreads) << ',' << row.runs << ',';
        if (row.trial) {
            const Trial &t = *row.trial;
            csv << QString::number(t.simulated, 'g', 6) << ','
                << (t.blewUp ? QStringLiteral("inf") : QString::number(t.maxStretch, 'g', 6)) << ','
                << QString::number(t.energyRise, 'g', 6) << ',' << QString::number(t.kineticEnd, 'g', 6) << ',';
        } else {
            csv << ",,,,";
        }
        csv << optional(row.kineticRatio) << ',' << row.reference << '\n';
    }
    csv.flush();
    if (!file.commit()) {
        out << "springlab-bench: cannot write " << path << '\n';
        return false;
    }
    return true;
}

const Row *findRow(const std::vector<Row> &rows, int size, double stiffness, core::Integrator integrator,
                   Criterion criterion)
{
    for (const Row &row : rows)
        if (row.size == size && row.stiffness == stiffness && row.integrator == integrator && row.criterion == criterion)
            return &row;
    return nullptr;
}

std::optional<double> costOrEstimate(const Row *row)
{
    if (row == nullptr)
        return std::nullopt;
    return row->cost ? row->cost : row->estimate;
}

// the best row (cheapest met, by CPU) of the unconditionally stable integrators for one cell and criterion
const Row *cheapest(const std::vector<Row> &rows, int n, double k, Criterion criterion, bool needTwoThreads)
{
    const Row *best = nullptr;
    for (core::Integrator integrator : kCompared) {
        const Row *row = findRow(rows, n, k, integrator, criterion);
        if (!row || row->status != Status::Met || !row->cost || (needTwoThreads && !row->twoThreads))
            continue;
        const double cost = needTwoThreads ? *row->twoThreads : *row->cost;
        if (!best || cost < (needTwoThreads ? *best->twoThreads : *best->cost))
            best = row;
    }
    return best;
}

// the targets, read off the rows at the stiffness nearest 1e7 N/m
QString targets(const std::vector<Row> &rows, const Plan &plan)
{
    double k = plan.stiffness.front();
    for (double s : plan.stiffness)
        if (std::abs(std::log10(s) - 7.0) < std::abs(std::log10(k) - 7.0))
            k = s;
    QString text;
    QTextStream t(&text);
    const auto describe = [&](const Row &row) {
        return QStringLiteral("%1 at %2 sub-steps (%3 s CPU per simulated s on 1 thread%4, KE/ref %5)")
            .arg(nameOf(row.integrator))
            .arg(row.substeps)
            .arg(*row.cost, 0, 'g', 3)
            .arg(row.twoThreads ? QStringLiteral(", %1 s wall on 2").arg(*row.twoThreads, 0, 'g', 3) : QString())
            .arg(row.kineticRatio ? QString::number(*row.kineticRatio, 'f', 2) : QStringLiteral("-"));
    };

    // 1: the 128 x 128 cloth (or the largest) in real time on 2 cores, stretch under 1%, KE/ref >= 0.9
    const int n1 = std::find(plan.sizes.begin(), plan.sizes.end(), 128) != plan.sizes.end() ? 128 : plan.sizes.back();
    t << QStringLiteral("target 1: the %1x%1 cloth at k = %2 N/m in real time on 2 cores (wall under 1 s per "
                        "simulated s), stretch under 1%, KE/ref at least 0.9: ")
             .arg(n1)
             .arg(k, 0, 'g', 2);
    const Row *best = nullptr;
    for (core::Integrator integrator : kCompared) {
        const Row *row = findRow(rows, n1, k, integrator, Criterion::Stretch);
        if (!row || row->status != Status::Met || !row->twoThreads || !row->kineticRatio || *row->kineticRatio < 0.9)
            continue;
        if (!best || *row->twoThreads < *best->twoThreads)
            best = row;
    }
    if (best)
        t << (*best->twoThreads < 1.0 ? QStringLiteral("MET by ") : QStringLiteral("MISSED, %1x too slow; best ")
                                                                         .arg(*best->twoThreads, 0, 'f', 1))
          << describe(*best) << '\n';
    else if (const Row *any = cheapest(rows, n1, k, Criterion::Stretch, true))
        t << "MISSED: no row keeps KE/ref at 0.9; the fastest within 1% stretch is " << describe(*any) << '\n';
    else if (n1 != plan.twoThreadSize)
        t << QStringLiteral("not measured: only the %1x%1 cloth is timed on 2 threads\n").arg(plan.twoThreadSize);
    else
        t << "MISSED: no integrator met the stretch within the ladder and the cap\n";

    // 2: the 256 x 256 cloth at 10 frames a second of the wall clock, a frame being 1/60 s simulated:
    // at most 6 s of wall per simulated second on 2 threads
    if (std::find(plan.sizes.begin(), plan.sizes.end(), 256) != plan.sizes.end()) {
        t << QStringLiteral("target 2: the 256x256 cloth at k = %1 N/m at 10 frames a second (6 s wall per "
                            "simulated s on 2 threads at 60 frames per simulated s): ")
                 .arg(k, 0, 'g', 2);
        if (const Row *row = cheapest(rows, 256, k, Criterion::Stretch, true))
            t << (*row->twoThreads <= 6.0 ? QStringLiteral("MET by ") : QStringLiteral("MISSED; best ")) << describe(*row)
              << '\n';
        else
            t << "MISSED: no row met the stretch\n";
    } else {
        t << "target 2: the 256x256 cloth is not in this run's sizes\n";
    }

    // 3 and 4: the solvers against xpbd (and implicit-euler) at equal stretch, 1 thread
    t << "target 4: projective or vbd at least 10x cheaper than xpbd for the same stretch (under 1%), 1 thread:\n";
    for (int size : plan.sizes)
        for (double s : plan.stiffness) {
            const Row *x = findRow(rows, size, s, core::Integrator::Xpbd, Criterion::Stretch);
            if (!x || x->status == Status::Soft)
                continue;
            t << QStringLiteral("  %1x%1 k = %2:").arg(size).arg(s, 0, 'g', 2);
            const std::optional<double> xc = costOrEstimate(x);
            for (core::Integrator solver : {core::Integrator::Projective, core::Integrator::Vbd,
                                            core::Integrator::ImplicitEuler}) {
                const Row *row = findRow(rows, size, s, solver, Criterion::Stretch);
                const std::optional<double> sc = costOrEstimate(row);
                if (!xc || !sc) {
                    t << QStringLiteral(" %1 not compared (%2);").arg(nameOf(solver), row ? substepsText(*row, plan) : "-");
                    continue;
                }
                const double ratio = *xc / *sc;
                t << QStringLiteral(" xpbd / %1 = %2%3;").arg(nameOf(solver)).arg(ratio, 0, 'f', 2).arg(
                    !x->cost || !row->cost ? QStringLiteral(" (est.)") : QString());
            }
            t << '\n';
        }
    return text;
}

// implicit-euler's two linear solves on one cloth, side by side: seconds a step (median of 3 runs of
// `steps` steps, alternating), conjugate-gradient iterations and residual
QString linearSolves(int n, double k, int steps)
{
    const core::SceneDesc scene = stiffCloth(n, k, core::Integrator::ImplicitEuler, 1);
    const std::shared_ptr<const core::Model> model = core::compileModel(scene);
    std::vector<double> direct, iterative;
    double iterations = 0.0, residualDirect = 0.0, residualIterative = 0.0;
    std::uint64_t caps = 0;
    for (int r = 0; r < 3; ++r)
        for (bool cg : {false, true}) {
            core::State state = core::makeState(*model, scene);
            core::Workspace work;
            work.implicitSolve = cg ? core::Workspace::ImplicitSolve::ConjugateGradients
                                    : core::Workspace::ImplicitSolve::Direct;
            const double before = cpuSeconds();
            for (int s = 0; s < steps; ++s)
                core::step(*model, state, work);
            (cg ? iterative : direct).push_back((cpuSeconds() - before) / steps);
            if (cg) {
                iterations = double(work.profile.solverIterationsTotal) / double(std::max<std::uint64_t>(1, work.profile.solves));
                residualIterative = work.profile.worstSolverResidual;
                caps = work.profile.solverCapHits;
            } else {
                residualDirect = work.profile.worstSolverResidual;
            }
        }
    return QStringLiteral("implicit-euler's linear solve, %1x%1 at k = %2 N/m, 1 sub-step, %3 steps, 1 thread, median "
                          "of 3: direct (sparse LDL^T) %4 s a step, residual up to %5; block-Jacobi conjugate "
                          "gradients %6 s a step, %7 iterations a step, residual up to %8, %9 capped\n")
        .arg(n)
        .arg(k, 0, 'g', 2)
        .arg(steps)
        .arg(median(direct), 0, 'g', 3)
        .arg(residualDirect, 0, 'g', 2)
        .arg(median(iterative), 0, 'g', 3)
        .arg(iterations, 0, 'f', 0)
        .arg(residualIterative, 0, 'g', 2)
        .arg(caps);
}

}  // namespace

int runStiff(const StiffOptions &options, QTextStream &out)
{
    const std::optional<QDir> folder = outputFolder(options.outDir, out);
    if (!folder)
        return 1;
    const QDir &dir = *folder;
    const RunClock clock;
    Plan plan = planFor(options.quick);
    if (!options.sizes.empty())
        plan.sizes = options.sizes;
    if (!options.stiffness.empty())
        plan.stiffness = options.stiffness;
    const int restoreThreads = core::threadCount();
    core::setThreadCount(1);

    const QString machine = machineDescription();
    const QString loadStart = loadText();
    QString header;
    QTextStream head(&header);
    head << "machine: " << machine << '\n';
    head << "load average at the start: " << loadStart << '\n';
    if (options.quick)
        head << "stiff --quick: a smoke test; a tiny cloth, two stiffnesses\n";
    head << QStringLiteral("cloth: n x n core::makeCloth, spacing 0.05 m, 5 g a particle, pinned at two corners, "
                           "structural k, shear %1 k, bend %2 k, damping 0.02 N s/m a spring; no contacts, "
                           "no drag; %3 s of draping from flat in steps of h = %4 s\n")
                .arg(kShearShare)
                .arg(kBendShare)
                .arg(kStiffDuration)
                .arg(kStiffTimeStep);
    head << "criteria, read at the end of every step: stretch: every structural spring within 1% of its rest "
            "length; stretch+energy: also the total energy never above its start\n";
    head << "search: symplectic-euler from the fewest sub-steps its stability limit allows (90% of the limit), "
            "then the ladder above it; the others over the ladder";
    for (int c : plan.ladder)
        head << ' ' << c;
    head << QStringLiteral("; a run predicted from its first %1 steps to take over %2 s of CPU is capped\n")
                .arg(kProbeSteps)
                .arg(plan.runCap);
    head << QStringLiteral("cost: CPU s of the step calls per simulated s, 1 thread, median of 3 runs (1 run when "
                           "longer than %1 s); xpbd on the %2x%2 cloth also on 2 threads, by the wall clock\n")
                .arg(plan.repeatBelow)
                .arg(plan.twoThreadSize);
    head << QStringLiteral("reference: rk4 at as many sub-steps as %1 s of CPU affords (at least its stability "
                           "count), else symplectic-euler at its stability count; KE/ref: kinetic energy at 1 s "
                           "over the reference's\n")
                .arg(plan.referenceBudget);
    out << header << '\n';
    out.flush();

    std::vector<Row> rows;
    bool repeatable = true;
    for (int n : plan.sizes) {
        // what an rk4 sub-step costs on this cloth, to size its reference runs
        const Trial probe = simulate(n, plan.stiffness.front(), core::Integrator::Rk4, 10, Stop::Never, 0.0);
        const double rk4PerSubstep = probe.cpuSeconds / (kProbeSteps * 10.0);
        const int steps = static_cast<int>(std::lround(kStiffDuration / kStiffTimeStep));
        for (double k : plan.stiffness) {
            Cell cell(n, k, plan);
            const core::SceneDesc scene = stiffCloth(n, k, core::Integrator::SymplecticEuler, 1);
            const std::shared_ptr<const core::Model> model = core::compileModel(scene);
            const core::StabilityLimit limit = core::stabilityLimit(*model, core::makeState(*model, scene));
            const double h = kStiffTimeStep;
            const int seCount = core::stableSubsteps(limit, core::Integrator::SymplecticEuler, h, 1, kMostSubsteps);
            const int rk4Stable = core::stableSubsteps(limit, core::Integrator::Rk4, h, 1, kMostSubsteps);

            // the reference
            const double affordable = plan.referenceBudget / (steps * rk4PerSubstep);
            int rk4Count = 0;
            for (int c : plan.ladder)
                if (c >= rk4Stable && c <= affordable)
                    rk4Count = c;
            if (rk4Count == 0 && rk4Stable <= affordable)
                rk4Count = rk4Stable;
            std::optional<Trial> reference;
            QString referenceName = QStringLiteral("none");
            if (rk4Count > 0) {
                reference = cell.run(core::Integrator::Rk4, rk4Count, Stop::Never);
                referenceName = QStringLiteral("rk4 x%1").arg(rk4Count);
            } else {
                const Trial &se = cell.run(core::Integrator::SymplecticEuler, seCount, Stop::Never);
                if (se.complete) {
                    reference = se;
                    referenceName = QStringLiteral("symplectic-euler x%1").arg(seCount);
                }
            }
            const bool soft = reference && reference->complete && !reference->stretchHeld();
            out << QStringLiteral("%1x%1, k = %2 N/m: %3 particles, %4 springs; stability counts: symplectic-euler "
                                  "%5, rk4 %6; reference %7")
                       .arg(n)
                       .arg(k, 0, 'g', 2)
                       .arg(model->particleCount())
                       .arg(model->springCount())
                       .arg(seCount)
                       .arg(rk4Stable)
                       .arg(referenceName);
            if (reference)
                out << QStringLiteral(" (stretch %1, kinetic energy at 1 s %2 J)")
                           .arg(percent(reference->maxStretch))
                           .arg(reference->kineticEnd, 0, 'g', 4);
            if (soft)
                out << ": the cloth itself stretches past 1%, nothing searched";
            out << '\n';
            out.flush();

            Row blank;
            blank.size = n;
            blank.particles = model->particleCount();
            blank.springs = model->springCount();
            blank.stiffness = k;
            blank.reference = referenceName;
            for (core::Integrator integrator : kCompared) {
                std::vector<Row> found;
                if (soft) {
                    for (Criterion criterion : kCriteria) {
                        Row row = blank;
                        row.integrator = integrator;
                        row.criterion = criterion;
                        row.status = Status::Soft;
                        found.push_back(row);
                    }
                } else {
                    found = search(cell, integrator, seCount, blank);
                }
                for (std::size_t i = 0; i < found.size(); ++i) {
                    Row &row = found[i];
                    if (row.status == Status::Met) {
                        const Row *same = i > 0 && found[0].status == Status::Met && found[0].substeps == row.substeps
                                              ? &found[0]
                                              : nullptr;
                        if (same) {
                            row.cost = same->cost;
                            row.runs = same->runs;
                            row.twoThreads = same->twoThreads;
                        } else {
                            repeatable = timeRow(row, plan) && repeatable;
                            if (unconditionallyStable(integrator) && n == plan.twoThreadSize)
                                timeTwoThreads(row, plan);
                        }
                    }
                    if (row.trial && row.trial->complete && reference && reference->kineticEnd > 0.0)
                        row.kineticRatio = row.trial->kineticEnd / reference->kineticEnd;
                    out << tableLine(row, plan) << '\n';
                    out.flush();
                    rows.push_back(std::move(row));
                }
            }
        }
    }
    core::setThreadCount(restoreThreads);

    // the summary: the table and the targets
    QString summary = header;
    QTextStream sum(&summary);
    sum << '\n' << tableHeader();
    for (const Row &row : rows)
        sum << tableLine(row, plan) << '\n';
    sum << (repeatable ? "every repetition ended on the same positions as the first, to the bit\n"
                       : "REPEATED runs ended on different positions: the figures are of the first run\n");
    sum << '\n' << targets(rows, plan);
    sum << linearSolves(options.quick ? 8 : 64, options.quick ? 1e6 : 1e7, options.quick ? 3 : 5);
    sum << "run time: " << clock.text() << "; load average at the end: " << loadText() << '\n';
    sum.flush();
    out << '\n' << summary.mid(header.size());
    out.flush();

    // the files
    if (!writeCsv(dir.filePath(QStringLiteral("stiff.csv")), rows, out))
        return 1;
    QSaveFile text(dir.filePath(QStringLiteral("stiff.txt")));
    if (!text.open(QIODevice::WriteOnly | QIODevice::Text) || text.write(summary.toUtf8()) < 0 || !text.commit()) {
        out << "springlab-bench: cannot write " << text.fileName() << '\n';
        return 1;
    }
    std::vector<StiffPoint> points;
    for (const Row &row : rows)
        if (row.criterion == Criterion::Stretch && (row.cost || row.estimate))
            points.push_back({row.integrator, row.size, row.stiffness, row.cost ? *row.cost : *row.estimate,
                              !row.cost.has_value()});
    const QString note =
        QStringLiteral("%1; load average %2 at the start. Cost: CPU s of the step calls per simulated s, 1 thread, "
                       "at the fewest sub-steps (of h = 0.01 s) that keep every structural spring within 1% over "
                       "1 s of draping. Hollow: capped, predicted from the first steps. Missing: no count up to %3 "
                       "sub-steps, or a cloth that itself stretches past 1%.")
            .arg(machine)
            .arg(loadStart.section(QLatin1Char(' '), 0, 0))
            .arg(plan.ladder.back());
    const QImage plot = drawStiff(QStringLiteral("Stiff cloth: cost of staying within 1% stretch"), points, note);
    const QString plotPath = dir.filePath(QStringLiteral("stiff.png"));
    if (!plot.save(plotPath)) {
        out << "springlab-bench: cannot write " << plotPath << '\n';
        return 1;
    }
    out << QStringLiteral("wrote %1 rows to stiff.csv, stiff.txt and stiff.png\n").arg(rows.size());
    return 0;
}

}  // namespace bench
