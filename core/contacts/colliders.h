#pragma once
// Colliders: the scene's planes as the contact solver reads them. A plane is unbounded and
// one-sided (a half-space: whatever lies behind it is pushed to the front), unbounded and
// two-sided (a thin wall: a particle stays on the side it came from), or a bounded rectangle of
// its plane (a two-sided sheet with edges and corners, for tables, shelves and boxes).

#include "core/model/scene.h"

#include <Eigen/Core>

namespace core {

struct Collider {
    Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  // unit
    double offset = 0.0;                                // m, n·p = offset
    bool twoSided = false;                              // true for every rectangle
    bool bounded = false;                               // a rectangle
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();   // m, the rectangle's, on the plane
    Eigen::Vector3d axisU = Eigen::Vector3d::UnitX();   // unit, along the width
    Eigen::Vector3d axisV = Eigen::Vector3d::UnitZ();   // unit, normal × axisU, along the height
    double halfWidth = 0.0;                             // m
    double halfHeight = 0.0;                            // m
    double friction = 0.0;                              // μk of its contacts
    double staticFriction = 0.0;                        // μs of its contacts
    double rollingFriction = 0.0;                       // μr of its contacts
    double spinningFriction = 0.0;                      // about the normal
};

// the collider a plane compiles to, with the settings' friction where the plane has none
Collider makeCollider(const PlaneDesc &plane, const Settings &settings);

// the in-plane direction a plane's rectangle and the viewport's quad take when none is given:
// normal × y, or normal × x when the normal lies within about 26° of y
Eigen::Vector3d defaultPlaneAxis(const Eigen::Vector3d &normal);

// the side of the collider a point is on: +1 in front (or on it), -1 behind; a one-sided plane has
// only its front
double sideOf(const Collider &collider, const Eigen::Vector3d &point);

// a point's separation from the collider: the unit direction from the collider's nearest point
// towards the point (on the given side) and the distance along it, negative when the point lies
// behind the surface on that side
struct Separation {
    Eigen::Vector3d normal;
    double distance = 0.0;  // m
};
Separation separation(const Collider &collider, const Eigen::Vector3d &point, double side);

}  // namespace core
