#pragma once
// Reference problems with closed-form solutions, for the accuracy tests and benchmark. Each comes
// as a scene generator and the exact answer it should produce.

#include "core/model/scene.h"

namespace core {

// 1. a particle on a damped spring to a pinned anchor at the origin, moving along x, no gravity:
//    m u'' = -k u - kc u', u the stretch of the spring
struct OscillatorOptions {
    double mass = 1.0;          // kg
    double stiffness = 100.0;   // N/m
    double damping = 1.0;       // N·s/m (underdamped: below 2 √(k m))
    double restLength = 1.0;    // m
    double displacement = 0.5;  // m, u(0)
    double speed = 0.0;         // m/s, u'(0)
};
SceneDesc makeOscillator(const OscillatorOptions &options);
// the stretch u(t) and its rate u'(t) of the exact solution
double oscillatorStretch(const OscillatorOptions &options, double t);
double oscillatorRate(const OscillatorOptions &options, double t);

// 2. a ball dropped from rest onto the floor y = 0 with restitution e, no drag: the times of the
//    impacts and the heights of the bounces
struct BounceOptions {
    double height = 1.0;       // m, of the centre
    double radius = 0.1;       // m
    double restitution = 0.8;
    double gravity = 9.81;     // m/s², pointing down
};
SceneDesc makeBounce(const BounceOptions &options);
double bounceImpactTime(const BounceOptions &options, int impact);  // s, impact 0 the first
double bounceApexHeight(const BounceOptions &options, int bounce);  // m, centre height after impact `bounce`

// 3. two particles in a head-on collision along x, no gravity: the velocities after contact
struct HeadOnOptions {
    double mass1 = 1.0, mass2 = 3.0;       // kg
    double speed1 = 2.0, speed2 = -1.0;    // m/s along x
    double radius = 0.1;                   // m, both
    double gap = 0.3;                      // m between the surfaces at t = 0
    double restitution = 1.0;
};
SceneDesc makeHeadOn(const HeadOnOptions &options);
double headOnSpeedAfter(const HeadOnOptions &options, int particle);  // m/s along x

}  // namespace core
