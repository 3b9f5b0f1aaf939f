#pragma once
// What tools/make_examples and tools/make_stress_scenes share: each checks its scenes and writes
// them, one NAME.json a scene, into the folder named on its command line.

#include "core/model/scene.h"

#include <vector>

namespace tools {

// main() of a scene-writing tool: `PROGRAM DIRECTORY`; 0 when every scene was written, 1 when one
// failed its checks or its save (named on stderr), 2 for a wrong command line
int writeScenes(int argc, char **argv, const std::vector<core::SceneDesc> &scenes);

}  // namespace tools
