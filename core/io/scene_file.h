#pragma once
// Scene files: JSON (format "springlab-scene", version 1), documented in docs/scene-format.md.
// Loading validates everything and either gives a whole scene or one message naming the file, the
// JSON path and the reason; nothing is half-loaded. Saving is atomic (QSaveFile) and writes
// doubles so that loading gives back the same bits.

#include "core/scene.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>

namespace io {

inline constexpr int kSceneFormatVersion = 1;

struct LoadResult {
    std::optional<core::SceneDesc> scene;  // set on success
    QString error;                         // set on failure: "FILE: particles[3].mass: must be ..."
    QStringList warnings;                  // non-fatal: "FILE: particles[0].colour: unknown key, ignored"
    bool ok() const { return scene.has_value(); }
};

struct SaveResult {
    QString error;  // empty on success
    bool ok() const { return error.isEmpty(); }
};

// reads and validates a scene file
LoadResult loadScene(const QString &path);

// the same from bytes in memory; sourceName stands for the file in messages
LoadResult parseScene(const QByteArray &json, const QString &sourceName);

// the scene as indented JSON with every key written out
QByteArray sceneToJson(const core::SceneDesc &scene);

// writes the scene atomically: the old file stays whole if anything fails
SaveResult saveScene(const QString &path, const core::SceneDesc &scene);

}  // namespace io
