// Design note. Reading goes token by token (scene_reader.h over json_pull.h) straight into a
// SceneDesc, so that a load needs the file's bytes and the scene and no tree of the document: a
// QJsonDocument of a scene took 12 to 14 times the file's size. Value ranges are checked
// afterwards by core::findProblem(), so a range is written once (core/model/parameters.cpp). Only text
// that is not one JSON object goes to QJsonDocument, for the words and the place of its syntax
// error. Writing is done by hand rather than by QJsonDocument::toJson() for two reasons: Qt writes
// -0.0 as "0" (losing the sign bit), and its indented style puts every number of every vector on a
// line of its own, which makes a cloth unreadable. Numbers are written with std::to_chars, whose
// output is the shortest text that reads back as the same double. The limits (io::LoadLimits)
// come first: the size before the file is read, the nesting depth and the lists' lengths by passes
// over the bytes that keep nothing, so a huge or hostile file gets a message instead of
// exhausting memory, and each list is made at its final size.

#include "scene_file.h"

#include "json_pull.h"
#include "json_scan.h"
#include "load_checks.h"
#include "safe_write.h"
#include "scene_reader.h"
#include "scene_words.h"

#include "core/contacts/solver_names.h"
#include "core/meshes/mesh_surface.h"
#include "core/model/validate.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QLocale>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <limits>
#include <new>
#include <system_error>

namespace io {

// the shortest text that reads back as the same double; JSON has no NaN or infinity, so a
// non-finite value (which a valid scene never holds) is written as null and refused on load
QByteArray formatNumber(double value)
{
    if (!std::isfinite(value))
        return "null";
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return QByteArray(buffer.data(), result.ptr - buffer.data());
}

namespace {

// the largest text that is not one JSON object whose message QJsonDocument makes (from the whole
// text, about ten times its size); past it the reader's own place of the fault is the message
constexpr qsizetype kLargestTextForQtMessage = qsizetype(16) << 20;

using namespace Qt::Literals::StringLiterals;

bool isWordChar(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '-' || c == '+' ||
           c == '.';
}

// "at byte 812, line 3, column 40" for an offset into the text
QString location(const QByteArray &json, qsizetype offset)
{
    const qsizetype lineStart = json.lastIndexOf('\n', offset - 1) + 1;
    return QStringLiteral("at byte %1, line %2, column %3")
        .arg(offset)
        .arg(std::count(json.constData(), json.constData() + offset, '\n') + 1)
        .arg(offset - lineStart + 1);
}

// the offset of the first bracket that has more than maxDepth arrays and objects open at once, or
// -1; one pass over the bytes, so that a deep file is refused before Qt's parser recurses into it
qsizetype tooDeepAt(const QByteArray &json, int maxDepth)
{
    const char *text = json.constData();
    int depth = 0;
    bool inString = false;
    bool escaped = false;
    for (qsizetype i = 0; i < json.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > maxDepth)
                return i;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return -1;
}

// "1073741824 bytes (1 GiB)"; the plain count alone when it is small
QString byteCount(qint64 bytes)
{
    const QString plain = QString::number(bytes) + u" bytes"_s;
    return bytes < 1024 ? plain : plain + u" ("_s + QLocale::c().formattedDataSize(bytes, 0) + u")"_s;
}

QString tooLarge(const QString &source, qint64 size, qint64 limit)
{
    return source + u": the file is too large: "_s + byteCount(size) + u", more than the limit of "_s + byteCount(limit);
}

// the text stops in the middle of a value: objects or arrays left open (scan, of all the text)
// and nothing after faultEnd, the end of the token where the parser gave up
bool endsTooEarly(const QByteArray &json, qsizetype faultEnd, const JsonScan &scan)
{
    qsizetype textEnd = json.size();
    while (textEnd > 0 && std::isspace(static_cast<unsigned char>(json[textEnd - 1])))
        --textEnd;
    return faultEnd >= textEnd && scan.openAtStop > 0;
}

// the message for text QJsonDocument could not parse, with the JSON path it broke off in
QString syntaxErrorOf(const QByteArray &json, const QJsonParseError &error, const QString &source)
{
    if (json.trimmed().isEmpty())
        return source + u": the file is empty (expected a JSON object)"_s;
    // a byte order mark alone, or a lone value where the object should be (Qt 6.4 calls both an
    // illegal value at byte 1)
    const QByteArray text = (json.startsWith("\xEF\xBB\xBF") ? json.mid(3) : json).trimmed();
    if (text.isEmpty())
        return source + u": the file is empty: it holds only a byte order mark (expected a JSON object)"_s;
    const char first = text[0];
    if (first != '{' && first != '[') {
        const char *got = first == '"'                                        ? "a string"
                          : text.startsWith("true") || text.startsWith("false") ? "true or false"
                          : text.startsWith("null")                          ? "null"
                          : (first == '-' || std::isdigit(static_cast<unsigned char>(first))) ? "a number"
                                                                                             : nullptr;
        if (got)
            return source + u": expected a JSON object at the top level, got "_s + QString::fromLatin1(got);
    }

    const qsizetype offset = std::clamp<qsizetype>(error.offset, 0, json.size());
    const QString where = error.errorString() + u' ' + location(json, offset);
    QString reason = u"not valid JSON ("_s + where + u")"_s;

    // an illegal number: most often one too large for a double, or a NaN or infinity
    qsizetype tokenStart = offset;
    qsizetype tokenEnd = offset;
    while (tokenStart > 0 && isWordChar(json[tokenStart - 1]))
        --tokenStart;
    while (tokenEnd < json.size() && isWordChar(json[tokenEnd]))
        ++tokenEnd;
    const QByteArray token = json.mid(tokenStart, tokenEnd - tokenStart);
    const bool numeric = !token.isEmpty() &&
                         (std::isdigit(static_cast<unsigned char>(token[0])) ||
                          (token.size() > 1 && token[0] == '-' && std::isdigit(static_cast<unsigned char>(token[1]))));
    // said in the words springlab-sim's --set uses for the same literal (scene_words.h)
    if (error.error == QJsonParseError::IllegalNumber || error.error == QJsonParseError::IllegalValue) {
        if (const QString unholdable = unholdableNumber(QString::fromLatin1(token)); !unholdable.isEmpty())
            reason = unholdable + u" ("_s + where + u")"_s;
        else if (error.error == QJsonParseError::IllegalNumber && numeric)
            reason = QString::fromLatin1(token) + u" is not a valid number ("_s + where + u")"_s;
    }

    if (endsTooEarly(json, std::max(offset, tokenEnd), scanJson(json)))
        reason = u"the file ends too early: is it truncated? ("_s + where + u")"_s;

    const QString path = scanJson(json, offset).pathAtStop;
    return path.isEmpty() ? source + u": "_s + reason : source + u": "_s + path + u": "_s + reason;
}

void appendVector(QByteArray &out, const Eigen::Vector3d &v)
{
    out += '[' + formatNumber(v.x()) + ", " + formatNumber(v.y()) + ", " + formatNumber(v.z()) + ']';
}

// every component a positive zero, bit for bit: the value a key left out reads back as
template <typename Vector>
bool isPositiveZero(const Vector &v)
{
    for (Eigen::Index k = 0; k < v.size(); ++k)
        if (v[k] != 0.0 || std::signbit(v[k]))
            return false;
    return true;
}

// a plane: its normal and offset, then only what differs from an unbounded one-sided plane with
// the settings' friction, so that files of plain planes read and write as before; a rectangle
// writes its size, centre and axis whatever they are
void appendPlane(QByteArray &out, const core::PlaneDesc &plane)
{
    out += "{\"normal\": ";
    appendVector(out, plane.normal);
    out += ", \"offset\": " + formatNumber(plane.offset);
    if (plane.twoSided)
        out += ", \"twoSided\": true";
    if (plane.friction)
        out += ", \"friction\": " + formatNumber(*plane.friction);
    if (plane.rollingFriction)
        out += ", \"rollingFriction\": " + formatNumber(*plane.rollingFriction);
    if (plane.spinningFriction)
        out += ", \"spinningFriction\": " + formatNumber(*plane.spinningFriction);
    const bool bounded = plane.bounded();
    if (bounded || !isPositiveZero(plane.size))
        out += ", \"size\": [" + formatNumber(plane.size[0]) + ", " + formatNumber(plane.size[1]) + ']';
    if (bounded || !isPositiveZero(plane.centre)) {
        out += ", \"centre\": ";
        appendVector(out, plane.centre);
    }
    if (bounded || !isPositiveZero(plane.axis)) {
        out += ", \"axis\": ";
        appendVector(out, plane.axis);
    }
    out += '}';
}

// a JSON string: quotes, backslashes and control characters escaped, UTF-8 kept as it is
void appendString(QByteArray &out, std::string_view text)
{
    out += '"';
    for (const char c : text) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        case '\b': out += "\\b"; break;
        case '\f': out += "\\f"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20)
                out += "\\u00" + QByteArray::number(static_cast<unsigned char>(c), 16).rightJustified(2, '0');
            else
                out += c;
        }
    }
    out += '"';
}

// an imported mesh: its vertices (a particle index, or [particle, weight, ...] pairs) and faces,
// a few to a line
void appendMesh(QByteArray &out, const core::MeshDesc &mesh)
{
    constexpr int kPerLine = 12;
    out += "{\"name\": ";
    appendString(out, mesh.name);
    out += ", \"source\": ";
    appendString(out, mesh.source);
    out += ", \"kind\": ";
    appendString(out, core::meshKindName(mesh.kind));
    if (mesh.scale != 1.0 || mesh.zUp || !isPositiveZero(mesh.offset)) {
        out += ",\n         \"scale\": " + formatNumber(mesh.scale) + ", \"zUp\": " + (mesh.zUp ? "true" : "false") + ", \"offset\": ";
        appendVector(out, mesh.offset);
    }
    out += ",\n         \"vertices\": [";
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        if (v > 0)
            out += v % kPerLine == 0 ? ",\n            " : ", ";
        const int first = mesh.offsets[std::size_t(v)], last = mesh.offsets[std::size_t(v) + 1];
        if (last - first == 1 && mesh.weights[std::size_t(first)] == 1.0) {
            out += QByteArray::number(mesh.particles[std::size_t(first)]);
            continue;
        }
        out += '[';
        for (int k = first; k < last; ++k)
            out += (k > first ? ", " : "") + QByteArray::number(mesh.particles[std::size_t(k)]) + ", " +
                   formatNumber(mesh.weights[std::size_t(k)]);
        out += ']';
    }
    out += "],\n         \"faces\": [";
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        if (f > 0)
            out += f % kPerLine == 0 ? ",\n            " : ", ";
        const std::array<int, 3> &t = mesh.faces[f];
        out += '[' + QByteArray::number(t[0]) + ", " + QByteArray::number(t[1]) + ", " + QByteArray::number(t[2]) + ']';
    }
    out += "]}";
}

// "key": [ one item per line ]
template <typename T, typename WriteItem>
void appendList(QByteArray &out, const char *key, const std::vector<T> &items, bool last, WriteItem writeItem)
{
    out += "    \"" + QByteArray(key) + "\": [";
    for (std::size_t i = 0; i < items.size(); ++i) {
        out += i == 0 ? "\n        " : ",\n        ";
        writeItem(items[i]);
    }
    out += items.empty() ? "]" : "\n    ]";
    out += last ? "\n" : ",\n";
}

}  // namespace

LoadResult parseScene(const QByteArray &json, const QString &sourceName, const LoadLimits &limits)
{
    LoadResult result;

    // limits first: size, then depth, both before the parser builds anything
    if (json.size() > limits.fileBytes) {
        result.error = tooLarge(sourceName, json.size(), limits.fileBytes);
        return result;
    }
    // bytes that are not UTF-8 text (UTF-16, a binary file) are named as such, not as bad JSON
    if (const QString problem = encodingProblem(json); !problem.isEmpty()) {
        result.error = sourceName + u": "_s + problem;
        return result;
    }
    if (QString deep = nestingError(json, sourceName, limits.nestingDepth); !deep.isEmpty()) {
        result.error = std::move(deep);
        return result;
    }

    // the lists' lengths, counted on the text before anything is made of them
    const QHash<QString, qsizetype> lengths = countTopLevelArrays(json);
    const std::pair<QString, qsizetype> lists[] = {{QStringLiteral("particles"), limits.particles},
                                                   {QStringLiteral("springs"), limits.springs},
                                                   {QStringLiteral("planes"), limits.planes},
                                                   {QStringLiteral("contactImpulses"), limits.contactImpulses},
                                                   {QStringLiteral("triangles"), limits.triangles}};
    for (const auto &[key, limit] : lists)
        if (const qsizetype count = lengths.value(key, 0); count > limit) {
            result.error = sourceName + u": "_s + key + u": "_s +
                           QStringLiteral("too many %1: %2, more than the limit of %3").arg(key).arg(count).arg(limit);
            return result;
        }

    // the scene, read token by token into its final lists
    if (std::optional<LoadResult> read = readSceneText(json, sourceName, lengths))
        return std::move(*read);

    // not one JSON object: why, from QJsonDocument or (a large text) the reader's own place of the fault
    result.error = jsonSyntaxError(json, sourceName);
    return result;
}

QString nestingError(const QByteArray &json, const QString &sourceName, int maxDepth)
{
    const qsizetype offset = tooDeepAt(json, maxDepth);
    if (offset < 0)
        return {};
    const QString path = scanJson(json, offset).pathAtStop;
    const QString reason = QStringLiteral("nested too deeply: more than the limit of %1 levels of arrays and objects (%2)")
                               .arg(maxDepth)
                               .arg(location(json, offset));
    return path.isEmpty() ? sourceName + u": "_s + reason : sourceName + u": "_s + path + u": "_s + reason;
}

QString jsonSyntaxError(const QByteArray &json, const QString &sourceName)
{
    // a large text's message comes from the reader's own place of the fault: QJsonDocument would
    // build a tree of all the text before it (216 MB for a 21 MB file cut at its end) only for
    // the words of its message
    if (json.size() > kLargestTextForQtMessage) {
        JsonPull pull(json, JsonStrings::Check);
        for (JsonToken token = pull.next(); token != JsonToken::End && token != JsonToken::Error; token = pull.next()) {
        }
        const qsizetype offset = pull.errorOffset() >= 0 ? pull.errorOffset() : json.size();
        // the token the reader stopped at, to its end: a number or a word cut off by the end
        qsizetype faultEnd = offset;
        while (faultEnd < json.size() && isWordChar(json[faultEnd]))
            ++faultEnd;
        // a cut file in the words a small one gets: the scan up to the fault says what is still open
        const JsonScan scan = scanJson(json, offset);
        const QString reason = endsTooEarly(json, faultEnd, scan)
                                   ? u"the file ends too early: is it truncated? (it stops "_s + location(json, offset) + u")"_s
                                   : u"not valid JSON (a fault in the text "_s + location(json, offset) + u")"_s;
        const QString &path = scan.pathAtStop;
        return path.isEmpty() ? sourceName + u": "_s + reason : sourceName + u": "_s + path + u": "_s + reason;
    }

    // QJsonDocument says why
    QJsonParseError parseError{};
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return syntaxErrorOf(json, parseError, sourceName);
    if (!document.isObject())
        return sourceName + u": expected a JSON object at the top level, got "_s +
               describe(document.isArray() ? QJsonValue(document.array()) : QJsonValue());
    return sourceName + u": not valid JSON"_s;
}

QString readFileWithin(const QString &path, qint64 limitBytes, QByteArray &bytes)
{
    const QString shown = QDir::toNativeSeparators(path);
    QFile file(path);
    errno = 0;
    if (!file.open(QIODevice::ReadOnly))
        return shown + u": cannot open: "_s + explainFailure(path, false, errno, file.errorString());

    // a file over the size limit is refused unread
    if (!file.isSequential() && file.size() > limitBytes)
        return tooLarge(shown, file.size(), limitBytes);

    // a device with no size (a pipe, /dev/zero) is read in pieces, stopping one byte past the limit
    errno = 0;
    bytes.clear();
    if (file.isSequential()) {
        constexpr qint64 kPiece = 1 << 16;
        while (bytes.size() <= limitBytes) {
            const QByteArray piece = file.read(std::min(kPiece, limitBytes + 1 - bytes.size()));
            if (piece.isEmpty())
                break;
            bytes += piece;
            // a zero byte is no text's (/dev/zero, a binary or UTF-16 stream): what came is enough
            // for the message, and reading on to the limit would only cost time and memory
            if (piece.contains('\0'))
                break;
        }
    } else {
        bytes = file.readAll();
    }
    if (file.error() != QFileDevice::NoError)
        return shown + u": cannot read: "_s + explainFailure(path, false, errno, file.errorString());
    if (file.isSequential() && bytes.size() > limitBytes)
        return shown + u": the file is too large: more than the limit of "_s + byteCount(limitBytes);
    return QString();
}

LoadResult loadScene(const QString &path, const LoadLimits &limits)
{
    // a file within the limits that still needs more memory than is free (a large file where
    // little is left, or one that is not JSON, whose message QJsonDocument makes from a tree of
    // all the text before the fault): a message, with the file's bytes let go, never an abort
    // that takes the editor's unsaved work with it
    try {
        QByteArray json;
        if (QString failure = readFileWithin(path, limits.fileBytes, json); !failure.isEmpty()) {
            LoadResult result;
            result.error = std::move(failure);
            return result;
        }
        return parseScene(json, QDir::toNativeSeparators(path), limits);
    } catch (const std::bad_alloc &) {
        LoadResult result;
        result.error = cannotLoadForMemory(QDir::toNativeSeparators(path));
        result.outOfMemory = true;
        return result;
    }
}

QByteArray sceneToJson(const core::SceneDesc &scene)
{
    const core::Settings &s = scene.settings;
    const std::string_view integrator = core::integratorName(s.integrator);
    auto flag = [](bool value) { return QByteArray(value ? "true" : "false"); };
    QByteArray out;

    // header
    out += "{\n    \"format\": \"" + QByteArray(kSceneFormatName.data(), kSceneFormatName.size()) + "\",\n";
    out += "    \"version\": " + QByteArray::number(kSceneFormatVersion) + ",\n";
    out += "    \"name\": ";
    appendString(out, scene.name);
    out += ",\n";

    // settings, one per line
    out += "    \"settings\": {\n";
    out += "        \"timeStep\": " + formatNumber(s.timeStep) + ",\n";
    out += "        \"substeps\": " + QByteArray::number(s.substeps) + ",\n";
    // only when on, so that files written before it existed read back byte for byte
    if (s.autoSubsteps)
        out += "        \"autoSubsteps\": true,\n";
    out += "        \"integrator\": ";
    appendString(out, integrator);
    // only when not the default, so that files written before it existed read back byte for byte
    if (s.xpbdIterations != 1)
        out += ",\n        \"xpbdIterations\": " + QByteArray::number(s.xpbdIterations);
    if (s.solverIterations != core::Settings{}.solverIterations)
        out += ",\n        \"solverIterations\": " + QByteArray::number(s.solverIterations);
    out += ",\n        \"tolerance\": " + formatNumber(s.tolerance);
    // only with a state that adaptive-rk45 stepped: the step size it was about to try
    if (s.adaptiveStep)
        out += ",\n        \"adaptiveStep\": " + formatNumber(*s.adaptiveStep);
    out += ",\n        \"gravity\": ";
    appendVector(out, s.gravity);
    out += ",\n        \"viscosity\": " + formatNumber(s.viscosity) + ",\n";
    out += "        \"restitution\": " + formatNumber(s.restitution) + ",\n";
    out += "        \"contactSolver\": ";
    appendString(out, core::contactSolverName(s.contactSolver));
    out += ",\n        \"friction\": " + formatNumber(s.friction) + ",\n";
    // only when set: unset, the static coefficient follows friction
    if (s.staticFriction)
        out += "        \"staticFriction\": " + formatNumber(*s.staticFriction) + ",\n";
    out += "        \"planeCollisions\": " + flag(s.planeCollisions) + ",\n";
    out += "        \"particleCollisions\": " + flag(s.particleCollisions);
    // the sheets' collisions, only where they differ from the defaults, so that other files stay
    // as they were
    if (s.triangleCollisions)
        out += ",\n        \"triangleCollisions\": true";
    if (!s.selfCollision)
        out += ",\n        \"selfCollision\": false";
    if (s.thickness > 0.0)
        out += ",\n        \"thickness\": " + formatNumber(s.thickness);
    // rolling resistance and spinning friction likewise
    if (s.rollingFriction != 0.0)
        out += ",\n        \"rollingFriction\": " + formatNumber(s.rollingFriction);
    if (s.spinningFriction != 0.0)
        out += ",\n        \"spinningFriction\": " + formatNumber(s.spinningFriction);
    if (!s.spin)
        out += ",\n        \"spin\": false";
    out += "\n    },\n";

    // particles, springs and planes, one per line
    appendList(out, "particles", scene.particles, false, [&](const core::ParticleDesc &p) {
        out += "{\"position\": ";
        appendVector(out, p.position);
        out += ", \"velocity\": ";
        appendVector(out, p.velocity);
        out += ", \"mass\": " + formatNumber(p.mass) + ", \"radius\": " + formatNumber(p.radius) +
               ", \"pinned\": " + flag(p.pinned);
        // the spin and orientation only where a particle has them, so that other files stay as they were
        if (!isPositiveZero(p.angularVelocity)) {
            out += ", \"angularVelocity\": ";
            appendVector(out, p.angularVelocity);
        }
        if (p.orientation != Eigen::Vector4d(1.0, 0.0, 0.0, 0.0)) {
            out += ", \"orientation\": [" + formatNumber(p.orientation[0]) + ", " + formatNumber(p.orientation[1]) +
                   ", " + formatNumber(p.orientation[2]) + ", " + formatNumber(p.orientation[3]) + ']';
        }
        out += '}';
    });
    appendList(out, "springs", scene.springs, false, [&](const core::SpringDesc &spring) {
        out += "{\"particles\": [" + QByteArray::number(spring.a) + ", " + QByteArray::number(spring.b) +
               "], \"stiffness\": " + formatNumber(spring.stiffness) +
               ", \"damping\": " + formatNumber(spring.damping) +
               ", \"restLength\": " + formatNumber(spring.restLength);
        // only breakable springs say so, so files of unbreakable ones stay as they were
        if (spring.breakStrain > 0.0)
            out += ", \"breakStrain\": " + formatNumber(spring.breakStrain);
        out += '}';
    });
    appendList(out, "planes", scene.planes, true, [&](const core::PlaneDesc &plane) { appendPlane(out, plane); });
    // the particle the arrow keys push, only in scenes that have one
    if (scene.steerable >= 0) {
        out.chop(1);  // the newline after the planes' closing bracket
        out += ",\n    \"steerable\": " + QByteArray::number(scene.steerable) + '\n';
    }
    // a saved run's contact impulses, only when it has some
    if (!scene.contactImpulses.empty()) {
        out.chop(1);
        out += ",\n";
        appendList(out, "contactImpulses", scene.contactImpulses, true, [&](const core::ContactImpulse &c) {
            out += "{\"particle\": " + QByteArray::number(c.i);
            out += c.withPlane() ? ", \"plane\": " + QByteArray::number(c.plane())
                                 : ", \"other\": " + QByteArray::number(c.j);
            out += ", \"normal\": " + formatNumber(c.normal) + ", \"friction\": ";
            appendVector(out, c.friction);
            out += '}';
        });
    }
    // the sheets' triangles, only when the scene lists them
    if (!scene.triangles.empty()) {
        out.chop(1);
        out += ",\n";
        appendList(out, "triangles", scene.triangles, true, [&](const std::array<int, 3> &t) {
            out += '[' + QByteArray::number(t[0]) + ", " + QByteArray::number(t[1]) + ", " + QByteArray::number(t[2]) + ']';
        });
    }
    // the imported meshes, only when there are some
    if (!scene.meshes.empty()) {
        out.chop(1);
        out += ",\n";
        appendList(out, "meshes", scene.meshes, true, [&](const core::MeshDesc &mesh) { appendMesh(out, mesh); });
    }
    out += "}\n";
    return out;
}

SaveResult saveScene(const QString &path, const core::SceneDesc &scene)
{
    const QString shown = QDir::toNativeSeparators(path);
    // atomic, flushed and synced (core/io/safe_write.h); a FIFO or a device is refused untouched
    if (const QString failure = writeFileAtomically(path, sceneToJson(scene)); !failure.isEmpty())
        return {shown + u": cannot save: "_s + failure};
    return {};
}

}  // namespace io
