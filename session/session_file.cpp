// Design note. A recording is read as a scene file is (core/io/scene_file.cpp): its bytes checked
// for UTF-8 text, then token by token (core/io/json_pull.h), keeping the span of each object and
// array to read again when its members are wanted, never a tree of the document, which took ten
// times the file's size. Its scenes are strings of whole scene files: they are checked, not
// decoded, until each is read, and let go once its scene is made.

#include "session_file.h"

#include "core/io/json_pull.h"
#include "core/io/load_checks.h"
#include "core/io/safe_write.h"
#include "core/io/scene_file.h"
#include "core/model/validate.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <utility>
#include <variant>
#include <vector>

namespace ui {

namespace {

using namespace Qt::Literals::StringLiterals;
using io::JsonPull;
using io::JsonStrings;
using io::JsonToken;

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

template <int Rows>
QByteArray matrix(const Eigen::Matrix<double, Rows, Eigen::Dynamic> &m)
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
    // the spins, where the scene can turn
    if (state.angularVelocity.cols() > 0)
        out += ",\n        \"angularVelocities\": " + matrix(state.angularVelocity) +
               ",\n        \"orientations\": " + matrix(state.orientation);
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
            else if constexpr (std::is_same_v<E, StrikeEdit>)
                return "\"edit\": \"strike\", \"particle\": " + QByteArray::number(e.particle) +
                       ", \"velocityChange\": " + vector(e.velocityChange) +
                       ", \"spinChange\": " + vector(e.spinChange);
            else
                return "\"edit\": \"none\"";  // requests that change nothing are never recorded
        },
        message);
}

// one value of a recording's text, as the pull reader met it: a number or a string as read, an
// object or an array as the span of its text, read again when its members are wanted, so that no
// tree of the document is ever made (a QJsonDocument of a recording took ten times its size)
struct Value {
    JsonToken kind = JsonToken::End;  // End: absent
    double number = 0.0;              // the sign of zero kept
    QByteArray text;                  // a string's, as UTF-8
    QByteArrayView span;              // an object's or array's text, bracket to bracket

    bool isNumber() const { return kind == JsonToken::Number; }
    bool isString() const { return kind == JsonToken::String; }
    bool isArray() const { return kind == JsonToken::BeginArray; }
    bool isObject() const { return kind == JsonToken::BeginObject; }
    // a string's text; empty for anything else, as QJsonValue::toString() gives
    QString string() const { return isString() ? QString::fromUtf8(text) : QString(); }
};

// the value whose first token the reader has just given; false where the text breaks the grammar
bool readValue(JsonPull &in, JsonToken first, QByteArrayView text, Value &out)
{
    out = Value{};
    out.kind = first;
    switch (first) {
    case JsonToken::Number: out.number = in.number(); return true;
    case JsonToken::String: out.text = in.utf8(); return true;
    case JsonToken::BeginObject:
    case JsonToken::BeginArray: {
        const qsizetype start = in.offset() - 1;  // its opening bracket
        if (!in.skipRest(first))
            return false;
        out.span = text.sliced(start, in.offset() - start);
        return true;
    }
    case JsonToken::True:
    case JsonToken::False:
    case JsonToken::Null: return true;
    default: return false;
    }
}

// each element of an array in turn, given to each(index, element) until it returns false
template <typename Each>
bool forEachElement(const Value &array, Each each)
{
    if (!array.isArray())
        return true;
    JsonPull in(array.span, JsonStrings::Check);
    in.next();  // its '['
    qsizetype index = 0;
    for (JsonToken token = in.next(); token != JsonToken::EndArray; token = in.next(), ++index) {
        Value element;
        if (!readValue(in, token, array.span, element) || !each(index, element))
            return false;
    }
    return true;
}

// the number of elements of an array (0 for anything else)
qsizetype sizeOf(const Value &array)
{
    qsizetype size = 0;
    forEachElement(array, [&size](qsizetype, const Value &) { return ++size > 0; });
    return size;
}

// an object's members, by key (anything else has none, as QJsonValue::toObject() gives); the
// whole text was checked before, keys that come twice refused
class Members {
public:
    explicit Members(const Value &object)
    {
        if (!object.isObject())
            return;
        JsonPull in(object.span, JsonStrings::Check);
        in.next();  // its '{'
        for (JsonToken token = in.next(); token == JsonToken::Key; token = in.next()) {
            m_members.emplace_back(in.text(), Value{});
            if (!readValue(in, in.next(), object.span, m_members.back().second))
                break;
        }
    }
    // the member's value; absent (kind End) when there is none
    const Value &value(QLatin1StringView key) const
    {
        static const Value absent;
        const auto found = std::find_if(m_members.begin(), m_members.end(), [&](const auto &m) { return m.first == key; });
        return found == m_members.end() ? absent : found->second;
    }
    // the same, moved out: a scene's text is let go once it is read
    Value take(QLatin1StringView key)
    {
        const auto found = std::find_if(m_members.begin(), m_members.end(), [&](const auto &m) { return m.first == key; });
        return found == m_members.end() ? Value{} : std::move(found->second);
    }

private:
    std::vector<std::pair<QString, Value>> m_members;
};

// reads one recording, stopping at the first problem with its JSON path
class Reader {
public:
    explicit Reader(QString source) : m_source(std::move(source)) {}
    QString error;

    bool fail(const QString &path, const QString &reason)
    {
        if (error.isEmpty())
            error = m_source + u": "_s + (path.isEmpty() ? QString() : path + u": "_s) + reason;
        return false;
    }
    bool number(const Value &value, const QString &path, double &out)
    {
        if (!value.isNumber())
            return fail(path, u"expected a number"_s);
        out = value.number;
        return true;
    }
    bool count(const Value &value, const QString &path, std::uint64_t &out)
    {
        double d = 0.0;
        if (!number(value, path, d))
            return false;
        if (!(d >= 0.0 && d <= 9007199254740992.0 && d == std::floor(d)))
            return fail(path, u"expected a whole number of at least 0"_s);
        out = static_cast<std::uint64_t>(d);
        return true;
    }
    // numbers into out, one per element (a path is made only for the message)
    template <typename Out>
    bool numbers(const Value &array, const QString &path, Out *out)
    {
        return forEachElement(array, [&](qsizetype i, const Value &element) {
            if (!element.isNumber())
                return fail(path + u"[%1]"_s.arg(i), u"expected a number"_s);
            out[i] = element.number;
            return true;
        });
    }
    bool vector3(const Value &value, const QString &path, Eigen::Vector3d &out)
    {
        if (!value.isArray() || sizeOf(value) != 3)
            return fail(path, u"expected 3 numbers"_s);
        return numbers(value, path, out.data());
    }
    template <int Rows>
    bool matrix(const Value &value, const QString &path, qsizetype columns, Eigen::Matrix<double, Rows, Eigen::Dynamic> &out)
    {
        if (!value.isArray() || sizeOf(value) != Rows * columns)
            return fail(path, u"expected %1 numbers (%2 per particle)"_s.arg(Rows * columns).arg(Rows));
        out.resize(Rows, columns);
        return numbers(value, path, out.data());
    }
    // a core::State of the scene, as stateJson() writes it
    bool state(const Value &value, const QString &path, const core::SceneDesc &scene, core::State &out)
    {
        if (!value.isObject())
            return fail(path, u"expected an object"_s);
        const Members o(value);
        const auto particles = qsizetype(scene.particles.size());
        if (!number(o.value("time"_L1), path + u".time"_s, out.time) ||
            !count(o.value("step"_L1), path + u".step"_s, out.step) ||
            !number(o.value("adaptiveStep"_L1), path + u".adaptiveStep"_s, out.adaptiveStep) ||
            !matrix(o.value("positions"_L1), path + u".positions"_s, particles, out.position) ||
            !matrix(o.value("velocities"_L1), path + u".velocities"_s, particles, out.velocity))
            return false;
        if (o.value("angularVelocities"_L1).isArray() &&
            (!matrix(o.value("angularVelocities"_L1), path + u".angularVelocities"_s, particles, out.angularVelocity) ||
             !matrix(o.value("orientations"_L1), path + u".orientations"_s, particles, out.orientation)))
            return false;
        const bool applied = forEachElement(o.value("applied"_L1), [&](qsizetype i, const Value &element) {
            const QString at = path + u".applied[%1]"_s.arg(i);
            const Members a(element);
            int p = -1;
            Eigen::Vector3d force;
            if (!particle(a.value("particle"_L1), at + u".particle"_s, scene, p) ||
                !vector3(a.value("force"_L1), at + u".force"_s, force))
                return false;
            if (p < 0)
                return fail(at + u".particle"_s, u"expected a particle of the scene"_s);
            core::setAppliedForce(out, p, force);
            return true;
        });
        if (!applied)
            return false;
        const Value &breaks = o.value("breaks"_L1);
        const auto springs = std::uint64_t(scene.springs.size());
        if (sizeOf(breaks) > 0)
            out.springBroken.assign(scene.springs.size(), 0);
        const bool broken = forEachElement(breaks, [&](qsizetype i, const Value &element) {
            const QString at = path + u".breaks[%1]"_s.arg(i);
            const Members b(element);
            std::uint64_t spring = 0;
            core::SpringBreak entry;
            if (!count(b.value("spring"_L1), at + u".spring"_s, spring) ||
                !count(b.value("step"_L1), at + u".step"_s, entry.step) ||
                !number(b.value("time"_L1), at + u".time"_s, entry.time))
                return false;
            if (spring >= springs)
                return fail(at + u".spring"_s, springs == 0 ? u"expected a spring of the scene, which has none"_s
                                                            : u"expected a spring of the scene (0 to %1)"_s.arg(qlonglong(springs) - 1));
            if (out.springBroken[spring] != 0)
                return fail(at + u".spring"_s, u"spring %1 broke twice"_s.arg(spring));
            out.springBroken[spring] = 1;
            entry.spring = int(spring);
            out.breaks.push_back(entry);
            return true;
        });
        if (!broken)
            return false;
        const Value &impulses = o.value("contactImpulses"_L1);
        out.contactImpulses.resize(std::size_t(sizeOf(impulses)));
        const bool pressed = forEachElement(impulses, [&](qsizetype k, const Value &element) {
            const QString at = path + u".contactImpulses[%1]"_s.arg(k);
            double values[6] = {};
            if (!element.isArray() || sizeOf(element) != 6)
                return fail(at, u"expected 6 numbers: particle, other (a plane as -1 - plane), normal, friction"_s);
            if (!numbers(element, at, values))
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
            return true;
        });
        if (!pressed)
            return false;
        if (const auto problem = core::findContactImpulseProblem(out.contactImpulses, scene.particles.size(),
                                                                 scene.planes.size()))
            return fail(path + u"."_s + QString::fromStdString(problem->path), QString::fromStdString(problem->message));
        std::sort(out.contactImpulses.begin(), out.contactImpulses.end());
        return true;
    }
    // a scene file's text, read as a scene file is; the text is let go once the scene is made
    bool scene(Value value, const QString &path, std::shared_ptr<const core::SceneDesc> &out)
    {
        if (!value.isString())
            return fail(path, u"expected the text of a scene file"_s);
        io::LoadResult loaded = io::parseScene(std::exchange(value.text, QByteArray()), m_source + u" "_s + path);
        if (!loaded.ok()) {
            if (error.isEmpty())
                error = loaded.error;
            return false;
        }
        out = std::make_shared<const core::SceneDesc>(std::move(*loaded.scene));
        return true;
    }
    bool particle(const Value &value, const QString &path, const core::SceneDesc &scene, int &out)
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

    bool message(Members &object, const QString &path, const core::SceneDesc &current, Message &out)
    {
        const QString kind = object.value("edit"_L1).string();
        if (kind == u"set-scene"_s) {
            SetSceneEdit e;
            const QString change = object.value("change"_L1).string();
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
            if (!scene(object.take("scene"_L1), path + u".scene"_s, e.scene))
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
            e.seed = object.value("seed"_L1).string().toULongLong(&ok);
            if (!ok)
                return fail(path + u".seed"_s, u"expected a seed as a string of digits"_s);
            if (!number(object.value("speed"_L1), path + u".speed"_s, e.speed))
                return false;
            out = e;
        } else if (kind == u"steer"_s) {
            SteerEdit e;
            if (!particle(object.value("particle"_L1), path + u".particle"_s, current, e.particle) ||
                !vector3(object.value("force"_L1), path + u".force"_s, e.force))
                return false;
            out = e;
        } else if (kind == u"grab"_s) {
            GrabEdit e;
            if (!particle(object.value("particle"_L1), path + u".particle"_s, current, e.particle) ||
                !vector3(object.value("target"_L1), path + u".target"_s, e.target))
                return false;
            out = e;
        } else if (kind == u"strike"_s) {
            StrikeEdit e;
            if (!particle(object.value("particle"_L1), path + u".particle"_s, current, e.particle) ||
                !vector3(object.value("velocityChange"_L1), path + u".velocityChange"_s, e.velocityChange) ||
                !vector3(object.value("spinChange"_L1), path + u".spinChange"_s, e.spinChange))
                return false;
            out = e;
        } else {
            return fail(path + u".edit"_s, u"unknown edit \"%1\""_s.arg(kind));
        }
        return true;
    }

private:
    QString m_source;
};

// a recording from its text; may throw std::bad_alloc
RecordingLoad readRecording(const QByteArray &json, const QString &sourceName)
{
    RecordingLoad result;
    const auto refuse = [&](const QString &reason) {
        result.error = sourceName + u": "_s + reason;
        return result;
    };

    // bytes that are not UTF-8 text (UTF-16, /dev/zero), in the scene files' words
    if (const QString problem = io::encodingProblem(json); !problem.isEmpty())
        return refuse(problem);

    // the depth first, as a scene file's (the reader keeps a little for each level open)
    if (QString deep = io::nestingError(json, sourceName); !deep.isEmpty()) {
        result.error = std::move(deep);
        return result;
    }

    // the grammar of the whole text then, in one pass that keeps nothing, with a syntax error in
    // the scene files' words (and from the same reader past 16 MiB, so no tree of the text is made)
    JsonPull whole(json, JsonStrings::Check);
    const JsonToken first = whole.next();
    if (!whole.skipRest(first) || whole.next() != JsonToken::End) {
        result.error = io::jsonSyntaxError(json, sourceName);
        return result;
    }
    if (first != JsonToken::BeginObject)
        return refuse(u"expected a JSON object at the top level, got an array"_s);
    // which of two values was meant cannot be known, and Qt's replacement character would change
    // the text without a word: both refused as a scene file refuses them
    if (!whole.duplicateKey().isNull())
        return refuse(whole.duplicateKey() + u": this key comes twice in its object: keep one"_s);
    if (!whole.loneSurrogate().isNull())
        return refuse(whole.loneSurrogate() +
                      u": a \\u escape is half of a UTF-16 pair (a lone surrogate), which is no character"_s);

    Value text;
    text.kind = JsonToken::BeginObject;
    text.span = json;
    Members root(text);
    if (root.value("format"_L1).string() != kFormat)
        return refuse(u"not a Springlab replay (format must be \"springlab-replay\")"_s);
    // the version as written: 1.5 is not version 1, nor version 0
    const Value &version = root.value("version"_L1);
    if (!version.isNumber() || version.number != kVersion) {
        const QString written =
            version.isNumber() ? QString::number(version.number, 'g', 17) : QStringLiteral("missing or not a number");
        return refuse(u"version %1 is not supported (this Springlab reads version %2)"_s.arg(written).arg(kVersion));
    }
    Reader reader(sourceName);
    auto r = std::make_shared<SessionRecording>();
    bool ok = reader.scene(root.take("scene"_L1), u"scene"_s, r->scene) &&
              reader.state(root.value("start"_L1), u"start"_s, *r->scene, r->start);
    // each edit is checked against the scene it applies to
    std::shared_ptr<const core::SceneDesc> current = r->scene;
    const Value &edits = root.value("edits"_L1);
    if (ok && !edits.isArray())
        ok = reader.fail(u"edits"_s, u"expected an array"_s);
    std::uint64_t previous = 0;
    ok = ok && forEachElement(edits, [&](qsizetype i, const Value &element) {
        const QString path = u"edits[%1]"_s.arg(i);
        Members edit(element);
        SessionRecording::Entry entry;
        if (!reader.count(edit.value("steps"_L1), path + u".steps"_s, entry.steps) ||
            !reader.message(edit, path, *current, entry.message))
            return false;
        if (entry.steps < previous)
            return reader.fail(path + u".steps"_s, u"goes back in time (%1 after %2)"_s.arg(entry.steps).arg(previous));
        previous = entry.steps;
        if (const auto *set = std::get_if<SetSceneEdit>(&entry.message))
            current = set->scene;
        r->entries.push_back(std::move(entry));
        return true;
    });
    ok = ok && reader.count(root.value("steps"_L1), u"steps"_s, r->steps);
    if (ok && r->steps < previous)
        ok = reader.fail(u"steps"_s, u"fewer than the last edit's (%1)"_s.arg(previous));
    if (ok) {
        r->finalHash = root.value("hash"_L1).string().toULongLong(&ok, 16);
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

RecordingLoad outOfMemory(const QString &sourceName)
{
    RecordingLoad result;
    result.error = io::cannotLoadForMemory(sourceName);
    result.outOfMemory = true;
    return result;
}

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
    // running out of memory part way is a message, never an abort
    try {
        return readRecording(json, sourceName);
    } catch (const std::bad_alloc &) {
        return outOfMemory(sourceName);
    }
}

RecordingLoad loadRecording(const QString &path, qint64 limitBytes)
{
    // read as a scene file is (io::loadScene): the size checked before reading, a device read in
    // pieces up to the limit or its first zero byte, and running out of memory a message, made
    // once the file's bytes are let go
    try {
        QByteArray json;
        if (QString failure = io::readFileWithin(path, limitBytes, json); !failure.isEmpty()) {
            RecordingLoad result;
            result.error = std::move(failure);
            return result;
        }
        return readRecording(json, path);
    } catch (const std::bad_alloc &) {
        return outOfMemory(path);
    }
}

QString saveRecording(const QString &path, const SessionRecording &recording)
{
    if (const QString failure = io::writeFileAtomically(path, recordingToJson(recording)); !failure.isEmpty())
        return path + u": cannot save: "_s + failure;
    return {};
}

}  // namespace ui
