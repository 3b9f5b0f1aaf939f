#include "session_file.h"

#include "core/io/json_scan.h"
#include "core/io/safe_write.h"
#include "core/io/scene_file.h"
#include "core/model/validate.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <variant>

namespace ui {

namespace {

using namespace Qt::Literals::StringLiterals;

constexpr QLatin1String kFormat("springlab-replay");
constexpr int kVersion = 1;

// a JSON string: the scene file's text, quotes, backslashes and control characters escaped
QByteArray quoted(const QByteArray &text)
{
    QByteArray out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        if (c == '\n')
            out += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20)
            out += "\\u00" + QByteArray::number(static_cast<unsigned char>(c), 16).rightJustified(2, '0');
        else
            out += c;
    }
    return out + '"';
}

QByteArray vector(const Eigen::Vector3d &v)
{
    return '[' + io::formatNumber(v.x()) + ", " + io::formatNumber(v.y()) + ", " + io::formatNumber(v.z()) + ']';
}

QByteArray matrix(const Eigen::Matrix3Xd &m)
{
    QByteArray out = "[";
    for (Eigen::Index i = 0; i < m.size(); ++i)
        out += (i ? ", " : "") + io::formatNumber(m.data()[i]);
    return out + ']';
}

// the whole core::State: what a resume needs. The applied forces, the broken springs and the
// breaks are left out while there are none
QByteArray stateJson(const core::State &state)
{
    QByteArray out = "{\"time\": " + io::formatNumber(state.time) + ", \"step\": " + QByteArray::number(state.step) +
                     ", \"adaptiveStep\": " + io::formatNumber(state.adaptiveStep) +
                     ",\n        \"positions\": " + matrix(state.position) + ",\n        \"velocities\": " + matrix(state.velocity);
    if (state.appliedCount > 0) {
        out += ",\n        \"applied\": [";
        bool first = true;
        for (Eigen::Index i = 0; i < state.applied.cols(); ++i) {
            if (state.applied.col(i).isZero(0.0))
                continue;
            out += QByteArray(first ? "" : ", ") + "{\"particle\": " + QByteArray::number(qlonglong(i)) + ", \"force\": [" +
                   io::formatNumber(state.applied(0, i)) + ", " + io::formatNumber(state.applied(1, i)) + ", " +
                   io::formatNumber(state.applied(2, i)) + "]}";
            first = false;
        }
        out += "]";
    }
    if (!state.breaks.empty()) {
        // the flags follow from the breaks: a spring is broken once it broke
        out += ",\n        \"breaks\": [";
        for (std::size_t i = 0; i < state.breaks.size(); ++i) {
            const core::SpringBreak &b = state.breaks[i];
            out += QByteArray(i ? ", " : "") + "{\"spring\": " + QByteArray::number(b.spring) +
                   ", \"step\": " + QByteArray::number(b.step) + ", \"time\": " + io::formatNumber(b.time) + "}";
        }
        out += "]";
    }
    if (!state.contactImpulses.empty()) {
        // [i, j, normal, friction x, y, z] each, j < 0 for plane -1 - j (core::ContactImpulse)
        out += ",\n        \"contactImpulses\": [";
        for (std::size_t k = 0; k < state.contactImpulses.size(); ++k) {
            const core::ContactImpulse &c = state.contactImpulses[k];
            out += QByteArray(k ? ", [" : "[") + QByteArray::number(c.i) + ", " + QByteArray::number(c.j) + ", " +
                   io::formatNumber(c.normal) + ", " + io::formatNumber(c.friction.x()) + ", " +
                   io::formatNumber(c.friction.y()) + ", " + io::formatNumber(c.friction.z()) + "]";
        }
        out += "]";
    }
    return out + "}";
}

const char *changeName(SceneChange change)
{
    switch (change) {
    case SceneChange::Replace: return "replace";
    case SceneChange::Structure: return "structure";
    case SceneChange::Parameters: return "parameters";
    case SceneChange::InitialConditions: return "initial-conditions";
    }
    return "replace";
}

QByteArray messageJson(const Message &message)
{
    return std::visit(
        [](const auto &e) -> QByteArray {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, SetSceneEdit>)
                return "\"edit\": \"set-scene\", \"change\": \"" + QByteArray(changeName(e.change)) +
                       "\", \"scene\": " + quoted(io::sceneToJson(*e.scene));
            else if constexpr (std::is_same_v<E, Play>)
                return "\"edit\": \"play\"";
            else if constexpr (std::is_same_v<E, Pause>)
                return "\"edit\": \"pause\"";
            else if constexpr (std::is_same_v<E, StepOnce>)
                return "\"edit\": \"step-once\"";
            else if constexpr (std::is_same_v<E, Reset>)
                return "\"edit\": \"reset\"";
            else if constexpr (std::is_same_v<E, TiltEdit>)
                return "\"edit\": \"tilt\", \"seed\": \"" + QByteArray::number(e.seed) +
                       "\", \"speed\": " + io::formatNumber(e.speed);
            else if constexpr (std::is_same_v<E, SteerEdit>)
                return "\"edit\": \"steer\", \"particle\": " + QByteArray::number(e.particle) +
                       ", \"force\": " + vector(e.force);
            else if constexpr (std::is_same_v<E, GrabEdit>)
                return "\"edit\": \"grab\", \"particle\": " + QByteArray::number(e.particle) +
                       ", \"target\": " + vector(e.target);
            else
                return "\"edit\": \"none\"";  // requests that change nothing are never recorded
        },
        message);
}

// reads one recording, stopping at the first problem with its JSON path
class Reader {
public:
    Reader(QString source, const QByteArray &json) : m_source(std::move(source))
    {
        // Qt's parser reads "-0" as +0: the scan says which numbers were negative zeros, so that
        // a recorded state keeps every bit (only a file with a "-0" in it can hold one)
        if (json.contains("-0"))
            m_negativeZeros = io::scanJson(json).negativeZeros;
    }
    QString error;

    bool fail(const QString &path, const QString &reason)
    {
        if (error.isEmpty())
            error = m_source + u": "_s + (path.isEmpty() ? QString() : path + u": "_s) + reason;
        return false;
    }
    bool number(const QJsonValue &value, const QString &path, double &out)
    {
        if (!value.isDouble())
            return fail(path, u"expected a number"_s);
        out = value.toDouble();
        if (out == 0.0 && m_negativeZeros.contains(path))
            out = -0.0;
        return true;
    }
    bool count(const QJsonValue &value, const QString &path, std::uint64_t &out)
    {
        double d = 0.0;
        if (!number(value, path, d))
            return false;
        if (!(d >= 0.0 && d <= 9007199254740992.0 && d == std::floor(d)))
            return fail(path, u"expected a whole number of at least 0"_s);
        out = static_cast<std::uint64_t>(d);
        return true;
    }
    bool vector3(const QJsonValue &value, const QString &path, Eigen::Vector3d &out)
    {
        const QJsonArray array = value.toArray();
        if (!value.isArray() || array.size() != 3)
            return fail(path, u"expected 3 numbers"_s);
        for (int axis = 0; axis < 3; ++axis)
            if (!number(array[axis], path + u"[%1]"_s.arg(axis), out[axis]))
                return false;
        return true;
    }
    bool matrix(const QJsonValue &value, const QString &path, qsizetype columns, Eigen::Matrix3Xd &out)
    {
        const QJsonArray array = value.toArray();
        if (!value.isArray() || array.size() != 3 * columns)
            return fail(path, u"expected %1 numbers (3 per particle)"_s.arg(3 * columns));
        out.resize(3, columns);
        for (qsizetype i = 0; i < array.size(); ++i)
            if (!number(array[i], path + u"[%1]"_s.arg(i), out.data()[i]))
                return false;
        return true;
    }
    // a core::State of the scene, as stateJson() writes it
    bool state(const QJsonValue &value, const QString &path, const core::SceneDesc &scene, core::State &out)
    {
        if (!value.isObject())
            return fail(path, u"expected an object"_s);
        const QJsonObject o = value.toObject();
        const auto particles = qsizetype(scene.particles.size());
        if (!number(o.value(u"time"_s), path + u".time"_s, out.time) ||
            !count(o.value(u"step"_s), path + u".step"_s, out.step) ||
            !number(o.value(u"adaptiveStep"_s), path + u".adaptiveStep"_s, out.adaptiveStep) ||
            !matrix(o.value(u"positions"_s), path + u".positions"_s, particles, out.position) ||
            !matrix(o.value(u"velocities"_s), path + u".velocities"_s, particles, out.velocity))
            return false;
        const QJsonArray applied = o.value(u"applied"_s).toArray();
        for (qsizetype i = 0; i < applied.size(); ++i) {
            const QString at = path + u".applied[%1]"_s.arg(i);
            int p = -1;
            Eigen::Vector3d force;
            if (!particle(applied[i].toObject().value(u"particle"_s), at + u".particle"_s, scene, p) ||
                !vector3(applied[i].toObject().value(u"force"_s), at + u".force"_s, force))
                return false;
            if (p < 0)
                return fail(at + u".particle"_s, u"expected a particle of the scene"_s);
            core::setAppliedForce(out, p, force);
        }
        const QJsonArray breaks = o.value(u"breaks"_s).toArray();
        const auto springs = std::uint64_t(scene.springs.size());
        if (!breaks.isEmpty())
            out.springBroken.assign(scene.springs.size(), 0);
        for (qsizetype i = 0; i < breaks.size(); ++i) {
            const QString at = path + u".breaks[%1]"_s.arg(i);
            const QJsonObject b = breaks[i].toObject();
            std::uint64_t spring = 0;
            core::SpringBreak entry;
            if (!count(b.value(u"spring"_s), at + u".spring"_s, spring) || !count(b.value(u"step"_s), at + u".step"_s, entry.step) ||
                !number(b.value(u"time"_s), at + u".time"_s, entry.time))
                return false;
            if (spring >= springs)
                return fail(at + u".spring"_s, springs == 0 ? u"expected a spring of the scene, which has none"_s
                                                            : u"expected a spring of the scene (0 to %1)"_s.arg(qlonglong(springs) - 1));
            if (out.springBroken[spring] != 0)
                return fail(at + u".spring"_s, u"spring %1 broke twice"_s.arg(spring));
            out.springBroken[spring] = 1;
            entry.spring = int(spring);
            out.breaks.push_back(entry);
        }
        const QJsonArray impulses = o.value(u"contactImpulses"_s).toArray();
        out.contactImpulses.resize(std::size_t(impulses.size()));
        for (qsizetype k = 0; k < impulses.size(); ++k) {
            const QString at = path + u".contactImpulses[%1]"_s.arg(k);
            const QJsonArray e = impulses[k].toArray();
            double values[6] = {};
            if (e.size() != 6)
                return fail(at, u"expected 6 numbers: particle, other (a plane as -1 - plane), normal, friction"_s);
            for (int v = 0; v < 6; ++v)
                if (!number(e[v], at + u"[%1]"_s.arg(v), values[v]))
                    return false;
            // whole numbers within an int; the scene's own check (core::findContactImpulseProblem) does the rest
            for (int v = 0; v < 2; ++v)
                if (!(std::abs(values[v]) <= 1e9) || std::trunc(values[v]) != values[v])
                    return fail(at + u"[%1]"_s.arg(v), u"expected a particle or plane index"_s);
            core::ContactImpulse &c = out.contactImpulses[std::size_t(k)];
            c.i = int(values[0]);
            c.j = int(values[1]);
            c.normal = values[2];
            c.friction = Eigen::Vector3d(values[3], values[4], values[5]);
        }
        if (const auto problem = core::findContactImpulseProblem(out.contactImpulses, scene.particles.size(),
                                                                 scene.planes.size()))
            return fail(path + u"."_s + QString::fromStdString(problem->path), QString::fromStdString(problem->message));
        std::sort(out.contactImpulses.begin(), out.contactImpulses.end());
        return true;
    }
    bool scene(const QJsonValue &value, const QString &path, std::shared_ptr<const core::SceneDesc> &out)
    {
        if (!value.isString())
            return fail(path, u"expected the text of a scene file"_s);
        const io::LoadResult loaded = io::parseScene(value.toString().toUtf8(), m_source + u" "_s + path);
        if (!loaded.ok()) {
            if (error.isEmpty())
                error = loaded.error;
            return false;
        }
        out = std::make_shared<const core::SceneDesc>(*loaded.scene);
        return true;
    }
    bool particle(const QJsonValue &value, const QString &path, const core::SceneDesc &scene, int &out)
    {
        double d = 0.0;
        if (!number(value, path, d))
            return false;
        if (!(d >= -1.0 && d < double(scene.particles.size()) && d == std::floor(d)))
            return fail(path, scene.particles.empty()
                                  ? u"expected -1: the scene has no particles"_s
                                  : u"expected -1 or a particle of the scene (0 to %1)"_s.arg(qlonglong(scene.particles.size()) - 1));
        out = int(d);
        return true;
    }

    bool message(const QJsonObject &object, const QString &path, const core::SceneDesc &current, Message &out)
    {
        const QString kind = object.value(u"edit"_s).toString();
        if (kind == u"set-scene"_s) {
            SetSceneEdit e;
            const QString change = object.value(u"change"_s).toString();
            if (change == u"replace"_s)
                e.change = SceneChange::Replace;
            else if (change == u"structure"_s)
                e.change = SceneChange::Structure;
            else if (change == u"parameters"_s)
                e.change = SceneChange::Parameters;
            else if (change == u"initial-conditions"_s)
                e.change = SceneChange::InitialConditions;
            else
                return fail(path + u".change"_s,
                            u"expected \"replace\", \"structure\", \"parameters\" or \"initial-conditions\""_s);
            if (!scene(object.value(u"scene"_s), path + u".scene"_s, e.scene))
                return false;
            out = e;
        } else if (kind == u"play"_s) {
            out = Play{};
        } else if (kind == u"pause"_s) {
            out = Pause{};
        } else if (kind == u"step-once"_s) {
            out = StepOnce{};
        } else if (kind == u"reset"_s) {
            out = Reset{};
        } else if (kind == u"tilt"_s) {
            TiltEdit e;
            bool ok = false;
            e.seed = object.value(u"seed"_s).toString().toULongLong(&ok);
            if (!ok)
                return fail(path + u".seed"_s, u"expected a seed as a string of digits"_s);
            if (!number(object.value(u"speed"_s), path + u".speed"_s, e.speed))
                return false;
            out = e;
        } else if (kind == u"steer"_s) {
            SteerEdit e;
            if (!particle(object.value(u"particle"_s), path + u".particle"_s, current, e.particle) ||
                !vector3(object.value(u"force"_s), path + u".force"_s, e.force))
                return false;
            out = e;
        } else if (kind == u"grab"_s) {
            GrabEdit e;
            if (!particle(object.value(u"particle"_s), path + u".particle"_s, current, e.particle) ||
                !vector3(object.value(u"target"_s), path + u".target"_s, e.target))
                return false;
            out = e;
        } else {
            return fail(path + u".edit"_s, u"unknown edit \"%1\""_s.arg(kind));
        }
        return true;
    }

private:
    QString m_source;
    QSet<QString> m_negativeZeros;  // JSON paths of the numbers written as a negative zero
};

}  // namespace

QByteArray recordingToJson(const SessionRecording &r)
{
    QByteArray out = "{\n    \"format\": \"springlab-replay\",\n    \"version\": " + QByteArray::number(kVersion) + ",\n";
    out += "    \"scene\": " + quoted(io::sceneToJson(*r.scene)) + ",\n";
    out += "    \"start\": " + stateJson(r.start) + ",\n";
    out += "    \"edits\": [";
    for (std::size_t i = 0; i < r.entries.size(); ++i)
        out += QByteArray(i ? ",\n" : "\n") + "        {\"steps\": " + QByteArray::number(r.entries[i].steps) + ", " +
               messageJson(r.entries[i].message) + '}';
    out += r.entries.empty() ? "],\n" : "\n    ],\n";
    out += "    \"steps\": " + QByteArray::number(r.steps) + ",\n";
    out += "    \"hash\": \"" + QByteArray::number(r.finalHash, 16).rightJustified(16, '0') + "\"\n}\n";
    return out;
}

RecordingLoad parseRecording(const QByteArray &json, const QString &sourceName)
{
    RecordingLoad result;
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    Reader reader(sourceName, json);
    if (parseError.error != QJsonParseError::NoError) {
        result.error = io::jsonSyntaxError(json, parseError, sourceName);
        return result;
    }
    if (!document.isObject()) {
        result.error = sourceName + u": expected a JSON object at the top level, got an array"_s;
        return result;
    }
    const QJsonObject root = document.object();
    if (root.value(u"format"_s).toString() != kFormat) {
        result.error = sourceName + u": not a Springlab replay (format must be \"springlab-replay\")"_s;
        return result;
    }
    // the version as written: 1.5 is not version 1, nor version 0
    const QJsonValue version = root.value(u"version"_s);
    if (!version.isDouble() || version.toDouble() != kVersion) {
        const QString written = version.isDouble() ? QString::number(version.toDouble(), 'g', 17)
                                                   : QStringLiteral("missing or not a number");
        result.error = sourceName + u": version %1 is not supported (this Springlab reads version %2)"_s
                                        .arg(written)
                                        .arg(kVersion);
        return result;
    }
    auto r = std::make_shared<SessionRecording>();
    bool ok = reader.scene(root.value(u"scene"_s), u"scene"_s, r->scene) &&
              reader.state(root.value(u"start"_s), u"start"_s, *r->scene, r->start);
    // each edit is checked against the scene it applies to
    std::shared_ptr<const core::SceneDesc> current = r->scene;
    const QJsonArray edits = root.value(u"edits"_s).toArray();
    if (ok && !root.value(u"edits"_s).isArray())
        ok = reader.fail(u"edits"_s, u"expected an array"_s);
    std::uint64_t previous = 0;
    for (qsizetype i = 0; ok && i < edits.size(); ++i) {
        const QString path = u"edits[%1]"_s.arg(i);
        SessionRecording::Entry entry;
        ok = reader.count(edits[i].toObject().value(u"steps"_s), path + u".steps"_s, entry.steps) &&
             reader.message(edits[i].toObject(), path, *current, entry.message);
        if (ok && entry.steps < previous)
            ok = reader.fail(path + u".steps"_s, u"goes back in time (%1 after %2)"_s.arg(entry.steps).arg(previous));
        if (!ok)
            break;
        previous = entry.steps;
        if (const auto *set = std::get_if<SetSceneEdit>(&entry.message))
            current = set->scene;
        r->entries.push_back(std::move(entry));
    }
    ok = ok && reader.count(root.value(u"steps"_s), u"steps"_s, r->steps);
    if (ok && r->steps < previous)
        ok = reader.fail(u"steps"_s, u"fewer than the last edit's (%1)"_s.arg(previous));
    if (ok) {
        r->finalHash = root.value(u"hash"_s).toString().toULongLong(&ok, 16);
        if (!ok)
            reader.fail(u"hash"_s, u"expected 16 hexadecimal digits"_s);
    }
    if (!ok) {
        result.error = reader.error;
        return result;
    }
    result.recording = std::move(r);
    return result;
}

RecordingLoad loadRecording(const QString &path, qint64 limitBytes)
{
    QByteArray json;
    if (const QString failure = io::readFileWithin(path, limitBytes, json); !failure.isEmpty())
        return {nullptr, failure};
    return parseRecording(json, path);
}

QString saveRecording(const QString &path, const SessionRecording &recording)
{
    if (const QString failure = io::writeFileAtomically(path, recordingToJson(recording)); !failure.isEmpty())
        return path + u": cannot save: "_s + failure;
    return {};
}

}  // namespace ui
