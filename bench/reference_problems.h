#pragma once
// The five reference problems of the accuracy benchmark (issue 5), each a scene, an end time and,
// where one exists, the exact positions at that time. The same scenes are shipped in
// resources/scenes/reference/ (written by `springlab-bench write-references`).

#include "core/model/scene.h"

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace bench {

struct ReferenceProblem {
    std::string name;       // file stem: "oscillator", "bounce", "head-on", "chain", "cloth"
    std::string title;      // one line for plots and tables
    core::SceneDesc scene;  // as shipped; the benchmark overrides the integrator and substeps
    double duration = 1.0;  // s, the end time; a whole number of the scene's time steps
    // the exact positions at the end time, one column per particle; empty where there is no
    // closed form and a fine RK4 run stands in for it
    std::optional<Eigen::Matrix3Xd> exact;
};

// the five problems, in the order of the issue
std::vector<ReferenceProblem> referenceProblems();

}  // namespace bench
