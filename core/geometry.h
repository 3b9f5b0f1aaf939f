#pragma once
// Small geometric helpers shared by the springs and the contacts.

#include <Eigen/Core>
#include <cmath>
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

// the axis two coincident particles are separated along: a direction on the unit sphere picked
// from the pair's indices (a Fibonacci spiral of 1024 points), so that a crowd of particles
// created at one point spreads out in every direction instead of along a single line
inline Eigen::Vector3d coincidentAxis(int i, int j)
{
    constexpr int kPoints = 1024;
    const int k = static_cast<int>((static_cast<unsigned>(i) * 7919u + static_cast<unsigned>(j)) % kPoints);
    const double y = 1.0 - (2.0 * k + 1.0) / kPoints;
    const double ring = std::sqrt(1.0 - y * y);
    const double angle = 2.399963229728653 * k;  // the golden angle, rad
    return Eigen::Vector3d(ring * std::cos(angle), y, ring * std::sin(angle));
}

}  // namespace core
