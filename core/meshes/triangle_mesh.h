#pragma once
// A triangle mesh as a file gives it (vertices in the file's order, faces over them) and what the
// importers need to know of it: its vertices welded where the file split them, its edges and
// whether it is closed, its area and volume.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace core {

struct TriangleMesh {
    std::vector<Eigen::Vector3d> vertices;   // m, in the file's order
    std::vector<std::array<int, 3>> faces;   // vertex indices, counter-clockwise seen from outside
};

// the mesh with its split vertices joined: points where the file has several vertices at one place
// (a seam of normals or texture coordinates), faces over the points
struct WeldedMesh {
    std::vector<int> pointOf;              // per vertex of the file: its point; -1 when no face uses it
    std::vector<Eigen::Vector3d> points;   // in the order of their first vertex
    std::vector<std::array<int, 3>> faces; // over points; faces that welding made degenerate dropped
    int droppedFaces = 0;                  // those faces
};

// welds vertices whose positions are equal to within `tolerance` (m) along every axis
WeldedMesh weldVertices(const TriangleMesh &mesh, double tolerance);

// the edges of faces over `pointCount` points, each once, with the faces on it
struct MeshEdges {
    std::vector<std::array<int, 2>> ends;     // lower point first
    std::vector<std::array<int, 2>> faces;    // the first two faces on the edge (-1: none)
    std::vector<int> faceCount;               // how many faces border the edge
    int boundary = 0;      // edges of one face: a hole's rim, or an open sheet's edge
    int nonManifold = 0;   // edges of three or more faces
    bool closed() const { return boundary == 0 && nonManifold == 0 && !ends.empty(); }
};
MeshEdges meshEdges(const std::vector<std::array<int, 3>> &faces, int pointCount);

// m², the faces' total area, and each point's share (a third of each face it is a corner of)
double surfaceArea(const std::vector<Eigen::Vector3d> &points, const std::vector<std::array<int, 3>> &faces,
                   std::vector<double> *pointShare = nullptr);

// m³, the volume a closed mesh encloses (positive when its faces turn counter-clockwise seen from
// outside)
double enclosedVolume(const std::vector<Eigen::Vector3d> &points, const std::vector<std::array<int, 3>> &faces);

// a polygon of the file (four or more corners, planar or nearly so) split into triangles by ear
// clipping in the plane of its Newell normal, so that a concave outline keeps its area; appends
// triangles over indices into `corners`, turning as the polygon does
void triangulatePolygon(const std::vector<Eigen::Vector3d> &corners, std::vector<std::array<int, 3>> &out);

// the axis-aligned box of the points
struct Box {
    Eigen::Vector3d low = Eigen::Vector3d::Constant(0.0);
    Eigen::Vector3d high = Eigen::Vector3d::Constant(0.0);
    Eigen::Vector3d size() const { return high - low; }
};
Box boundingBox(const std::vector<Eigen::Vector3d> &points);

}  // namespace core
