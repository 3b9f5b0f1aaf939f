#include "core/contacts/colliders.h"

#include "core/model/validate.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace core {

Eigen::Vector3d defaultPlaneAxis(const Eigen::Vector3d &normal)
{
    const Eigen::Vector3d helper = std::abs(normal.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
    return normal.cross(helper).normalized();
}

Collider makeCollider(const PlaneDesc &plane, const Settings &settings)
{
    Collider c;
    c.normal = unitNormal(plane.normal);
    c.offset = plane.offset;
    c.bounded = plane.bounded();
    c.twoSided = plane.twoSided || c.bounded;
    c.friction = plane.friction.value_or(settings.friction);
    c.staticFriction = plane.friction ? *plane.friction : settings.staticFriction.value_or(settings.friction);
    c.rollingFriction = plane.rollingFriction.value_or(settings.rollingFriction);
    c.spinningFriction = plane.spinningFriction.value_or(settings.spinningFriction);
    if (c.bounded) {
        // the given axis projected onto the plane; along the normal (or zero) it says nothing
        const Eigen::Vector3d along = plane.axis - plane.axis.dot(c.normal) * c.normal;
        c.axisU = along.norm() > 1e-9 * std::max(1.0, plane.axis.norm()) ? along.normalized()
                                                                        : defaultPlaneAxis(c.normal);
        c.axisV = c.normal.cross(c.axisU);
        c.centre = plane.centre - (c.normal.dot(plane.centre) - c.offset) * c.normal;
        c.halfWidth = 0.5 * plane.size[0];
        c.halfHeight = 0.5 * plane.size[1];
    }
    return c;
}

double sideOf(const Collider &collider, const Eigen::Vector3d &point)
{
    if (!collider.twoSided)
        return 1.0;
    return collider.normal.dot(point) - collider.offset < 0.0 ? -1.0 : 1.0;
}

Separation separation(const Collider &collider, const Eigen::Vector3d &point, double side)
{
    const double height = collider.normal.dot(point) - collider.offset;
    if (!collider.bounded)
        return {side * collider.normal, side * height};

    // the nearest point of the rectangle: inside its outline the point faces the sheet; outside it
    // the nearest point lies on an edge or a corner, and the direction to it is the contact normal
    const Eigen::Vector3d local = point - collider.centre;
    const double u = collider.axisU.dot(local);
    const double v = collider.axisV.dot(local);
    const double cu = std::clamp(u, -collider.halfWidth, collider.halfWidth);
    const double cv = std::clamp(v, -collider.halfHeight, collider.halfHeight);
    if (cu == u && cv == v)
        return {side * collider.normal, side * height};
    const Eigen::Vector3d nearest = collider.centre + cu * collider.axisU + cv * collider.axisV;
    const Eigen::Vector3d d = point - nearest;
    const double distance = d.norm();
    if (!(distance > 0.0))
        return {side * collider.normal, 0.0};
    return {d / distance, distance};
}

}  // namespace core
