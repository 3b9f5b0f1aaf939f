// Design note. The text is read once, in file order, but the format's checks have an order of
// their own (the header before the particles, a particle's position before its mass), so each
// part of the file keeps its first problem in a Section and the parts are judged in the format's
// order at the end. An element's members are taken into small Items first and then checked in
// the format's order; an unknown key's value is skipped unread. A part that has failed is skipped
// too, so nothing is built past the first problem. Paths for messages are made only when a
// message is.

#include "scene_reader.h"

#include "json_pull.h"
#include "json_scan.h"
#include "scene_words.h"

#include "core/contacts/solver_names.h"
#include "core/meshes/mesh_surface.h"
#include "core/model/validate.h"

#include <QJsonValue>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace io {

namespace {

using namespace Qt::Literals::StringLiterals;

enum class Need { Required, Optional };

// one value taken from the text, with what the checks need of it
struct Item {
    JsonToken kind = JsonToken::End;  // End: the key was absent
    double number = 0.0;
    QString text;                     // a string's
    qsizetype size = 0;               // an array's length, and its first elements
    std::array<JsonToken, 4> itemKinds{};  // (4: a quaternion's)
    std::array<double, 4> items{};
    bool present() const { return kind != JsonToken::End; }
};

// "a number", "an object", ... in the words of scene_words.h
QString describe(JsonToken kind)
{
    switch (kind) {
    case JsonToken::Null: return io::describe(QJsonValue(QJsonValue::Null));
    case JsonToken::True:
    case JsonToken::False: return io::describe(QJsonValue(QJsonValue::Bool));
    case JsonToken::Number: return io::describe(QJsonValue(QJsonValue::Double));
    case JsonToken::String: return io::describe(QJsonValue(QJsonValue::String));
    case JsonToken::BeginArray: return io::describe(QJsonValue(QJsonValue::Array));
    case JsonToken::BeginObject: return io::describe(QJsonValue(QJsonValue::Object));
    default: return io::describe(QJsonValue(QJsonValue::Undefined));
    }
}

// the first problem of one part of the file, and its warnings up to there
struct Section {
    QString error;
    QStringList warnings;
    qsizetype moreWarnings = 0;  // unknown keys past the warnings listed
    bool failed() const { return !error.isNull(); }
};

// warnings listed one by one; past them they are counted, so that a file of many unknown keys
// cannot make its warnings take more memory than its text
constexpr qsizetype kListedWarnings = 100;

// the keys of each kind of element, in the order their checks run
constexpr std::array kSettingsKeys{"timeStep"_L1,      "substeps"_L1,        "autoSubsteps"_L1,  "integrator"_L1,
                                   "xpbdIterations"_L1, "solverIterations"_L1, "tolerance"_L1,     "adaptiveStep"_L1,    "gravity"_L1,       "viscosity"_L1,
                                   "restitution"_L1,   "contactSolver"_L1,   "friction"_L1,      "staticFriction"_L1,
                                   "planeCollisions"_L1, "particleCollisions"_L1, "triangleCollisions"_L1,
                                   "selfCollision"_L1, "thickness"_L1, "rollingFriction"_L1, "spinningFriction"_L1, "spin"_L1};
constexpr std::array kParticleKeys{"position"_L1, "velocity"_L1,        "mass"_L1,       "radius"_L1,
                                   "pinned"_L1,   "angularVelocity"_L1, "orientation"_L1};
constexpr std::array kSpringKeys{"particles"_L1, "stiffness"_L1, "damping"_L1, "restLength"_L1, "breakStrain"_L1};
constexpr std::array kPlaneKeys{"normal"_L1, "offset"_L1, "twoSided"_L1, "friction"_L1,        "size"_L1,
                                "centre"_L1, "axis"_L1,   "rollingFriction"_L1, "spinningFriction"_L1};
constexpr std::array kImpulseKeys{"particle"_L1, "other"_L1, "plane"_L1, "normal"_L1, "friction"_L1};
constexpr std::array kRootKeys{"format"_L1, "version"_L1, "name"_L1,     "settings"_L1,       "particles"_L1,
                               "springs"_L1, "planes"_L1, "steerable"_L1, "contactImpulses"_L1, "triangles"_L1,
                               "meshes"_L1};
constexpr std::array kMeshKeys{"name"_L1, "source"_L1, "kind"_L1, "scale"_L1, "zUp"_L1, "offset"_L1, "vertices"_L1, "faces"_L1};

// where a top-level key is in kRootKeys
std::size_t rootIndex(QLatin1StringView key)
{
    return std::size_t(std::find(kRootKeys.begin(), kRootKeys.end(), key) - kRootKeys.begin());
}

class SceneTextReader {
public:
    SceneTextReader(QByteArrayView json, const QString &source, const QHash<QString, qsizetype> &lengths)
        : m_in(json), m_source(source), m_lengths(lengths)
    {
    }

    // false: the text is not one JSON object
    bool read();
    LoadResult result();

private:
    // syntax: each returns false when the text breaks the grammar
    bool take(JsonToken first, Item &item);
    template <std::size_t N>
    bool takeMembers(const std::array<QLatin1StringView, N> &keys, std::array<Item, N> &items, QStringList &unknown);
    bool readSettings(JsonToken first);
    template <typename Element>
    bool readList(JsonToken first, Section &section, QLatin1StringView key, Element element);

    // the elements' checks
    void checkSettings(std::array<Item, kSettingsKeys.size()> &items);
    bool checkParticle(std::array<Item, kParticleKeys.size()> &items, qsizetype i);
    bool checkSpring(std::array<Item, kSpringKeys.size()> &items, qsizetype i);
    bool checkPlane(std::array<Item, kPlaneKeys.size()> &items, qsizetype i);
    bool checkImpulse(std::array<Item, kImpulseKeys.size()> &items, qsizetype i);
    bool readTriangles(JsonToken first);
    bool readMeshes(JsonToken first);
    bool readMesh(qsizetype m);
    bool readMeshVertices(JsonToken first, core::MeshDesc &mesh, const QString &path);
    bool readMeshFaces(JsonToken first, core::MeshDesc &mesh, const QString &path);
    bool readIndexTriples(JsonToken first, const QString &listPath, const QString &of, std::vector<std::array<int, 3>> &out);
    bool checkHeader();

    bool fail(const QString &path, const QString &reason)
    {
        if (!m_section->failed())
            m_section->error = path.isEmpty() ? m_source + u": "_s + reason : m_source + u": "_s + path + u": "_s + reason;
        return false;
    }

    template <typename Path>
    bool expected(const Path &path, const QString &what, JsonToken got)
    {
        return fail(path(), u"expected "_s + what + u", got "_s + describe(got));
    }

    void warnUnknownKeys(QStringList &unknown, const QString &path)
    {
        // in the order Qt's objects list their keys, as before
        std::sort(unknown.begin(), unknown.end());
        for (const QString &key : unknown) {
            if (m_listedWarnings++ < kListedWarnings)
                m_section->warnings += m_source + u": "_s + memberPath(path, key) + u": unknown key, ignored"_s;
            else
                ++m_section->moreWarnings;
        }
    }

    // one value of each kind, from its kind and number
    template <typename Path>
    bool read(JsonToken kind, double number, const Path &path, double &out)
    {
        if (kind != JsonToken::Number)
            return expected(path, u"a number"_s, kind);
        out = number;
        return true;
    }

    template <typename Path>
    bool read(JsonToken kind, double number, const Path &path, int &out)
    {
        if (kind != JsonToken::Number)
            return expected(path, u"an integer"_s, kind);
        if (std::trunc(number) != number)
            return fail(path(), u"expected an integer, got "_s + QString::fromLatin1(formatNumber(number)));
        if (number < std::numeric_limits<int>::min() || number > std::numeric_limits<int>::max())
            return fail(path(), u"the integer "_s + QString::fromLatin1(formatNumber(number)) + u" is too large"_s);
        out = static_cast<int>(number);
        return true;
    }

    template <typename Path, typename T>
    bool read(const Item &item, const Path &path, T &out)
    {
        return read(item.kind, item.number, path, out);
    }

    template <typename Path>
    bool read(const Item &item, const Path &path, bool &out)
    {
        if (item.kind != JsonToken::True && item.kind != JsonToken::False)
            return expected(path, u"true or false"_s, item.kind);
        out = item.kind == JsonToken::True;
        return true;
    }

    template <typename Path>
    bool read(const Item &item, const Path &path, QString &out)
    {
        if (item.kind != JsonToken::String)
            return expected(path, u"a string"_s, item.kind);
        out = item.text;
        return true;
    }

    template <typename Path, int N>
    bool read(const Item &item, const Path &path, Eigen::Matrix<double, N, 1> &out)
    {
        const QString what = QStringLiteral("an array of %1 numbers").arg(N);
        if (item.kind != JsonToken::BeginArray)
            return expected(path, what, item.kind);
        if (item.size != N)
            return fail(path(), u"expected "_s + what + u", got "_s + QString::number(item.size));
        for (int axis = 0; axis < N; ++axis)
            if (!read(item.itemKinds[axis], item.items[axis], [&] { return elementPath(path(), axis); }, out[axis]))
                return false;
        return true;
    }

    // a member of an object; an optional one that is absent leaves out as it was
    template <typename Path, typename T>
    bool member(const Item &item, const Path &parent, QLatin1StringView key, Need need, T &out, bool *present = nullptr)
    {
        if (present)
            *present = item.present();
        const auto path = [&] { return memberPath(parent(), key); };
        if (!item.present())
            return need == Need::Optional || fail(path(), QStringLiteral("missing: this key is required"));
        return read(item, path, out);
    }

    JsonPull m_in;
    QString m_source;
    const QHash<QString, qsizetype> &m_lengths;
    core::SceneDesc m_scene;

    // the parts, in the order they are judged
    Section m_header;
    Section m_settings;
    Section m_particles;
    Section m_springs;
    Section m_planes;
    Section m_steerable;
    Section m_impulses;
    Section m_triangles;
    Section m_meshes;
    Section m_root;  // the top-level object's own warnings
    Section *m_section = &m_header;

    std::array<Item, kRootKeys.size()> m_rootItems;  // the small top-level values (the last of two)
    std::array<bool, kRootKeys.size()> m_seen{};     // the top-level keys met
    QStringList m_unknownRootKeys;
    qsizetype m_listedWarnings = 0;
    std::vector<bool> m_restLengthGiven;  // by spring; one not given is the particles' distance
};

bool SceneTextReader::take(JsonToken first, Item &item)
{
    item = Item{};
    item.kind = first;
    switch (first) {
    case JsonToken::Number: item.number = m_in.number(); return true;
    case JsonToken::String: item.text = m_in.text(); return true;
    case JsonToken::BeginObject: return m_in.skipRest(first);
    case JsonToken::BeginArray:
        // the length, and the first elements' kinds and numbers
        for (JsonToken token = m_in.next(); token != JsonToken::EndArray; token = m_in.next(), ++item.size) {
            if (item.size < qsizetype(item.items.size())) {
                item.itemKinds[std::size_t(item.size)] = token;
                item.items[std::size_t(item.size)] = token == JsonToken::Number ? m_in.number() : 0.0;
            }
            if (!m_in.skipRest(token))
                return false;
        }
        return true;
    case JsonToken::Error:
    case JsonToken::End:
    case JsonToken::Key:
    case JsonToken::EndObject:
    case JsonToken::EndArray: return false;
    default: return true;
    }
}

// the members of one object (its '{' just read), by key; unknown keys are listed, their values skipped
template <std::size_t N>
bool SceneTextReader::takeMembers(const std::array<QLatin1StringView, N> &keys, std::array<Item, N> &items,
                                  QStringList &unknown)
{
    for (Item &item : items)
        item.kind = JsonToken::End;
    for (JsonToken token = m_in.next(); token != JsonToken::EndObject; token = m_in.next()) {
        if (token != JsonToken::Key)
            return false;
        const auto known = std::find_if(keys.begin(), keys.end(), [&](QLatin1StringView key) { return m_in.isText(key); });
        if (known == keys.end()) {
            // (Qt names a key that began with a byte order mark without it)
            if (!m_in.lostMark() || std::find(keys.begin(), keys.end(), m_in.text()) == keys.end())
                unknown += m_in.text();
            if (!m_in.skipRest(m_in.next()))
                return false;
        } else if (!take(m_in.next(), items[std::size_t(known - keys.begin())])) {
            return false;
        }
    }
    return true;
}

void SceneTextReader::checkSettings(std::array<Item, kSettingsKeys.size()> &items)
{
    // every key is optional: an absent one keeps its default
    core::Settings &settings = m_scene.settings;
    const auto path = [] { return u"settings"_s; };
    const auto at = [&](QLatin1StringView key) -> const Item & {
        return items[std::size_t(std::find(kSettingsKeys.begin(), kSettingsKeys.end(), key) - kSettingsKeys.begin())];
    };
    const std::string_view defaultName = core::integratorName(settings.integrator);
    QString integrator = QString::fromUtf8(defaultName.data(), static_cast<qsizetype>(defaultName.size()));
    const std::string_view defaultSolver = core::contactSolverName(settings.contactSolver);
    QString contactSolver = QString::fromUtf8(defaultSolver.data(), static_cast<qsizetype>(defaultSolver.size()));
    double staticFriction = 0.0;
    bool hasStaticFriction = false;
    double adaptiveStep = 0.0;
    bool hasAdaptiveStep = false;
    constexpr auto optional = Need::Optional;
    if (!member(at("timeStep"_L1), path, "timeStep"_L1, optional, settings.timeStep) ||
        !member(at("substeps"_L1), path, "substeps"_L1, optional, settings.substeps) ||
        !member(at("autoSubsteps"_L1), path, "autoSubsteps"_L1, optional, settings.autoSubsteps) ||
        !member(at("integrator"_L1), path, "integrator"_L1, optional, integrator) ||
        !member(at("xpbdIterations"_L1), path, "xpbdIterations"_L1, optional, settings.xpbdIterations) ||
        !member(at("solverIterations"_L1), path, "solverIterations"_L1, optional, settings.solverIterations) ||
        !member(at("tolerance"_L1), path, "tolerance"_L1, optional, settings.tolerance) ||
        !member(at("adaptiveStep"_L1), path, "adaptiveStep"_L1, optional, adaptiveStep, &hasAdaptiveStep) ||
        !member(at("gravity"_L1), path, "gravity"_L1, optional, settings.gravity) ||
        !member(at("viscosity"_L1), path, "viscosity"_L1, optional, settings.viscosity) ||
        !member(at("restitution"_L1), path, "restitution"_L1, optional, settings.restitution) ||
        !member(at("contactSolver"_L1), path, "contactSolver"_L1, optional, contactSolver) ||
        !member(at("friction"_L1), path, "friction"_L1, optional, settings.friction) ||
        !member(at("staticFriction"_L1), path, "staticFriction"_L1, optional, staticFriction, &hasStaticFriction) ||
        !member(at("planeCollisions"_L1), path, "planeCollisions"_L1, optional, settings.planeCollisions) ||
        !member(at("particleCollisions"_L1), path, "particleCollisions"_L1, optional, settings.particleCollisions) ||
        !member(at("triangleCollisions"_L1), path, "triangleCollisions"_L1, optional, settings.triangleCollisions) ||
        !member(at("selfCollision"_L1), path, "selfCollision"_L1, optional, settings.selfCollision) ||
        !member(at("thickness"_L1), path, "thickness"_L1, optional, settings.thickness) ||
        !member(at("rollingFriction"_L1), path, "rollingFriction"_L1, optional, settings.rollingFriction) ||
        !member(at("spinningFriction"_L1), path, "spinningFriction"_L1, optional, settings.spinningFriction) ||
        !member(at("spin"_L1), path, "spin"_L1, optional, settings.spin))
        return;

    // the integrator and the contact solver by name; the static coefficient only when given
    QString unknown;
    const auto chosen = integratorNamed(integrator, unknown);
    if (!chosen) {
        fail(u"settings.integrator"_s, unknown);
        return;
    }
    settings.integrator = *chosen;
    const auto solver = contactSolverNamed(contactSolver, unknown);
    if (!solver) {
        fail(u"settings.contactSolver"_s, unknown);
        return;
    }
    settings.contactSolver = *solver;
    if (hasStaticFriction)
        settings.staticFriction = staticFriction;
    if (hasAdaptiveStep)
        settings.adaptiveStep = adaptiveStep;
}

bool SceneTextReader::readSettings(JsonToken first)
{
    m_section = &m_settings;
    if (first != JsonToken::BeginObject) {
        Item item;
        if (!take(first, item))
            return false;
        expected([] { return u"settings"_s; }, u"an object"_s, first);
        return true;
    }
    std::array<Item, kSettingsKeys.size()> items;
    QStringList unknown;
    if (!takeMembers(kSettingsKeys, items, unknown))
        return false;
    checkSettings(items);
    if (!m_settings.failed())
        warnUnknownKeys(unknown, u"settings"_s);
    return true;
}

// a top-level list (its first token just read), element by element; element(items, index) checks
// one and keeps it, or fails, after which the rest of the list is only read through
template <typename Element>
bool SceneTextReader::readList(JsonToken first, Section &section, QLatin1StringView key, Element element)
{
    m_section = &section;
    if (first != JsonToken::BeginArray) {
        Item item;
        if (!take(first, item))
            return false;
        expected([&] { return QString(key); }, u"an array"_s, first);
        return true;
    }
    using Items = typename std::remove_reference_t<decltype(element)>::Items;
    Items items;
    QStringList unknown;
    for (qsizetype i = 0;; ++i) {
        const JsonToken token = m_in.next();
        if (token == JsonToken::EndArray)
            return true;
        if (section.failed() || token != JsonToken::BeginObject) {
            if (!m_in.skipRest(token))
                return false;
            if (!section.failed())
                expected([&] { return elementPath(QString(key), i); }, u"an object"_s, token);
            continue;
        }
        unknown.clear();
        if (!takeMembers(Element::keys(), items, unknown))
            return false;
        if (element(items, i))
            warnUnknownKeys(unknown, elementPath(QString(key), i));
    }
}

// the element checks, each a small callable with its keys, for readList
template <typename Check, auto &Keys>
struct ElementCheck {
    using Items = std::array<Item, Keys.size()>;
    static constexpr const auto &keys() { return Keys; }
    Check check;
    bool operator()(Items &items, qsizetype i) { return check(items, i); }
};

template <auto &Keys, typename Check>
ElementCheck<Check, Keys> elementCheck(Check check)
{
    return {check};
}

bool SceneTextReader::checkParticle(std::array<Item, kParticleKeys.size()> &items, qsizetype i)
{
    const auto path = [i] { return elementPath(u"particles"_s, i); };
    core::ParticleDesc particle;
    if (!member(items[0], path, kParticleKeys[0], Need::Required, particle.position) ||
        !member(items[1], path, kParticleKeys[1], Need::Optional, particle.velocity) ||
        !member(items[2], path, kParticleKeys[2], Need::Required, particle.mass) ||
        !member(items[3], path, kParticleKeys[3], Need::Required, particle.radius) ||
        !member(items[4], path, kParticleKeys[4], Need::Optional, particle.pinned) ||
        !member(items[5], path, kParticleKeys[5], Need::Optional, particle.angularVelocity) ||
        !member(items[6], path, kParticleKeys[6], Need::Optional, particle.orientation))
        return false;
    m_scene.particles.push_back(particle);
    return true;
}

bool SceneTextReader::checkSpring(std::array<Item, kSpringKeys.size()> &items, qsizetype i)
{
    const auto path = [i] { return elementPath(u"springs"_s, i); };
    core::SpringDesc spring;
    bool hasRestLength = false;
    const Item &ends = items[0];
    if (!ends.present())
        return fail(memberPath(path(), kSpringKeys[0]), QStringLiteral("missing: this key is required"));
    const auto endsPath = [&] { return memberPath(path(), kSpringKeys[0]); };
    if (ends.kind != JsonToken::BeginArray)
        return expected(endsPath, u"an array"_s, ends.kind);

    // the two ends: particle indices; findProblem() checks they exist and differ
    if (ends.size != 2)
        return fail(endsPath(), u"expected an array of 2 particle indices, got "_s + QString::number(ends.size));
    if (!read(ends.itemKinds[0], ends.items[0], [&] { return elementPath(endsPath(), 0); }, spring.a) ||
        !read(ends.itemKinds[1], ends.items[1], [&] { return elementPath(endsPath(), 1); }, spring.b))
        return false;
    if (!member(items[1], path, kSpringKeys[1], Need::Required, spring.stiffness) ||
        !member(items[2], path, kSpringKeys[2], Need::Required, spring.damping) ||
        !member(items[3], path, kSpringKeys[3], Need::Optional, spring.restLength, &hasRestLength) ||
        !member(items[4], path, kSpringKeys[4], Need::Optional, spring.breakStrain))
        return false;
    m_scene.springs.push_back(spring);
    m_restLengthGiven.push_back(hasRestLength);
    return true;
}

bool SceneTextReader::checkPlane(std::array<Item, kPlaneKeys.size()> &items, qsizetype i)
{
    const auto path = [i] { return elementPath(u"planes"_s, i); };
    core::PlaneDesc plane;
    double friction = 0.0;
    bool hasFriction = false;
    if (!member(items[0], path, kPlaneKeys[0], Need::Required, plane.normal) ||
        !member(items[1], path, kPlaneKeys[1], Need::Required, plane.offset) ||
        !member(items[2], path, kPlaneKeys[2], Need::Optional, plane.twoSided) ||
        !member(items[3], path, kPlaneKeys[3], Need::Optional, friction, &hasFriction) ||
        !member(items[4], path, kPlaneKeys[4], Need::Optional, plane.size) ||
        !member(items[5], path, kPlaneKeys[5], Need::Optional, plane.centre) ||
        !member(items[6], path, kPlaneKeys[6], Need::Optional, plane.axis))
        return false;
    double rolling = 0.0, spinning = 0.0;
    bool hasRolling = false, hasSpinning = false;
    if (!member(items[7], path, kPlaneKeys[7], Need::Optional, rolling, &hasRolling) ||
        !member(items[8], path, kPlaneKeys[8], Need::Optional, spinning, &hasSpinning))
        return false;
    // a plane without friction of its own takes the settings'
    if (hasFriction)
        plane.friction = friction;
    if (hasRolling)
        plane.rollingFriction = rolling;
    if (hasSpinning)
        plane.spinningFriction = spinning;
    m_scene.planes.push_back(plane);
    return true;
}

// a saved run's contact impulse, with a particle ("other") or with a plane
bool SceneTextReader::checkImpulse(std::array<Item, kImpulseKeys.size()> &items, qsizetype k)
{
    const auto path = [k] { return elementPath(u"contactImpulses"_s, k); };
    core::ContactImpulse impulse;
    int plane = 0;
    bool hasOther = false;
    bool hasPlane = false;
    if (!member(items[0], path, kImpulseKeys[0], Need::Required, impulse.i) ||
        !member(items[1], path, kImpulseKeys[1], Need::Optional, impulse.j, &hasOther) ||
        !member(items[2], path, kImpulseKeys[2], Need::Optional, plane, &hasPlane) ||
        !member(items[3], path, kImpulseKeys[3], Need::Required, impulse.normal) ||
        !member(items[4], path, kImpulseKeys[4], Need::Required, impulse.friction))
        return false;
    if (hasOther == hasPlane)
        return fail(path(), QStringLiteral("needs either \"other\" (a particle) or \"plane\", not both or neither"));
    // findProblem() checks the plane exists
    if (hasPlane) {
        if (plane < 0)
            return fail(memberPath(path(), "plane"_L1), u"plane index "_s + QString::number(plane) + u" is out of range"_s);
        impulse.j = -1 - plane;
    } else if (impulse.j < 0) {
        return fail(memberPath(path(), "other"_L1),
                    u"particle index "_s + QString::number(impulse.j) + u" is out of range"_s);
    }
    m_scene.contactImpulses.push_back(impulse);
    return true;
}

// the sheets' triangles: an array of arrays of three particle indices (findProblem() checks they
// exist and differ)
bool SceneTextReader::readTriangles(JsonToken first)
{
    m_section = &m_triangles;
    return readIndexTriples(first, u"triangles"_s, u"particle"_s, m_scene.triangles);
}

// an array of arrays of three indices, of particles (a sheet's triangles) or of vertices (a mesh's
// faces), into out; the section's first failure stops the reading of values, not of tokens
bool SceneTextReader::readIndexTriples(JsonToken first, const QString &listPath, const QString &of,
                                       std::vector<std::array<int, 3>> &out)
{
    if (first != JsonToken::BeginArray) {
        Item item;
        if (!take(first, item))
            return false;
        expected([&] { return listPath; }, u"an array"_s, first);
        return true;
    }
    const QString triple = u"an array of 3 "_s + of + u" indices"_s;
    for (qsizetype i = 0;; ++i) {
        const JsonToken token = m_in.next();
        if (token == JsonToken::EndArray)
            return true;
        Item item;
        if (!take(token, item))
            return false;
        if (m_section->failed())
            continue;
        const auto path = [&] { return elementPath(listPath, i); };
        if (item.kind != JsonToken::BeginArray) {
            expected(path, triple, item.kind);
            continue;
        }
        if (item.size != 3) {
            fail(path(), u"expected "_s + triple + u", got "_s + QString::number(item.size));
            continue;
        }
        std::array<int, 3> corners{};
        bool ok = true;
        for (int c = 0; c < 3 && ok; ++c)
            ok = read(item.itemKinds[std::size_t(c)], item.items[std::size_t(c)], [&] { return elementPath(path(), c); },
                      corners[std::size_t(c)]);
        if (ok)
            out.push_back(corners);
    }
}

// the imported meshes: an array of objects (docs/scene-format.md, "Meshes")
bool SceneTextReader::readMeshes(JsonToken first)
{
    m_section = &m_meshes;
    if (first != JsonToken::BeginArray) {
        Item item;
        if (!take(first, item))
            return false;
        expected([] { return u"meshes"_s; }, u"an array"_s, first);
        return true;
    }
    for (qsizetype m = 0;; ++m) {
        const JsonToken token = m_in.next();
        if (token == JsonToken::EndArray)
            return true;
        if (m_meshes.failed() || token != JsonToken::BeginObject) {
            if (!m_in.skipRest(token))
                return false;
            if (!m_meshes.failed())
                expected([m] { return elementPath(u"meshes"_s, m); }, u"an object"_s, token);
            continue;
        }
        if (!readMesh(m))
            return false;
    }
}

// one mesh, its '{' just read: the small members taken as items, the vertices and faces read in place
bool SceneTextReader::readMesh(qsizetype m)
{
    const QString path = elementPath(u"meshes"_s, m);
    const auto at = [&] { return path; };
    core::MeshDesc mesh;
    std::array<Item, kMeshKeys.size()> items;
    bool hasVertices = false, hasFaces = false;
    QStringList unknown;
    for (JsonToken token = m_in.next(); token != JsonToken::EndObject; token = m_in.next()) {
        if (token != JsonToken::Key)
            return false;
        const auto known = std::find_if(kMeshKeys.begin(), kMeshKeys.end(), [&](QLatin1StringView key) { return m_in.isText(key); });
        const QString unknownKey = known == kMeshKeys.end() ? m_in.text() : QString();
        const JsonToken value = m_in.next();
        if (known == kMeshKeys.end()) {
            unknown += unknownKey;
            if (!m_in.skipRest(value))
                return false;
        } else if (*known == "vertices"_L1) {
            hasVertices = true;
            if (!readMeshVertices(value, mesh, memberPath(path, *known)))
                return false;
        } else if (*known == "faces"_L1) {
            hasFaces = true;
            if (!readMeshFaces(value, mesh, memberPath(path, *known)))
                return false;
        } else if (!take(value, items[std::size_t(known - kMeshKeys.begin())])) {
            return false;
        }
    }
    if (m_meshes.failed())
        return true;
    QString name = u"mesh"_s, source, kind;
    bool zUp = false;
    if (!member(items[0], at, kMeshKeys[0], Need::Optional, name) || !member(items[1], at, kMeshKeys[1], Need::Optional, source) ||
        !member(items[2], at, kMeshKeys[2], Need::Required, kind) ||
        !member(items[3], at, kMeshKeys[3], Need::Optional, mesh.scale) ||
        !member(items[4], at, kMeshKeys[4], Need::Optional, zUp) ||
        !member(items[5], at, kMeshKeys[5], Need::Optional, mesh.offset))
        return true;
    const std::string kindText = kind.toStdString();
    const auto named = core::meshKindNamed(kindText);
    if (!named) {
        fail(memberPath(path, "kind"_L1), u"unknown mesh kind \""_s + kind + u"\" (known: "_s +
                                              QString::fromLatin1(core::knownMeshKinds().data(), qsizetype(core::knownMeshKinds().size())) + u")"_s);
        return true;
    }
    if (!hasVertices || !hasFaces) {
        fail(memberPath(path, hasVertices ? "faces"_L1 : "vertices"_L1), QStringLiteral("missing: this key is required"));
        return true;
    }
    if (!(mesh.scale > 0.0)) {
        fail(memberPath(path, "scale"_L1), u"must be greater than 0 (got "_s + QString::fromLatin1(formatNumber(mesh.scale)) + u")"_s);
        return true;
    }
    mesh.kind = *named;
    mesh.zUp = zUp;
    mesh.name = name.toStdString();
    mesh.source = source.toStdString();
    m_scene.meshes.push_back(std::move(mesh));
    warnUnknownKeys(unknown, path);
    return true;
}

// a mesh's vertices: each a particle index, or an array of particle index and weight pairs
bool SceneTextReader::readMeshVertices(JsonToken first, core::MeshDesc &mesh, const QString &path)
{
    if (first != JsonToken::BeginArray) {
        Item item;
        if (!take(first, item))
            return false;
        expected([&] { return path; }, u"an array"_s, first);
        return true;
    }
    const QString what = u"a particle index or an array of particle index and weight pairs"_s;
    for (qsizetype v = 0;; ++v) {
        const JsonToken token = m_in.next();
        if (token == JsonToken::EndArray)
            return true;
        const auto vertexPath = [&] { return elementPath(path, v); };
        if (m_meshes.failed()) {
            if (!m_in.skipRest(token))
                return false;
            continue;
        }
        if (token == JsonToken::Number) {
            int particle = 0;
            if (read(token, m_in.number(), vertexPath, particle)) {
                mesh.particles.push_back(particle);
                mesh.weights.push_back(1.0);
                mesh.offsets.push_back(int(mesh.particles.size()));
            }
            continue;
        }
        if (token != JsonToken::BeginArray) {
            if (!m_in.skipRest(token))
                return false;
            expected(vertexPath, what, token);
            continue;
        }
        qsizetype count = 0;
        for (JsonToken inner = m_in.next(); inner != JsonToken::EndArray; inner = m_in.next(), ++count) {
            if (m_meshes.failed() || inner != JsonToken::Number) {
                if (!m_in.skipRest(inner))
                    return false;
                if (!m_meshes.failed())
                    expected([&] { return elementPath(vertexPath(), count); }, u"a number"_s, inner);
                continue;
            }
            if (count % 2 == 0) {
                int particle = 0;
                if (read(inner, m_in.number(), [&] { return elementPath(vertexPath(), count); }, particle))
                    mesh.particles.push_back(particle);
            } else {
                mesh.weights.push_back(m_in.number());
            }
        }
        if (m_meshes.failed())
            continue;
        if (count == 0 || count % 2 != 0 || count > 2 * core::kMostMeshBindings) {
            fail(vertexPath(), u"expected "_s + what + u" (1 to %1 pairs), got %2 numbers"_s.arg(core::kMostMeshBindings).arg(count));
            continue;
        }
        mesh.offsets.push_back(int(mesh.particles.size()));
    }
}

// a mesh's faces: arrays of three vertex indices
bool SceneTextReader::readMeshFaces(JsonToken first, core::MeshDesc &mesh, const QString &path)
{
    return readIndexTriples(first, path, u"vertex"_s, mesh.faces);
}

bool SceneTextReader::read()
{
    if (m_in.next() != JsonToken::BeginObject)
        return false;
    for (JsonToken token = m_in.next(); token != JsonToken::EndObject; token = m_in.next()) {
        if (token != JsonToken::Key)
            return false;
        const auto known =
            std::find_if(kRootKeys.begin(), kRootKeys.end(), [&](QLatin1StringView key) { return m_in.isText(key); });
        const auto index = std::size_t(known - kRootKeys.begin());
        if (known == kRootKeys.end()) {
            if (!m_in.lostMark() || std::find(kRootKeys.begin(), kRootKeys.end(), m_in.text()) == kRootKeys.end())
                m_unknownRootKeys += m_in.text();
            if (!m_in.skipRest(m_in.next()))
                return false;
            continue;
        }
        const JsonToken first = m_in.next();
        const QLatin1StringView key = *known;
        const bool again = std::exchange(m_seen[index], true);
        bool ok = true;
        // a list met a second time is only read through: the key that comes twice is the message
        if (again && (key == "settings"_L1 || key == "particles"_L1 || key == "springs"_L1 || key == "planes"_L1 ||
                      key == "contactImpulses"_L1 || key == "triangles"_L1 || key == "meshes"_L1)) {
            ok = m_in.skipRest(first);
        } else if (key == "settings"_L1) {
            ok = readSettings(first);
        } else if (key == "particles"_L1) {
            m_scene.particles.reserve(std::size_t(m_lengths.value(key, 0)));
            ok = readList(first, m_particles, key, elementCheck<kParticleKeys>([this](auto &items, qsizetype i) {
                              return checkParticle(items, i);
                          }));
        } else if (key == "springs"_L1) {
            m_scene.springs.reserve(std::size_t(m_lengths.value(key, 0)));
            m_restLengthGiven.reserve(std::size_t(m_lengths.value(key, 0)));
            ok = readList(first, m_springs, key,
                          elementCheck<kSpringKeys>([this](auto &items, qsizetype i) { return checkSpring(items, i); }));
        } else if (key == "planes"_L1) {
            m_scene.planes.reserve(std::size_t(m_lengths.value(key, 0)));
            ok = readList(first, m_planes, key,
                          elementCheck<kPlaneKeys>([this](auto &items, qsizetype i) { return checkPlane(items, i); }));
        } else if (key == "contactImpulses"_L1) {
            m_scene.contactImpulses.reserve(std::size_t(m_lengths.value(key, 0)));
            ok = readList(first, m_impulses, key,
                          elementCheck<kImpulseKeys>([this](auto &items, qsizetype i) { return checkImpulse(items, i); }));
        } else if (key == "triangles"_L1) {
            m_scene.triangles.reserve(std::size_t(m_lengths.value(key, 0)));
            ok = readTriangles(first);
        } else if (key == "meshes"_L1) {
            ok = readMeshes(first);
        } else {
            // format, version, name, steerable: small values; the last of two is the one kept, as
            // in Qt's objects
            ok = take(first, m_rootItems[index]);
        }
        if (!ok)
            return false;
    }
    return m_in.next() == JsonToken::End;
}

bool SceneTextReader::checkHeader()
{
    m_section = &m_header;
    const auto root = [] { return QString(); };
    const auto item = [&](QLatin1StringView key) -> const Item & { return m_rootItems[rootIndex(key)]; };

    // format: a file of another kind says only that
    const Item &format = item("format"_L1);
    if (!format.present())
        return fail(u"format"_s, u"missing: not a Springlab scene (expected \"format\": \""_s + kSceneFormatName + u"\")"_s);
    if (format.kind != JsonToken::String || format.text != kSceneFormatName)
        return fail(u"format"_s, u"not a Springlab scene (expected \""_s + kSceneFormatName + u"\", got "_s +
                                     (format.kind == JsonToken::String ? u'"' + format.text + u'"' : describe(format.kind)) +
                                     u")"_s);

    // version: this build reads every version up to its own
    int version = 0;
    if (!member(item("version"_L1), root, "version"_L1, Need::Required, version))
        return false;
    if (version > kSceneFormatVersion)
        return fail(u"version"_s, QStringLiteral("the file is version %1, newer than this build of Springlab reads "
                                                 "(version %2 at most); open it with a newer Springlab")
                                      .arg(version)
                                      .arg(kSceneFormatVersion));
    if (version < 1)
        return fail(u"version"_s, QStringLiteral("there is no version %1 (versions start at 1)").arg(version));

    // which of two values for one key was meant cannot be known: neither is taken
    if (!m_in.duplicateKey().isNull())
        return fail(m_in.duplicateKey(), QStringLiteral("this key comes twice in its object: keep one"));
    // Qt would read it as a replacement character: the text would change without a word
    if (!m_in.loneSurrogate().isNull())
        return fail(m_in.loneSurrogate(), QStringLiteral("a \\u escape is half of a UTF-16 pair (a lone surrogate), "
                                                         "which is no character"));
    QString name;
    if (!member(item("name"_L1), root, "name"_L1, Need::Required, name))
        return false;
    m_scene.name = name.toStdString();
    return true;
}

LoadResult SceneTextReader::result()
{
    LoadResult result;
    if (!checkHeader()) {
        result.error = m_header.error;
        return result;
    }

    // the parts in order: the first that failed gives the message, with the warnings before it
    const auto root = [] { return QString(); };
    for (const auto &[section, key] : {std::pair{&m_particles, "particles"_L1}, std::pair{&m_springs, "springs"_L1},
                                       std::pair{&m_planes, "planes"_L1}}) {
        m_section = section;
        if (!m_seen[rootIndex(key)])
            fail(QString(key), QStringLiteral("missing: this key is required"));
    }
    m_section = &m_steerable;
    member(m_rootItems[rootIndex("steerable"_L1)], root, "steerable"_L1, Need::Optional, m_scene.steerable);
    m_section = &m_root;
    warnUnknownKeys(m_unknownRootKeys, QString());
    qsizetype moreWarnings = 0;
    const auto countMore = [&] {
        if (moreWarnings > 0)
            result.warnings += m_source + u": "_s + QString::number(moreWarnings) + u" more unknown keys, ignored"_s;
    };
    for (const Section *section :
         {&m_settings, &m_particles, &m_springs, &m_planes, &m_steerable, &m_impulses, &m_triangles, &m_meshes, &m_root}) {
        result.warnings += section->warnings;
        moreWarnings += section->moreWarnings;
        if (section->failed()) {
            countMore();
            result.error = section->error;
            return result;
        }
    }
    countMore();

    // a spring that gives no rest length rests at its initial length
    const auto count = static_cast<int>(m_scene.particles.size());
    for (std::size_t k = 0; k < m_scene.springs.size(); ++k) {
        core::SpringDesc &spring = m_scene.springs[k];
        if (!m_restLengthGiven[k] && spring.a >= 0 && spring.a < count && spring.b >= 0 && spring.b < count)
            spring.restLength = (m_scene.particles[std::size_t(spring.a)].position -
                                 m_scene.particles[std::size_t(spring.b)].position)
                                    .norm();
    }

    // values: the same checks and messages as the editor's
    if (const auto problem = core::findProblem(m_scene)) {
        const QString path = QString::fromStdString(problem->path);
        // a rest length the file did not give is the distance between the spring's particles
        const QString prefix = u"springs["_s;
        const QString suffix = u"].restLength"_s;
        bool isIndex = false;
        const qsizetype k = path.startsWith(prefix) && path.endsWith(suffix)
                                ? path.mid(prefix.size(), path.size() - prefix.size() - suffix.size()).toLongLong(&isIndex)
                                : -1;
        const bool derived = isIndex && k >= 0 && std::size_t(k) < m_restLengthGiven.size() && !m_restLengthGiven[std::size_t(k)];
        const QString why =
            derived ? u" (the distance between its particles, taken since the spring gives no restLength)"_s : QString();
        result.error = m_source + u": "_s + path + u": "_s + QString::fromStdString(problem->message) + why;
        return result;
    }

    // planes are kept with unit normals
    for (core::PlaneDesc &plane : m_scene.planes)
        plane.normal = core::unitNormal(plane.normal);
    result.scene = std::move(m_scene);
    return result;
}

}  // namespace

std::optional<LoadResult> readSceneText(QByteArrayView json, const QString &sourceName,
                                        const QHash<QString, qsizetype> &lengths)
{
    SceneTextReader reader(json, sourceName, lengths);
    if (!reader.read())
        return std::nullopt;
    return reader.result();
}

}  // namespace io
