#pragma once
// Render data: a core::Snapshot turned into the flat float arrays the viewport uploads, with no GL,
// so that the packing can be unit-tested. Positions need no packing (the snapshot's xyz floats are
// streamed as they are); the particle style (radius, colour, marks) changes rarely and is packed
// only when its inputs change; spring lines and the scene's decorations (grid, axes, planes) are
// packed as line or triangle vertices of position and colour.

#include "core/model/scene.h"
#include "core/model/snapshot.h"

#include <QVector3D>

#include <array>
#include <cstdint>
#include <vector>

namespace ui {

using Rgb = std::array<float, 3>;

// the palette, linear 0..1
inline constexpr Rgb kBackgroundColour{0.16f, 0.17f, 0.20f};
inline constexpr Rgb kFreeColour{0.93f, 0.60f, 0.22f};      // amber
inline constexpr Rgb kPinnedColour{0.56f, 0.38f, 0.88f};    // violet, with a dark ring
inline constexpr Rgb kSelectedColour{0.25f, 0.88f, 1.00f};  // cyan, with a bright rim
inline constexpr Rgb kHoverColour{1.00f, 0.95f, 0.55f};     // pale yellow: what a click would pick
inline constexpr Rgb kRestColour{0.62f, 0.62f, 0.62f};      // a spring at its rest length
inline constexpr Rgb kCompressedColour{0.20f, 0.42f, 1.00f};
inline constexpr Rgb kStretchedColour{1.00f, 0.20f, 0.16f};
inline constexpr Rgb kGridColour{0.32f, 0.33f, 0.37f};
inline constexpr Rgb kPlaneColour{0.55f, 0.70f, 0.85f};
inline constexpr float kPlaneAlpha = 0.22f;
inline constexpr Rgb kSurfaceFrontColour{0.84f, 0.78f, 0.64f};  // linen: a cloth's side its normals point to
inline constexpr Rgb kSurfaceBackColour{0.60f, 0.48f, 0.56f};   // mauve: its other side

// line widths on screen, in pixels of the view (an exported image scales them with its size)
inline constexpr float kSpringPixels = 2.0f;
inline constexpr float kHighlightedSpringPixels = 4.0f;  // selected or under the cursor
inline constexpr float kDecorationPixels = 1.0f;         // the grid and the axes

// a strain (l - l0) / l0 of this size or more shows the full compressed or stretched colour
inline constexpr float kFullStrain = 0.10f;

// rest grey blending to blue when compressed and to red when stretched
Rgb strainColour(float strain, float fullStrain = kFullStrain);

// per particle, interleaved as the viewport's buffer takes it: radius (m), colour (rgb), pinned
// (0 or 1), selected (0 or 1)
inline constexpr int kStyleFloats = 6;
struct ParticleStyle {
    std::vector<float> values;
    int count() const { return static_cast<int>(values.size() / kStyleFloats); }
    float radius(int i) const { return values[std::size_t(i) * kStyleFloats]; }
    Rgb colour(int i) const;
    bool pinned(int i) const { return values[std::size_t(i) * kStyleFloats + 4] != 0.0f; }
    bool selected(int i) const { return values[std::size_t(i) * kStyleFloats + 5] != 0.0f; }
};

// The particles a style draws, for the instanced draws to leave the others out altogether: a
// hidden sphere (radius 0) still costs its vertices, and on a software renderer the 10⁶ spheres a
// sheet hides took a third of a frame. `all`: every particle is drawn, in index order, and `rows`
// is empty; else `rows` lists those drawn (radius not 0), in index order.
struct DrawnParticles {
    bool all = true;
    std::vector<std::uint32_t> rows;
};
DrawnParticles drawnParticles(const ParticleStyle &style);
// the given rows of an array of `width` floats a row, in order, into `to`
void gatherRows(const float *from, int width, const std::vector<std::uint32_t> &rows, std::vector<float> &to);

// selection: indices of selected particles, in any order; those out of range are ignored; hover:
// the particle under the cursor (-1: none), drawn in the hover colour over any other; hidden: 1 per
// particle not to be drawn (radius 0) unless selected or hovered, or empty for none
ParticleStyle packParticleStyle(const core::Snapshot &snapshot, const std::vector<int> &selection, int hover = -1,
                                const std::vector<std::uint8_t> &hidden = {});

// what a ParticleStyle was packed from, to tell whether a new snapshot needs a new one
class StyleKey {
public:
    bool matches(const core::Snapshot &snapshot) const;
    void remember(const core::Snapshot &snapshot);
    void clear();

private:
    bool m_valid = false;
    std::vector<float> m_radii;
    std::vector<std::uint8_t> m_pinned;
};

// line and triangle vertices: xyz then rgba
inline constexpr int kVertexFloats = 7;

// the springs drawn apart from the strain colours: selected ones in the selection colour, the one
// under the cursor in the hover colour
struct SpringHighlight {
    std::vector<int> selected;  // any order; those out of range are ignored
    int hover = -1;
};

// two vertices per spring, coloured by its strain unless highlighted; the highlighted springs come
// last (drawn wider and over the others), and their number is returned; hidden: 1 per spring not
// to be drawn unless highlighted, or empty for none
int packSpringLines(const core::Snapshot &snapshot, std::vector<float> &vertices, float fullStrain = kFullStrain,
                    const SpringHighlight &highlight = {}, const std::vector<std::uint8_t> &hidden = {});

// the bounding sphere of the particles (their radii included), leaving out any that are not
// finite; radius 0 when none is left
struct Sphere {
    QVector3D centre;
    float radius = 0.0f;
};
Sphere particleBounds(const core::Snapshot &snapshot);

// a round number (1, 2 or 5 times a power of ten) near the given length
float niceStep(float length);

// a square grid of lines on the plane y = height, centred under the scene and covering it
std::vector<float> packGrid(const Sphere &scene, float height);

// a plane whose unit normal is within about 8° of +y is a floor, and the ground grid lies on it
inline constexpr float kFloorNormalY = 0.99f;
bool isFloor(const core::PlaneDesc &plane);

// the ground grid, on every floor and in its plane, a hair above it: on a whole plane a square
// grid about the scene as packGrid's, on a rectangle (a table top) lines across it within its
// edges, the square cut where walls around the scene stand (a pool's grid ends at its walls);
// nothing when the scene has no floor, so that a grid never shows a floor that is not there
std::vector<float> packFloorGrids(const std::vector<core::PlaneDesc> &planes, const Sphere &scene);

// a unit sphere made by splitting each face of an icosahedron into four, `subdivisions` times:
// 20·4^s triangles, counter-clockwise seen from outside; each vertex is also its normal
struct SphereMesh {
    std::vector<float> vertices;        // xyz
    std::vector<std::uint32_t> indices;  // three per triangle
};
SphereMesh icosphere(int subdivisions);

// the x, y and z axes from the origin in red, green and blue
std::vector<float> packAxes(float length);

// what a view of the whole scene takes in: the scene's bounds, grown to hold a floor that walls
// close in on every side (a pool's table, so that the view starts outside its walls, not inside
// the near one); the scene's bounds alone where no walls close a floor in
Sphere withEnclosedFloors(const std::vector<core::PlaneDesc> &planes, const Sphere &scene);

// translucent triangles per plane: for a rectangle (core::PlaneDesc::bounded) exactly the rectangle
// that collides; for an unbounded plane a square of it around the scene's centre, cut where it
// leaves the room the other one-sided planes enclose the scene in (a pool's floor ends at its walls
// and the walls stand on it), and wide enough to reach those walls
std::vector<float> packPlaneQuads(const std::vector<core::PlaneDesc> &planes, const Sphere &scene);

}  // namespace ui
