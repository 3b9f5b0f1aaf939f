#pragma once
// Small geometric helpers shared by the springs and the contacts.

#include <Eigen/Core>
#include <limits>

namespace core {

// whether two points lie far enough apart for the direction between them to be computed: the
// reciprocal of a subnormal length overflows, so such lengths count as coincident points
inline bool apart(double length)
{
    return length >= std::numeric_limits<double>::min();
}

// the unit vector along d (of length `length`), by one division and three multiplications (the
// spring kernels do the same, to the bit); when the two points coincide the direction is
// undefined, so a fixed axis (+y) stands in: deterministic, and never NaN
inline Eigen::Vector3d directionOr(const Eigen::Vector3d &d, double length)
{
    return apart(length) ? Eigen::Vector3d(d * (1.0 / length)) : Eigen::Vector3d::UnitY();
}

}  // namespace core
