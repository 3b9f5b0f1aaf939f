#pragma once
// springlab-sim --import MESH --as cloth|soft|collider --output SCENE.json [--into SCENE.json]:
// the scene made of a mesh file (core/io/mesh_file.h, core/meshes/mesh_import.h), written, with
// what the import did printed. Exit code 0 done, 2 a bad file or argument.

#include "sim_options.h"

namespace app {

int runImport(const SimOptions &options);

}  // namespace app
