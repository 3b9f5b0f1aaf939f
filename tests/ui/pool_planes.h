#pragma once
// The pool example's planes, for the tests of what is drawn and framed around them: a floor at
// y = 0 and four walls 5 m from the middle, facing in.

#include "core/model/scene.h"

#include <vector>

namespace test {

inline std::vector<core::PlaneDesc> poolPlanes()
{
    std::vector<core::PlaneDesc> planes(5);
    planes[0].normal = {0.0, 1.0, 0.0};
    const Eigen::Vector3d walls[] = {{1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int k = 0; k < 4; ++k) {
        planes[std::size_t(k + 1)].normal = walls[k];
        planes[std::size_t(k + 1)].offset = -5.0;
    }
    return planes;
}

}  // namespace test
