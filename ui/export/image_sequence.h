#pragma once
// Image sequences of a run, as the editor's File › Export › Image Sequence and springlab-sim
// --render write them: frame k belongs at k / fps simulated seconds after the start, and since a
// scene's time step need not divide 1 / fps, frame k shows the first step at or after that time
// (step ceil(k / (fps · h)), counted from the start). So each frame is a state the run really
// passed through, never an interpolation, and no frame is early; it is late by less than one step.
// The frames are frame-00000.png, frame-00001.png, ... in one folder, the pattern ffmpeg reads.

#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace ui {

// frames for a duration: enough to cover it (ceil(duration · fps)), at least one
int sequenceFrameCount(double fps, double duration);

// the step, counted from the start, that each of count frames shows (see above); fps > 0, h > 0
std::vector<std::uint64_t> sequenceFrameSteps(double fps, int count, double timeStep);

// frame-00042.png in folder; and the pattern of the names as ffmpeg's -i reads them
QString sequenceFramePath(const QString &folder, int index);
inline constexpr const char *kSequenceFramePattern = "frame-%05d.png";

// the frame-NNNNN.png files already in folder (a new sequence removes them first, so that none is
// left over from a longer one for ffmpeg to append)
QStringList sequenceFramesIn(const QString &folder);
// removes them; empty on success, else the message
QString removeSequenceFrames(const QString &folder);

// whether path is a file that a new sequence in folder would remove or write over: a
// frame-NNNNN.png in it. The folder is compared as a folder (io::sameFile: another spelling, a
// link or a bind mount of it counts), a link at path counts both where it is and where it leads,
// and the name is matched in any case, for a file system that ignores it
bool isSequenceFrame(const QString &path, const QString &folder);

}  // namespace ui
