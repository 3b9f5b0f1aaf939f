#include "steering.h"

#include "core/model/model.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ui {

void Steering::turn(int presses)
{
    angle = std::fmod(angle + presses * kTurnDegrees, 360.0);
    if (angle < 0.0)
        angle += 360.0;
}

void Steering::change(int presses)
{
    level = std::clamp(level + presses, 0, kMaxLevel);
}

void Steering::changeCue(int presses)
{
    cueLevel = std::clamp(cueLevel + presses, 1, kMaxCueLevel);
}

void Steering::raiseCue(int presses)
{
    cueHeight = std::clamp(cueHeight + presses, -kMaxCueHeight, kMaxCueHeight);
}

void Steering::apply(const Change &keys)
{
    turn(keys.turn);
    change(keys.push);
    changeCue(keys.cue);
    raiseCue(keys.height);
}

Eigen::Vector3d Steering::direction() const
{
    // counter-clockwise seen from +y turns +x towards -z
    const double radians = angle * std::numbers::pi / 180.0;
    return {std::cos(radians), 0.0, -std::sin(radians)};
}

double Steering::strength(double mass) const
{
    return level * kAccelerationPerLevel * mass;
}

Eigen::Vector3d Steering::force(double mass) const
{
    return strength(mass) * direction();
}

double Steering::strikeSpeed() const
{
    return cueLevel * kStrikeSpeedPerLevel;
}

Steering::Stroke Steering::stroke(double radius) const
{
    // an impulse J = m s d through the point h up from the centre: Δv = s d, and Δω = I⁻¹ (h up × J)
    // with I = (2/5) m r², so the mass drops out. At h = 2r/5 the ball leaves rolling (Δω r = s)
    Stroke stroke;
    const double speed = strikeSpeed();
    stroke.velocityChange = speed * direction();
    if (radius > 0.0) {
        const double height = cueHeight / 10.0 * radius;
        stroke.spinChange = height * speed / (core::kSolidSphereInertia * radius * radius) *
                            Eigen::Vector3d::UnitY().cross(direction());
    }
    return stroke;
}

}  // namespace ui
