// Design note. Each family of keys (settings, particles, springs, planes) has one table: the key as
// the scene file spells it, the kind of value it takes, and how it is written into the element.
// No range is written here: the changed scene is checked by core::findProblem against the
// parameter table (core/model/parameters.h), as the file itself was when it was loaded. An
// override that reaches no element is written into a scene of stand-in elements instead, so that
// its value meets the same check.

#include "sim_set.h"

#include "core/io/scene_words.h"
#include "core/model/validate.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QStringList>

#include <cmath>
#include <limits>
#include <iterator>

namespace app {

using namespace Qt::Literals::StringLiterals;

namespace {

enum class Kind { Number, Integer, Boolean, Vector, IntegratorName, ContactSolverName };

template <typename Element>
struct Field {
    const char *name;
    Kind kind;
    void (*set)(Element &, const OverrideValue &);
};

// every settings key of the scene format (docs/scene-format.md)
constexpr Field<core::Settings> kSettingsFields[] = {
    {"timeStep", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.timeStep = v.number; }},
    {"substeps", Kind::Integer, [](core::Settings &s, const OverrideValue &v) { s.substeps = v.integer; }},
    {"xpbdIterations", Kind::Integer, [](core::Settings &s, const OverrideValue &v) { s.xpbdIterations = v.integer; }},
    {"solverIterations", Kind::Integer,
     [](core::Settings &s, const OverrideValue &v) { s.solverIterations = v.integer; }},
    {"autoSubsteps", Kind::Boolean, [](core::Settings &s, const OverrideValue &v) { s.autoSubsteps = v.flag; }},
    {"integrator", Kind::IntegratorName, [](core::Settings &s, const OverrideValue &v) { s.integrator = v.integrator; }},
    {"tolerance", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.tolerance = v.number; }},
    {"adaptiveStep", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.adaptiveStep = v.number; }},
    {"gravity", Kind::Vector, [](core::Settings &s, const OverrideValue &v) { s.gravity = v.vector; }},
    {"viscosity", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.viscosity = v.number; }},
    {"restitution", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.restitution = v.number; }},
    {"contactSolver", Kind::ContactSolverName,
     [](core::Settings &s, const OverrideValue &v) { s.contactSolver = v.contactSolver; }},
    {"friction", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.friction = v.number; }},
    {"staticFriction", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.staticFriction = v.number; }},
    {"spin", Kind::Boolean, [](core::Settings &s, const OverrideValue &v) { s.spin = v.flag; }},
    {"rollingFriction", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.rollingFriction = v.number; }},
    {"spinningFriction", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.spinningFriction = v.number; }},
    {"planeCollisions", Kind::Boolean, [](core::Settings &s, const OverrideValue &v) { s.planeCollisions = v.flag; }},
    {"particleCollisions", Kind::Boolean,
     [](core::Settings &s, const OverrideValue &v) { s.particleCollisions = v.flag; }},
    {"triangleCollisions", Kind::Boolean,
     [](core::Settings &s, const OverrideValue &v) { s.triangleCollisions = v.flag; }},
    {"selfCollision", Kind::Boolean, [](core::Settings &s, const OverrideValue &v) { s.selfCollision = v.flag; }},
    {"thickness", Kind::Number, [](core::Settings &s, const OverrideValue &v) { s.thickness = v.number; }},
};

// a particle's values; a spring's rest length that the file left out was measured from the
// file's positions, before any --set of a position
constexpr Field<core::ParticleDesc> kParticleFields[] = {
    {"mass", Kind::Number, [](core::ParticleDesc &p, const OverrideValue &v) { p.mass = v.number; }},
    {"radius", Kind::Number, [](core::ParticleDesc &p, const OverrideValue &v) { p.radius = v.number; }},
    {"pinned", Kind::Boolean, [](core::ParticleDesc &p, const OverrideValue &v) { p.pinned = v.flag; }},
    {"position", Kind::Vector, [](core::ParticleDesc &p, const OverrideValue &v) { p.position = v.vector; }},
    {"velocity", Kind::Vector, [](core::ParticleDesc &p, const OverrideValue &v) { p.velocity = v.vector; }},
    {"angularVelocity", Kind::Vector,
     [](core::ParticleDesc &p, const OverrideValue &v) { p.angularVelocity = v.vector; }},
};

// a spring's values; which particles it joins is the scene's structure, not a value
constexpr Field<core::SpringDesc> kSpringFields[] = {
    {"stiffness", Kind::Number, [](core::SpringDesc &s, const OverrideValue &v) { s.stiffness = v.number; }},
    {"damping", Kind::Number, [](core::SpringDesc &s, const OverrideValue &v) { s.damping = v.number; }},
    {"restLength", Kind::Number, [](core::SpringDesc &s, const OverrideValue &v) { s.restLength = v.number; }},
    {"breakStrain", Kind::Number, [](core::SpringDesc &s, const OverrideValue &v) { s.breakStrain = v.number; }},
};

constexpr Field<core::PlaneDesc> kPlaneFields[] = {
    {"normal", Kind::Vector, [](core::PlaneDesc &p, const OverrideValue &v) { p.normal = v.vector; }},
    {"offset", Kind::Number, [](core::PlaneDesc &p, const OverrideValue &v) { p.offset = v.number; }},
    {"twoSided", Kind::Boolean, [](core::PlaneDesc &p, const OverrideValue &v) { p.twoSided = v.flag; }},
    {"friction", Kind::Number, [](core::PlaneDesc &p, const OverrideValue &v) { p.friction = v.number; }},
    {"rollingFriction", Kind::Number, [](core::PlaneDesc &p, const OverrideValue &v) { p.rollingFriction = v.number; }},
    {"spinningFriction", Kind::Number,
     [](core::PlaneDesc &p, const OverrideValue &v) { p.spinningFriction = v.number; }},
};

template <typename Fields>
int fieldNamed(const Fields &fields, const QString &name)
{
    for (std::size_t row = 0; row < std::size(fields); ++row)
        if (name == QLatin1StringView(fields[row].name))
            return static_cast<int>(row);
    return -1;
}

template <typename Fields>
QString fieldNames(const Fields &fields)
{
    QStringList names;
    for (const auto &field : fields)
        names += QString::fromLatin1(field.name);
    return names.join(u", "_s);
}

// the value text as a file would hold it: JSON where it reads as one value, else a bare word
// (so that integrator=rk4 needs no quotes on a command line); isJson says which
QJsonValue valueOf(const QString &text, bool &isJson)
{
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(u"["_s.append(text).append(u']').toUtf8(), &error);
    isJson = error.error == QJsonParseError::NoError && document.array().size() == 1;
    return isJson ? document.array().first() : QJsonValue(text);
}

// a number in the text that no double holds (1e400, 1e-400, nan, inf), which JSON does not read,
// said as the scene file's loader says it (io::unholdableNumber) at the same path:
// "settings.gravity[0]: the number 1e400 is too large for a double: ..."; empty when there is none
QString unholdableIn(Kind kind, const QString &key, const QString &text)
{
    const QString trimmed = text.trimmed();
    if (kind == Kind::Number || kind == Kind::Integer) {
        const QString why = io::unholdableNumber(trimmed);
        return why.isEmpty() ? why : key + u": "_s + why;
    }
    if (kind != Kind::Vector || !trimmed.startsWith(u'[') || !trimmed.endsWith(u']'))
        return {};
    const QStringList items = trimmed.mid(1, trimmed.size() - 2).split(u',');
    for (qsizetype axis = 0; axis < items.size(); ++axis)
        if (const QString why = io::unholdableNumber(items[axis].trimmed()); !why.isEmpty())
            return key + u'[' + QString::number(axis) + u"]: "_s + why;
    return {};
}

// the value converted to its key's kind; empty on success, else why not, in the reader's words
QString convert(Kind kind, const QJsonValue &value, const QString &text, OverrideValue &out)
{
    const auto expected = [&](const QString &what) { return u"expected "_s + what + u", got "_s + io::describe(value); };
    switch (kind) {
    case Kind::Number:
        if (!value.isDouble())
            return expected(u"a number"_s);
        out.number = value.toDouble();
        // Qt reads "-0" as +0; the sign is kept, as the scene reader keeps it
        if (out.number == 0.0 && text.trimmed().startsWith(u'-'))
            out.number = -0.0;
        return {};
    case Kind::Integer: {
        if (!value.isDouble())
            return expected(u"an integer"_s);
        const double number = value.toDouble();
        if (std::trunc(number) != number)
            return u"expected an integer, got "_s + text.trimmed();
        if (number < std::numeric_limits<int>::min() || number > std::numeric_limits<int>::max())
            return u"the integer "_s + text.trimmed() + u" is too large"_s;
        out.integer = static_cast<int>(number);
        return {};
    }
    case Kind::Boolean:
        if (!value.isBool())
            return expected(u"true or false"_s);
        out.flag = value.toBool();
        return {};
    case Kind::Vector: {
        const QJsonArray array = value.toArray();
        if (!value.isArray() || array.size() != 3)
            return value.isArray() ? u"expected an array of 3 numbers, got "_s + QString::number(array.size())
                                   : expected(u"an array of 3 numbers"_s);
        for (int axis = 0; axis < 3; ++axis) {
            if (!array[axis].isDouble())
                return u"["_s + QString::number(axis) + u"]: expected a number, got "_s + io::describe(array[axis]);
            out.vector[axis] = array[axis].toDouble();
        }
        return {};
    }
    case Kind::IntegratorName:
    case Kind::ContactSolverName: {
        if (!value.isString())
            return expected(u"a string"_s);
        QString unknown;
        if (kind == Kind::IntegratorName) {
            const auto integrator = io::integratorNamed(value.toString(), unknown);
            out.integrator = integrator.value_or(out.integrator);
        } else {
            const auto solver = io::contactSolverNamed(value.toString(), unknown);
            out.contactSolver = solver.value_or(out.contactSolver);
        }
        return unknown;
    }
    }
    return {};
}

// the key's family and row, and the kind of value it takes; empty on success, else why not
QString lookUp(const QString &family, const QString &name, bool indexed, SceneOverride &out, Kind &kind)
{
    const auto find = [&](const auto &fields, const char *plural) -> QString {
        out.field = fieldNamed(fields, name);
        if (out.field < 0)
            return u"unknown key \"%1\" (%2 take: %3)"_s.arg(out.key, QString::fromLatin1(plural), fieldNames(fields));
        kind = fields[static_cast<std::size_t>(out.field)].kind;
        return {};
    };
    if (family == u"settings"_s) {
        out.family = SceneOverride::Family::Settings;
        if (indexed)
            return u"settings is one object, not a list: use settings.NAME"_s;
        return find(kSettingsFields, "settings");
    }
    if (family == u"particles"_s) {
        out.family = SceneOverride::Family::Particles;
        return find(kParticleFields, "particles");
    }
    if (family == u"springs"_s) {
        out.family = SceneOverride::Family::Springs;
        return find(kSpringFields, "springs");
    }
    out.family = SceneOverride::Family::Planes;
    return find(kPlaneFields, "planes");
}

// one element (index) or every element of a list; an index past the list changes nothing
// (matchesNothing() has refused it before)
template <typename Element>
void setElements(std::vector<Element> &elements, const Field<Element> &field, const SceneOverride &override)
{
    if (override.index < 0) {
        for (Element &element : elements)
            field.set(element, override.converted);
    } else if (static_cast<std::size_t>(override.index) < elements.size()) {
        field.set(elements[static_cast<std::size_t>(override.index)], override.converted);
    }
}

// the override written into the scene's elements
void writeOverride(const SceneOverride &override, core::SceneDesc &scene)
{
    const auto row = static_cast<std::size_t>(override.field);
    switch (override.family) {
    case SceneOverride::Family::Settings: kSettingsFields[row].set(scene.settings, override.converted); break;
    case SceneOverride::Family::Particles: setElements(scene.particles, kParticleFields[row], override); break;
    case SceneOverride::Family::Springs: setElements(scene.springs, kSpringFields[row], override); break;
    case SceneOverride::Family::Planes: setElements(scene.planes, kPlaneFields[row], override); break;
    }
}

// why the override reaches no element of the scene, by the index as typed; empty when it reaches one
QString matchesNothing(const SceneOverride &override, const core::SceneDesc &scene)
{
    if (override.family == SceneOverride::Family::Settings)
        return {};
    const std::size_t count = override.family == SceneOverride::Family::Particles ? scene.particles.size()
                              : override.family == SceneOverride::Family::Springs ? scene.springs.size()
                                                                                  : scene.planes.size();
    const QString plural = override.key.section(u'.', 0, 0).section(u'[', 0, 0);  // "planes"
    if (override.index < 0)
        return count == 0 ? override.key + u": matches nothing: the scene has no "_s + plural : QString();
    if (static_cast<std::size_t>(override.index) < count)
        return {};
    return u"%1[%2]: index %2 is out of range (the scene has %3 %1)"_s.arg(plural, override.indexText).arg(count);
}

// the value's problem, found by writing it into a scene of one stand-in element of each kind (two
// particles, for a spring between them with a rest length, so that a breakStrain is judged) and
// checking that scene as a loaded file is; the path is the key's, "planes.friction: must be at
// most 10 (got 99)". Empty when the value is one the scene could hold.
QString standInProblem(const SceneOverride &override)
{
    core::SceneDesc standIn;
    standIn.particles.resize(2);
    standIn.particles[1].position.x() = 1.0;
    core::SpringDesc spring;
    spring.a = 0;
    spring.b = 1;
    spring.restLength = 1.0;
    standIn.springs.push_back(spring);
    standIn.planes.resize(1);
    SceneOverride first = override;
    first.index = 0;
    writeOverride(first, standIn);
    const auto problem = core::findProblem(standIn);
    if (!problem)
        return {};

    // "planes[0].friction" named as the key names it: "planes.friction", "planes[5].friction"
    QString path = QString::fromStdString(problem->path);
    const QString element = override.key.left(override.key.lastIndexOf(u'.'));
    const QString standInElement = path.section(u'[', 0, 0) + u"[0]"_s;
    if (path.startsWith(standInElement))
        path = element + path.mid(standInElement.size());
    return path + u": "_s + QString::fromStdString(problem->message);
}

}  // namespace

std::optional<SceneOverride> parseOverride(const QString &argument, QString &error)
{
    const auto fail = [&](const QString &why) {
        error = u"--set "_s + argument + u": "_s + why;
        return std::nullopt;
    };

    // KEY=VALUE, the key one of FAMILY.NAME or FAMILY[INDEX].NAME
    SceneOverride parsed;
    parsed.argument = argument;
    const qsizetype equals = argument.indexOf(u'=');
    if (equals < 0)
        return fail(u"expected KEY=VALUE, such as settings.restitution=0.5"_s);
    parsed.key = argument.left(equals).trimmed();
    const QString text = argument.mid(equals + 1);
    if (parsed.key.isEmpty())
        return fail(u"no key before the \"=\" (expected KEY=VALUE, such as settings.restitution=0.5)"_s);
    if (text.trimmed().isEmpty())
        return fail(u"no value after the \"=\" for %1"_s.arg(parsed.key));
    static const QRegularExpression pattern(u"^(settings|particles|springs|planes)(?:\\[(\\d+)\\])?\\.(\\w+)$"_s);
    const QRegularExpressionMatch match = pattern.match(parsed.key);
    if (!match.hasMatch())
        return fail(u"unknown key \"%1\" (keys are settings.NAME, and particles.NAME, springs.NAME or planes.NAME "
                    "for every element, or particles[i].NAME and the like for one)"_s.arg(parsed.key));
    Kind kind = Kind::Number;
    if (const QString why = lookUp(match.captured(1), match.captured(3), match.hasCaptured(2), parsed, kind);
        !why.isEmpty())
        return fail(why);
    if (match.hasCaptured(2)) {
        parsed.indexText = match.captured(2);
        bool ok = false;
        parsed.index = parsed.indexText.toLongLong(&ok);
        if (!ok)  // more digits than a count has: past the end of any list
            parsed.index = std::numeric_limits<qsizetype>::max();
    }

    // the value, of the kind the key takes; a number JSON cannot read is named as the file's
    // loader names it, not as "a string"
    bool isJson = false;
    parsed.value = valueOf(text, isJson);
    if (!isJson)
        if (const QString why = unholdableIn(kind, parsed.key, text); !why.isEmpty())
            return fail(why);
    if (const QString why = convert(kind, parsed.value, text, parsed.converted); !why.isEmpty())
        return fail(parsed.key + u": "_s + why);
    return parsed;
}

QString applyOverride(const SceneOverride &override, core::SceneDesc &scene)
{
    // one that reaches no element would change nothing: refused, its value judged all the same
    if (const QString nothing = matchesNothing(override, scene); !nothing.isEmpty()) {
        const QString value = standInProblem(override);
        return u"--set "_s + override.argument + u": "_s + nothing +
               (value.isEmpty() ? QString() : u"; and "_s + value);
    }
    writeOverride(override, scene);

    // the scene was valid before, so the first problem is this value's
    if (const auto problem = core::findProblem(scene))
        return u"--set "_s + override.argument + u": "_s + QString::fromStdString(problem->path) + u": "_s +
               QString::fromStdString(problem->message);
    // planes are kept with unit normals, as the reader keeps them
    for (core::PlaneDesc &plane : scene.planes)
        plane.normal = core::unitNormal(plane.normal);
    return {};
}

}  // namespace app
