#include "status_text.h"

#include "ui/document/scene_edits.h"
#include "ui/simulation/playback_speed.h"

#include "session/simulation_runner.h"

#include "core/model/parameters.h"
#include "core/integrators/stability.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <iterator>

namespace ui {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("ui::StatusText", text);
}

}  // namespace

QString timeText(double seconds)
{
    return tr("t = %1 s").arg(seconds, 0, 'f', 3);
}

QString cueHeightText(int tenths, bool brief)
{
    if (tenths == 0)
        return brief ? tr("centre") : tr("at the centre");
    const QString height = QString::number(std::abs(tenths) / 10.0, 'g', 2);
    if (brief)
        return (tenths > 0 ? QStringLiteral("+%1r") : QStringLiteral("−%1r")).arg(height);
    return (tenths > 0 ? tr("%1 r above the centre") : tr("%1 r below the centre")).arg(height);
}

QString steerText(double pushNewtons, double degrees, double cueSpeed, int cueTenths)
{
    return tr("push %1 N %2°; cue %3 m/s %4")
        .arg(pushNewtons, 0, 'g', 4)
        .arg(degrees, 0, 'f', 0)
        .arg(cueSpeed, 0, 'g', 3)
        .arg(cueHeightText(cueTenths, true));
}

namespace {

// a rate as it reads best: whole from 10 up, two significant digits below ("4.2", "0.19"),
// so that a slow one never reads 0
QString rateFigure(double perSecond)
{
    return perSecond >= 10.0 ? QString::number(perSecond, 'f', 0) : QString::number(perSecond, 'g', 2);
}

}  // namespace

QString rateText(bool running, double realTimeFactor, double speed)
{
    if (!running)
        return tr("paused");
    if (realTimeFactor <= 0.0)
        return QStringLiteral("×…");
    // two decimals, or two significant digits where two decimals would read ×0.00
    const QString factor = realTimeFactor >= 0.1 ? QString::number(realTimeFactor, 'f', 2)
                                                 : QString::number(realTimeFactor, 'g', 2);
    if (!(speed > SimulationRunner::kAsFastAsItGoes))
        return tr("×%1 — as fast as it goes").arg(factor);
    if (realTimeFactor < kRealTimeTolerance * speed)
        return speed == 1.0 ? tr("×%1 — slower than real time").arg(factor)
                            : tr("×%1 — slower than the %2 asked").arg(factor, speedText(speed));
    return QStringLiteral("×%1").arg(factor);
}

QString stepsText(bool running, double stepsPerSecond, std::uint64_t owed)
{
    // paused with a Step still being taken (a slow scene: seconds at 10⁶ particles)
    if (!running && owed > 0)
        return owed == 1 ? tr("taking a step…") : tr("taking %1 steps…").arg(owed);
    if (!running)
        return QString();
    return stepsPerSecond > 0.0 ? tr("%1 steps/s").arg(rateFigure(stepsPerSecond)) : tr("… steps/s");
}

QString framesText(bool running, double framesPerSecond)
{
    if (!running)
        return QString();
    return framesPerSecond > 0.0 ? tr("%1 frames/s").arg(rateFigure(framesPerSecond)) : tr("… frames/s");
}

QString energyText(double joules)
{
    return tr("E = %1 J").arg(joules, 0, 'g', 6);
}

QString energyText(const core::Energies &energies)
{
    const double total = energies.total();
    const double parts = std::abs(energies.kinetic) + std::abs(energies.gravitational) + std::abs(energies.spring);
    const bool roundOff = std::abs(total) < kRoundOffJoules || std::abs(total) <= 1e-9 * parts;
    return energyText(roundOff ? 0.0 : total);
}

QString scientificText(double value, int digits)
{
    // Qt writes "3.0e-06": drop the mantissa's trailing zeros, the exponent's plus sign and its
    // leading zeros
    QString text = QString::number(value, 'e', std::max(0, digits - 1));
    const qsizetype e = text.indexOf(QLatin1Char('e'));
    if (e < 0)
        return text;
    QString exponent = text.mid(e + 1);
    QString mantissa = text.left(e);
    if (mantissa.contains(QLatin1Char('.'))) {
        while (mantissa.endsWith(QLatin1Char('0')))
            mantissa.chop(1);
        if (mantissa.endsWith(QLatin1Char('.')))
            mantissa.chop(1);
    }
    const bool negative = exponent.startsWith(QLatin1Char('-'));
    exponent.remove(0, exponent.startsWith(QLatin1Char('-')) || exponent.startsWith(QLatin1Char('+')) ? 1 : 0);
    while (exponent.size() > 1 && exponent.startsWith(QLatin1Char('0')))
        exponent.remove(0, 1);
    if (exponent == QLatin1String("0"))
        return mantissa;
    return mantissa + QLatin1Char('e') + (negative ? QStringLiteral("-") : QString()) + exponent;
}

QString durationText(double seconds)
{
    // the unit that puts the figure between 0.5 and 1000, then two significant digits
    struct Unit {
        double size;
        const char *name;
    };
    constexpr Unit kUnits[] = {{1.0, "s"}, {1e-3, "ms"}, {1e-6, "µs"}, {1e-9, "ns"}};
    Unit unit = kUnits[std::size(kUnits) - 1];
    for (const Unit &candidate : kUnits) {
        if (seconds >= 0.5 * candidate.size) {
            unit = candidate;
            break;
        }
    }
    const double figure = seconds / unit.size;
    const QString number = figure >= 100.0 ? QString::number(figure, 'f', 0) : QString::number(figure, 'g', 2);
    return number + QLatin1Char(' ') + QString::fromUtf8(unit.name);
}

QString localErrorText(std::optional<double> metres)
{
    if (!metres)
        return tr("local error ≈ ?");
    return tr("local error ≈ %1 m/step").arg(scientificText(*metres));
}

QString driftText(const core::Energies &initial, double current)
{
    // a signed number: one decimal from 0.1 up, whole from 10 up, scientific below 0.001
    auto signedText = [](double value) {
        if (value == 0.0)
            return QStringLiteral("0");
        const QString sign = value > 0.0 ? QStringLiteral("+") : QStringLiteral("-");
        const double size = std::abs(value);
        if (size >= 10.0)
            return sign + QString::number(size, 'f', 0);
        if (size >= 0.1)
            return sign + QString::number(size, 'f', 1);
        if (size >= 1e-3)
            return sign + QString::number(size, 'g', 2);
        return sign + scientificText(size);
    };
    const double start = initial.total();
    const double parts = std::abs(initial.kinetic) + std::abs(initial.gravitational) + std::abs(initial.spring);
    const double change = current - start;
    // joules when the start is nothing beside its parts (they cancel), or beside the change: a
    // start of rounding noise, 1e-31 J, would give a 30-digit percentage
    if (!(std::abs(start) > kZeroEnergyShare * parts) || !(std::abs(change) * kZeroEnergyShare < std::abs(start)))
        return tr("ΔE = %1 J").arg(signedText(change));
    return tr("ΔE = %1 %").arg(signedText(100.0 * change / std::abs(start)));
}

QString selectionText(std::size_t particles, std::size_t springs)
{
    const auto count = [](std::size_t n, const QString &one, const QString &many) {
        return QString::number(n) + QLatin1Char(' ') + (n == 1 ? one : many);
    };
    QStringList parts;
    if (particles > 0)
        parts += count(particles, tr("particle"), tr("particles"));
    if (springs > 0)
        parts += count(springs, tr("spring"), tr("springs"));
    if (parts.isEmpty())
        return tr("Nothing selected");
    return parts.join(tr(" and ")) + tr(" selected");
}

QString lengthText(double metres)
{
    return QString::number(metres, 'g', 4) + tr(" m");
}

QString distanceText(const Eigen::Vector3d &delta)
{
    const auto number = [](double value) { return QString::number(value, 'g', 6); };
    return tr("%1 m (Δx %2, Δy %3, Δz %4)")
        .arg(number(delta.norm()), number(delta.x()), number(delta.y()), number(delta.z()));
}

QString distanceLines(const Eigen::Vector3d &delta)
{
    return distanceText(delta).replace(QStringLiteral(" ("), QStringLiteral("\n("));
}

QString particleLimitText(const QString &notDone, std::size_t total)
{
    return tr("%1: the scene would have %2 particles, more than the %3 the editor allows; nothing was changed")
        .arg(notDone)
        .arg(total)
        .arg(kMaxSceneParticles);
}

QString planText(const core::AccuracyPlan &plan)
{
    const QString tolerance = scientificText(plan.tolerance);
    if (plan.candidates.empty())
        return tr("No scene to plan for");
    const core::PlanCandidate *pick = plan.pick();
    if (!pick)
        return tr("No fixed-step integrator meets %1 m/step within %2 substeps; try a looser tolerance or a "
                  "smaller time step")
            .arg(tolerance)
            .arg(core::parameterInfo(core::Parameter::Substeps).maximum, 0, 'f', 0);
    int feasible = 0;
    for (const core::PlanCandidate &row : plan.candidates)
        feasible += row.feasible ? 1 : 0;
    const std::string_view name = core::integratorName(pick->integrator);
    const QString integrator = QString::fromLatin1(name.data(), qsizetype(name.size()));
    QString text = pick->substeps == 1 ? tr("%1 with 1 substep").arg(integrator)
                                       : tr("%1 with %2 substeps").arg(integrator).arg(pick->substeps);
    text += tr(": ≈ %1 m/step at %2 per simulated second")
                .arg(scientificText(pick->localError), durationText(pick->secondsPerSimulatedSecond));
    text += feasible == 1 ? tr(", the only integrator that meets %1 m/step").arg(tolerance)
                          : tr(", the cheapest of %1 integrators that meet %2 m/step").arg(feasible).arg(tolerance);
    if (pick->stabilityLimited)
        text += tr(" (the substeps are set by its stability limit)");
    return text;
}

StabilityNote stabilityNote(double maxSubStep, double subStep, double timeStep, core::Integrator integrator)
{
    const std::string_view name = core::integratorName(integrator);
    const QString integratorText = QString::fromUtf8(name.data(), qsizetype(name.size()));
    if (std::isinf(maxSubStep)) {
        if (integrator == core::Integrator::Xpbd)
            return {tr("xpbd has no explicit stability limit: its springs are constraints"), StabilityLevel::Safe};
        const bool implicit = integrator == core::Integrator::ImplicitEuler ||
                              integrator == core::Integrator::AdaptiveRk45 || core::isVariational(integrator);
        return {implicit ? tr("%1 is stable at any time step").arg(integratorText)
                         : tr("No springs: no stability limit on the time step"),
                StabilityLevel::Safe};
    }
    if (!(maxSubStep > 0.0))
        return {tr("%1 is unstable at any time step on undamped springs: use "
                                                  "symplectic-euler or projective")
                    .arg(integratorText),
                StabilityLevel::Past};

    const double share = subStep / maxSubStep;
    StabilityNote note;
    note.text = tr("Stable sub-step ≤ %1; each is %2")
                    .arg(durationText(maxSubStep), durationText(subStep));
    if (share > 1.0) {
        const double substeps = std::ceil(timeStep / (core::kStableShare * maxSubStep));
        note.level = StabilityLevel::Past;
        note.text += tr(", %1× over: use ≥ %2 substeps or projective")
                         .arg(share, 0, 'g', 2)
                         .arg(substeps, 0, 'f', 0);
    } else {
        note.level = share >= kNearStabilityShare ? StabilityLevel::Near : StabilityLevel::Safe;
        note.text += tr(" (%1 % of it)").arg(std::round(100.0 * share), 0, 'f', 0);
    }
    return note;
}

}  // namespace ui
