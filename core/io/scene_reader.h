#pragma once
// Reads a scene file's text token by token (json_pull.h) straight into a core::SceneDesc, so that
// loading needs memory for the text and the scene and for no tree of the document. The checks
// and their order are those of the format (docs/scene-format.md): the header first, then a key
// that comes twice, a lone surrogate, the name, the settings, the particles, springs, planes, the
// steerable particle, the contact impulses, and last the values' ranges (core::findProblem());
// wherever in the text each part comes, the first problem in that order is the one reported.

#include "scene_file.h"

#include <QByteArrayView>
#include <QHash>

#include <optional>

namespace io {

// the scene in json, or a message; nullopt when json is not one JSON object (the caller asks
// QJsonDocument why). lengths: the number of elements of each top-level list, counted beforehand
// (json_scan.h), so that each list is made at its final size
std::optional<LoadResult> readSceneText(QByteArrayView json, const QString &sourceName,
                                        const QHash<QString, qsizetype> &lengths);

}  // namespace io
