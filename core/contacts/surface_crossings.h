#pragma once
// Crossings of a sheet: an edge of a sheet passing through a triangle of a sheet (the same or
// another) that shares none of its particles. A configuration without crossings is what the
// triangle collisions keep (triangle_collisions.cpp); the tests and the cloth-contacts benchmark
// count them at every step.

#include "core/contacts/cloth_surface.h"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace core {

// the crossings at positions x, of the triangles and edges that no broken spring has torn
// (springBroken as State::springBroken: empty when none can break)
int countCrossings(const ClothSurface &surface, const Eigen::Matrix3Xd &x, const std::vector<std::uint8_t> &springBroken);

// whether segment p q passes through the inside of triangle a b c (touching counts as not)
bool segmentCrossesTriangle(const Eigen::Vector3d &p, const Eigen::Vector3d &q, const Eigen::Vector3d &a,
                            const Eigen::Vector3d &b, const Eigen::Vector3d &c);

}  // namespace core
