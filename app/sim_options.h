#pragma once
// The command line of springlab-sim, parsed with QCommandLineParser and checked against the same
// parameter table as scene files (core/model/parameters.h), so "--time-step 5" is refused with the
// same words as "timeStep": 5 in a file.

#include "sim_set.h"
#include "sim_summary.h"

#include "core/integrators/integrator.h"
#include "core/meshes/mesh_import.h"
#include "core/meshes/mesh_surface.h"
#include "core/model/scene.h"

#include <QJsonObject>
#include <QSize>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace app {

// steps run when neither --steps nor --duration is given
inline constexpr std::uint64_t kDefaultSteps = 1000;

// springlab-sim --import MESH --as KIND --output SCENE.json: a scene made of a mesh file
struct ImportRequest {
    QString meshPath;    // --import MESH
    QString intoPath;    // --into SCENE.json: added to that scene; empty: a new scene
    core::MeshKind kind = core::MeshKind::Cloth;                // --as
    double scale = 1.0;                                         // --scale S
    bool zUp = false;                                           // --up z
    std::optional<Eigen::Vector3d> at;                          // --at X,Y,Z
    core::ClothMaterial material = core::ClothMaterial::Cotton; // --material NAME
    std::optional<double> density;                              // --density D
    std::optional<double> stiffness;                            // --stiffness K
    std::optional<double> damping;                              // --damping C
    double spacing = 0.0;                                       // --spacing H
    core::PinSide pin = core::PinSide::None;                    // --pin SIDE
    QString name;                                               // --name NAME
};

struct SimOptions {
    std::optional<ImportRequest> import;  // --import: make a scene of a mesh instead of running one
    QString scenePath;
    std::optional<std::uint64_t> steps;  // --steps N
    std::optional<double> duration;      // --duration SECONDS
    std::optional<double> timeStep;      // --time-step H, s
    std::optional<int> substeps;         // --substeps S
    std::optional<core::Integrator> integrator;
    std::optional<double> tolerance;     // --tolerance TOL, for adaptive-rk45
    std::optional<core::ContactSolver> contactSolver;  // --contact-solver NAME
    std::optional<double> friction;                    // --friction MU
    std::optional<double> staticFriction;              // --static-friction MU
    std::vector<SceneOverride> sets;  // --set KEY=VALUE, in the order given (a later one wins)
    QString outputPath;       // --output FINAL.json; empty: none
    QString tracePath;        // --trace TRACE.csv; empty: none
    std::uint64_t every = 1;  // --every K: a trace row set every K steps
    QString summaryJsonPath;  // --summary-json SUMMARY.json; empty: none
    QString summaryCsvPath;   // --summary-csv ROW.csv; empty: none
    QString renderDirectory;      // --render DIR: PNG frames of the run; empty: none
    double fps = 30.0;            // --fps F: frames per simulated second (of --render and the exports)
    QString pc2Path;              // --export-pc2 FILE.pc2: the surfaces' point cache
    QString objFolder;            // --export-obj FOLDER: an OBJ a frame
    QString meshPath;             // --export-mesh FILE: the last frame, in the format of its extension
    double exportFrom = 0.0;      // --export-from T, s
    std::optional<double> exportTo;  // --export-to T, s
    core::MeshSpace exportSpace = core::MeshSpace::File;  // --export-space file|scene
    QSize frameSize{1280, 720};   // --size WxH, px
    bool quiet = false;
    bool replay = false;  // --replay: scenePath is a session recording (ui/session_file.h)
};

struct ParsedOptions {
    std::optional<SimOptions> options;  // set when the run should go ahead
    QString error;                      // bad arguments: print it and exit 2
    QString text;                       // --help, --version or --summary-csv-header: print it and exit 0
    // bad arguments are still reported in the summary files when they were named and name no
    // file the run reads or writes otherwise (empty: no such file)
    QString summaryJsonPath;
    QString summaryCsvPath;
    RunSummary refused;  // the scene and the overrides as far as they were read, the error
};

// arguments as main() gets them, the program name first
ParsedOptions parseSimOptions(const QStringList &arguments);

// whether the run writes an animation export
inline bool exportsAnimation(const SimOptions &options)
{
    return !options.pc2Path.isEmpty() || !options.objFolder.isEmpty() || !options.meshPath.isEmpty();
}

// why the files options name cannot be used together (empty: they can): an output (--output,
// --trace, --summary-json, --summary-csv, the --render folder) that is the file read, two outputs
// that are one file, or a file read or written that is one of --render's frames. Files are
// compared by identity (device and inode, io::sameFile), so links, bind mounts and other
// spellings of a path are caught
QString clashingPaths(const SimOptions &options);

// what the command line changes in the scene, by the keys --set names them with:
// {"settings.timeStep": 0.001, "springs.stiffness": 500}
QJsonObject overridesApplied(const SimOptions &options);

// the command line's settings written over the file's, then each --set in turn; empty on success,
// else the message
QString applyOverrides(const SimOptions &options, core::SceneDesc &scene);

// how many steps to run: --steps N, or round(--duration / time step), or kDefaultSteps;
// nullopt (with error set) when the duration asks for more steps than can be counted
std::optional<std::uint64_t> stepsToRun(const SimOptions &options, const core::Settings &settings, QString &error);

}  // namespace app
