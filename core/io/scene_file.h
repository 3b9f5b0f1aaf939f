#pragma once
// Scene files: JSON (format "springlab-scene", version 1), documented in docs/scene-format.md.
// Loading validates everything and either gives a whole scene or one message naming the file, the
// JSON path and the reason; nothing is half-loaded. Saving is atomic (safe_write.h) and writes
// doubles so that loading gives back the same bits.

#include "core/model/scene.h"

#include <QByteArray>
#include <QLatin1StringView>
#include <QString>
#include <QStringList>

#include <optional>

namespace io {

inline constexpr int kSceneFormatVersion = 1;
inline constexpr QLatin1StringView kSceneFormatName("springlab-scene");

// what a scene file may hold before it is refused with a message, so that a huge or hostile file
// cannot exhaust memory; generous for real scenes (docs/scene-format.md says why these numbers)
inline constexpr qint64 kMaxSceneFileBytes = qint64(1) << 30;  // 1 GiB: about 5 million particles as saved
inline constexpr qsizetype kMaxParticles = 10'000'000;
inline constexpr qsizetype kMaxSprings = 100'000'000;          // room for a cloth's ~6 springs per particle
inline constexpr qsizetype kMaxPlanes = 10'000;
inline constexpr qsizetype kMaxContactImpulses = 100'000'000;  // a pile's ~3 contacts per particle, with room
inline constexpr qsizetype kMaxTriangles = 100'000'000;        // a sheet's ~2 triangles per particle, with room
inline constexpr int kMaxNestingDepth = 32;  // arrays and objects open at once; the format itself needs 4

// the limits a load checks; a caller (or a test) may pass smaller ones
struct LoadLimits {
    qint64 fileBytes = kMaxSceneFileBytes;
    qsizetype particles = kMaxParticles;
    qsizetype springs = kMaxSprings;
    qsizetype planes = kMaxPlanes;
    qsizetype contactImpulses = kMaxContactImpulses;
    qsizetype triangles = kMaxTriangles;
    int nestingDepth = kMaxNestingDepth;
};

struct LoadResult {
    std::optional<core::SceneDesc> scene;  // set on success
    QString error;                         // set on failure: "FILE: particles[3].mass: must be ..."
    QStringList warnings;                  // non-fatal: "FILE: particles[0].colour: unknown key, ignored"
    bool outOfMemory = false;              // the failure was memory that ran out, not the file
    bool ok() const { return scene.has_value(); }
};

struct SaveResult {
    QString error;  // empty on success
    bool ok() const { return error.isEmpty(); }
};

// why json, which a pull reader (json_pull.h) refused, is not one JSON object, in the words of a
// scene file's messages ("FILE: the file is empty", "FILE: expected a JSON object at the top
// level, got a number", "FILE: PATH: the file ends too early: is it truncated? (...)", "FILE:
// PATH: not valid JSON (... at byte N, line L, column C)"), for other files of JSON (recordings)
// too. Over 16 MiB the place of the fault is the pull reader's, with no tree of the text made.
QString jsonSyntaxError(const QByteArray &json, const QString &sourceName);

// "FILE: PATH: nested too deeply: more than the limit of 32 levels of arrays and objects (at byte
// N, line L, column C)" when json has more than maxDepth arrays and objects open at once, else
// empty; one pass over the bytes that keeps nothing, before any reader keeps a frame per level
QString nestingError(const QByteArray &json, const QString &sourceName, int maxDepth = kMaxNestingDepth);

// reads a whole file of at most limitBytes into bytes; a device with no size (a pipe, /dev/zero)
// is read in pieces and refused one byte past the limit, or read only up to a piece that holds a
// zero byte, which no text has (the parser then says why: load_checks.h). Empty on success, else
// the message: "FILE: cannot open: ...", "FILE: the file is too large: ..."
QString readFileWithin(const QString &path, qint64 limitBytes, QByteArray &bytes);

// reads and validates a scene file
LoadResult loadScene(const QString &path, const LoadLimits &limits = {});

// the same from bytes in memory; sourceName stands for the file in messages
LoadResult parseScene(const QByteArray &json, const QString &sourceName, const LoadLimits &limits = {});

// the shortest text that reads back as the same double, sign of zero included (QJsonDocument
// writes -0.0 as 0); null for a value that is not finite
QByteArray formatNumber(double value);

// the scene as indented JSON with every key written out
QByteArray sceneToJson(const core::SceneDesc &scene);

// writes the scene atomically: the old file stays whole if anything fails
SaveResult saveScene(const QString &path, const core::SceneDesc &scene);

}  // namespace io
