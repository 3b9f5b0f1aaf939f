// Scene files: every bad-file case gives one message naming the file, the JSON path and the
// reason; defaults and unknown keys; save then load gives back the same bits, for hand-made
// scenes and for every example in resources/scenes, and no example starts with a particle in a
// plane (the pool's balls inside its cushions); the contact keys (solver, friction, two-sided
// planes, rectangles) are written when they say something and read back exactly; saving is
// atomic; files past a size, count or nesting limit are refused with the limit named, files at
// the limits load.

#include "tests/test_files.h"
#include "core/contacts/colliders.h"
#include "core/io/safe_write.h"
#include "core/io/scene_file.h"
#include "core/model/generators.h"
#include "core/model/validate.h"
#include "tests/address_space_cap.h"

#include <QDir>
#include <QFile>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <sys/stat.h>

using namespace Qt::Literals::StringLiterals;

namespace {

using test::readAll;
using test::writeAll;

// a small valid scene that the bad-file cases each break in one place
const QByteArray kBase = R"({
    "format": "springlab-scene",
    "version": 1,
    "name": "base",
    "settings": {"timeStep": 0.01, "substeps": 1, "integrator": "symplectic-euler", "gravity": [0, -9.81, 0],
                 "viscosity": 0, "restitution": 1, "planeCollisions": true, "particleCollisions": true},
    "particles": [
        {"position": [0, 1, 0], "velocity": [3, 0, 0], "mass": 1, "radius": 0.1, "pinned": false},
        {"position": [0.4, 1, 0], "mass": 2, "radius": 0.2},
        {"position": [0.8, 1, 0], "mass": 3, "radius": 0.3, "pinned": true}
    ],
    "springs": [
        {"particles": [0, 1], "stiffness": 4000, "damping": 0, "restLength": 0.4},
        {"particles": [1, 2], "stiffness": 5000, "damping": 1}
    ],
    "planes": [
        {"normal": [0, 1, 0], "offset": 0}
    ]
}
)";

std::uint64_t bits(double value)
{
    return std::bit_cast<std::uint64_t>(value);
}

// compares every double by its bits (operator== would take -0.0 for 0.0)
bool sameBits(double a, double b, const QString &what, QString &difference)
{
    if (bits(a) == bits(b))
        return true;
    difference = QStringLiteral("%1: %2 (0x%3) != %4 (0x%5)")
                     .arg(what)
                     .arg(a, 0, 'g', 17)
                     .arg(bits(a), 16, 16, QLatin1Char('0'))
                     .arg(b, 0, 'g', 17)
                     .arg(bits(b), 16, 16, QLatin1Char('0'));
    return false;
}

template <int N>
bool sameBits(const Eigen::Matrix<double, N, 1> &a, const Eigen::Matrix<double, N, 1> &b, const QString &what,
              QString &difference)
{
    for (int axis = 0; axis < N; ++axis)
        if (!sameBits(a[axis], b[axis], what + u'[' + QString::number(axis) + u']', difference))
            return false;
    return true;
}

// both unset, or both set to the same bits
bool sameBits(const std::optional<double> &a, const std::optional<double> &b, const QString &what,
              QString &difference)
{
    if (a.has_value() != b.has_value()) {
        difference = what + (a ? u": set, then unset"_s : u": unset, then set"_s);
        return false;
    }
    return !a || sameBits(*a, *b, what, difference);
}

// empty when the two scenes hold the same bits; else the first difference
QString bitDifference(const core::SceneDesc &a, const core::SceneDesc &b)
{
    QString d;
    const core::Settings &s = a.settings;
    const core::Settings &t = b.settings;
    if (a.name != b.name)
        return QStringLiteral("name");
    if (s.substeps != t.substeps || s.xpbdIterations != t.xpbdIterations || s.integrator != t.integrator ||
        s.planeCollisions != t.planeCollisions ||
        s.particleCollisions != t.particleCollisions || s.contactSolver != t.contactSolver)
        return QStringLiteral("settings");
    if (!sameBits(s.timeStep, t.timeStep, QStringLiteral("timeStep"), d) ||
        !sameBits(s.gravity, t.gravity, QStringLiteral("gravity"), d) ||
        !sameBits(s.viscosity, t.viscosity, QStringLiteral("viscosity"), d) ||
        !sameBits(s.restitution, t.restitution, QStringLiteral("restitution"), d) ||
        !sameBits(s.friction, t.friction, QStringLiteral("friction"), d) ||
        !sameBits(s.staticFriction, t.staticFriction, QStringLiteral("staticFriction"), d) ||
        !sameBits(s.adaptiveStep, t.adaptiveStep, QStringLiteral("adaptiveStep"), d))
        return d;
    if (a.particles.size() != b.particles.size() || a.springs.size() != b.springs.size() ||
        a.planes.size() != b.planes.size())
        return QStringLiteral("counts");
    for (std::size_t i = 0; i < a.particles.size(); ++i) {
        const core::ParticleDesc &p = a.particles[i];
        const core::ParticleDesc &q = b.particles[i];
        const QString at = QStringLiteral("particles[%1].").arg(i);
        if (p.pinned != q.pinned)
            return at + u"pinned"_s;
        if (!sameBits(p.position, q.position, at + u"position"_s, d) ||
            !sameBits(p.velocity, q.velocity, at + u"velocity"_s, d) || !sameBits(p.mass, q.mass, at + u"mass"_s, d) ||
            !sameBits(p.radius, q.radius, at + u"radius"_s, d))
            return d;
    }
    for (std::size_t i = 0; i < a.springs.size(); ++i) {
        const core::SpringDesc &p = a.springs[i];
        const core::SpringDesc &q = b.springs[i];
        const QString at = QStringLiteral("springs[%1].").arg(i);
        if (p.a != q.a || p.b != q.b)
            return at + u"particles"_s;
        if (!sameBits(p.stiffness, q.stiffness, at + u"stiffness"_s, d) ||
            !sameBits(p.damping, q.damping, at + u"damping"_s, d) ||
            !sameBits(p.restLength, q.restLength, at + u"restLength"_s, d) ||
            !sameBits(p.breakStrain, q.breakStrain, at + u"breakStrain"_s, d))
            return d;
    }
    for (std::size_t i = 0; i < a.planes.size(); ++i) {
        const core::PlaneDesc &p = a.planes[i];
        const core::PlaneDesc &q = b.planes[i];
        const QString at = QStringLiteral("planes[%1].").arg(i);
        if (p.twoSided != q.twoSided)
            return at + u"twoSided"_s;
        if (!sameBits(p.normal, q.normal, at + u"normal"_s, d) || !sameBits(p.offset, q.offset, at + u"offset"_s, d) ||
            !sameBits(p.friction, q.friction, at + u"friction"_s, d) || !sameBits(p.size, q.size, at + u"size"_s, d) ||
            !sameBits(p.centre, q.centre, at + u"centre"_s, d) || !sameBits(p.axis, q.axis, at + u"axis"_s, d))
            return d;
    }
    if (a.contactImpulses.size() != b.contactImpulses.size())
        return QStringLiteral("contactImpulses: counts");
    for (std::size_t k = 0; k < a.contactImpulses.size(); ++k) {
        const core::ContactImpulse &p = a.contactImpulses[k];
        const core::ContactImpulse &q = b.contactImpulses[k];
        const QString at = QStringLiteral("contactImpulses[%1].").arg(k);
        if (p.i != q.i || p.j != q.j)
            return at + u"particle, other or plane"_s;
        if (!sameBits(p.normal, q.normal, at + u"normal"_s, d) || !sameBits(p.friction, q.friction, at + u"friction"_s, d))
            return d;
    }
    return {};
}

// a scene full of values that are hard to write and read back exactly
core::SceneDesc awkwardScene()
{
    const double denormal = std::numeric_limits<double>::denorm_min();  // 5e-324
    core::SceneDesc scene;
    scene.name = "awkward \"quoted\" \\ back\tslash\nnewline \x01 na\xc3\xafve \xe2\x98\x83 \xf0\x9f\x98\x80";
    scene.settings.timeStep = 1.0 / 3.0;
    scene.settings.substeps = 7;
    scene.settings.autoSubsteps = true;
    scene.settings.integrator = core::Integrator::ExplicitEuler;
    scene.settings.xpbdIterations = 13;
    scene.settings.gravity = {-0.0, -9.81, 1e-300};
    scene.settings.viscosity = denormal;
    scene.settings.restitution = 0.1;
    scene.settings.contactSolver = core::ContactSolver::Handout;
    scene.settings.friction = denormal;
    scene.settings.staticFriction = 1.0 / 3.0;
    scene.settings.adaptiveStep = 1.0 / 7.0;
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = true;

    core::ParticleDesc p;
    p.position = {0.1, 1.0 / 3.0, 1e-300};
    p.velocity = {-0.0, denormal, -denormal};
    p.mass = 1e-300;
    p.radius = 0.30000000000000004;
    scene.particles.push_back(p);

    p.position = {-1e9, std::nextafter(1e9, 0.0), std::numeric_limits<double>::min()};
    p.velocity = {2.0 / 3.0, -1e9, 123456.789e-3};
    p.mass = 1e9;
    p.radius = denormal;
    p.pinned = true;
    scene.particles.push_back(p);

    p.position = {std::nextafter(0.0, 1.0) * 3, -std::nextafter(1.0, 2.0), 1e-7};
    p.velocity = {1e-5, 900719925.4740993, -0.0};
    p.mass = 0.1 + 0.2;
    p.radius = 1e6;
    p.pinned = false;
    scene.particles.push_back(p);

    scene.springs.push_back({0, 1, 1e9, 1.0 / 7.0, -0.0});
    scene.springs.push_back({2, 0, denormal, 0.0, 1e6});
    scene.springs.push_back({1, 2, 3.0, 0.0, 0.5, 1.0 / 3.0});  // breakable
    scene.planes.push_back({{0.6, 0.8, -0.0}, -0.0});
    scene.planes.push_back({{0.0, -1.0, 0.0}, 1.0 / 3.0});

    // a two-sided wall with its own friction, and a tilted rectangle
    core::PlaneDesc wall;
    wall.normal = {1.0, 0.0, 0.0};
    wall.offset = -2.5;
    wall.twoSided = true;
    wall.friction = 0.1 + 0.2;
    scene.planes.push_back(wall);
    core::PlaneDesc table;
    table.normal = {0.0, 0.8, -0.6};
    table.offset = 1.0 / 7.0;
    table.size = {2.0 / 3.0, denormal};
    table.centre = {-0.0, 1e-300, 1e9};
    table.axis = {-0.0, 0.6, 0.8};
    table.friction = 0.0;
    scene.planes.push_back(table);

    // a saved run's contact impulses: with a particle, and with the last plane
    scene.contactImpulses.push_back({0, 2, 1.0 / 3.0, {-0.0, denormal, 1e-300}});
    scene.contactImpulses.push_back({2, -4, 0.0, {2.0 / 3.0, 0.0, -1e9}});
    return scene;
}

QStringList exampleFiles()
{
    const QDir dir(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes"));
    QStringList files;
    for (const QString &name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        files += dir.filePath(name);
    return files;
}

// kBase with an unknown key whose value brings the document to `depth` arrays and objects open at
// once (the top-level object is the first)
QByteArray nestedTo(int depth)
{
    const QByteArray value = QByteArray(depth - 1, '[') + QByteArray(depth - 1, ']');
    return QByteArray(kBase).replace("\"name\": \"base\",", "\"name\": \"base\", \"extra\": " + value + ',');
}

io::LoadLimits limitsWith(qint64 fileBytes, qsizetype particles, qsizetype springs, qsizetype planes)
{
    io::LoadLimits limits;
    limits.fileBytes = fileBytes;
    limits.particles = particles;
    limits.springs = springs;
    limits.planes = planes;
    return limits;
}

}  // namespace

Q_DECLARE_METATYPE(io::LoadLimits)

class TestSceneFile : public QObject {
    Q_OBJECT

private slots:
    void baseIsValid();
    void outOfMemoryIsAMessage();
    void badFile_data();
    void badFile();
    void unreadableFile_data();
    void unreadableFile();
    void defaults();
    void unknownKeysWarn();
    void contactSettings_data();
    void contactSettings();
    void planeKeys_data();
    void planeKeys();
    void negativeZeroLiterals_data();
    void negativeZeroLiterals();
    void normalsNormalised_data();
    void normalsNormalised();
    void tinyNormalHasADirection();
    void keyLikeAPathNamesNoOtherMember();
    void surrogatePairIsACharacter();
    void roundTripAwkward();
    void roundTripRandomBits();
    void trianglesAndSheetSettingsRoundTrip();
    void badTrianglesAreNamed_data();
    void badTrianglesAreNamed();
    void examplesExist();
    void roundTripExamples_data();
    void roundTripExamples();
    void examplesStartClearOfTheirPlanes_data();
    void examplesStartClearOfTheirPlanes();
    void saveWritesEveryKey();
    void saveFailureKeepsOldFile_data();
    void saveFailureKeepsOldFile();
    void saveRefusesWhatIsNotAFile();
    void limits_data();
    void limits();
    void oversizedFileNotRead();
    void endlessDeviceRefused();
};

void TestSceneFile::baseIsValid()
{
    const io::LoadResult result = io::parseScene(kBase, QStringLiteral("base.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY(result.warnings.isEmpty());
    QCOMPARE(result.scene->particles.size(), std::size_t(3));
    QCOMPARE(result.scene->springs.size(), std::size_t(2));
    QCOMPARE(result.scene->planes.size(), std::size_t(1));
}

void TestSceneFile::badFile_data()
{
    // from: text of kBase to replace ("" replaces the whole file); to: its replacement
    QTest::addColumn<QByteArray>("from");
    QTest::addColumn<QByteArray>("to");
    QTest::addColumn<QString>("path");  // "" when the problem has no JSON path
    QTest::addColumn<QString>("reason");

    // not JSON, empty, truncated, not an object
    QTest::newRow("not json") << QByteArray() << QByteArray("hello") << QString()
                              << QStringLiteral("not valid JSON (illegal value at byte");
    QTest::newRow("empty") << QByteArray() << QByteArray(" \n") << QString() << QStringLiteral("the file is empty");
    QTest::newRow("truncated") << QByteArray() << kBase.left(kBase.indexOf("0.4, 1") + 4)
                               << QStringLiteral("particles[1].position[1]")
                               << QStringLiteral("the file ends too early: is it truncated?");
    QTest::newRow("truncated in a string")
        << QByteArray() << kBase.left(kBase.indexOf("symplectic") + 4) << QStringLiteral("settings.integrator")
        << QStringLiteral("the file ends too early");
    QTest::newRow("missing comma") << QByteArray("\"mass\": 2,") << QByteArray("\"mass\": 2")
                                   << QStringLiteral("particles[1].mass")
                                   << QStringLiteral("not valid JSON (unterminated object at byte");
    QTest::newRow("trailing garbage") << QByteArray("\n}\n") << QByteArray("\n} }") << QString()
                                      << QStringLiteral("garbage at the end of the document");
    QTest::newRow("not an object") << QByteArray() << QByteArray("[1, 2]") << QString()
                                   << QStringLiteral("expected a JSON object at the top level, got an array");
    QTest::newRow("a number at the top") << QByteArray() << QByteArray(" 7\n") << QString()
                                         << QStringLiteral("expected a JSON object at the top level, got a number");
    QTest::newRow("a string at the top") << QByteArray() << QByteArray("\"scene\"") << QString()
                                         << QStringLiteral("expected a JSON object at the top level, got a string");
    QTest::newRow("only a byte order mark") << QByteArray() << QByteArray("\xEF\xBB\xBF\n") << QString()
                                            << QStringLiteral("the file is empty: it holds only a byte order mark");

    // a key twice in one object: Qt keeps the last, silently; Springlab takes neither
    QTest::newRow("particles twice") << QByteArray("\"particles\": [\n") << QByteArray("\"particles\": [], \"particles\": [\n")
                                     << QStringLiteral("particles") << QStringLiteral("this key comes twice in its object");
    QTest::newRow("rest length from far apart particles")
        << QByteArray("{\"position\": [0.8, 1, 0]") << QByteArray("{\"position\": [0.8, 2e6, 0]")
        << QStringLiteral("springs[1].restLength")
        << QStringLiteral("(the distance between its particles, taken since the spring gives no restLength)");
    QTest::newRow("lone surrogate") << QByteArray("\"name\": \"base\"") << QByteArray("\"name\": \"ba\\ud800se\"")
                                    << QStringLiteral("name") << QStringLiteral("a lone surrogate");
    QTest::newRow("lone low surrogate") << QByteArray("\"name\": \"base\"") << QByteArray("\"name\": \"base\\udc00\"")
                                        << QStringLiteral("name") << QStringLiteral("a lone surrogate");
    QTest::newRow("mass twice") << QByteArray("\"mass\": 2,") << QByteArray("\"mass\": 2, \"mass\": 5,")
                                << QStringLiteral("particles[1].mass") << QStringLiteral("this key comes twice in its object");

    // huge numbers and NaN, which JSON cannot hold
    QTest::newRow("1e999") << QByteArray("\"mass\": 3") << QByteArray("\"mass\": 1e999")
                           << QStringLiteral("particles[2].mass")
                           << QStringLiteral("the number 1e999 is too large for a double: JSON has no infinity or NaN");
    QTest::newRow("-1e999") << QByteArray("\"offset\": 0") << QByteArray("\"offset\": -1e999")
                            << QStringLiteral("planes[0].offset")
                            << QStringLiteral("the number -1e999 is too large for a double");
    QTest::newRow("1e-999") << QByteArray("[3, 0, 0]") << QByteArray("[3, 1e-999, 0]")
                            << QStringLiteral("particles[0].velocity[1]")
                            << QStringLiteral("the number 1e-999 is too close to zero for a double");
    QTest::newRow("NaN") << QByteArray("\"mass\": 2") << QByteArray("\"mass\": NaN")
                         << QStringLiteral("particles[1].mass")
                         << QStringLiteral("NaN is not a JSON number: JSON has no NaN or infinity");
    QTest::newRow("Infinity") << QByteArray("\"radius\": 0.2") << QByteArray("\"radius\": Infinity")
                              << QStringLiteral("particles[1].radius")
                              << QStringLiteral("Infinity is not a JSON number");

    // another format, another version
    QTest::newRow("other format") << QByteArray("\"format\": \"springlab-scene\"")
                                  << QByteArray("\"format\": \"blender-scene\"") << QStringLiteral("format")
                                  << QStringLiteral(
                                         "not a Springlab scene (expected \"springlab-scene\", got \"blender-scene\")");
    QTest::newRow("format missing") << QByteArray("\"format\": \"springlab-scene\",") << QByteArray()
                                    << QStringLiteral("format") << QStringLiteral("missing: not a Springlab scene");
    QTest::newRow("format not a string") << QByteArray("\"format\": \"springlab-scene\"") << QByteArray("\"format\": 1")
                                         << QStringLiteral("format") << QStringLiteral("got a number");
    QTest::newRow("newer version") << QByteArray("\"version\": 1") << QByteArray("\"version\": 2")
                                   << QStringLiteral("version")
                                   << QStringLiteral("the file is version 2, newer than this build of Springlab reads "
                                                     "(version 1 at most)");
    QTest::newRow("version 0") << QByteArray("\"version\": 1") << QByteArray("\"version\": 0")
                               << QStringLiteral("version") << QStringLiteral("there is no version 0");
    QTest::newRow("version a string") << QByteArray("\"version\": 1") << QByteArray("\"version\": \"1\"")
                                      << QStringLiteral("version")
                                      << QStringLiteral("expected an integer, got a string");
    QTest::newRow("version missing") << QByteArray("\"version\": 1,") << QByteArray() << QStringLiteral("version")
                                     << QStringLiteral("missing: this key is required");

    // wrong types
    QTest::newRow("mass a string") << QByteArray("\"mass\": 3") << QByteArray("\"mass\": \"heavy\"")
                                   << QStringLiteral("particles[2].mass")
                                   << QStringLiteral("expected a number, got a string");
    QTest::newRow("pinned a string") << QByteArray("\"pinned\": true") << QByteArray("\"pinned\": \"yes\"")
                                     << QStringLiteral("particles[2].pinned")
                                     << QStringLiteral("expected true or false, got a string");
    QTest::newRow("name a number") << QByteArray("\"name\": \"base\"") << QByteArray("\"name\": 7")
                                   << QStringLiteral("name") << QStringLiteral("expected a string, got a number");
    QTest::newRow("settings an array") << QByteArray("\"settings\": {") << QByteArray("\"settings\": [], \"x\": {")
                                       << QStringLiteral("settings")
                                       << QStringLiteral("expected an object, got an array");
    QTest::newRow("particles an object") << QByteArray("\"particles\": [\n")
                                         << QByteArray("\"particles\": {}, \"x\": [\n") << QStringLiteral("particles")
                                         << QStringLiteral("expected an array, got an object");
    QTest::newRow("particle a number") << QByteArray("\"particles\": [\n") << QByteArray("\"particles\": [7, ")
                                       << QStringLiteral("particles[0]")
                                       << QStringLiteral("expected an object, got a number");
    QTest::newRow("gravity a number") << QByteArray("\"gravity\": [0, -9.81, 0]") << QByteArray("\"gravity\": -9.81")
                                      << QStringLiteral("settings.gravity")
                                      << QStringLiteral("expected an array of 3 numbers, got a number");
    QTest::newRow("position component null")
        << QByteArray("[0.8, 1, 0]") << QByteArray("[0.8, null, 0]") << QStringLiteral("particles[2].position[1]")
        << QStringLiteral("expected a number, got null");
    QTest::newRow("substeps a fraction") << QByteArray("\"substeps\": 1") << QByteArray("\"substeps\": 2.5")
                                         << QStringLiteral("settings.substeps")
                                         << QStringLiteral("expected an integer, got 2.5");
    QTest::newRow("unknown integrator") << QByteArray("\"symplectic-euler\"") << QByteArray("\"rk9\"")
                                        << QStringLiteral("settings.integrator")
                                        << QStringLiteral(
                                               "unknown integrator \"rk9\" (known: symplectic-euler, explicit-euler, velocity-verlet, rk4, implicit-euler, adaptive-rk45, xpbd, projective, vbd)");

    // the contact keys: names, types and shapes
    QTest::newRow("unknown contact solver")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"contactSolver\": \"box2d\",")
        << QStringLiteral("settings.contactSolver")
        << QStringLiteral("unknown contact solver \"box2d\" (known: iterative, handout)");
    QTest::newRow("contact solver in capitals")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"contactSolver\": \"Handout\",")
        << QStringLiteral("settings.contactSolver") << QStringLiteral("unknown contact solver \"Handout\"");
    QTest::newRow("contact solver a number")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"contactSolver\": 2,")
        << QStringLiteral("settings.contactSolver") << QStringLiteral("expected a string, got a number");
    QTest::newRow("friction a string")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"friction\": \"high\",")
        << QStringLiteral("settings.friction") << QStringLiteral("expected a number, got a string");
    QTest::newRow("static friction null")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"staticFriction\": null,")
        << QStringLiteral("settings.staticFriction") << QStringLiteral("expected a number, got null");
    QTest::newRow("two-sided a number") << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"twoSided\": 1}")
                                        << QStringLiteral("planes[0].twoSided")
                                        << QStringLiteral("expected true or false, got a number");
    QTest::newRow("plane friction an array")
        << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"friction\": [0.5]}")
        << QStringLiteral("planes[0].friction") << QStringLiteral("expected a number, got an array");
    QTest::newRow("size a number") << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"size\": 2}")
                                   << QStringLiteral("planes[0].size")
                                   << QStringLiteral("expected an array of 2 numbers, got a number");
    QTest::newRow("size of three") << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"size\": [1, 2, 3]}")
                                   << QStringLiteral("planes[0].size")
                                   << QStringLiteral("expected an array of 2 numbers, got 3");
    QTest::newRow("size component a string")
        << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"size\": [1, \"2\"]}")
        << QStringLiteral("planes[0].size[1]") << QStringLiteral("expected a number, got a string");
    QTest::newRow("short centre") << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"centre\": [1, 2]}")
                                  << QStringLiteral("planes[0].centre")
                                  << QStringLiteral("expected an array of 3 numbers, got 2");
    QTest::newRow("axis an object") << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"axis\": {}}")
                                    << QStringLiteral("planes[0].axis")
                                    << QStringLiteral("expected an array of 3 numbers, got an object");

    // missing keys, vectors of the wrong length
    QTest::newRow("radius missing") << QByteArray("\"mass\": 2, \"radius\": 0.2}") << QByteArray("\"mass\": 2}")
                                    << QStringLiteral("particles[1].radius")
                                    << QStringLiteral("missing: this key is required");
    QTest::newRow("position missing") << QByteArray("\"position\": [0.8, 1, 0], ") << QByteArray()
                                      << QStringLiteral("particles[2].position") << QStringLiteral("missing");
    QTest::newRow("stiffness missing") << QByteArray("\"stiffness\": 5000, ") << QByteArray()
                                       << QStringLiteral("springs[1].stiffness") << QStringLiteral("missing");
    QTest::newRow("springs missing") << QByteArray("\"springs\": [") << QByteArray("\"springz\": [")
                                     << QStringLiteral("springs") << QStringLiteral("missing: this key is required");
    QTest::newRow("normal missing") << QByteArray("\"normal\": [0, 1, 0], ") << QByteArray()
                                    << QStringLiteral("planes[0].normal") << QStringLiteral("missing");
    QTest::newRow("short position") << QByteArray("[0.4, 1, 0]") << QByteArray("[0.4, 1]")
                                    << QStringLiteral("particles[1].position")
                                    << QStringLiteral("expected an array of 3 numbers, got 2");
    QTest::newRow("long velocity") << QByteArray("[3, 0, 0]") << QByteArray("[3, 0, 0, 0]")
                                   << QStringLiteral("particles[0].velocity")
                                   << QStringLiteral("expected an array of 3 numbers, got 4");

    // spring ends
    QTest::newRow("fractional index") << QByteArray("[1, 2]") << QByteArray("[1, 1.5]")
                                      << QStringLiteral("springs[1].particles[1]")
                                      << QStringLiteral("expected an integer, got 1.5");
    QTest::newRow("index a string") << QByteArray("[1, 2]") << QByteArray("[\"1\", 2]")
                                    << QStringLiteral("springs[1].particles[0]")
                                    << QStringLiteral("expected an integer, got a string");
    QTest::newRow("three ends") << QByteArray("[1, 2]") << QByteArray("[1, 2, 0]")
                                << QStringLiteral("springs[1].particles")
                                << QStringLiteral("expected an array of 2 particle indices, got 3");
    QTest::newRow("index out of range") << QByteArray("[1, 2]") << QByteArray("[1, 3]")
                                        << QStringLiteral("springs[1].particles[1]")
                                        << QStringLiteral(
                                               "particle index 3 is out of range (the scene has 3 particles)");
    QTest::newRow("negative index") << QByteArray("[0, 1]") << QByteArray("[-1, 1]")
                                    << QStringLiteral("springs[0].particles[0]")
                                    << QStringLiteral("particle index -1 is out of range");
    QTest::newRow("huge index") << QByteArray("[0, 1]") << QByteArray("[0, 1e12]")
                                << QStringLiteral("springs[0].particles[1]")
                                << QStringLiteral("the integer 1e+12 is too large");
    QTest::newRow("self spring") << QByteArray("[1, 2]") << QByteArray("[2, 2]")
                                 << QStringLiteral("springs[1].particles")
                                 << QStringLiteral("joins particle 2 to itself");

    // values out of range, as core::findProblem() words them
    QTest::newRow("zero mass") << QByteArray("\"mass\": 3") << QByteArray("\"mass\": 0")
                               << QStringLiteral("particles[2].mass")
                               << QStringLiteral("must be greater than 0 kg (got 0 kg)");
    QTest::newRow("negative mass") << QByteArray("\"mass\": 2") << QByteArray("\"mass\": -1")
                                   << QStringLiteral("particles[1].mass")
                                   << QStringLiteral("must be greater than 0 kg (got -1 kg)");
    QTest::newRow("zero radius") << QByteArray("\"radius\": 0.1") << QByteArray("\"radius\": 0")
                                 << QStringLiteral("particles[0].radius") << QStringLiteral("must be greater than 0 m");
    QTest::newRow("negative radius") << QByteArray("\"radius\": 0.3") << QByteArray("\"radius\": -0.3")
                                     << QStringLiteral("particles[2].radius")
                                     << QStringLiteral("must be greater than 0 m");
    QTest::newRow("time step 5 s") << QByteArray("\"timeStep\": 0.01") << QByteArray("\"timeStep\": 5")
                                   << QStringLiteral("settings.timeStep")
                                   << QStringLiteral("must be at most 1 s (got 5 s)");
    QTest::newRow("restitution 2") << QByteArray("\"restitution\": 1") << QByteArray("\"restitution\": 2")
                                   << QStringLiteral("settings.restitution") << QStringLiteral("must be at most 1");
    QTest::newRow("negative stiffness") << QByteArray("\"stiffness\": 5000") << QByteArray("\"stiffness\": -5")
                                        << QStringLiteral("springs[1].stiffness")
                                        << QStringLiteral("must be at least 0");
    QTest::newRow("negative breaking strain")
        << QByteArray("\"restLength\": 0.4}") << QByteArray("\"restLength\": 0.4, \"breakStrain\": -1}")
        << QStringLiteral("springs[0].breakStrain") << QStringLiteral("must be at least 0");
    QTest::newRow("zero normal") << QByteArray("\"normal\": [0, 1, 0]") << QByteArray("\"normal\": [0, 0, 0]")
                                 << QStringLiteral("planes[0].normal")
                                 << QStringLiteral("is zero: a plane needs a direction");
    QTest::newRow("huge coordinate") << QByteArray("[0.8, 1, 0]") << QByteArray("[0.8, 1, 1e300]")
                                     << QStringLiteral("particles[2].position[2]") << QStringLiteral("must be at most");

    // the contact values, against the same table
    QTest::newRow("friction above 10")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"friction\": 10.5,")
        << QStringLiteral("settings.friction") << QStringLiteral("must be at most 10 (got 10.5)");
    QTest::newRow("adaptive step of 0")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"adaptiveStep\": 0,")
        << QStringLiteral("settings.adaptiveStep") << QStringLiteral("must be greater than 0 s (got 0");
    QTest::newRow("no xpbd iterations")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"xpbdIterations\": 0,")
        << QStringLiteral("settings.xpbdIterations") << QStringLiteral("must be at least 1 (got 0)");
    QTest::newRow("too many xpbd iterations")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"xpbdIterations\": 101,")
        << QStringLiteral("settings.xpbdIterations") << QStringLiteral("must be at most 100 (got 101)");
    QTest::newRow("negative static friction")
        << QByteArray("\"restitution\": 1,") << QByteArray("\"restitution\": 1, \"staticFriction\": -0.1,")
        << QStringLiteral("settings.staticFriction") << QStringLiteral("must be at least 0 (got -0.1)");
    QTest::newRow("plane friction above 10")
        << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"friction\": 12}")
        << QStringLiteral("planes[0].friction") << QStringLiteral("must be at most 10 (got 12)");
    QTest::newRow("third plane's friction")
        << QByteArray("{\"normal\": [0, 1, 0], \"offset\": 0}")
        << QByteArray("{\"normal\": [0, 1, 0], \"offset\": 0}, {\"normal\": [1, 0, 0], \"offset\": -3},\n"
                      "        {\"normal\": [-1, 0, 0], \"offset\": -3, \"friction\": -1}")
        << QStringLiteral("planes[2].friction") << QStringLiteral("must be at least 0 (got -1)");
    QTest::newRow("negative size") << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"size\": [-1, 2]}")
                                   << QStringLiteral("planes[0].size[0]")
                                   << QStringLiteral("must be at least 0 m (got -1 m)");
    QTest::newRow("size past 1e6") << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"size\": [1, 2e6]}")
                                   << QStringLiteral("planes[0].size[1]") << QStringLiteral("must be at most 1e+06 m");
    QTest::newRow("one side zero") << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"size\": [2, 0]}")
                                   << QStringLiteral("planes[0].size")
                                   << QStringLiteral("needs both sides greater than 0 m for a rectangle, or both 0");
    QTest::newRow("centre far away")
        << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"size\": [1, 1], \"centre\": [0, 2e9, 0]}")
        << QStringLiteral("planes[0].centre[1]") << QStringLiteral("must be at most");
    QTest::newRow("axis huge") << QByteArray("\"offset\": 0}") << QByteArray("\"offset\": 0, \"axis\": [-1e10, 0, 0]}")
                               << QStringLiteral("planes[0].axis[0]") << QStringLiteral("must be at least");

    // a saved run's contact impulses
    const auto impulse = [](const char *entry) {
        return QByteArray("\n    ],\n    \"contactImpulses\": [") + entry + "]\n}\n";
    };
    const QByteArray planesEnd("\n    ]\n}\n");
    QTest::newRow("impulse on a missing plane")
        << planesEnd << impulse(R"({"particle": 0, "plane": 1, "normal": 0.1, "friction": [0, 0, 0]})")
        << QStringLiteral("contactImpulses[0].plane") << QStringLiteral("plane index 1 is out of range (the scene has 1 planes)");
    QTest::newRow("impulse on a missing particle")
        << planesEnd << impulse(R"({"particle": 0, "other": 3, "normal": 0.1, "friction": [0, 0, 0]})")
        << QStringLiteral("contactImpulses[0].other") << QStringLiteral("particle index 3 is out of range");
    QTest::newRow("impulse with itself")
        << planesEnd << impulse(R"({"particle": 1, "other": 1, "normal": 0.1, "friction": [0, 0, 0]})")
        << QStringLiteral("contactImpulses[0].other") << QStringLiteral("is the particle itself");
    QTest::newRow("impulse with a plane and a particle")
        << planesEnd << impulse(R"({"particle": 0, "other": 1, "plane": 0, "normal": 0.1, "friction": [0, 0, 0]})")
        << QStringLiteral("contactImpulses[0]") << QStringLiteral("needs either \"other\" (a particle) or \"plane\"");
    QTest::newRow("impulse that pulls")
        << planesEnd << impulse(R"({"particle": 0, "plane": 0, "normal": -0.1, "friction": [0, 0, 0]})")
        << QStringLiteral("contactImpulses[0].normal") << QStringLiteral("a contact pushes, never pulls");
    QTest::newRow("impulse friction huge")
        << planesEnd << impulse(R"({"particle": 0, "plane": 0, "normal": 0.1, "friction": [0, 1e300, 0]})")
        << QStringLiteral("contactImpulses[0].friction[1]") << QStringLiteral("must be from -1e9 to 1e9 N·s (got 1e+300 N·s)");
    QTest::newRow("impulse without friction")
        << planesEnd << impulse(R"({"particle": 0, "plane": 0, "normal": 0.1})")
        << QStringLiteral("contactImpulses[0].friction") << QStringLiteral("missing: this key is required");
}

void TestSceneFile::badFile()
{
    QFETCH(QByteArray, from);
    QFETCH(QByteArray, to);
    QFETCH(QString, path);
    QFETCH(QString, reason);

    // one change to a valid scene
    QByteArray json = to;
    if (!from.isEmpty()) {
        QCOMPARE(kBase.count(from), qsizetype(1));
        json = QByteArray(kBase).replace(from, to);
    }

    const io::LoadResult result = io::parseScene(json, QStringLiteral("dir/bad.json"));
    QVERIFY(!result.ok());
    QVERIFY(!result.scene.has_value());
    const QString prefix = path.isEmpty() ? QStringLiteral("dir/bad.json: ") : u"dir/bad.json: "_s + path + u": "_s;
    QVERIFY2(result.error.startsWith(prefix), qPrintable(result.error));
    QVERIFY2(result.error.contains(reason), qPrintable(result.error));
    QVERIFY2(!result.error.contains(u'\n'), qPrintable(result.error));
}

void TestSceneFile::unreadableFile_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("reason");
    QTest::newRow("missing") << QStringLiteral("nothing-here.json") << QStringLiteral("cannot open: no such file");
    QTest::newRow("a folder") << QStringLiteral("folder.json")
                              << QStringLiteral("cannot open: it is a folder, not a file");
}

void TestSceneFile::unreadableFile()
{
    QFETCH(QString, name);
    QFETCH(QString, reason);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("folder.json")));
    const QString path = dir.filePath(name);
    const io::LoadResult result = io::loadScene(path);
    QVERIFY(!result.ok());
    QCOMPARE(result.error, QDir::toNativeSeparators(path) + u": "_s + reason);
}

void TestSceneFile::defaults()
{
    // only the required keys; settings left out altogether
    const QByteArray json = R"({"format": "springlab-scene", "version": 1, "name": "minimal",
        "particles": [{"position": [0, 0, 0], "mass": 1, "radius": 0.5},
                      {"position": [3, 4, 0], "mass": 2, "radius": 0.5}],
        "springs": [{"particles": [0, 1], "stiffness": 10, "damping": 0.5}],
        "planes": [{"normal": [0, 1, 0], "offset": 0}]})";
    const io::LoadResult result = io::parseScene(json, QStringLiteral("minimal.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY(result.warnings.isEmpty());
    const core::SceneDesc &scene = *result.scene;
    QCOMPARE(scene.name, std::string("minimal"));
    QVERIFY(scene.settings == core::Settings{});
    for (const core::ParticleDesc &particle : scene.particles) {
        QVERIFY(particle.velocity == Eigen::Vector3d::Zero());
        QVERIFY(!particle.pinned);
    }
    QCOMPARE(scene.springs[0].restLength, 5.0);
    // a plane is unbounded and one-sided, with the settings' friction
    QVERIFY(scene.planes[0] == core::PlaneDesc{});
    QVERIFY(!scene.planes[0].twoSided && !scene.planes[0].friction && !scene.planes[0].bounded());
    QVERIFY(scene.settings.contactSolver == core::ContactSolver::Iterative);
    QCOMPARE(scene.settings.friction, 0.0);
    QVERIFY(!scene.settings.staticFriction);

    // an empty settings object is the same; a key in it overrides only itself
    QByteArray withSettings = json;
    withSettings.replace("\"planes\": [", "\"settings\": {\"viscosity\": 0.25}, \"planes\": [");
    const io::LoadResult other = io::parseScene(withSettings, QStringLiteral("minimal.json"));
    QVERIFY2(other.ok(), qPrintable(other.error));
    core::Settings expected;
    expected.viscosity = 0.25;
    QVERIFY(other.scene->settings == expected);
}

void TestSceneFile::unknownKeysWarn()
{
    QByteArray json = kBase;
    json.replace("\"name\": \"base\",", "\"name\": \"base\", \"author\": \"me\",");
    json.replace("\"substeps\": 1,", "\"substeps\": 1, \"solver\": {\"x\": 1},");
    json.replace("\"mass\": 2,", "\"mass\": 2, \"colour\": [1, 0, 0],");
    json.replace("\"damping\": 1}", "\"damping\": 1, \"breakable\": true}");
    json.replace("\"offset\": 0}", "\"offset\": 0, \"colour\": \"grey\"}");
    const io::LoadResult result = io::parseScene(json, QStringLiteral("extra.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));

    QStringList warnings = result.warnings;
    warnings.sort();
    const QStringList expected = {
        QStringLiteral("extra.json: author: unknown key, ignored"),
        QStringLiteral("extra.json: particles[1].colour: unknown key, ignored"),
        QStringLiteral("extra.json: planes[0].colour: unknown key, ignored"),
        QStringLiteral("extra.json: settings.solver: unknown key, ignored"),
        QStringLiteral("extra.json: springs[1].breakable: unknown key, ignored"),
    };
    QCOMPARE(warnings, expected);

    // the known keys read as if the others were not there
    const io::LoadResult base = io::parseScene(kBase, QStringLiteral("base.json"));
    QVERIFY(*result.scene == *base.scene);
}

void TestSceneFile::contactSettings_data()
{
    // keys: put into kBase's settings; staticFriction -1: unset; written: what saving writes of them
    QTest::addColumn<QByteArray>("keys");
    QTest::addColumn<int>("solver");
    QTest::addColumn<double>("friction");
    QTest::addColumn<double>("staticFriction");
    QTest::addColumn<QByteArray>("written");

    const QByteArray iterative = "        \"contactSolver\": \"iterative\",\n";
    const QByteArray handout = "        \"contactSolver\": \"handout\",\n";
    const int it = int(core::ContactSolver::Iterative);
    QTest::newRow("absent: the defaults") << QByteArray() << it << 0.0 << -1.0
                                          << iterative + "        \"friction\": 0,\n        \"planeCollisions\"";
    QTest::newRow("the handout's") << QByteArray("\"contactSolver\": \"handout\",") << int(core::ContactSolver::Handout)
                                   << 0.0 << -1.0 << handout + "        \"friction\": 0,\n        \"planeCollisions\"";
    QTest::newRow("iterative, named") << QByteArray("\"contactSolver\": \"iterative\",") << it << 0.0 << -1.0
                                      << iterative + "        \"friction\": 0,\n        \"planeCollisions\"";
    QTest::newRow("kinetic only: static follows")
        << QByteArray("\"friction\": 0.5,") << it << 0.5 << -1.0
        << iterative + "        \"friction\": 0.5,\n        \"planeCollisions\"";
    QTest::newRow("static of its own") << QByteArray("\"friction\": 0.5, \"staticFriction\": 0.8,") << it << 0.5 << 0.8
                                       << iterative + "        \"friction\": 0.5,\n        \"staticFriction\": 0.8,\n";
    QTest::newRow("static set equal is kept")
        << QByteArray("\"staticFriction\": 0.5, \"friction\": 0.5,") << it << 0.5 << 0.5
        << iterative + "        \"friction\": 0.5,\n        \"staticFriction\": 0.5,\n";
    QTest::newRow("static zero is kept") << QByteArray("\"staticFriction\": 0,") << it << 0.0 << 0.0
                                         << iterative + "        \"friction\": 0,\n        \"staticFriction\": 0,\n";
    QTest::newRow("the table's ends") << QByteArray("\"friction\": 10, \"staticFriction\": 10,") << it << 10.0 << 10.0
                                      << iterative + "        \"friction\": 10,\n        \"staticFriction\": 10,\n";
}

void TestSceneFile::contactSettings()
{
    QFETCH(QByteArray, keys);
    QFETCH(int, solver);
    QFETCH(double, friction);
    QFETCH(double, staticFriction);
    QFETCH(QByteArray, written);

    // read
    const QByteArray json = QByteArray(kBase).replace("\"restitution\": 1,", "\"restitution\": 1, " + keys);
    const io::LoadResult result = io::parseScene(json, QStringLiteral("contacts.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY2(result.warnings.isEmpty(), qPrintable(result.warnings.join(u'\n')));
    const core::Settings &settings = result.scene->settings;
    QCOMPARE(int(settings.contactSolver), solver);
    QCOMPARE(settings.friction, friction);
    QCOMPARE(settings.staticFriction.has_value(), staticFriction >= 0.0);
    if (settings.staticFriction)
        QCOMPARE(*settings.staticFriction, staticFriction);

    // written after the restitution, the static coefficient only when set; read back the same
    const QByteArray saved = io::sceneToJson(*result.scene);
    QVERIFY2(saved.contains("        \"restitution\": 1,\n" + written), saved.constData());
    QCOMPARE(saved.contains("staticFriction"), staticFriction >= 0.0);
    const io::LoadResult again = io::parseScene(saved, QStringLiteral("again.json"));
    QVERIFY2(again.ok(), qPrintable(again.error));
    QCOMPARE(bitDifference(*result.scene, *again.scene), QString());
    QCOMPARE(io::sceneToJson(*again.scene), saved);
}

void TestSceneFile::planeKeys_data()
{
    // plane: kBase's plane replaced by this; written: how saving writes it (keys in a fixed order,
    // each only when it says something: two-sided when true, friction when the plane has its own,
    // size, centre and axis for a rectangle or when not zero)
    QTest::addColumn<QByteArray>("plane");
    QTest::addColumn<QByteArray>("written");

    const QByteArray plain = R"({"normal": [0, 1, 0], "offset": 0})";
    QTest::newRow("plain") << plain << plain;
    QTest::newRow("defaults written out are left out")
        << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "twoSided": false, "size": [0, 0], "centre": [0, 0, 0],
                         "axis": [0, 0, 0]})")
        << plain;
    QTest::newRow("two-sided") << QByteArray(R"({"normal": [1, 0, 0], "offset": -2, "twoSided": true})")
                               << QByteArray(R"({"normal": [1, 0, 0], "offset": -2, "twoSided": true})");
    QTest::newRow("own friction") << QByteArray(R"({"friction": 0.4, "normal": [0, 1, 0], "offset": 0})")
                                  << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "friction": 0.4})");
    QTest::newRow("own friction of 0") << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "friction": 0})")
                                       << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "friction": 0})");
    QTest::newRow("rectangle, default axis")
        << QByteArray(R"({"normal": [0, 1, 0], "offset": 0.75, "size": [2, 1], "centre": [0.5, 0, 0]})")
        << QByteArray(R"({"normal": [0, 1, 0], "offset": 0.75, "size": [2, 1], "centre": [0.5, 0, 0], "axis": [0, 0, 0]})");
    QTest::newRow("rectangle at the origin")
        << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "size": [3, 4]})")
        << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "size": [3, 4], "centre": [0, 0, 0], "axis": [0, 0, 0]})");
    QTest::newRow("every key")
        << QByteArray(R"({"axis": [1, 1, 0], "centre": [0, 1, -2], "size": [0.5, 1e6], "friction": 10, "twoSided": true,
                         "offset": -1, "normal": [0, 0, 1]})")
        << QByteArray(R"({"normal": [0, 0, 1], "offset": -1, "twoSided": true, "friction": 10, "size": [0.5, 1e+06], )"
                      R"("centre": [0, 1, -2], "axis": [1, 1, 0]})");
    QTest::newRow("unbounded, centre and axis kept")
        << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "centre": [1, 2, 3], "axis": [0, 0, -1]})")
        << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "centre": [1, 2, 3], "axis": [0, 0, -1]})");
    QTest::newRow("negative zeros kept")
        << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "size": [-0, 0], "axis": [0, -0, 0]})")
        << QByteArray(R"({"normal": [0, 1, 0], "offset": 0, "size": [-0, 0], "axis": [0, -0, 0]})");
}

void TestSceneFile::planeKeys()
{
    QFETCH(QByteArray, plane);
    QFETCH(QByteArray, written);

    const QByteArray json = QByteArray(kBase).replace(R"({"normal": [0, 1, 0], "offset": 0})", plane);
    const io::LoadResult result = io::parseScene(json, QStringLiteral("plane.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY2(result.warnings.isEmpty(), qPrintable(result.warnings.join(u'\n')));

    // the plane's line as saved, then the same bits and text again
    const QByteArray saved = io::sceneToJson(*result.scene);
    QVERIFY2(saved.contains("\"planes\": [\n        " + written + "\n    ]"), saved.constData());
    const io::LoadResult again = io::parseScene(saved, QStringLiteral("again.json"));
    QVERIFY2(again.ok(), qPrintable(again.error));
    QCOMPARE(bitDifference(*result.scene, *again.scene), QString());
    QCOMPARE(io::sceneToJson(*again.scene), saved);
}

void TestSceneFile::negativeZeroLiterals_data()
{
    QTest::addColumn<QByteArray>("literal");
    QTest::addColumn<bool>("negative");
    QTest::newRow("0") << QByteArray("0") << false;
    QTest::newRow("0.0") << QByteArray("0.0") << false;
    QTest::newRow("-0") << QByteArray("-0") << true;
    QTest::newRow("-0.0") << QByteArray("-0.0") << true;
    QTest::newRow("-0e3") << QByteArray("-0e3") << true;
    QTest::newRow("-0.000E-2") << QByteArray("-0.000E-2") << true;
}

void TestSceneFile::negativeZeroLiterals()
{
    QFETCH(QByteArray, literal);
    QFETCH(bool, negative);
    const QByteArray json = QByteArray(kBase).replace("[3, 0, 0]", "[3, " + literal + ", 0]");
    const io::LoadResult result = io::parseScene(json, QStringLiteral("zero.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    const double value = result.scene->particles[0].velocity.y();
    QCOMPARE(value, 0.0);
    QCOMPARE(std::signbit(value), negative);
    // only that one
    QVERIFY(!std::signbit(result.scene->particles[0].velocity.z()));
    QVERIFY(!std::signbit(result.scene->planes[0].offset));
}

void TestSceneFile::tinyNormalHasADirection()
{
    // [1e-200, 0, 0] is not zero, though its square underflows: it points along x
    const QByteArray json = QByteArray(kBase).replace("\"normal\": [0, 1, 0]", "\"normal\": [1e-200, 0, -1e-200]");
    const io::LoadResult result = io::parseScene(json, QStringLiteral("plane.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    const Eigen::Vector3d normal = result.scene->planes[0].normal;
    QVERIFY((normal - Eigen::Vector3d(1.0, 0.0, -1.0) / std::sqrt(2.0)).norm() < 1e-15);

    // and only an exact zero is refused
    const io::LoadResult zero = io::parseScene(QByteArray(kBase).replace("\"normal\": [0, 1, 0]", "\"normal\": [0, 0, -0]"),
                                               QStringLiteral("plane.json"));
    QVERIFY(!zero.ok());
    QVERIFY2(zero.error.contains(u"planes[0].normal: is zero"_s), qPrintable(zero.error));
}

void TestSceneFile::keyLikeAPathNamesNoOtherMember()
{
    // an unknown key spelt like the path of a real member: its -0 must not reach that member, and
    // the warning names it so that it cannot be taken for the member
    const QByteArray json = QByteArray(kBase).replace(
        "\"name\": \"base\",", "\"name\": \"base\", \"particles[1].velocity\": [-0, -0, -0],");
    const io::LoadResult result = io::parseScene(json, QStringLiteral("keys.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    const Eigen::Vector3d velocity = result.scene->particles[1].velocity;
    QVERIFY(!std::signbit(velocity.x()) && !std::signbit(velocity.y()) && !std::signbit(velocity.z()));
    QCOMPARE(result.warnings, QStringList{u"keys.json: [\"particles[1].velocity\"]: unknown key, ignored"_s});
}

void TestSceneFile::surrogatePairIsACharacter()
{
    // both halves of a pair, escaped: one character outside the basic plane, as written
    const QByteArray json = QByteArray(kBase).replace("\"name\": \"base\"", "\"name\": \"ball \\ud83c\\udfb1\"");
    const io::LoadResult result = io::parseScene(json, QStringLiteral("pair.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QCOMPARE(QString::fromStdString(result.scene->name), u"ball \U0001F3B1"_s);
}

void TestSceneFile::normalsNormalised_data()
{
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<double>("z");
    QTest::newRow("up, unit already") << 0.0 << 1.0 << 0.0;
    QTest::newRow("up, long") << 0.0 << 2.5 << 0.0;
    QTest::newRow("3-4-5") << 3.0 << 4.0 << 0.0;
    QTest::newRow("diagonal") << 1.0 << 1.0 << 1.0;
    QTest::newRow("tiny") << 1e-9 << -2e-9 << 0.0;
    QTest::newRow("large") << -7e8 << 1e8 << 3e8;
}

void TestSceneFile::normalsNormalised()
{
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(double, z);
    const Eigen::Vector3d raw(x, y, z);
    const QByteArray literal =
        QByteArray::number(x, 'g', 17) + ", " + QByteArray::number(y, 'g', 17) + ", " + QByteArray::number(z, 'g', 17);
    const QByteArray json = QByteArray(kBase).replace("\"normal\": [0, 1, 0]", "\"normal\": [" + literal + "]");
    const io::LoadResult result = io::parseScene(json, QStringLiteral("plane.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));

    // unit length, same direction, through core::unitNormal()
    const Eigen::Vector3d normal = result.scene->planes[0].normal;
    QVERIFY(std::abs(normal.norm() - 1.0) < 1e-15);
    QVERIFY((normal - raw.normalized()).norm() < 1e-15);
    QVERIFY(normal == core::unitNormal(raw));

    // saving and loading again leaves it alone, bit for bit
    const io::LoadResult again = io::parseScene(io::sceneToJson(*result.scene), QStringLiteral("again.json"));
    QVERIFY2(again.ok(), qPrintable(again.error));
    QCOMPARE(bitDifference(*result.scene, *again.scene), QString());
}

void TestSceneFile::roundTripAwkward()
{
    const core::SceneDesc scene = awkwardScene();
    QVERIFY(!core::findProblem(scene).has_value());

    const QByteArray json = io::sceneToJson(scene);
    const io::LoadResult result = io::parseScene(json, QStringLiteral("awkward.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY(result.warnings.isEmpty());
    QCOMPARE(bitDifference(scene, *result.scene), QString());

    // written again, the text is the same too
    QCOMPARE(io::sceneToJson(*result.scene), json);

    // and through a file
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("awkward.json"));
    const io::SaveResult saved = io::saveScene(path, scene);
    QVERIFY2(saved.ok(), qPrintable(saved.error));
    const io::LoadResult loaded = io::loadScene(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    QCOMPARE(bitDifference(scene, *loaded.scene), QString());
}

void TestSceneFile::roundTripRandomBits()
{
    // random bit patterns: every finite double inside the coordinate range is fair game
    QRandomGenerator random(20240531);
    core::SceneDesc scene;
    while (scene.particles.size() < 2000) {
        core::ParticleDesc particle;
        for (int axis = 0; axis < 6; ++axis) {
            double value = 0.0;
            do {
                value = std::bit_cast<double>(random.generate64());
            } while (!std::isfinite(value) || std::abs(value) > 1e9);
            (axis < 3 ? particle.position : particle.velocity)[axis % 3] = value;
        }
        scene.particles.push_back(particle);
    }
    const io::LoadResult result = io::parseScene(io::sceneToJson(scene), QStringLiteral("random.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QCOMPARE(bitDifference(scene, *result.scene), QString());
}

void TestSceneFile::trianglesAndSheetSettingsRoundTrip()
{
    // a cloth lists its triangles; the sheets' settings are written where they are not the defaults
    core::ClothOptions options;
    options.rows = 3;
    options.cols = 4;
    options.sheetCollisions = true;
    core::SceneDesc scene = core::makeCloth(options);
    QCOMPARE(scene.triangles.size(), std::size_t(12));
    scene.settings.thickness = 0.004;
    scene.settings.selfCollision = false;
    const QByteArray json = io::sceneToJson(scene);
    QVERIFY(json.contains("\"triangles\": ["));
    QVERIFY(json.contains("\"thickness\": 0.004"));
    QVERIFY(json.contains("\"selfCollision\": false"));
    QVERIFY(json.contains("\"triangleCollisions\": true"));
    const io::LoadResult result = io::parseScene(json, QStringLiteral("sheet.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY(result.scene->triangles == scene.triangles);
    QVERIFY(result.scene->settings == scene.settings);
    // the defaults are left out, so that other files stay as they were
    core::SceneDesc plain = core::makeChain({});
    const QByteArray chain = io::sceneToJson(plain);
    QVERIFY(!chain.contains("triangles") && !chain.contains("thickness") && !chain.contains("selfCollision"));
}

void TestSceneFile::badTrianglesAreNamed_data()
{
    QTest::addColumn<QByteArray>("triangles");
    QTest::addColumn<QString>("message");
    QTest::newRow("not a list") << QByteArray("3") << u"triangles: expected an array"_s;
    QTest::newRow("two corners") << QByteArray("[[0, 1]]") << u"triangles[0]: expected an array of 3 particle indices, got 2"_s;
    QTest::newRow("not an integer") << QByteArray("[[0, 1, 1.5]]") << u"triangles[0][2]: expected an integer"_s;
    QTest::newRow("out of range") << QByteArray("[[0, 1, 7]]") << u"triangles[0][2]: particle index 7 is out of range"_s;
    QTest::newRow("a corner twice") << QByteArray("[[0, 1, 1]]") << u"triangles[0]: names a particle twice"_s;
}

void TestSceneFile::badTrianglesAreNamed()
{
    QFETCH(QByteArray, triangles);
    QFETCH(QString, message);
    const QByteArray json = R"({"format": "springlab-scene", "version": 1, "name": "t", "particles": [
        {"position": [0, 0, 0], "mass": 1, "radius": 0.1}, {"position": [1, 0, 0], "mass": 1, "radius": 0.1},
        {"position": [0, 0, 1], "mass": 1, "radius": 0.1}], "springs": [], "planes": [], "triangles": )" +
                            triangles + "}";
    const io::LoadResult result = io::parseScene(json, QStringLiteral("t.json"));
    QVERIFY(!result.ok());
    QVERIFY2(result.error.contains(message), qPrintable(result.error));
}

void TestSceneFile::examplesExist()
{
    // so that roundTripExamples cannot pass with nothing to test
    QVERIFY2(exampleFiles().size() >= 5, qPrintable(exampleFiles().join(u", "_s)));
}

void TestSceneFile::roundTripExamples_data()
{
    QTest::addColumn<QString>("path");
    for (const QString &path : exampleFiles())
        QTest::newRow(qPrintable(QFileInfo(path).fileName())) << path;
    if (exampleFiles().isEmpty())
        QTest::newRow("none") << QString();
}

void TestSceneFile::roundTripExamples()
{
    QFETCH(QString, path);
    if (path.isEmpty())
        QFAIL("no example scenes in resources/scenes");
    const io::LoadResult original = io::loadScene(path);
    QVERIFY2(original.ok(), qPrintable(original.error));
    QVERIFY2(original.warnings.isEmpty(), qPrintable(original.warnings.join(u'\n')));

    // save, load: the same bits; save again: the same text
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString copy = dir.filePath(QStringLiteral("copy.json"));
    const io::SaveResult saved = io::saveScene(copy, *original.scene);
    QVERIFY2(saved.ok(), qPrintable(saved.error));
    const io::LoadResult reloaded = io::loadScene(copy);
    QVERIFY2(reloaded.ok(), qPrintable(reloaded.error));
    QCOMPARE(bitDifference(*original.scene, *reloaded.scene), QString());
    QCOMPARE(io::sceneToJson(*reloaded.scene), readAll(copy));
}

void TestSceneFile::examplesStartClearOfTheirPlanes_data()
{
    roundTripExamples_data();
}

void TestSceneFile::examplesStartClearOfTheirPlanes()
{
    // every particle's centre at least its radius from every plane, on the side it starts on (a
    // one-sided plane's front; a rectangle's nearest point): resting on one is fine, starting
    // inside one is not, since the first contact would throw the particle out. A nanometre is
    // left for the rounding of the distance.
    QFETCH(QString, path);
    if (path.isEmpty())
        QFAIL("no example scenes in resources/scenes");
    const io::LoadResult loaded = io::loadScene(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    const core::SceneDesc &scene = *loaded.scene;
    constexpr double kRounding = 1e-9;  // m
    for (std::size_t k = 0; k < scene.planes.size(); ++k) {
        const core::Collider plane = core::makeCollider(scene.planes[k], scene.settings);
        for (std::size_t i = 0; i < scene.particles.size(); ++i) {
            const core::ParticleDesc &particle = scene.particles[i];
            const double distance =
                core::separation(plane, particle.position, core::sideOf(plane, particle.position)).distance;
            QVERIFY2(distance >= particle.radius - kRounding,
                     qPrintable(u"particle %1 is %2 m from plane %3, inside its radius %4"_s.arg(i)
                                    .arg(distance, 0, 'g', 17)
                                    .arg(k)
                                    .arg(particle.radius)));
        }
    }
}

void TestSceneFile::saveWritesEveryKey()
{
    // every key, defaults included, so a file says all it means
    core::SceneDesc scene;
    scene.name = "keys";
    scene.particles.resize(2);
    scene.particles[1].position = {1, 0, 0};
    scene.springs.push_back({0, 1, 10, 0, 1});
    scene.planes.push_back({});
    const QByteArray json = io::sceneToJson(scene);
    for (const char *key :
         {"format",     "version",   "name",      "settings",    "timeStep",        "substeps",
          "integrator", "tolerance", "gravity",   "viscosity", "restitution", "contactSolver", "friction",
          "planeCollisions", "particleCollisions",
          "particles",  "position",  "velocity",  "mass",        "radius",          "pinned",
          "springs",    "stiffness", "damping",   "restLength",  "planes",          "normal",
          "offset"})
        QVERIFY2(json.contains(QByteArray("\"") + key + "\": "), key);
    QVERIFY(json.contains('\n'));
    // but autoSubsteps only when on, so that files from before it read back byte for byte
    QVERIFY(!json.contains("autoSubsteps"));
    scene.settings.autoSubsteps = true;
    QVERIFY(io::sceneToJson(scene).contains("\"autoSubsteps\": true,"));
    // and xpbdIterations only when not 1, after the integrator
    QVERIFY(!json.contains("xpbdIterations"));
    scene.settings.xpbdIterations = 4;
    QVERIFY(io::sceneToJson(scene).contains("\"integrator\": \"symplectic-euler\",\n        \"xpbdIterations\": 4,\n"));
    // and the contact keys that can be unset, or that only a rectangle needs, only when they say
    // something (planeKeys has the cases)
    for (const char *key : {"staticFriction", "twoSided", "\"friction\": 0}", "size", "centre", "axis"})
        QVERIFY2(!json.contains(key), key);
    // and a run's contact impulses only once it has some, so a scene not yet run reads as before
    QVERIFY(!json.contains("contactImpulses"));
    scene.contactImpulses.push_back({1, -1, 0.5, {0.0, 0.0, 0.25}});
    QVERIFY(io::sceneToJson(scene).contains(
        "\"contactImpulses\": [\n        {\"particle\": 1, \"plane\": 0, \"normal\": 0.5, \"friction\": [0, 0, 0.25]}\n    ]\n}\n"));

    // an empty scene is still a whole file
    const io::LoadResult empty = io::parseScene(io::sceneToJson(core::SceneDesc{}), QStringLiteral("empty.json"));
    QVERIFY2(empty.ok(), qPrintable(empty.error));
    QVERIFY(*empty.scene == core::SceneDesc{});
}

void TestSceneFile::saveFailureKeepsOldFile_data()
{
    QTest::addColumn<QString>("target");  // relative to a fresh temporary folder
    QTest::addColumn<QString>("reason");

    // a name one short of the limit: the file fits, its temporary twin (name + suffix) does not
    QTest::newRow("temporary file cannot be made") << QString(250, u'a') << QStringLiteral("cannot save: ");
    QTest::newRow("folder missing") << QStringLiteral("no/such/folder/scene.json")
                                    << QStringLiteral("cannot save: the folder ");
    QTest::newRow("target is a folder") << QStringLiteral("folder.json")
                                        << QStringLiteral("cannot save: it is a folder, not a file");
}

void TestSceneFile::saveFailureKeepsOldFile()
{
    QFETCH(QString, target);
    QFETCH(QString, reason);

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("folder.json")));
    const QString path = dir.filePath(target);

    // an old file where there can be one
    const QByteArray old = "old contents\n";
    const bool hasOld = QFileInfo(path).absoluteDir().exists() && !QFileInfo(path).isDir();
    if (hasOld)
        QVERIFY(writeAll(path, old));
    const QStringList before = QDir(QFileInfo(path).absolutePath()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot);

    const io::SaveResult result = io::saveScene(path, awkwardScene());
    QVERIFY(!result.ok());
    QVERIFY2(result.error.startsWith(QDir::toNativeSeparators(path) + u": "_s + reason), qPrintable(result.error));

    // the old file whole, and nothing left beside it
    if (hasOld)
        QCOMPARE(readAll(path), old);
    if (QFileInfo(path).absoluteDir().exists())
        QCOMPARE(QDir(QFileInfo(path).absolutePath()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot), before);
}

void TestSceneFile::saveRefusesWhatIsNotAFile()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());

    // a FIFO stays a FIFO: the save is refused before a temporary file is made, so nothing is renamed
    // over it and nothing is left beside it
    const QString fifo = dir.filePath(u"pipe.json"_s);
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    const io::SaveResult refused = io::saveScene(fifo, awkwardScene());
    QVERIFY(!refused.ok());
    QCOMPARE(refused.error,
             QDir::toNativeSeparators(fifo) + u": cannot save: it is a named pipe (FIFO), not a regular file"_s);
    struct stat status {};
    QCOMPARE(::lstat(QFile::encodeName(fifo).constData(), &status), 0);
    QVERIFY(S_ISFIFO(status.st_mode));
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::System),
             QStringList{u"pipe.json"_s});

    // a device is named as one; only the check runs here, which reads and never writes
    if (QFileInfo::exists(u"/dev/null"_s))
        QCOMPARE(io::refuseToReplace(u"/dev/null"_s), u"it is a character device, not a regular file"_s);

    // a symbolic link to a regular file is saved through, and stays a link
    const QString target = dir.filePath(u"target.json"_s);
    const QString link = dir.filePath(u"link.json"_s);
    QVERIFY(writeAll(target, "old contents\n"));
    QVERIFY(QFile::link(target, link));
    QCOMPARE(io::refuseToReplace(link), QString());
    const io::SaveResult saved = io::saveScene(link, awkwardScene());
    QVERIFY2(saved.ok(), qPrintable(saved.error));
    QVERIFY(QFileInfo(link).isSymLink());
    const io::LoadResult loaded = io::loadScene(target);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    QVERIFY(*loaded.scene == awkwardScene());

    // nothing there yet, or a regular file: a save may go ahead
    QCOMPARE(io::refuseToReplace(dir.filePath(u"new.json"_s)), QString());
    QCOMPARE(io::refuseToReplace(target), QString());
}

void TestSceneFile::limits_data()
{
    // kBase holds 3 particles, 2 springs and 1 plane; "" for error: accepted
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<io::LoadLimits>("limits");
    QTest::addColumn<QString>("error");

    const qint64 size = kBase.size();
    const QString over = QStringLiteral("dir/s.json: the file is too large: %1 bytes, more than the limit of %2 bytes");
    QTest::newRow("size at the limit") << kBase << limitsWith(size, 3, 2, 1) << QString();
    QTest::newRow("size one over") << kBase << limitsWith(size - 1, 3, 2, 1) << over.arg(size).arg(size - 1);

    // counts, each exactly at its limit and one over
    QTest::newRow("particles one over") << kBase << limitsWith(size, 2, 2, 1)
                                        << QStringLiteral("dir/s.json: particles: too many particles: 3, more than the limit of 2");
    QTest::newRow("springs one over") << kBase << limitsWith(size, 3, 1, 1)
                                      << QStringLiteral("dir/s.json: springs: too many springs: 2, more than the limit of 1");
    QTest::newRow("planes one over") << kBase << limitsWith(size, 3, 2, 0)
                                     << QStringLiteral("dir/s.json: planes: too many planes: 1, more than the limit of 0");
    // counted on the text before the parser builds anything: a list over its limit is refused even
    // where the text after it would not parse (the parser's objects for a long list took 12-14
    // times the file's size, and a file refused for its count used that much first)
    QTest::newRow("counted before parsing")
        << kBase.left(kBase.indexOf("\"springs\"")) + "garbage" << limitsWith(size, 2, 2, 1)
        << QStringLiteral("dir/s.json: particles: too many particles: 3, more than the limit of 2");
    QTest::newRow("empty list, limit 0") << QByteArray(kBase).replace("{\"normal\": [0, 1, 0], \"offset\": 0}", "")
                                         << limitsWith(size, 3, 2, 0) << QString();

    // nesting, with the default limit; brackets inside strings do not count
    const QString deep = QStringLiteral("nested too deeply: more than the limit of %1 levels of arrays and objects")
                             .arg(io::kMaxNestingDepth);
    QTest::newRow("depth at the limit") << nestedTo(io::kMaxNestingDepth) << io::LoadLimits{} << QString();
    const QString deepError = u"dir/s.json: extra"_s + QString(u"[0]"_s).repeated(io::kMaxNestingDepth - 1) + u": "_s +
                              deep + u" (at byte "_s;
    QTest::newRow("depth one over") << nestedTo(io::kMaxNestingDepth + 1) << io::LoadLimits{} << deepError;
    QTest::newRow("deeper than Qt's own limit") << nestedTo(100000) << io::LoadLimits{} << deepError;
    QTest::newRow("brackets in a string") << QByteArray(kBase).replace("\"base\"", '"' + QByteArray(100, '[') + '"')
                                          << io::LoadLimits{} << QString();
}

void TestSceneFile::limits()
{
    QFETCH(QByteArray, json);
    QFETCH(io::LoadLimits, limits);
    QFETCH(QString, error);

    const io::LoadResult result = io::parseScene(json, QStringLiteral("dir/s.json"), limits);
    if (error.isEmpty()) {
        QVERIFY2(result.ok(), qPrintable(result.error));
        return;
    }
    QVERIFY(!result.ok());
    QVERIFY2(result.error.startsWith(error), qPrintable(result.error));
}

void TestSceneFile::oversizedFileNotRead()
{
    // a sparse file one byte over the default limit: refused from its size, so the test needs
    // neither the disk nor the memory that reading it would
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("huge.json"));
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        if (!file.resize(io::kMaxSceneFileBytes + 1))
            QSKIP("this file system cannot make a sparse file of the limit's size");
    }
    const io::LoadResult huge = io::loadScene(path);
    QVERIFY(!huge.ok());
    QCOMPARE(huge.error, QDir::toNativeSeparators(path) +
                             u": the file is too large: 1073741825 bytes (1 GiB), more than the limit of "
                             u"1073741824 bytes (1 GiB)"_s);

    // a real file exactly at a limit loads; one byte under it does not
    QVERIFY(writeAll(path, kBase));
    io::LoadLimits limits;
    limits.fileBytes = kBase.size();
    const io::LoadResult atLimit = io::loadScene(path, limits);
    QVERIFY2(atLimit.ok(), qPrintable(atLimit.error));
    limits.fileBytes = kBase.size() - 1;
    const io::LoadResult over = io::loadScene(path, limits);
    QVERIFY(!over.ok());
    QVERIFY2(over.error.contains(QStringLiteral("more than the limit of %1 bytes").arg(limits.fileBytes)),
             qPrintable(over.error));
}

void TestSceneFile::endlessDeviceRefused()
{
    // a device with no size and no end is read only up to the limit
    if (!QFile::exists(QStringLiteral("/dev/zero")))
        QSKIP("no /dev/zero here");
    io::LoadLimits limits;
    limits.fileBytes = 1000;
    const io::LoadResult result = io::loadScene(QStringLiteral("/dev/zero"), limits);
    QVERIFY(!result.ok());
    QCOMPARE(result.error, u"/dev/zero: the file is too large: more than the limit of 1000 bytes"_s);
}

void TestSceneFile::outOfMemoryIsAMessage()
{
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    QSKIP("the sanitizers reserve terabytes of address space: a cap on it cannot be set");
#endif
    // a file of 300 000 particles (26 MB) with 8 MB more than the test has mapped: reading it
    // runs out of memory, and the load says so instead of aborting; with the memory back it loads
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("big.json"));
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{\"format\": \"springlab-scene\", \"version\": 1, \"name\": \"big\", \"particles\": [");
        const QByteArray particle = "{\"position\": [0.125, 1.5, -2.25], \"velocity\": [0, 0, 0], \"mass\": 1, \"radius\": 0.1, \"pinned\": false},\n";
        for (int i = 0; i < 300000; ++i)
            file.write(particle);
        file.write("{\"position\": [0, 0, 0], \"velocity\": [0, 0, 0], \"mass\": 1, \"radius\": 0.1, \"pinned\": false}], \"springs\": [], \"planes\": []}\n");
    }
    io::LoadResult starved;
    {
        const test::AddressSpaceCap cap(8u << 20);
        QVERIFY(cap.capped());
        starved = io::loadScene(path);
    }
    // the cap is the process's limit, not the machine's memory: the message names it
    QVERIFY(!starved.ok());
    QVERIFY(starved.outOfMemory);
    const QString expected = QDir::toNativeSeparators(path) +
                             u": cannot load: out of memory: reading it needs more memory than this process may use "
                             "(its address space is limited to "_s;
    QVERIFY2(starved.error.startsWith(expected) && starved.error.endsWith(u": see ulimit -v)"_s),
             qPrintable(starved.error));
    const io::LoadResult fed = io::loadScene(path);
    QVERIFY2(fed.ok(), qPrintable(fed.error));
    QCOMPARE(fed.scene->particles.size(), std::size_t(300001));
}

QTEST_GUILESS_MAIN(TestSceneFile)
#include "test_scene_file.moc"
