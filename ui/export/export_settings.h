#pragma once
// What File › Export's dialog asks for, one struct per kind of export.

#include <QSize>
#include <QString>

namespace ui {

enum class ExportKind { Image, Sequence, Trace, Animation };

// the view as a PNG of any size (device pixels)
struct ImageExport {
    QString path;
    QSize size;
};

// an image sequence of the run from where it is (image_sequence.h), and an MP4 of it if asked for
struct SequenceExport {
    QString folder;
    double fps = 30.0;      // frames per simulated second
    double duration = 5.0;  // s of simulated time
    QSize size;
    bool video = false;  // also an MP4, made by ffmpeg
};

// the run's positions and velocities from where it is, as springlab-sim --trace writes them
struct TraceExport {
    QString path;
    double duration = 1.0;  // s of simulated time: round(duration / time step) steps
    int every = 1;          // a set of rows every K steps, the first included
};

// File › Export Animation: the deforming surfaces (imported meshes, or the scene's sheet) of a run
// on from where it is, or of the run the timeline recorded, as a PC2 point cache with the OBJ of
// its first frame beside it, an OBJ a frame, and the last frame in a format of its extension's
// (core/io/animation_export.h); any may be left out
struct MeshAnimationExport {
    QString pc2Path;
    QString objFolder;
    QString meshPath;
    double fps = 24.0;      // frames per simulated second
    double duration = 5.0;  // s of simulated time, run on from the current state
    bool fileSpace = true;  // where the imported files have their vertices, else the scene's
    // the recorded run instead, from `from` to `to` (s of the run's time), replayed from the
    // timeline's keyframes: what was seen, to the bit, without running on
    bool fromTimeline = false;
    double from = 0.0;
    double to = 0.0;
};

}  // namespace ui
