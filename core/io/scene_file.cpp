// Design note. Reading goes through QJsonDocument, then a Reader walks the objects and stops at
// the first problem with one message; value ranges are checked afterwards by core::findProblem(),
// so a range is written once (core/parameters.cpp). Writing is done by hand rather than by
// QJsonDocument::toJson() for two reasons: Qt writes -0.0 as "0" (losing the sign bit), and its
// indented style puts every number of every vector on a line of its own, which makes a cloth
// unreadable. Numbers are written with std::to_chars, whose output is the shortest text that
// reads back as the same double. Qt's parser also turns a "-0" literal into +0; json_scan.h
// finds those literals so the Reader can give the sign back. The limits (io::LoadLimits) come first:
// the size before the file is read, the nesting depth by one pass over the bytes before Qt parses
// them, the item counts before any item is made, so a huge or hostile file gets a message instead
// of exhausting memory.

#include "scene_file.h"

#include "json_scan.h"
#include "safe_write.h"
#include "scene_words.h"

#include "core/solver_names.h"
#include "core/validate.h"

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
#include <initializer_list>
#include <limits>
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

using namespace Qt::Literals::StringLiterals;

constexpr QLatin1String kFormatName("springlab-scene");

enum class Need { Required, Optional };

// walks a parsed document into a SceneDesc, stopping at the first problem
class Reader {
public:
    // scan: the pass over the text (json_scan.h): its negative zeros, a key that comes twice in
    // one object (Qt keeps the last), a lone surrogate
    Reader(const QString &source, JsonScan scan, const LoadLimits &limits) : m_source(source), m_limits(limits)
    {
        m_negativeZeros = std::move(scan.negativeZeros);
        m_duplicateKey = std::move(scan.duplicateKey);
        m_loneSurrogate = std::move(scan.loneSurrogate);
    }

    QString error() const { return m_error; }
    QStringList warnings() const { return m_warnings; }

    bool readScene(const QJsonObject &root, core::SceneDesc &scene);

private:
    bool fail(const QString &path, const QString &reason)
    {
        if (m_error.isEmpty())
            m_error = path.isEmpty() ? m_source + u": "_s + reason : m_source + u": "_s + path + u": "_s + reason;
        return false;
    }

    // a list longer than its limit is refused before anything is made for it
    bool withinLimit(const QJsonArray &array, const QString &path, qsizetype limit)
    {
        if (array.size() <= limit)
            return true;
        return fail(path, QStringLiteral("too many %1: %2, more than the limit of %3")
                              .arg(path)
                              .arg(array.size())
                              .arg(limit));
    }

    bool expected(const QString &path, const QString &what, const QJsonValue &got)
    {
        return fail(path, u"expected "_s + what + u", got "_s + describe(got));
    }

    void warnUnknownKeys(const QJsonObject &object, const QString &path, std::initializer_list<QLatin1String> known)
    {
        for (auto it = object.begin(); it != object.end(); ++it)
            if (std::find(known.begin(), known.end(), it.key()) == known.end())
                m_warnings += m_source + u": "_s + memberPath(path, it.key()) + u": unknown key, ignored"_s;
    }

    // one value of each kind
    bool read(const QJsonValue &value, const QString &path, double &out)
    {
        if (!value.isDouble())
            return expected(path, QStringLiteral("a number"), value);
        out = value.toDouble();
        if (out == 0.0 && m_negativeZeros.contains(path))
            out = -0.0;
        return true;
    }

    bool read(const QJsonValue &value, const QString &path, int &out)
    {
        if (!value.isDouble())
            return expected(path, QStringLiteral("an integer"), value);
        const double number = value.toDouble();
        if (std::trunc(number) != number)
            return fail(path, u"expected an integer, got "_s + QString::fromLatin1(formatNumber(number)));
        if (number < std::numeric_limits<int>::min() || number > std::numeric_limits<int>::max())
            return fail(path, u"the integer "_s + QString::fromLatin1(formatNumber(number)) + u" is too large"_s);
        out = static_cast<int>(number);
        return true;
    }

    bool read(const QJsonValue &value, const QString &path, bool &out)
    {
        if (!value.isBool())
            return expected(path, QStringLiteral("true or false"), value);
        out = value.toBool();
        return true;
    }

    bool read(const QJsonValue &value, const QString &path, QString &out)
    {
        if (!value.isString())
            return expected(path, QStringLiteral("a string"), value);
        out = value.toString();
        return true;
    }

    bool read(const QJsonValue &value, const QString &path, Eigen::Vector3d &out)
    {
        if (!value.isArray())
            return expected(path, QStringLiteral("an array of 3 numbers"), value);
        const QJsonArray array = value.toArray();
        if (array.size() != 3)
            return fail(path, u"expected an array of 3 numbers, got "_s + QString::number(array.size()));
        for (int axis = 0; axis < 3; ++axis)
            if (!read(array[axis], elementPath(path, axis), out[axis]))
                return false;
        return true;
    }

    bool read(const QJsonValue &value, const QString &path, Eigen::Vector2d &out)
    {
        if (!value.isArray())
            return expected(path, QStringLiteral("an array of 2 numbers"), value);
        const QJsonArray array = value.toArray();
        if (array.size() != 2)
            return fail(path, u"expected an array of 2 numbers, got "_s + QString::number(array.size()));
        for (int axis = 0; axis < 2; ++axis)
            if (!read(array[axis], elementPath(path, axis), out[axis]))
                return false;
        return true;
    }

    bool read(const QJsonValue &value, const QString &path, QJsonObject &out)
    {
        if (!value.isObject())
            return expected(path, QStringLiteral("an object"), value);
        out = value.toObject();
        return true;
    }

    bool read(const QJsonValue &value, const QString &path, QJsonArray &out)
    {
        if (!value.isArray())
            return expected(path, QStringLiteral("an array"), value);
        out = value.toArray();
        return true;
    }

    // a member of an object; an optional one that is absent leaves out as it was
    template <typename T>
    bool member(const QJsonObject &object, const QString &parent, QLatin1String key, Need need, T &out,
                bool *present = nullptr)
    {
        const auto it = object.constFind(key);
        if (present)
            *present = it != object.constEnd();
        if (it == object.constEnd())
            return need == Need::Optional ||
                   fail(memberPath(parent, key), QStringLiteral("missing: this key is required"));
        return read(it.value(), memberPath(parent, key), out);
    }

    bool readHeader(const QJsonObject &root);
    bool readSettings(const QJsonObject &root, core::Settings &settings);
    bool readParticles(const QJsonObject &root, std::vector<core::ParticleDesc> &particles);
    bool readSprings(const QJsonObject &root, core::SceneDesc &scene);
    bool readPlanes(const QJsonObject &root, std::vector<core::PlaneDesc> &planes);
    bool readContactImpulses(const QJsonObject &root, std::vector<core::ContactImpulse> &impulses);

    QString m_source;
    LoadLimits m_limits;
    QString m_error;
    QStringList m_warnings;
    QSet<QString> m_negativeZeros;
    QString m_duplicateKey;  // the first member whose key came before in its object (null: none)
    QString m_loneSurrogate;  // the first string with half a UTF-16 pair (null: none)
    QSet<QString> m_derivedRestLengths;  // paths of the rest lengths taken from the particles' distance
};

bool Reader::readHeader(const QJsonObject &root)
{
    // format: a file of another kind says only that
    const auto format = root.constFind(QLatin1String("format"));
    if (format == root.constEnd())
        return fail(QStringLiteral("format"),
                    u"missing: not a Springlab scene (expected \"format\": \""_s + kFormatName + u"\")"_s);
    if (!format->isString() || format->toString() != kFormatName)
        return fail(QStringLiteral("format"),
                    u"not a Springlab scene (expected \""_s + kFormatName + u"\", got "_s +
                        (format->isString() ? u'"' + format->toString() + u'"' : describe(*format)) + u")"_s);

    // version: this build reads every version up to its own
    int version = 0;
    if (!member(root, {}, QLatin1String("version"), Need::Required, version))
        return false;
    if (version > kSceneFormatVersion)
        return fail(QStringLiteral("version"),
                    QStringLiteral("the file is version %1, newer than this build of Springlab reads "
                                   "(version %2 at most); open it with a newer Springlab")
                        .arg(version)
                        .arg(kSceneFormatVersion));
    if (version < 1)
        return fail(QStringLiteral("version"),
                    QStringLiteral("there is no version %1 (versions start at 1)").arg(version));
    return true;
}

bool Reader::readSettings(const QJsonObject &root, core::Settings &settings)
{
    // the settings object and every key in it are optional: an absent one keeps its default
    QJsonObject object;
    const QString path = QStringLiteral("settings");
    if (!member(root, {}, QLatin1String("settings"), Need::Optional, object))
        return false;
    const std::string_view defaultName = core::integratorName(settings.integrator);
    QString integrator = QString::fromUtf8(defaultName.data(), static_cast<qsizetype>(defaultName.size()));
    const std::string_view defaultSolver = core::contactSolverName(settings.contactSolver);
    QString contactSolver = QString::fromUtf8(defaultSolver.data(), static_cast<qsizetype>(defaultSolver.size()));
    double staticFriction = 0.0;
    bool hasStaticFriction = false;
    double adaptiveStep = 0.0;
    bool hasAdaptiveStep = false;
    if (!member(object, path, QLatin1String("timeStep"), Need::Optional, settings.timeStep) ||
        !member(object, path, QLatin1String("substeps"), Need::Optional, settings.substeps) ||
        !member(object, path, QLatin1String("autoSubsteps"), Need::Optional, settings.autoSubsteps) ||
        !member(object, path, QLatin1String("integrator"), Need::Optional, integrator) ||
        !member(object, path, QLatin1String("tolerance"), Need::Optional, settings.tolerance) ||
        !member(object, path, QLatin1String("adaptiveStep"), Need::Optional, adaptiveStep, &hasAdaptiveStep) ||
        !member(object, path, QLatin1String("gravity"), Need::Optional, settings.gravity) ||
        !member(object, path, QLatin1String("viscosity"), Need::Optional, settings.viscosity) ||
        !member(object, path, QLatin1String("restitution"), Need::Optional, settings.restitution) ||
        !member(object, path, QLatin1String("contactSolver"), Need::Optional, contactSolver) ||
        !member(object, path, QLatin1String("friction"), Need::Optional, settings.friction) ||
        !member(object, path, QLatin1String("staticFriction"), Need::Optional, staticFriction, &hasStaticFriction) ||
        !member(object, path, QLatin1String("planeCollisions"), Need::Optional, settings.planeCollisions) ||
        !member(object, path, QLatin1String("particleCollisions"), Need::Optional, settings.particleCollisions))
        return false;

    // the integrator by name
    QString unknown;
    const auto chosen = integratorNamed(integrator, unknown);
    if (!chosen)
        return fail(QStringLiteral("settings.integrator"), unknown);
    settings.integrator = *chosen;

    // the contact solver by name; the static coefficient only when given (else it follows friction)
    const auto solver = contactSolverNamed(contactSolver, unknown);
    if (!solver)
        return fail(QStringLiteral("settings.contactSolver"), unknown);
    settings.contactSolver = *solver;
    if (hasStaticFriction)
        settings.staticFriction = staticFriction;
    if (hasAdaptiveStep)
        settings.adaptiveStep = adaptiveStep;

    warnUnknownKeys(object, path,
                    {QLatin1String("timeStep"), QLatin1String("substeps"), QLatin1String("autoSubsteps"),
                     QLatin1String("integrator"),
                     QLatin1String("tolerance"), QLatin1String("adaptiveStep"), QLatin1String("gravity"), QLatin1String("viscosity"), QLatin1String("restitution"),
                     QLatin1String("contactSolver"), QLatin1String("friction"), QLatin1String("staticFriction"),
                     QLatin1String("planeCollisions"), QLatin1String("particleCollisions")});
    return true;
}

bool Reader::readParticles(const QJsonObject &root, std::vector<core::ParticleDesc> &particles)
{
    QJsonArray array;
    if (!member(root, {}, QLatin1String("particles"), Need::Required, array) ||
        !withinLimit(array, QStringLiteral("particles"), m_limits.particles))
        return false;
    particles.resize(static_cast<std::size_t>(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = elementPath(QStringLiteral("particles"), i);
        core::ParticleDesc &particle = particles[static_cast<std::size_t>(i)];
        QJsonObject object;
        if (!read(array[i], path, object) ||
            !member(object, path, QLatin1String("position"), Need::Required, particle.position) ||
            !member(object, path, QLatin1String("velocity"), Need::Optional, particle.velocity) ||
            !member(object, path, QLatin1String("mass"), Need::Required, particle.mass) ||
            !member(object, path, QLatin1String("radius"), Need::Required, particle.radius) ||
            !member(object, path, QLatin1String("pinned"), Need::Optional, particle.pinned))
            return false;
        warnUnknownKeys(object, path,
                        {QLatin1String("position"), QLatin1String("velocity"), QLatin1String("mass"),
                         QLatin1String("radius"), QLatin1String("pinned")});
    }
    return true;
}

bool Reader::readSprings(const QJsonObject &root, core::SceneDesc &scene)
{
    QJsonArray array;
    if (!member(root, {}, QLatin1String("springs"), Need::Required, array) ||
        !withinLimit(array, QStringLiteral("springs"), m_limits.springs))
        return false;
    scene.springs.resize(static_cast<std::size_t>(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = elementPath(QStringLiteral("springs"), i);
        core::SpringDesc &spring = scene.springs[static_cast<std::size_t>(i)];
        QJsonObject object;
        QJsonArray ends;
        bool hasRestLength = false;
        if (!read(array[i], path, object) || !member(object, path, QLatin1String("particles"), Need::Required, ends))
            return false;

        // the two ends: particle indices; findProblem() checks they exist and differ
        const QString endsPath = memberPath(path, QLatin1String("particles"));
        if (ends.size() != 2)
            return fail(endsPath, u"expected an array of 2 particle indices, got "_s + QString::number(ends.size()));
        if (!read(ends[0], elementPath(endsPath, 0), spring.a) || !read(ends[1], elementPath(endsPath, 1), spring.b))
            return false;

        if (!member(object, path, QLatin1String("stiffness"), Need::Required, spring.stiffness) ||
            !member(object, path, QLatin1String("damping"), Need::Required, spring.damping) ||
            !member(object, path, QLatin1String("restLength"), Need::Optional, spring.restLength, &hasRestLength) ||
            !member(object, path, QLatin1String("breakStrain"), Need::Optional, spring.breakStrain))
            return false;
        warnUnknownKeys(object, path,
                        {QLatin1String("particles"), QLatin1String("stiffness"), QLatin1String("damping"),
                         QLatin1String("restLength"), QLatin1String("breakStrain")});

        // no rest length: the spring rests at its initial length
        const auto count = static_cast<int>(scene.particles.size());
        if (!hasRestLength && spring.a >= 0 && spring.a < count && spring.b >= 0 && spring.b < count) {
            spring.restLength = (scene.particles[static_cast<std::size_t>(spring.a)].position -
                                 scene.particles[static_cast<std::size_t>(spring.b)].position)
                                    .norm();
            m_derivedRestLengths.insert(memberPath(path, QLatin1String("restLength")));
        }
    }
    return true;
}

bool Reader::readPlanes(const QJsonObject &root, std::vector<core::PlaneDesc> &planes)
{
    QJsonArray array;
    if (!member(root, {}, QLatin1String("planes"), Need::Required, array) ||
        !withinLimit(array, QStringLiteral("planes"), m_limits.planes))
        return false;
    planes.resize(static_cast<std::size_t>(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = elementPath(QStringLiteral("planes"), i);
        core::PlaneDesc &plane = planes[static_cast<std::size_t>(i)];
        QJsonObject object;
        double friction = 0.0;
        bool hasFriction = false;
        if (!read(array[i], path, object) ||
            !member(object, path, QLatin1String("normal"), Need::Required, plane.normal) ||
            !member(object, path, QLatin1String("offset"), Need::Required, plane.offset) ||
            !member(object, path, QLatin1String("twoSided"), Need::Optional, plane.twoSided) ||
            !member(object, path, QLatin1String("friction"), Need::Optional, friction, &hasFriction) ||
            !member(object, path, QLatin1String("size"), Need::Optional, plane.size) ||
            !member(object, path, QLatin1String("centre"), Need::Optional, plane.centre) ||
            !member(object, path, QLatin1String("axis"), Need::Optional, plane.axis))
            return false;
        // a plane without friction of its own takes the settings'
        if (hasFriction)
            plane.friction = friction;
        warnUnknownKeys(object, path,
                        {QLatin1String("normal"), QLatin1String("offset"), QLatin1String("twoSided"),
                         QLatin1String("friction"), QLatin1String("size"), QLatin1String("centre"),
                         QLatin1String("axis")});
    }
    return true;
}

// optional: a saved run's contact impulses, with a particle ("other") or with a plane
bool Reader::readContactImpulses(const QJsonObject &root, std::vector<core::ContactImpulse> &impulses)
{
    QJsonArray array;
    if (!member(root, {}, QLatin1String("contactImpulses"), Need::Optional, array) ||
        !withinLimit(array, QStringLiteral("contactImpulses"), m_limits.contactImpulses))
        return false;
    impulses.resize(static_cast<std::size_t>(array.size()));
    for (qsizetype k = 0; k < array.size(); ++k) {
        const QString path = elementPath(QStringLiteral("contactImpulses"), k);
        core::ContactImpulse &impulse = impulses[static_cast<std::size_t>(k)];
        QJsonObject object;
        int plane = 0;
        bool hasOther = false;
        bool hasPlane = false;
        if (!read(array[k], path, object) ||
            !member(object, path, QLatin1String("particle"), Need::Required, impulse.i) ||
            !member(object, path, QLatin1String("other"), Need::Optional, impulse.j, &hasOther) ||
            !member(object, path, QLatin1String("plane"), Need::Optional, plane, &hasPlane) ||
            !member(object, path, QLatin1String("normal"), Need::Required, impulse.normal) ||
            !member(object, path, QLatin1String("friction"), Need::Required, impulse.friction))
            return false;
        if (hasOther == hasPlane)
            return fail(path, QStringLiteral("needs either \"other\" (a particle) or \"plane\", not both or neither"));
        // findProblem() checks the plane exists
        if (hasPlane) {
            if (plane < 0)
                return fail(memberPath(path, QLatin1String("plane")),
                            u"plane index "_s + QString::number(plane) + u" is out of range"_s);
            impulse.j = -1 - plane;
        } else if (impulse.j < 0) {
            return fail(memberPath(path, QLatin1String("other")),
                        u"particle index "_s + QString::number(impulse.j) + u" is out of range"_s);
        }
        warnUnknownKeys(object, path,
                        {QLatin1String("particle"), QLatin1String("other"), QLatin1String("plane"),
                         QLatin1String("normal"), QLatin1String("friction")});
    }
    return true;
}

bool Reader::readScene(const QJsonObject &root, core::SceneDesc &scene)
{
    // structure and types, in file order
    QString name;
    if (!readHeader(root))
        return false;
    // which of two values for one key was meant cannot be known: neither is taken
    if (!m_duplicateKey.isNull())
        return fail(m_duplicateKey, QStringLiteral("this key comes twice in its object: keep one"));
    // Qt would read it as a replacement character: the text would change without a word
    if (!m_loneSurrogate.isNull())
        return fail(m_loneSurrogate, QStringLiteral("a \\u escape is half of a UTF-16 pair (a lone surrogate), "
                                                    "which is no character"));
    if (!member(root, {}, QLatin1String("name"), Need::Required, name) ||
        !readSettings(root, scene.settings) || !readParticles(root, scene.particles) || !readSprings(root, scene) ||
        !readPlanes(root, scene.planes) ||
        !member(root, {}, QLatin1String("steerable"), Need::Optional, scene.steerable) ||
        !readContactImpulses(root, scene.contactImpulses))
        return false;
    scene.name = name.toStdString();
    warnUnknownKeys(root, {},
                    {QLatin1String("format"), QLatin1String("version"), QLatin1String("name"),
                     QLatin1String("settings"), QLatin1String("particles"), QLatin1String("springs"),
                     QLatin1String("planes"), QLatin1String("steerable"), QLatin1String("contactImpulses")});

    // values: the same checks and messages as the editor's
    if (const auto problem = core::findProblem(scene)) {
        const QString path = QString::fromStdString(problem->path);
        // a rest length the file did not give is the distance between the spring's particles
        const QString why = m_derivedRestLengths.contains(path)
                                ? u" (the distance between its particles, taken since the spring gives no restLength)"_s
                                : QString();
        return fail(path, QString::fromStdString(problem->message) + why);
    }

    // planes are kept with unit normals
    for (core::PlaneDesc &plane : scene.planes)
        plane.normal = core::unitNormal(plane.normal);
    return true;
}

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
        .arg(json.left(offset).count('\n') + 1)
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
    if (error.error == QJsonParseError::IllegalNumber && numeric) {
        double value = 0.0;
        const auto parsed = std::from_chars(token.constData(), token.constData() + token.size(), value);
        const bool tiny = token.contains("e-") || token.contains("E-");
        if (parsed.ec == std::errc::result_out_of_range)
            reason = u"the number "_s + QString::fromLatin1(token) +
                     (tiny ? u" is too close to zero for a double ("_s
                           : u" is too large for a double: JSON has no infinity or NaN ("_s) +
                     where + u")"_s;
        else
            reason = QString::fromLatin1(token) + u" is not a valid number ("_s + where + u")"_s;
    } else if (error.error == QJsonParseError::IllegalNumber || error.error == QJsonParseError::IllegalValue) {
        const QByteArray lower = token.toLower();
        if (lower.contains("nan") || lower.contains("inf"))
            reason =
                QString::fromLatin1(token) + u" is not a JSON number: JSON has no NaN or infinity ("_s + where + u")"_s;
    }

    // the text stops in the middle of a value: objects or arrays left open and nothing after the
    // place the parser gave up
    qsizetype textEnd = json.size();
    while (textEnd > 0 && std::isspace(static_cast<unsigned char>(json[textEnd - 1])))
        --textEnd;
    if (std::max(offset, tokenEnd) >= textEnd && scanJson(json).openAtStop > 0)
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
    if (const qsizetype offset = tooDeepAt(json, limits.nestingDepth); offset >= 0) {
        const QString path = scanJson(json, offset).pathAtStop;
        const QString reason = QStringLiteral("nested too deeply: more than the limit of %1 levels of arrays and "
                                              "objects (%2)")
                                   .arg(limits.nestingDepth)
                                   .arg(location(json, offset));
        result.error = path.isEmpty() ? sourceName + u": "_s + reason : sourceName + u": "_s + path + u": "_s + reason;
        return result;
    }

    // the lists' lengths, counted on the text before the parser builds anything of them
    JsonScan scan = scanJson(json);
    const std::pair<QString, qsizetype> lists[] = {{QStringLiteral("particles"), limits.particles},
                                                   {QStringLiteral("springs"), limits.springs},
                                                   {QStringLiteral("planes"), limits.planes},
                                                   {QStringLiteral("contactImpulses"), limits.contactImpulses}};
    for (const auto &[key, limit] : lists)
        if (const qsizetype count = scan.topLevelArrays.value(key, 0); count > limit) {
            result.error = sourceName + u": "_s + key + u": "_s +
                           QStringLiteral("too many %1: %2, more than the limit of %3").arg(key).arg(count).arg(limit);
            return result;
        }

    // syntax
    QJsonParseError parseError{};
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        result.error = syntaxErrorOf(json, parseError, sourceName);
        return result;
    }
    if (!document.isObject()) {
        result.error = sourceName + u": expected a JSON object at the top level, got "_s +
                       describe(document.isArray() ? QJsonValue(document.array()) : QJsonValue());
        return result;
    }

    // structure, types and values; the scene is handed out only when all of it is right
    Reader reader(sourceName, std::move(scan), limits);
    core::SceneDesc scene;
    const bool ok = reader.readScene(document.object(), scene);
    result.warnings = reader.warnings();
    if (ok)
        result.scene = std::move(scene);
    else
        result.error = reader.error();
    return result;
}

QString jsonSyntaxError(const QByteArray &json, const QJsonParseError &error, const QString &sourceName)
{
    return syntaxErrorOf(json, error, sourceName);
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
    QByteArray json;
    if (QString failure = readFileWithin(path, limits.fileBytes, json); !failure.isEmpty()) {
        LoadResult result;
        result.error = std::move(failure);
        return result;
    }
    return parseScene(json, QDir::toNativeSeparators(path), limits);
}

QByteArray sceneToJson(const core::SceneDesc &scene)
{
    const core::Settings &s = scene.settings;
    const std::string_view integrator = core::integratorName(s.integrator);
    auto flag = [](bool value) { return QByteArray(value ? "true" : "false"); };
    QByteArray out;

    // header
    out += "{\n    \"format\": \"" + QByteArray(kFormatName.data(), kFormatName.size()) + "\",\n";
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
    out += "        \"particleCollisions\": " + flag(s.particleCollisions) + "\n    },\n";

    // particles, springs and planes, one per line
    appendList(out, "particles", scene.particles, false, [&](const core::ParticleDesc &p) {
        out += "{\"position\": ";
        appendVector(out, p.position);
        out += ", \"velocity\": ";
        appendVector(out, p.velocity);
        out += ", \"mass\": " + formatNumber(p.mass) + ", \"radius\": " + formatNumber(p.radius) +
               ", \"pinned\": " + flag(p.pinned) + '}';
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
