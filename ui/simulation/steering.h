#pragma once
// Steering: the force the arrow keys put on a scene's steerable particle (the pool's cue ball), as
// in the handout's pool: left and right turn its direction in the horizontal plane, up and down
// change its strength. The strength is counted in levels of a fixed acceleration, so the same key
// presses push a heavy ball as hard as a light one. Qt-free.

#include <Eigen/Core>

namespace ui {

struct Steering {
    static constexpr double kTurnDegrees = 15.0;           // per left or right press
    static constexpr double kAccelerationPerLevel = 1.0;   // m/s² per up press
    static constexpr int kMaxLevel = 20;

    double angle = 0.0;  // degrees: 0 along +x, counter-clockwise seen from above (+y)
    int level = 0;       // 0 (no force) .. kMaxLevel

    void turn(int presses);    // positive: left (counter-clockwise)
    void change(int presses);  // positive: stronger

    Eigen::Vector3d direction() const;  // unit, horizontal
    double strength(double mass) const;  // N, for a particle of this mass (kg)
    Eigen::Vector3d force(double mass) const;  // N
};

}  // namespace ui
