#pragma once
// The speeds a playing run can go at, as the Simulation menu and the toolbar offer them: a multiple
// of real time (¼ to 8), or as fast as the core goes (SimulationRunner::kAsFastAsItGoes), each frame
// shown as it comes. Playing faster than real time fills the timeline ahead of watching it, as a
// bake does; slower shows a fast event. The speed changes how many steps a second of wall time
// asks for, never the steps themselves.

#include <QString>

#include <span>

namespace ui {

struct PlaybackSpeed {
    double factor;           // simulated seconds per wall-clock second; 0: as fast as it goes
    const char *objectName;  // of its menu action, for the tests and for scripts
};

// ×¼, ×½, ×1, ×2, ×4, ×8 and as fast as it goes, in that order
std::span<const PlaybackSpeed> playbackSpeeds();
// the speed as the menu and the toolbar name it: "×¼", "×2", "As fast as it goes"
QString speedText(double factor);

}  // namespace ui
