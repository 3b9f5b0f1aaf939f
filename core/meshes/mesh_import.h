#pragma once
// A triangle mesh made into a Springlab body and added to a scene (docs/scene-format.md,
// "Meshes"): a cloth (a particle per welded vertex, springs along its edges and across its
// folds), a soft body (a lattice of particles filling a closed mesh, the surface carried by its
// cell's corners) or a collider (pinned particles whose triangles others collide with). The scene
// keeps the mesh (SceneDesc::meshes) with the file's vertices, for drawing and for export.

#include "core/meshes/triangle_mesh.h"
#include "core/model/scene.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace core {

// a cloth's material: what it weighs and how its springs resist stretch, shear and bending.
// Stiffness per spring is the sheet's in-plane modulus (N/m), the same for any fineness of mesh
enum class ClothMaterial { Cotton, Silk, Denim, RubberSheet };
struct ClothMaterialValues {
    ClothMaterial material;
    std::string_view name;  // as the command line and the dialog spell it
    double density;         // kg/m²
    double stretch;         // N/m, the springs along the edges
    double shear;           // N/m, the springs across a pair of faces that spans one quad
    double bend;            // N/m, the springs across a pair of faces that folds
    double damping;         // N·s/m, every spring
};
const ClothMaterialValues &clothMaterial(ClothMaterial material);
std::optional<ClothMaterial> clothMaterialNamed(std::string_view name);
std::string_view knownClothMaterials();  // "cotton, silk, denim, rubber-sheet"

// the side of a mesh whose vertices are pinned (those within a thousandth of its box's longest
// side of that face of the box): +y, -y, -x, +x, +z, -z
enum class PinSide { None, Top, Bottom, Left, Right, Front, Back };
std::optional<PinSide> pinSideNamed(std::string_view name);
std::string_view knownPinSides();  // "none, top, bottom, left, right, front, back"

// how the file's coordinates become the scene's: scaled, turned from z-up to y-up if the file is
// z-up, then moved so that the bottom centre of its box is at `at` (unset: left where it is)
struct MeshPlacement {
    double scale = 1.0;
    bool zUp = false;
    std::optional<Eigen::Vector3d> at;
};

// the mesh placed; *offset (if given) is the move that followed the scale and turn
TriangleMesh placedMesh(const TriangleMesh &mesh, const MeshPlacement &placement, Eigen::Vector3d *offset = nullptr);

struct MeshImportOptions {
    MeshKind kind = MeshKind::Cloth;
    std::string name;    // the mesh's in the scene (default: "mesh")
    std::string source;  // the file, as the user named it
    MeshPlacement placement;
    ClothMaterial material = ClothMaterial::Cotton;
    // kg/m² for a cloth, kg/m³ for a soft body (unset: the material's, or kDefaultSoftDensity)
    std::optional<double> density;
    // N/m: a cloth's edge springs (its shear and bend springs keep the material's proportion to
    // them), or every spring of a soft body (unset: the material's, or kDefaultSoftStiffness × h / 0.1 m)
    std::optional<double> stiffness;
    std::optional<double> damping;  // N·s/m, every spring (unset: the material's, or 0.5)
    // m, a soft body's lattice spacing; 0: a tenth of the longest side of its box
    double spacing = 0.0;
    PinSide pin = PinSide::None;
};

inline constexpr double kDefaultSoftDensity = 200.0;     // kg/m³, a foam ball
inline constexpr double kDefaultSoftStiffness = 2000.0;  // N/m, each spring of a 0.1 m lattice
// the most particles one import may make (the generators' limit)
inline constexpr int kMaxImportedParticles = 200000;

struct MeshImportResult {
    std::string error;               // set: the scene is as it was
    std::vector<std::string> notes;  // what the import did that the user should know
    int particles = 0;
    int springs = 0;
    int triangles = 0;  // listed for drawing and collisions
    int weldedVertices = 0;  // the file's vertices joined to another at the same place
    double mass = 0.0;       // kg, the free particles'
    double area = 0.0;       // m²
    double volume = 0.0;     // m³, a soft body's
    bool ok() const { return error.empty(); }
};

// adds the mesh to the scene as options.kind says, with the settings the body needs switched on
// (triangle collisions for a cloth and a collider, automatic substeps for a cloth and a soft body);
// on failure the scene is untouched and the error says why
MeshImportResult addMeshToScene(SceneDesc &scene, const TriangleMesh &mesh, const MeshImportOptions &options);

// a scene of the mesh alone, with gravity and a floor plane under it (at y = 0, or at its lowest
// point when it reaches below), named after it
MeshImportResult sceneFromMesh(SceneDesc &scene, const TriangleMesh &mesh, const MeshImportOptions &options);

}  // namespace core
