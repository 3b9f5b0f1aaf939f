// springlab-sim for sweeps, end to end: --set changes the run exactly as an edited file would and
// refuses what the file would refuse; --summary-json and --summary-csv hold the run's figures,
// also when it blows up or is refused; tools/sweep_parallel.sh gathers a sweep into one table.

#include "core/model/diagnostics.h"
#include "core/io/scene_file.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "sim_run.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace Qt::Literals::StringLiterals;

namespace {

using test::sim;
using test::readAll;
using test::readJson;

// a rope of three springs from a pinned particle, and a ball dropped on the floor beside it:
// springs, masses, radii and contacts all change the run
core::SceneDesc ropeAndBall()
{
    core::SceneDesc scene;
    scene.name = "rope and ball";
    scene.settings.timeStep = 0.004;
    scene.settings.substeps = 2;
    scene.settings.restitution = 0.8;
    for (int i = 0; i < 4; ++i) {
        core::ParticleDesc particle;
        particle.position = {0.25 * i, 1.5, 0.0};
        particle.mass = 0.2;
        particle.radius = 0.05;
        particle.pinned = i == 0;
        scene.particles.push_back(particle);
        if (i > 0)
            scene.springs.push_back({i - 1, i, 300.0, 0.2, 0.25});
    }
    core::ParticleDesc ball;
    ball.position = {2.0, 0.6, 0.0};
    ball.velocity = {0.5, 0.0, 0.0};
    ball.radius = 0.15;
    scene.particles.push_back(ball);
    scene.planes.push_back({{0.0, 1.0, 0.0}, 0.0});
    return scene;
}

// the cells of one CSV line (RFC 4180 quoting)
QStringList csvCells(const QString &line)
{
    QStringList cells{QString()};
    bool quoted = false;
    for (qsizetype k = 0; k < line.size(); ++k) {
        const QChar c = line[k];
        if (quoted && c == u'"' && k + 1 < line.size() && line[k + 1] == u'"')
            cells.last() += c, ++k;
        else if (c == u'"')
            quoted = !quoted;
        else if (c == u',' && !quoted)
            cells += QString();
        else
            cells.last() += c;
    }
    return cells;
}

// a --set and the edit of the file that it stands for
struct SetCase {
    const char *name;
    QStringList sets;
    void (*edit)(core::SceneDesc &);
};

const SetCase kSetCases[] = {
    {"a setting", {u"settings.restitution=0.3"_s}, [](core::SceneDesc &s) { s.settings.restitution = 0.3; }},
    {"every spring", {u"springs.stiffness=800"_s},
     [](core::SceneDesc &s) { for (auto &spring : s.springs) spring.stiffness = 800.0; }},
    {"one spring", {u"springs[1].damping=2.5"_s}, [](core::SceneDesc &s) { s.springs[1].damping = 2.5; }},
    {"every mass", {u"particles.mass=0.35"_s},
     [](core::SceneDesc &s) { for (auto &p : s.particles) p.mass = 0.35; }},
    {"one radius", {u"particles[4].radius=0.25"_s}, [](core::SceneDesc &s) { s.particles[4].radius = 0.25; }},
    {"a vector and a name", {u"particles[4].velocity=[-1, 2, 0.5]"_s, u"settings.integrator=rk4"_s},
     [](core::SceneDesc &s) {
         s.particles[4].velocity = {-1.0, 2.0, 0.5};
         s.settings.integrator = core::Integrator::Rk4;
     }},
    {"rest length and gravity", {u"springs.restLength=0.3"_s, u"settings.gravity=[0,-1.62,0]"_s},
     [](core::SceneDesc &s) {
         for (auto &spring : s.springs) spring.restLength = 0.3;
         s.settings.gravity = {0.0, -1.62, 0.0};
     }},
    {"xpbd and its iterations", {u"settings.integrator=xpbd"_s, u"settings.xpbdIterations=3"_s},
     [](core::SceneDesc &s) {
         s.settings.integrator = core::Integrator::Xpbd;
         s.settings.xpbdIterations = 3;
     }},
    {"later wins", {u"springs.stiffness=100"_s, u"springs[2].stiffness=900"_s, u"particles[1].mass=1"_s,
                    u"particles[1].mass=0.5"_s},
     [](core::SceneDesc &s) {
         for (auto &spring : s.springs) spring.stiffness = 100.0;
         s.springs[2].stiffness = 900.0;
         s.particles[1].mass = 0.5;
     }},
};

}  // namespace

class TestSimSweep : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void setEqualsAnEditedFile_data();
    void setEqualsAnEditedFile();
    void setRefusals_data();
    void setRefusals();
    void rangeWordsAreTheFiles_data();
    void rangeWordsAreTheFiles();
    void summaryJsonHoldsTheRun();
    void summaryOnBlowUp();
    void summaryOnRefusal_data();
    void summaryOnRefusal();
    void summaryNeverReplacesAnInput();
    void csvHeaderAndRowAgree();
    void parallelSweep();

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }

    QTemporaryDir m_dir;
};

void TestSimSweep::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_SIM)).isExecutable());
    QVERIFY(m_dir.isValid());
    QVERIFY(io::saveScene(path(u"rope.json"_s), ropeAndBall()).ok());
}

void TestSimSweep::setEqualsAnEditedFile_data()
{
    QTest::addColumn<int>("index");
    for (int k = 0; k < int(std::size(kSetCases)); ++k)
        QTest::newRow(kSetCases[k].name) << k;
}

void TestSimSweep::setEqualsAnEditedFile()
{
    QFETCH(int, index);
    const SetCase &set = kSetCases[index];

    // the file edited by hand, run as it is
    core::SceneDesc edited = ropeAndBall();
    set.edit(edited);
    QVERIFY(io::saveScene(path(u"edited.json"_s), edited).ok());
    const QStringList common{u"--steps"_s, u"400"_s, u"--quiet"_s};
    test::ProgramRun run = sim(QStringList{path(u"edited.json"_s), u"--output"_s, path(u"by-file.json"_s)} + common);
    QVERIFY2(run.exitCode == 0, run.err.constData());

    // the same change by --set, on the file as it was
    QStringList arguments{path(u"rope.json"_s), u"--output"_s, path(u"by-set.json"_s)};
    for (const QString &argument : set.sets)
        arguments << u"--set"_s << argument;
    run = sim(arguments + common);
    QVERIFY2(run.exitCode == 0, run.err.constData());

    // the same final state, bit for bit, and not the state the file alone gives
    run = sim(QStringList{path(u"rope.json"_s), u"--output"_s, path(u"plain.json"_s)} + common);
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QByteArray bySet = readAll(path(u"by-set.json"_s));
    QVERIFY(!bySet.isEmpty());
    QCOMPARE(bySet, readAll(path(u"by-file.json"_s)));
    QVERIFY(bySet != readAll(path(u"plain.json"_s)));
}

void TestSimSweep::setRefusals_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");

    const auto set = [](const QString &argument) { return QStringList{u"--set"_s, argument}; };
    QTest::newRow("no =") << set(u"settings.timeStep"_s)
                          << u"--set settings.timeStep: expected KEY=VALUE, such as settings.restitution=0.5"_s;
    QTest::newRow("no value") << set(u"settings.timeStep="_s)
                              << u"--set settings.timeStep=: no value after the \"=\" for settings.timeStep"_s;
    QTest::newRow("no key") << set(u"=3"_s) << u"--set =3: no key before the \"=\""_s;
    QTest::newRow("unknown family") << set(u"gravity=1"_s) << u"--set gravity=1: unknown key \"gravity\""_s;
    QTest::newRow("unknown setting")
        << set(u"settings.timestep=0.1"_s)
        << u"--set settings.timestep=0.1: unknown key \"settings.timestep\" (settings take: timeStep, substeps"_s;
    QTest::newRow("unknown spring key")
        << set(u"springs.particles=[0,1]"_s)
        << u"unknown key \"springs.particles\" (springs take: stiffness, damping, restLength, breakStrain)"_s;
    QTest::newRow("settings indexed") << set(u"settings[0].timeStep=0.1"_s)
                                      << u"settings is one object, not a list: use settings.NAME"_s;
    QTest::newRow("text for a number") << set(u"springs.stiffness=stiff"_s)
                                       << u"--set springs.stiffness=stiff: springs.stiffness: expected a number, got a string"_s;
    QTest::newRow("number for a boolean") << set(u"settings.planeCollisions=1"_s)
                                          << u"settings.planeCollisions: expected true or false, got a number"_s;
    QTest::newRow("fraction for an integer") << set(u"settings.substeps=2.5"_s)
                                             << u"settings.substeps: expected an integer, got 2.5"_s;
    QTest::newRow("short vector") << set(u"settings.gravity=[0,-9.81]"_s)
                                  << u"settings.gravity: expected an array of 3 numbers, got 2"_s;
    QTest::newRow("unknown integrator") << set(u"settings.integrator=rk9"_s)
                                        << u"settings.integrator: unknown integrator \"rk9\" (known: symplectic-euler"_s;
    QTest::newRow("index past the particles")
        << set(u"particles[5].mass=2"_s)
        << u"--set particles[5].mass=2: particles[5]: index 5 is out of range (the scene has 5 particles)"_s;
    QTest::newRow("index past the springs")
        << set(u"springs[12].stiffness=5"_s)
        << u"--set springs[12].stiffness=5: springs[12]: index 12 is out of range (the scene has 3 springs)"_s;
    QTest::newRow("huge index") << set(u"planes[99999999999999999999].offset=1"_s)
                                << u"planes[99999999999999999999]: index 99999999999999999999 is out of range "
                                   "(the scene has 1 planes)"_s;
    QTest::newRow("out of range") << set(u"settings.timeStep=5"_s)
                                  << u"--set settings.timeStep=5: settings.timeStep: must be at most 1 s (got 5 s)"_s;
    QTest::newRow("xpbd iterations out of range")
        << set(u"settings.xpbdIterations=0"_s)
        << u"--set settings.xpbdIterations=0: settings.xpbdIterations: must be at least 1 (got 0)"_s;
    QTest::newRow("every element out of range")
        << set(u"particles.mass=0"_s)
        << u"--set particles.mass=0: particles[0].mass: must be greater than 0 kg (got 0 kg)"_s;
    QTest::newRow("option and --set")
        << (QStringList{u"--time-step"_s, u"0.01"_s} + set(u"settings.timeStep=0.02"_s))
        << u"--time-step and --set settings.timeStep both set settings.timeStep: give one of them"_s;
    QTest::newRow("--set with --replay") << (QStringList{u"--replay"_s} + set(u"settings.timeStep=0.02"_s))
                                         << u"--replay runs the recording as it was recorded: --set cannot change it"_s;
}

void TestSimSweep::setRefusals()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const test::ProgramRun run = sim(QStringList{path(u"rope.json"_s)} + arguments);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(QString::fromUtf8(run.err).contains(message), run.err.constData());
    QVERIFY(run.out.isEmpty());
}

void TestSimSweep::rangeWordsAreTheFiles_data()
{
    QTest::addColumn<QString>("argument");
    QTest::addColumn<int>("index");  // the edit of the file that says the same

    QTest::newRow("restitution") << u"settings.restitution=1.5"_s << 0;
    QTest::newRow("stiffness") << u"springs[1].stiffness=-3"_s << 1;
    QTest::newRow("radius") << u"particles.radius=0"_s << 2;
}

void TestSimSweep::rangeWordsAreTheFiles()
{
    QFETCH(QString, argument);
    QFETCH(int, index);
    core::SceneDesc edited = ropeAndBall();
    switch (index) {
    case 0: edited.settings.restitution = 1.5; break;
    case 1: edited.springs[1].stiffness = -3.0; break;
    default: for (auto &p : edited.particles) p.radius = 0.0;
    }
    const QString file = path(u"out-of-range.json"_s);
    QVERIFY(io::saveScene(file, edited).ok());
    const io::LoadResult loaded = io::loadScene(file);
    QVERIFY(!loaded.ok());
    // the file's message less its name, and --set's less the argument, are the same words
    const QString fileWords = loaded.error.mid(QDir::toNativeSeparators(file).size() + 2);
    const test::ProgramRun run = sim({path(u"rope.json"_s), u"--set"_s, argument});
    QCOMPARE(run.exitCode, 2);
    const QString setWords = QString::fromUtf8(run.err).section(u'\n', 0, 0).mid(QStringLiteral("springlab-sim: --set ").size() + argument.size() + 2);
    QCOMPARE(setWords, fileWords);
}

void TestSimSweep::summaryJsonHoldsTheRun()
{
    const QString summaryPath = path(u"summary.json"_s);
    const QString finalPath = path(u"final.json"_s);
    const test::ProgramRun run =
        sim({path(u"rope.json"_s), u"--steps"_s, u"300"_s, u"--set"_s, u"settings.restitution=0.5"_s, u"--set"_s,
             u"springs[0].stiffness=450"_s, u"--substeps"_s, u"3"_s, u"--output"_s, finalPath, u"--summary-json"_s,
             summaryPath});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    // the printed summary lists the overrides too
    QVERIFY2(run.out.contains("  overrides  settings.restitution=0.5 settings.substeps=3 springs[0].stiffness=450"),
             run.out.constData());

    const QJsonObject summary = readJson(summaryPath);
    QCOMPARE(summary[u"scene"_s].toString(), path(u"rope.json"_s));
    const QJsonObject overrides{{u"settings.restitution"_s, 0.5}, {u"settings.substeps"_s, 3},
                                {u"springs[0].stiffness"_s, 450}};
    QCOMPARE(summary[u"overrides"_s].toObject(), overrides);
    QCOMPARE(summary[u"status"_s].toString(), u"ok"_s);
    QCOMPARE(summary[u"exitCode"_s].toInt(-1), 0);
    QCOMPARE(summary[u"integrator"_s].toString(), u"symplectic-euler"_s);
    QCOMPARE(summary[u"contactSolver"_s].toString(), u"iterative"_s);
    QCOMPARE(summary[u"timeStep"_s].toDouble(), 0.004);
    QCOMPARE(summary[u"substeps"_s].toInt(), 3);
    QCOMPARE(summary[u"stepsRequested"_s].toInt(), 300);
    QCOMPARE(summary[u"steps"_s].toInt(), 300);
    QVERIFY(std::abs(summary[u"simulatedTime"_s].toDouble() - 300 * 0.004) < 1e-12);
    const double wall = summary[u"wallTime"_s].toDouble();
    QVERIFY(wall > 0.0);
    QVERIFY(std::abs(summary[u"stepsPerSecond"_s].toDouble() * wall - 300.0) < 1e-6);
    QCOMPARE(summary[u"springBreaks"_s].toInt(-1), 0);
    QCOMPARE(summary[u"warnings"_s].toArray(), QJsonArray());
    QCOMPARE(summary[u"error"_s].toString(u"unset"_s), QString());

    // the energies are those of the scene the run started from, and of the final state it saved
    core::SceneDesc first = ropeAndBall();
    first.settings.restitution = 0.5;
    first.springs[0].stiffness = 450.0;
    const io::LoadResult final = io::loadScene(finalPath);
    QVERIFY2(final.ok(), qPrintable(final.error));
    for (const auto &[scene, when] : {std::pair{first, u"Start"_s}, std::pair{*final.scene, u"End"_s}}) {
        const auto model = core::compileModel(scene);
        const core::Energies e = core::energies(*model, core::makeState(*model, scene));
        QCOMPARE(summary[u"kinetic"_s + when].toDouble(), e.kinetic);
        QCOMPARE(summary[u"gravitational"_s + when].toDouble(), e.gravitational);
        QCOMPARE(summary[u"spring"_s + when].toDouble(), e.spring);
        QCOMPARE(summary[u"total"_s + when].toDouble(), e.total());
    }
    QVERIFY(summary[u"kineticEnd"_s].toDouble() != summary[u"kineticStart"_s].toDouble());
}

void TestSimSweep::summaryOnBlowUp()
{
    // a stiff spring at a long step runs away within a few steps
    const QString summaryPath = path(u"boom-summary.json"_s);
    const test::ProgramRun run =
        sim({path(u"rope.json"_s), u"--steps"_s, u"100"_s, u"--set"_s, u"springs.stiffness=1e9"_s, u"--time-step"_s,
             u"0.05"_s, u"--summary-json"_s, summaryPath, u"--quiet"_s});
    QCOMPARE(run.exitCode, 3);
    const QJsonObject summary = readJson(summaryPath);
    QCOMPARE(summary[u"status"_s].toString(), u"blew-up"_s);
    QCOMPARE(summary[u"exitCode"_s].toInt(), 3);
    QCOMPARE(summary[u"stepsRequested"_s].toInt(), 100);
    QVERIFY(summary[u"steps"_s].toInt(-1) >= 0 && summary[u"steps"_s].toInt() < 100);
    const QString error = summary[u"error"_s].toString();
    QVERIFY2(error.contains(u"became"_s) && error.contains(u"stability limit"_s), qPrintable(error));
    QVERIFY(QString::fromUtf8(run.err).contains(error));
}

void TestSimSweep::summaryOnRefusal_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");

    QTest::newRow("bad --set value") << QStringList{u"@/rope.json"_s, u"--set"_s, u"settings.restitution=2"_s}
                                     << u"settings.restitution: must be at most 1 (got 2)"_s;
    QTest::newRow("bad --set key") << QStringList{u"@/rope.json"_s, u"--set"_s, u"springs.stiff=2"_s}
                                   << u"unknown key \"springs.stiff\""_s;
    QTest::newRow("missing file") << QStringList{u"@/none.json"_s} << u"none.json: cannot open"_s;
    QTest::newRow("unknown option") << QStringList{u"@/rope.json"_s, u"--fast"_s} << u"Unknown option 'fast'"_s;
}

void TestSimSweep::summaryOnRefusal()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    for (QString &argument : arguments)
        argument.replace(u'@', m_dir.path());
    const QString json = path(u"refused.json"_s);
    const QString csv = path(u"refused.csv"_s);
    QFile::remove(json);
    QFile::remove(csv);

    const test::ProgramRun run = sim(arguments + QStringList{u"--summary-json"_s, json, u"--summary-csv"_s, csv});
    QCOMPARE(run.exitCode, 2);
    const QJsonObject summary = readJson(json);
    QCOMPARE(summary[u"status"_s].toString(), u"bad-input"_s);
    QCOMPARE(summary[u"exitCode"_s].toInt(), 2);
    QCOMPARE(summary[u"scene"_s].toString(), arguments.first());
    QVERIFY2(summary[u"error"_s].toString().contains(message), qPrintable(summary[u"error"_s].toString()));
    QVERIFY(summary[u"steps"_s].isNull());
    QVERIFY(summary[u"totalEnd"_s].isNull());
    // the row says the same
    const QStringList row = csvCells(QString::fromUtf8(readAll(csv)).trimmed());
    QVERIFY(row.contains(u"bad-input"_s));
    QVERIFY(row.last().contains(message));
}

void TestSimSweep::summaryNeverReplacesAnInput()
{
    // a summary that names the scene, --output or --trace is refused, and nothing is written
    const QByteArray scene = readAll(path(u"rope.json"_s));
    const struct {
        QStringList arguments;
        QString message;
    } cases[] = {
        {{u"--summary-json"_s, path(u"rope.json"_s)}, u"--summary-json "_s + path(u"rope.json"_s) + u" names the scene's file"_s},
        {{u"--summary-csv"_s, path(u"rope.json"_s)}, u"--summary-csv "_s + path(u"rope.json"_s) + u" names the scene's file"_s},
        {{u"--output"_s, path(u"same.json"_s), u"--summary-json"_s, path(u"same.json"_s)},
         u"--output and --summary-json name one file"_s},
        {{u"--trace"_s, path(u"same.csv"_s), u"--summary-csv"_s, path(u"same.csv"_s)},
         u"--trace and --summary-csv name one file"_s},
        {{u"--summary-json"_s, path(u"same.txt"_s), u"--summary-csv"_s, path(u"same.txt"_s)},
         u"--summary-json and --summary-csv name one file"_s},
    };
    for (const auto &c : cases) {
        const test::ProgramRun run = sim(QStringList{path(u"rope.json"_s), u"--steps"_s, u"3"_s} + c.arguments);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(QString::fromUtf8(run.err).contains(c.message), run.err.constData());
        QCOMPARE(readAll(path(u"rope.json"_s)), scene);
        QVERIFY(!QFile::exists(path(u"same.json"_s)) && !QFile::exists(path(u"same.csv"_s)) &&
                !QFile::exists(path(u"same.txt"_s)));
    }
}

void TestSimSweep::csvHeaderAndRowAgree()
{
    const test::ProgramRun header = sim({u"--summary-csv-header"_s});
    QCOMPARE(header.exitCode, 0);
    QVERIFY(header.out.endsWith('\n') && header.out.count('\n') == 1);
    const QStringList names = QString::fromUtf8(header.out).trimmed().split(u',');

    const QString json = path(u"row.json"_s);
    const QString csv = path(u"row.csv"_s);
    const test::ProgramRun run =
        sim({path(u"rope.json"_s), u"--steps"_s, u"50"_s, u"--set"_s, u"particles[4].velocity=[1,2,3]"_s, u"--set"_s,
             u"settings.restitution=0.25"_s, u"--summary-json"_s, json, u"--summary-csv"_s, csv, u"--quiet"_s});
    QCOMPARE(run.exitCode, 0);
    const QByteArray rowText = readAll(csv);
    QVERIFY(rowText.endsWith('\n') && rowText.count('\n') == 1);
    const QStringList row = csvCells(QString::fromUtf8(rowText).trimmed());
    QCOMPARE(row.size(), names.size());

    // the same names in the same order as the JSON object, and the same values
    const QByteArray jsonText = readAll(json);
    const QJsonObject summary = QJsonDocument::fromJson(jsonText).object();
    QCOMPARE(summary.size(), names.size());
    qsizetype at = 0;
    for (qsizetype k = 0; k < names.size(); ++k) {
        const qsizetype found = jsonText.indexOf('"' + names[k].toUtf8() + "\":", at);
        QVERIFY2(found > at, qPrintable(names[k]));
        at = found;
        const QJsonValue value = summary[names[k]];
        if (value.isDouble())
            QCOMPARE(row[k].toDouble(), value.toDouble());
        else if (value.isString())
            QCOMPARE(row[k], value.toString());
    }
    QCOMPARE(row[names.indexOf(u"overrides"_s)], u"particles[4].velocity=[1,2,3] settings.restitution=0.25"_s);
}

void TestSimSweep::parallelSweep()
{
    if (QStandardPaths::findExecutable(u"parallel"_s).isEmpty())
        QSKIP("GNU parallel is not installed (Debian: apt-get install parallel; tools/dev.sh test installs it)");

    // docs/batch.md's sweep, 2 x 2, on the pool example
    QTemporaryDir out;
    QVERIFY(out.isValid());
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(u"SIM"_s, QStringLiteral(SPRINGLAB_SIM));
    environment.insert(u"RESTITUTIONS"_s, u"0.5 1"_s);
    environment.insert(u"TIME_STEPS"_s, u"0.01 0.005"_s);
    environment.insert(u"JOBS"_s, u"2"_s);
    const test::ProgramRun run = test::runProgram(u"bash"_s, {QStringLiteral(SPRINGLAB_SOURCE_DIR "/tools/sweep_parallel.sh"),
                                                          out.path()}, 300000, environment);
    QVERIFY2(run.exitCode == 0, run.err.constData());

    // one header and four rows, one per pair
    const QStringList lines = QString::fromUtf8(readAll(out.filePath(u"sweep.csv"_s))).trimmed().split(u'\n');
    QCOMPARE(lines.size(), 5);
    const QStringList names = csvCells(lines[0]);
    const qsizetype overridesColumn = names.indexOf(u"overrides"_s);
    QVERIFY(overridesColumn >= 0);
    QMap<QString, double> kineticEnd;  // by "restitution timeStep"
    for (const QString &line : lines.mid(1)) {
        const QStringList row = csvCells(line);
        QCOMPARE(row.size(), names.size());
        const auto cell = [&](const QString &name) { return row[names.indexOf(name)]; };
        QCOMPARE(cell(u"status"_s), u"ok"_s);
        const double h = cell(u"timeStep"_s).toDouble();
        QVERIFY(h == 0.01 || h == 0.005);
        QCOMPARE(cell(u"steps"_s).toLongLong(), std::llround(1.5 / h));
        const QString overrides = row[overridesColumn];
        const QString restitution = overrides.section(u"settings.restitution="_s, 1).section(u' ', 0, 0);
        QVERIFY2(restitution == u"0.5"_s || restitution == u"1"_s, qPrintable(overrides));
        QVERIFY(overrides.contains(u"settings.timeStep="_s + cell(u"timeStep"_s)));
        kineticEnd[restitution + u' ' + cell(u"timeStep"_s)] = cell(u"kineticEnd"_s).toDouble();
    }
    QCOMPARE(kineticEnd.size(), 4);
    // the shot hits the other ball: the less elastic the contact, the less motion is left
    for (const QString &h : {u"0.01"_s, u"0.005"_s})
        QVERIFY2(kineticEnd[u"0.5 "_s + h] < kineticEnd[u"1 "_s + h], qPrintable(h));
}

QTEST_MAIN(TestSimSweep)
#include "test_sim_sweep.moc"
