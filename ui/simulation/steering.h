#pragma once
// Steering: the force the arrow keys put on a scene's steerable particle (the pool's cue ball), as
// in the handout's pool: left and right turn its direction in the horizontal plane, up and down
// change its strength. The strength is counted in levels of a fixed acceleration, so the same key
// presses push a heavy ball as hard as a light one. The cue strikes along the same direction, at a
// speed of its own (Shift+Up, Shift+Down), and meets the ball above or below its centre (Page Up,
// Page Down): an impulse through a point above the centre gives the ball topspin, below it backspin
// (about the horizontal axis across the stroke: 5 s h / (2 r²) for a solid ball struck at s from a
// height h). Qt-free.

#include <Eigen/Core>

namespace ui {

struct Steering {
    static constexpr double kTurnDegrees = 15.0;           // per left or right press
    static constexpr double kAccelerationPerLevel = 1.0;   // m/s² per up press
    static constexpr int kMaxLevel = 20;
    // the cue's speed, m/s per level: level 16 strikes at the pool break's 8 m/s
    static constexpr double kStrikeSpeedPerLevel = 0.5;
    static constexpr int kMaxCueLevel = 20;
    // tenths of the radius: a real cue slips off (miscues) past about half the radius
    static constexpr int kMaxCueHeight = 5;

    double angle = 0.0;  // degrees: 0 along +x, counter-clockwise seen from above (+y)
    int level = 0;       // 0 (no force) .. kMaxLevel
    int cueLevel = 8;    // 1 .. kMaxCueLevel: 4 m/s
    // where the cue meets the ball: tenths of its radius above (+) or below (-) the centre
    int cueHeight = 0;

    void turn(int presses);    // positive: left (counter-clockwise)
    void change(int presses);  // positive: stronger
    void changeCue(int presses);  // positive: a faster stroke
    void raiseCue(int presses);   // positive: higher, to ±kMaxCueHeight
    // one key's presses of each of the four
    struct Change {
        int turn = 0;
        int push = 0;
        int cue = 0;
        int height = 0;
    };
    void apply(const Change &keys);

    Eigen::Vector3d direction() const;  // unit, horizontal
    double strength(double mass) const;  // N, for a particle of this mass (kg)
    Eigen::Vector3d force(double mass) const;  // N

    // the cue's stroke on a solid ball of this radius (m): the velocity and spin it adds
    struct Stroke {
        Eigen::Vector3d velocityChange = Eigen::Vector3d::Zero();  // m/s, along direction()
        Eigen::Vector3d spinChange = Eigen::Vector3d::Zero();      // rad/s, about up × direction()
    };
    double strikeSpeed() const;  // m/s
    Stroke stroke(double radius) const;
};

}  // namespace ui
