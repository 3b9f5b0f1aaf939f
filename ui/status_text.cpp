#include "status_text.h"

#include <QCoreApplication>

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

QString rateText(bool running, double realTimeFactor)
{
    if (!running)
        return tr("paused");
    if (realTimeFactor <= 0.0)
        return QStringLiteral("×…");
    if (realTimeFactor < kRealTimeTolerance)
        return tr("×%1 — slower than real time").arg(realTimeFactor, 0, 'f', 2);
    return QStringLiteral("×%1").arg(realTimeFactor, 0, 'f', 2);
}

QString stepsText(bool running, double stepsPerSecond)
{
    return running ? tr("%1 steps/s").arg(stepsPerSecond, 0, 'f', 0) : QString();
}

QString energyText(double joules)
{
    return tr("E = %1 J").arg(joules, 0, 'g', 6);
}

}  // namespace ui
