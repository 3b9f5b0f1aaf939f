#pragma once
// Small geometric helpers shared by the springs and the contacts.

#include <Eigen/Core>

namespace core {

// the unit vector along d (of length `length`); when the two points coincide the direction is
// undefined, so a fixed axis (+y) stands in: deterministic, and never NaN
inline Eigen::Vector3d directionOr(const Eigen::Vector3d &d, double length)
{
    return length > 0.0 ? Eigen::Vector3d(d / length) : Eigen::Vector3d::UnitY();
}

}  // namespace core
