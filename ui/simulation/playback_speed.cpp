#include "playback_speed.h"

#include "session/simulation_runner.h"

#include <QCoreApplication>

#include <array>

namespace ui {

std::span<const PlaybackSpeed> playbackSpeeds()
{
    static constexpr std::array<PlaybackSpeed, 7> speeds{{
        {0.25, "actionSpeedQuarter"},
        {0.5, "actionSpeedHalf"},
        {1.0, "actionSpeedRealTime"},
        {2.0, "actionSpeedTwice"},
        {4.0, "actionSpeedFourTimes"},
        {8.0, "actionSpeedEightTimes"},
        {SimulationRunner::kAsFastAsItGoes, "actionSpeedAsFast"},
    }};
    return speeds;
}

QString speedText(double factor)
{
    if (!(factor > SimulationRunner::kAsFastAsItGoes))
        return QCoreApplication::translate("ui::PlaybackSpeed", "As fast as it goes");
    if (factor == 0.25)
        return QStringLiteral("×¼");
    if (factor == 0.5)
        return QStringLiteral("×½");
    return QStringLiteral("×%1").arg(factor);
}

}  // namespace ui
