#pragma once
// What the contacts benchmark reads off a run, the same way for either engine: from positions,
// velocities, masses and radii alone, so the core and Bullet are judged by one ruler.

#include "core/model/scene.h"

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace bench {

// J, ½ Σ m v² over the particles given (one column each)
double kineticEnergy(const Eigen::Matrix3Xd &velocity, const Eigen::VectorXd &mass);

// m, the deepest overlap of two balls, or of a ball and one of the scene's planes (infinite,
// one-sided: a ball behind a plane overlaps it by its whole distance behind it); 0 when none
double deepestOverlap(const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius,
                      const std::vector<core::PlaneDesc> &planes);

// the slope of a heap of balls on the floor y = 0 about the vertical axis through (x, z) = axis
struct Repose {
    // degrees: a least-squares line through the heap's outer surface, height against distance from
    // the axis, both in bins of one diameter: each bin's highest ball top, over the bins from the
    // second outwards while they hold a ball above the first layer (a top above 3 r); empty when
    // fewer than 3 bins qualify
    std::optional<double> fitDegrees;
    int flankBins = 0;        // the bins the line was fitted through
    // degrees: atan(height / base radius), the heap as a cone
    double coneDegrees = 0.0;
    double height = 0.0;      // m, the highest ball top above the floor
    double baseRadius = 0.0;  // m, the 95th percentile of the balls' distances from the axis, plus r
};
Repose reposeAngle(const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius, const Eigen::Vector2d &axis);

}  // namespace bench
