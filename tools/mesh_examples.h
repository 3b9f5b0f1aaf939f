#pragma once
// The example scenes made of the model files in resources/meshes/, through the same import as
// File › Import Mesh and springlab-sim --import: a flag (cloth), a tablecloth over a table
// (cloth on a collider) and a soft ball dropped on the table (soft body on a collider).

#include "core/model/scene.h"

#include <QString>
#include <vector>

namespace tools {

// the scenes, or none and *error set when a mesh cannot be read or imported
std::vector<core::SceneDesc> meshExamples(const QString &meshFolder, QString *error);

}  // namespace tools
