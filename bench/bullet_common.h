#pragma once
// What both Bullet peers (bullet_cloth.cpp, bullet_spheres.cpp) need: the check that the Bullet
// headers and the library CMake linked agree on btScalar, and Eigen's vectors in Bullet's.

#include <Eigen/Core>
#include <LinearMath/btScalar.h>
#include <LinearMath/btVector3.h>

// the precision CMake linked must be the one the headers were read with, or every Bullet type
// has another layout than the library's
static_assert(sizeof(btScalar) == (SPRINGLAB_BULLET_DOUBLE ? sizeof(double) : sizeof(float)),
              "btScalar does not match the Bullet library CMake linked");

namespace bench {

inline btVector3 toBullet(const Eigen::Vector3d &v)
{
    return {static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()), static_cast<btScalar>(v.z())};
}

}  // namespace bench
