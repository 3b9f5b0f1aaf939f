#pragma once
// Session files: a SessionRecording as JSON (format "springlab-replay", version 1), documented in
// docs/scene-format.md. Scenes go in as the text of a scene file (a JSON string), and every
// number as the shortest text that reads back as the same double, so that a replay starts from
// the very bits recorded.

#include "session_recording.h"

#include "core/io/scene_file.h"

#include <QByteArray>
#include <QString>

namespace ui {

QByteArray recordingToJson(const SessionRecording &recording);

struct RecordingLoad {
    std::shared_ptr<const SessionRecording> recording;  // set on success
    QString error;                                       // "FILE: edits[3].particle: ..." on failure
    bool outOfMemory = false;                            // the failure was memory that ran out, not the file
};
// a recording from its text, read token by token (no tree of the document); running out of
// memory is a message ("FILE: cannot load: out of memory (...)"), never an exception
RecordingLoad parseRecording(const QByteArray &json, const QString &sourceName);
// reads a recording file of at most limitBytes (the scene files' limit unless told) as a scene
// file is read (io::loadScene): its size checked before it is read, a device with no size read up
// to the limit or to its first zero byte, bytes that are not UTF-8 text named as such
RecordingLoad loadRecording(const QString &path, qint64 limitBytes = io::kMaxSceneFileBytes);

// writes atomically (QSaveFile); empty on success, else why not
QString saveRecording(const QString &path, const SessionRecording &recording);

}  // namespace ui
