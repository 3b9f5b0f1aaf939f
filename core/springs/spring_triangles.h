#pragma once
// Spring triangles: the triangles of a spring mesh, so that a cloth can be drawn as a sheet rather
// than as beads and lines. A triangle is three particles joined pairwise by springs. A grid cell
// with both diagonals (a cloth's shear springs) holds four such triangles that cover it twice, and
// a cloth's bend springs make thin and long ones across two cells; so the triangles are taken
// smallest first, and one is left out when it lies on a side already taken by another triangle
// folded onto it (their far corners on the same side of that spring): each cell is then covered
// once, by two triangles of two neighbour springs and one diagonal. Triangles whose corners lie on
// a line (a row and its bend spring) are left out. The shapes are judged at the scene's positions,
// once per scene (compileModel), and the triangles are turned so that neighbours agree, which
// smooth normals need. A triangle is drawn while none of its three springs has broken.

#include "core/model/scene.h"

#include <vector>

namespace core {

struct SpringTriangles {
    // three particles per triangle, counter-clockwise seen from the side its normal points to;
    // neighbouring triangles are turned alike
    std::vector<int> corners;
    // the springs of its sides, three per triangle: side s joins corners s and (s + 1) % 3
    std::vector<int> sides;
    // the ends a and b of every spring of the scene, two per spring, so that a drawing can tell
    // the springs that lie within the sheet (a cloth's bend springs are no triangle's sides)
    std::vector<int> springEnds;

    int count() const { return static_cast<int>(corners.size() / 3); }
    bool empty() const { return corners.empty(); }
};

// the triangles of the scene's spring mesh, judged at its particles' positions
SpringTriangles findSpringTriangles(const SceneDesc &scene);

}  // namespace core
