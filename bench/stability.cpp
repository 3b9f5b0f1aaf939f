// The stability benchmark. For each explicit integrator and each cell of a grid of link stiffness
// (N/m), particle mass (kg) and chain length, the largest stable time step is found by bisection
// (stable: the energy stays below 10× its start at every step of the trial, see stability_sweep.h)
// and set against the limit core/integrators/stability.h predicts from ω_max of the chain.
//
// - The chain's dynamics depend on k and m only through √(k/m), so the grid covers the limit over
//   many decades of time step; the ratio measured / theory should not move across it. Cells whose
//   trial bracket (twice the predicted limit) passes the largest time step a scene may have (1 s)
//   are skipped: nothing that soft can become unstable within the allowed steps.
// - Implicit Euler has no limit; it is run at 100× symplectic Euler's limit on every cell where
//   that step is allowed, for as many steps as a trial, and must stay stable.
#include "stability.h"

#include "bench_common.h"

#include "stability_plot.h"
#include "stability_sweep.h"

#include "core/model/parameters.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QSaveFile>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <vector>

namespace bench {

namespace {

constexpr core::Integrator kExplicit[] = {core::Integrator::SymplecticEuler, core::Integrator::ExplicitEuler,
                                          core::Integrator::VelocityVerlet, core::Integrator::Rk4};
constexpr double kImplicitFactor = 100.0;  // × symplectic Euler's limit

// the grid and the trials; --quick shrinks both
struct Grid {
    std::vector<double> stiffness;  // N/m
    std::vector<double> mass;       // kg
    std::vector<int> particles;
    LimitSearch search;
};

Grid gridFor(bool quick)
{
    Grid grid;
    grid.search.largestTimeStep = core::parameterInfo(core::Parameter::TimeStep).maximum;
    if (quick) {
        grid.stiffness = {1e1, 1e4, 1e7};
        grid.mass = {1e-3, 1e3};
        grid.particles = {2, 10};
        grid.search.steps = 1000;
        grid.search.relativeWidth = 2e-2;
        return grid;
    }
    grid.stiffness = {1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7};
    grid.mass = {1e-3, 1e-2, 1e-1, 1.0, 1e1, 1e2, 1e3};
    grid.particles = {2, 10};
    grid.search.steps = 100000;
    grid.search.relativeWidth = 1e-3;
    return grid;
}

struct Row {
    core::Integrator integrator;
    ChainCase chain;
    double theory = 0.0;    // s
    double measured = 0.0;  // s
    double ratio() const { return measured / theory; }
};



bool writeCsv(const QString &path, const std::vector<Row> &rows, QTextStream &out)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        out << "springlab-bench: cannot write " << path << '\n';
        return false;
    }
    QTextStream csv(&file);
    csv << "integrator,stiffness,mass,particles,theory_time_step,measured_time_step,ratio\n";
    for (const Row &row : rows)
        csv << nameOf(row.integrator) << ',' << QString::number(row.chain.stiffness, 'g', 6) << ','
            << QString::number(row.chain.mass, 'g', 6) << ',' << row.chain.particles << ','
            << QString::number(row.theory, 'g', 8) << ',' << QString::number(row.measured, 'g', 8) << ','
            << QString::number(row.ratio(), 'f', 4) << '\n';
    csv.flush();
    if (!file.commit()) {
        out << "springlab-bench: cannot write " << path << '\n';
        return false;
    }
    return true;
}

// min, median and max of the ratios of one integrator on one chain length
void printRatios(const std::vector<Row> &rows, core::Integrator integrator, int particles, int skipped,
                 QTextStream &out)
{
    std::vector<double> ratios;
    for (const Row &row : rows)
        if (row.integrator == integrator && row.chain.particles == particles)
            ratios.push_back(row.ratio());
    std::sort(ratios.begin(), ratios.end());
    out << QStringLiteral("  %1 %2 particles: ").arg(nameOf(integrator), -17).arg(particles, 2);
    if (ratios.empty()) {
        out << "no cell measured\n";
        return;
    }
    out << QStringLiteral("ratio %1 .. %2 (median %3) over %4 cells")
               .arg(ratios.front(), 0, 'f', 4)
               .arg(ratios.back(), 0, 'f', 4)
               .arg(ratios[ratios.size() / 2], 0, 'f', 4)
               .arg(ratios.size());
    if (skipped > 0)
        out << QStringLiteral(", %1 skipped (limit past the 1 s step)").arg(skipped);
    out << '\n';
}

}  // namespace

int runStability(const StabilityOptions &options, QTextStream &out)
{
    const std::optional<QDir> folder = outputFolder(options.outDir, out);
    if (!folder)
        return 1;
    const QDir &dir = *folder;
    const RunClock clock;
    const Grid grid = gridFor(options.quick);
    out << "machine: " << machineDescription() << '\n';
    if (options.quick)
        out << "stability --quick: a smoke test; short trials, coarse bisection\n";
    out << QStringLiteral("chains of %1 particles (the first pinned), links of %2 kg particles and %3 N/m springs "
                          "with damping ratio %4; %5 grid cells per integrator and chain\n")
               .arg(grid.particles.size() == 2 ? QStringLiteral("%1 and %2").arg(grid.particles[0]).arg(grid.particles[1])
                                               : QString::number(grid.particles.size()))
               .arg(QStringLiteral("%1..%2").arg(grid.mass.front()).arg(grid.mass.back()))
               .arg(QStringLiteral("%1..%2").arg(grid.stiffness.front()).arg(grid.stiffness.back()))
               .arg(kLinkDampingRatio)
               .arg(grid.stiffness.size() * grid.mass.size());
    out << QStringLiteral("stable: energy below %1x its start over %2 steps; bisection to %3 relative width\n")
               .arg(kEnergyGrowthLimit)
               .arg(grid.search.steps)
               .arg(grid.search.relativeWidth);
    out << "ratio = measured largest stable step / theoretical limit (core/integrators/stability.h)\n\n";
    out.flush();

    // every explicit integrator on every cell
    std::vector<Row> rows;
    std::vector<StabilityPoint> points;
    for (core::Integrator integrator : kExplicit) {
        const double start = cpuSeconds();
        for (int particles : grid.particles) {
            int skipped = 0;
            for (double stiffness : grid.stiffness)
                for (double mass : grid.mass) {
                    const ChainCase chain{stiffness, mass, particles};
                    const core::SceneDesc scene = stabilityChain(chain);
                    const double theory = theoreticalStep(scene, integrator);
                    const std::optional<double> measured =
                        measureStableStep(scene, integrator, theory, grid.search);
                    if (!measured) {
                        ++skipped;
                        continue;
                    }
                    rows.push_back({integrator, chain, theory, *measured});
                    points.push_back({integrator, particles, theory, *measured});
                }
            printRatios(rows, integrator, particles, skipped, out);
            out.flush();
        }
        out << QStringLiteral("  (%1 s CPU for %2)\n").arg(cpuSeconds() - start, 0, 'f', 0).arg(nameOf(integrator));
    }

    // implicit Euler at 100× symplectic Euler's limit, wherever that step is allowed
    int implicitRuns = 0, implicitStable = 0;
    for (int particles : grid.particles)
        for (double stiffness : grid.stiffness)
            for (double mass : grid.mass) {
                const core::SceneDesc scene = stabilityChain({stiffness, mass, particles});
                const double step =
                    kImplicitFactor * theoreticalStep(scene, core::Integrator::SymplecticEuler);
                if (!(step <= grid.search.largestTimeStep))
                    continue;
                ++implicitRuns;
                implicitStable +=
                    stableAt(scene, core::Integrator::ImplicitEuler, step, grid.search.steps) ? 1 : 0;
            }
    const QString implicitLine = QStringLiteral("implicit-euler at %1x symplectic-euler's limit: stable in %2 of %3 "
                                                "cells (%4 steps each)")
                                     .arg(kImplicitFactor)
                                     .arg(implicitStable)
                                     .arg(implicitRuns)
                                     .arg(grid.search.steps);
    out << '\n' << implicitLine << '\n';

    // the files
    if (!writeCsv(dir.filePath(QStringLiteral("stability.csv")), rows, out))
        return 1;
    const QImage plot = drawStabilityMap(QStringLiteral("Largest stable time step on spring chains, measured / theory"),
                                         points, implicitLine);
    const QString plotPath = dir.filePath(QStringLiteral("stability.png"));
    if (!plot.save(plotPath)) {
        out << "springlab-bench: cannot write " << plotPath << '\n';
        return 1;
    }
    out << QStringLiteral("wrote %1 rows to stability.csv, and stability.png\n").arg(rows.size());
    out << "run time: " << clock.text() << '\n';
    return 0;
}

}  // namespace bench
