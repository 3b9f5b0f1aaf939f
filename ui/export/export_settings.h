#pragma once
// What File › Export's dialog asks for, one struct per kind of export.

#include <QSize>
#include <QString>

namespace ui {

enum class ExportKind { Image, Sequence, Trace };

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

}  // namespace ui
