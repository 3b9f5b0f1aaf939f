#pragma once
// `springlab-bench mesh-import`: what bringing in a model costs at 100 000 triangles (File ›
// Import Mesh, springlab-sim --import): reading the file in each format, making the body of each
// kind, compiling the scene, each the median of several runs; and what taking the motion out
// holds in memory: the peak resident memory of a PC2 export of a 200 × 200 sheet at a few frames
// and at many, which streaming keeps the same. See mesh_import.cpp and docs/benchmarks.md.

#include <QString>
#include <QTextStream>

namespace bench {

struct MeshImportOptions {
    QString outDir;
    int runs = 5;        // timed runs of each row, after one untimed
    bool quick = false;  // meshes of about 2 000 triangles, one run: a smoke test only
    int frames = 2000;   // the long export's frames (the short one's: 100)
};

// writes mesh-import.csv to outDir and prints the table; returns the exit code (0 done, 1 a mesh
// could not be written, read, imported or exported, or the CSV not written)
int runMeshImport(const MeshImportOptions &options, QTextStream &out);

}  // namespace bench
