#pragma once
// SteeringArrow: the push the arrow keys put on the steerable particle (the pool's cue ball),
// drawn in the view as an arrow from the particle's centre along the push, so that the player sees
// where the ball will be pushed and how hard before it moves. Its length beyond the ball grows with
// the push, up to kArrowRadii radii at the strongest; with no push (or nothing to steer) there is
// no arrow. The arrow is packed as line vertices for the viewport's line program, with no GL, so
// that the packing can be unit-tested; the viewport draws it over everything else.

#include "render_data.h"

#include "core/model/snapshot.h"

#include <QVector3D>

#include <vector>

namespace ui {

inline constexpr Rgb kSteeringColour{1.00f, 0.25f, 0.85f};  // magenta: no other part of the view has it
inline constexpr float kSteeringArrowPixels = 3.0f;        // line width in the view's logical pixels

struct SteeringArrow {
    // how far past the ball's surface the arrow reaches at the strongest push, in radii of the ball
    static constexpr float kArrowRadii = 4.0f;

    int particle = -1;     // the steered particle, an index into the snapshot (-1: none)
    QVector3D direction;   // unit: the way the push points
    float strength = 0.0f;  // the push over the strongest push, 0 .. 1

    bool visible() const { return particle >= 0 && strength > 0.0f; }
    bool operator==(const SteeringArrow &) const = default;
};

// two vertices per line (xyz, rgba), as packSpringLines makes them: the shaft from the particle's
// centre to r (1 + kArrowRadii strength) along the direction, and two barbs at its tip, turned
// towards the eye so that the head reads from any side; nothing when the arrow is hidden or the
// snapshot has no such particle
std::vector<float> packSteeringArrow(const SteeringArrow &arrow, const core::Snapshot &snapshot, const QVector3D &eye);

}  // namespace ui
