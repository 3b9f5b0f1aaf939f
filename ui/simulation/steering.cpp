#include "steering.h"

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

}  // namespace ui
