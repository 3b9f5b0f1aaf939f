// springlab-sim end to end, through QProcess: exit codes, the CSV trace's shape, and that
// --output then resuming gives the same bits as a run that never stopped.

#include "core/model/generators.h"
#include "core/integrators/reference.h"
#include "core/io/scene_file.h"
#include "sim_run.h"
#include "session/session_file.h"
#include "session/simulation_runner.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <cmath>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <bit>
#include <charconv>
#include <cstdint>

#include <sys/stat.h>

using namespace Qt::Literals::StringLiterals;

namespace {

using test::sim;
using test::readAll;

using Run = test::ProgramRun;

// a scene that runs every pass: gravity, drag, springs, both kinds of collision, a pinned end
core::SceneDesc testScene()
{
    core::SceneDesc scene;
    scene.name = "cli test";
    scene.settings.timeStep = 0.005;
    scene.settings.substeps = 2;
    scene.settings.viscosity = 0.05;
    scene.settings.restitution = 0.7;

    // a chain hanging from a pinned particle
    for (int i = 0; i < 5; ++i) {
        core::ParticleDesc particle;
        particle.position = {0.3 * i, 2.0, 0.0};
        particle.mass = 0.5;
        particle.pinned = i == 0;
        scene.particles.push_back(particle);
        if (i > 0)
            scene.springs.push_back({i - 1, i, 500.0, 0.5, 0.3});
    }

    // two balls that meet, then fall on the floor
    core::ParticleDesc ball;
    ball.position = {1.5, 0.5, 0.0};
    ball.velocity = {-1.0, 0.0, 0.3};
    ball.radius = 0.2;
    scene.particles.push_back(ball);
    ball.position = {1.0, 0.45, 0.05};
    ball.velocity = {0.5, 1.0, 0.0};
    scene.particles.push_back(ball);

    // a floor and a wall
    scene.planes.push_back({{0.0, 1.0, 0.0}, 0.0});
    scene.planes.push_back({{1.0, 0.0, 0.0}, -1.0});
    return scene;
}

// a stiff spring and a long step: the explicit integration runs away within a few steps
core::SceneDesc explodingScene()
{
    core::SceneDesc scene;
    scene.name = "boom";
    scene.settings.timeStep = 0.1;
    core::ParticleDesc particle;
    particle.pinned = true;
    scene.particles.push_back(particle);
    particle.pinned = false;
    particle.position = {1.0, 0.0, 0.0};
    scene.particles.push_back(particle);
    scene.springs.push_back({0, 1, 1e9, 0.0, 0.5});
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

double parseDouble(const QByteArray &text, bool &ok)
{
    double value = 0.0;
    const auto result = std::from_chars(text.constData(), text.constData() + text.size(), value);
    ok = result.ec == std::errc() && result.ptr == text.constData() + text.size();
    return value;
}

}  // namespace

namespace {

// a horizontal chain pinned at one end, of alternating masses and stiffnesses, with auto substeps:
// it swings down, and the count the stability limit asks for falls from 5 at the start to 4
core::SceneDesc autoSubstepsChain()
{
    core::SceneDesc scene;
    scene.name = "chain";
    scene.settings.timeStep = 0.01;
    scene.settings.autoSubsteps = true;
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    for (int i = 0; i < 12; ++i)
        scene.particles.push_back({{0.1 * i, 1.0, 0.0}, Eigen::Vector3d::Zero(), i % 2 ? 0.1 : 1.0, 0.01, i == 0});
    for (int i = 0; i + 1 < 12; ++i)
        scene.springs.push_back({i, i + 1, i % 3 ? 1e4 : 3e4, 0.0, 0.1});
    return scene;
}

}  // namespace

class TestSimCli : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void exitCodes_data();
    void exitCodes();
    void examplesRun_data();
    void examplesRun();
    void traceShape_data();
    void traceShape();
    void durationRoundsToSteps_data();
    void durationRoundsToSteps();
    void overridesReachTheOutput();
    void outputRefusesWhatIsNotAFile();
    void outputOntoAFullDiskFails();
    void outOfMemoryIsAMessage();
    void bigClothRunsInItsMemory();
    void traceOntoAFullDiskSaysWhy();
    void printsWhatIsSafeForATerminal();
    void summaryThatCannotBeWrittenFails();
    void linkLoopIsNamed();
    void energyGrowthIsAWarning();
    void energyThatRunsAwayIsABlowup();
    void autoSubstepsSaysWhatRan();
    void runLeavingTheFileRangeBlowsUp();
    void outputsMustNotNameTheInputOrEachOther();
    void resumeEqualsUninterrupted_data();
    void resumeEqualsUninterrupted();
    void replayRunsARecordingToItsBits();
    void tearableClothTears();

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }

    QTemporaryDir m_dir;
};

void TestSimCli::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_SIM)).isExecutable());
    QVERIFY(m_dir.isValid());
    QVERIFY(io::saveScene(path(u"scene.json"_s), testScene()).ok());
    QVERIFY(io::saveScene(path(u"boom.json"_s), explodingScene()).ok());
    QVERIFY(io::saveScene(path(u"chain-auto.json"_s), autoSubstepsChain()).ok());
    QFile bad(path(u"bad.json"_s));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("{\"format\": \"springlab-scene\", \"version\": 1, \"particles\": [");
}

void TestSimCli::exitCodes_data()
{
    // "@" stands for the temporary folder
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QStringList>("stderrHas");

    QTest::newRow("runs") << QStringList{u"@/scene.json"_s, u"--steps"_s, u"20"_s} << 0 << QStringList();
    QTest::newRow("help") << QStringList{u"--help"_s} << 0 << QStringList();
    QTest::newRow("bad file") << QStringList{u"@/bad.json"_s} << 2
                              << QStringList{u"bad.json: particles[0]: the file ends too early"_s};
    QTest::newRow("no such file") << QStringList{u"@/none.json"_s} << 2
                                  << QStringList{u"none.json: cannot open: no such file"_s};
    QTest::newRow("no scene") << QStringList{u"--steps"_s, u"3"_s} << 2 << QStringList{u"missing the scene file"_s};
    QTest::newRow("time step 5") << QStringList{u"@/scene.json"_s, u"--time-step"_s, u"5"_s} << 2
                                 << QStringList{u"--time-step: must be at most 1 s (got 5 s)"_s};
    QTest::newRow("time step text") << QStringList{u"@/scene.json"_s, u"--time-step"_s, u"fast"_s} << 2
                                    << QStringList{u"--time-step: expected a number of seconds, got \"fast\""_s};
    QTest::newRow("substeps 0") << QStringList{u"@/scene.json"_s, u"--substeps"_s, u"0"_s} << 2
                                << QStringList{u"--substeps: must be at least 1"_s};
    QTest::newRow("unknown integrator") << QStringList{u"@/scene.json"_s, u"--integrator"_s, u"rk9"_s} << 2
                                        << QStringList{u"--integrator: unknown integrator \"rk9\""_s,
                                                       u"symplectic-euler"_s};
    QTest::newRow("unknown contact solver")
        << QStringList{u"@/scene.json"_s, u"--contact-solver"_s, u"pbd"_s} << 2
        << QStringList{u"--contact-solver: unknown contact solver \"pbd\" (known: iterative, handout)"_s};
    QTest::newRow("friction above 10") << QStringList{u"@/scene.json"_s, u"--friction"_s, u"11"_s} << 2
                                       << QStringList{u"--friction"_s, u"must be at most 10"_s};
    QTest::newRow("static friction text") << QStringList{u"@/scene.json"_s, u"--static-friction"_s, u"grippy"_s} << 2
                                          << QStringList{u"--static-friction"_s};
    QTest::newRow("negative steps") << QStringList{u"@/scene.json"_s, u"--steps"_s, u"-4"_s} << 2
                                    << QStringList{u"--steps:"_s};
    QTest::newRow("steps and duration") << QStringList{u"@/scene.json"_s, u"--steps"_s, u"4"_s, u"--duration"_s, u"1"_s}
                                        << 2 << QStringList{u"cannot be used together"_s};
    QTest::newRow("every without trace") << QStringList{u"@/scene.json"_s, u"--every"_s, u"2"_s} << 2
                                         << QStringList{u"--every only makes sense with --trace"_s};
    QTest::newRow("every 0") << QStringList{u"@/scene.json"_s, u"--trace"_s, u"@/t.csv"_s, u"--every"_s, u"0"_s} << 2
                             << QStringList{u"--every:"_s};
    QTest::newRow("fps without render") << QStringList{u"@/scene.json"_s, u"--fps"_s, u"24"_s} << 2
                                        << QStringList{u"--fps only makes sense with --render"_s};
    QTest::newRow("size without render") << QStringList{u"@/scene.json"_s, u"--size"_s, u"64x48"_s} << 2
                                         << QStringList{u"--size only makes sense with --render"_s};
    QTest::newRow("unknown option") << QStringList{u"@/scene.json"_s, u"--fast"_s} << 2 << QStringList{u"fast"_s};
    QTest::newRow("output folder missing")
        << QStringList{u"@/scene.json"_s, u"--steps"_s, u"2"_s, u"--output"_s, u"@/no/such/out.json"_s} << 2
        << QStringList{u"cannot save: the folder"_s};
    QTest::newRow("blows up") << QStringList{u"@/boom.json"_s, u"--steps"_s, u"100"_s, u"--output"_s,
                                             u"@/boom-out.json"_s}
                              << 3
                              << QStringList{u"Particle 1's velocity became"_s, u"(step "_s,
                                             u"the stability limit"_s, u"substeps or the projective integrator"_s};
}

void TestSimCli::exitCodes()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QStringList, stderrHas);
    for (QString &argument : arguments)
        argument.replace(u'@', m_dir.path());

    const Run run = sim(arguments);
    QVERIFY2(run.exitCode == exitCode, run.err.constData());
    for (const QString &text : stderrHas)
        QVERIFY2(QString::fromUtf8(run.err).contains(text), run.err.constData());
    if (exitCode == 0)
        QVERIFY2(run.err.isEmpty(), run.err.constData());

    // a run that blew up writes no final state
    QVERIFY(!QFile::exists(path(u"boom-out.json"_s)));
}

void TestSimCli::examplesRun_data()
{
    QTest::addColumn<QString>("scene");
    for (const QString &file : exampleFiles())
        QTest::newRow(qPrintable(QFileInfo(file).fileName())) << file;
    if (exampleFiles().isEmpty())
        QTest::newRow("none") << QString();
}

void TestSimCli::examplesRun()
{
    QFETCH(QString, scene);
    if (scene.isEmpty())
        QFAIL("no example scenes in resources/scenes");
    const Run run = sim({scene, u"--steps"_s, u"50"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    QVERIFY(run.out.contains("ran        50 of 50 steps"));
}

void TestSimCli::traceShape_data()
{
    QTest::addColumn<int>("steps");
    QTest::addColumn<int>("every");
    QTest::newRow("every step") << 12 << 1;
    QTest::newRow("every 5 of 20") << 20 << 5;
    QTest::newRow("every 7 of 20") << 20 << 7;
    QTest::newRow("every 50 of 20") << 20 << 50;
    QTest::newRow("no steps") << 0 << 3;
}

void TestSimCli::traceShape()
{
    QFETCH(int, steps);
    QFETCH(int, every);
    const QString trace = path(u"trace.csv"_s);
    const Run run = sim({path(u"scene.json"_s), u"--steps"_s, QString::number(steps), u"--trace"_s, trace, u"--every"_s,
                         QString::number(every), u"--quiet"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY(run.out.isEmpty());

    // a header, then one row per particle for step 0 and every K steps after it
    const core::SceneDesc scene = testScene();
    const auto particles = static_cast<int>(scene.particles.size());
    QList<QByteArray> lines = readAll(trace).split('\n');
    QCOMPARE(lines.takeLast(), QByteArray());  // the file ends with a newline
    QCOMPARE(lines.takeFirst(), QByteArray("step,time,particle,x,y,z,vx,vy,vz"));
    QCOMPARE(lines.size(), particles * (steps / every + 1));

    for (int row = 0; row < lines.size(); ++row) {
        const QList<QByteArray> fields = lines[row].split(',');
        QCOMPARE(fields.size(), 9);
        QCOMPARE(fields[0].toLongLong(), static_cast<long long>(row / particles * every));
        QCOMPARE(fields[2].toInt(), row % particles);
        for (int column = 1; column < 9; ++column) {
            bool ok = false;
            parseDouble(fields[column], ok);
            QVERIFY2(ok, lines[row].constData());
        }
    }

    // step 0 is the initial state, bit for bit
    for (int i = 0; i < particles; ++i) {
        const QList<QByteArray> fields = lines[i].split(',');
        const core::ParticleDesc &p = scene.particles[static_cast<std::size_t>(i)];
        bool ok = false;
        for (int axis = 0; axis < 3; ++axis) {
            QCOMPARE(std::bit_cast<std::uint64_t>(parseDouble(fields[3 + axis], ok)),
                     std::bit_cast<std::uint64_t>(p.position[axis]));
            const double velocity = p.pinned ? 0.0 : p.velocity[axis];
            QCOMPARE(std::bit_cast<std::uint64_t>(parseDouble(fields[6 + axis], ok)),
                     std::bit_cast<std::uint64_t>(velocity));
        }
    }
}

void TestSimCli::durationRoundsToSteps_data()
{
    QTest::addColumn<QString>("duration");
    QTest::addColumn<QString>("timeStep");
    QTest::addColumn<int>("steps");
    QTest::newRow("exact") << u"0.5"_s << u"0.01"_s << 50;
    QTest::newRow("rounds up") << u"0.126"_s << u"0.01"_s << 13;
    QTest::newRow("rounds down") << u"0.124"_s << u"0.01"_s << 12;
    QTest::newRow("zero") << u"0"_s << u"0.01"_s << 0;
    QTest::newRow("file's time step") << u"0.1"_s << QString() << 20;  // testScene: 0.005 s
}

void TestSimCli::durationRoundsToSteps()
{
    QFETCH(QString, duration);
    QFETCH(QString, timeStep);
    QFETCH(int, steps);
    QStringList arguments{path(u"scene.json"_s), u"--duration"_s, duration, u"--trace"_s,
                          path(u"d.csv"_s),      u"--every"_s,    u"1"_s};
    if (!timeStep.isEmpty())
        arguments += {u"--time-step"_s, timeStep};
    const Run run = sim(arguments);
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.out.contains(QStringLiteral("ran        %1 of %1 steps").arg(steps).toUtf8()), run.out.constData());

    // the last traced step is the last step
    const QList<QByteArray> lines = readAll(path(u"d.csv"_s)).trimmed().split('\n');
    QCOMPARE(lines.last().split(',').first().toInt(), steps);
}

void TestSimCli::overridesReachTheOutput()
{
    // the command line's settings win over the file's, and the final state keeps them
    const QString output = path(u"overridden.json"_s);
    const Run run = sim({path(u"scene.json"_s), u"--steps"_s, u"10"_s, u"--time-step"_s, u"0.002"_s, u"--substeps"_s,
                         u"3"_s, u"--integrator"_s, u"explicit-euler"_s, u"--contact-solver"_s, u"handout"_s,
                         u"--friction"_s, u"0.25"_s, u"--static-friction"_s, u"0.75"_s, u"--output"_s, output,
                         u"--quiet"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const io::LoadResult result = io::loadScene(output);
    QVERIFY2(result.ok(), qPrintable(result.error));
    QCOMPARE(result.scene->settings.timeStep, 0.002);
    QCOMPARE(result.scene->settings.substeps, 3);
    QVERIFY(result.scene->settings.integrator == core::Integrator::ExplicitEuler);
    QVERIFY(result.scene->settings.contactSolver == core::ContactSolver::Handout);
    QCOMPARE(result.scene->settings.friction, 0.25);
    QCOMPARE(result.scene->settings.staticFriction.value_or(-1.0), 0.75);
    QCOMPARE(result.scene->settings.viscosity, testScene().settings.viscosity);
    QVERIFY(result.scene->particles[1].position != testScene().particles[1].position);
}

void TestSimCli::outputRefusesWhatIsNotAFile()
{
    // a FIFO as --output: exit 2 naming it and what it is, before the run; it is still a FIFO after
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString fifo = dir.filePath(u"final.json"_s);
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    const Run run = sim({path(u"scene.json"_s), u"--steps"_s, u"5"_s, u"--output"_s, fifo});
    QVERIFY2(run.exitCode == 2, run.err.constData());
    const QString expected =
        QDir::toNativeSeparators(fifo) + u": cannot save: it is a named pipe (FIFO), not a regular file"_s;
    QVERIFY2(QString::fromUtf8(run.err).contains(expected), run.err.constData());
    QVERIFY(run.out.isEmpty());
    struct stat status {};
    QCOMPARE(::lstat(QFile::encodeName(fifo).constData(), &status), 0);
    QVERIFY(S_ISFIFO(status.st_mode));
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::System),
             QStringList{u"final.json"_s});
}

void TestSimCli::outputOntoAFullDiskFails()
{
    // an old final state, and a scene whose final state is small (Qt buffers up to 16 KiB before
    // it writes anything) but larger than the disk's room: every file is limited to 512 bytes
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString output = dir.filePath(u"final.json"_s);
    QVERIFY(io::saveScene(output, explodingScene()).ok());
    const QByteArray before = readAll(output);
    constexpr int kLimit = 512;
    const qsizetype size = io::sceneToJson(testScene()).size();
    QVERIFY2(size > kLimit && size < 16384, qPrintable(QString::number(size)));

    // exit 2 naming the file and why; the old file whole, no temporary file beside it
    const Run run = test::runProgram(QStringLiteral(SPRINGLAB_WITH_FILE_LIMIT),
                                     {QString::number(kLimit), QStringLiteral(SPRINGLAB_SIM), path(u"scene.json"_s),
                                      u"--steps"_s, u"5"_s, u"--output"_s, output},
                                     120000);
    QVERIFY2(run.exitCode == 2, run.err.constData());
    const QString expected = QDir::toNativeSeparators(output) + u": cannot save: File too large"_s;
    QVERIFY2(QString::fromUtf8(run.err).contains(expected), run.err.constData());
    QVERIFY(!run.out.contains("output"));
    QCOMPARE(readAll(output), before);
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::System),
             QStringList{u"final.json"_s});
}

void TestSimCli::outOfMemoryIsAMessage()
{
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    QSKIP("the sanitizers reserve terabytes of address space: ulimit -v cannot be set under them");
#endif
    // 20 000 particles on one spot (a 1.8 MB file): a run of it peaks at about 245 MB resident, most
    // of it their contacts (up to 64 a particle). Under a 200 MB address space (ulimit -v) the run stops with a message and exit 2,
    // not std::bad_alloc's abort (134); with the memory it runs.
    core::SceneDesc crowd;
    crowd.name = "crowd";
    crowd.settings.particleCollisions = true;
    crowd.settings.contactSolver = core::ContactSolver::Iterative;
    crowd.particles.assign(20000, core::ParticleDesc{});
    const QString scene = path(u"crowd.json"_s);
    QVERIFY(io::saveScene(scene, crowd).ok());
    const QStringList run{scene, u"--steps"_s, u"2"_s, u"--quiet"_s};

    const auto capped = [&](int kib) {
        return test::runProgram(u"/bin/sh"_s,
                                QStringList{u"-c"_s, u"ulimit -v %1 && exec \"$0\" \"$@\""_s.arg(kib),
                                            QStringLiteral(SPRINGLAB_SIM)} + run,
                                120000);
    };
    const Run starved = capped(200 * 1024);
    QVERIFY2(starved.exitCode == 2, qPrintable(u"exit %1: %2"_s.arg(starved.exitCode).arg(QString::fromUtf8(starved.err))));
    QVERIFY2(QString::fromUtf8(starved.err).contains(QDir::toNativeSeparators(scene) + u": out of memory in step 1: "_s),
             starved.err.constData());
    const Run fed = sim(run);
    QVERIFY2(fed.exitCode == 0, fed.err.constData());
}

void TestSimCli::bigClothRunsInItsMemory()
{
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    QSKIP("the sanitizers reserve terabytes of address space: ulimit -v cannot be set under them");
#endif
    // a cloth of 100 489 particles over a floor with both kinds of collision runs in 300 MB of
    // address space. When the contact solver reserved room for a dense packing before the first
    // step, such a cloth (structural springs only) needed 490 MB and ended in std::bad_alloc below
    // that; it needs 175 MB now (docs/reliability.md, "Memory when running").
    core::ClothOptions options;
    options.rows = options.cols = 317;
    core::SceneDesc cloth = core::makeCloth(options);
    cloth.settings.planeCollisions = cloth.settings.particleCollisions = true;
    cloth.settings.contactSolver = core::ContactSolver::Iterative;
    cloth.settings.substeps = 2;
    cloth.planes = {core::PlaneDesc{{0.0, 1.0, 0.0}, 0.0}};
    const QString scene = path(u"big-cloth.json"_s);
    QVERIFY(io::saveScene(scene, cloth).ok());
    QProcessEnvironment environment = test::offscreenEnvironment();
    environment.insert(u"OMP_NUM_THREADS"_s, u"1"_s);  // one thread: no second heap arena to count
    const Run run = test::runProgram(u"/bin/sh"_s,
                                     {u"-c"_s, u"ulimit -v 307200 && exec \"$0\" \"$@\""_s, QStringLiteral(SPRINGLAB_SIM),
                                      scene, u"--steps"_s, u"3"_s, u"--quiet"_s},
                                     120000, environment);
    QVERIFY2(run.exitCode == 0, qPrintable(u"exit %1: %2"_s.arg(run.exitCode).arg(QString::fromUtf8(run.err))));
}

void TestSimCli::traceOntoAFullDiskSaysWhy()
{
    // a trace that outgrows the room on the disk (every file limited to 4096 bytes) stops the run
    // with exit 2 and the system's reason, not "Unknown error"
    const QString trace = path(u"full.csv"_s);
    const Run run = test::runProgram(QStringLiteral(SPRINGLAB_WITH_FILE_LIMIT),
                                     {u"4096"_s, QStringLiteral(SPRINGLAB_SIM), path(u"scene.json"_s), u"--steps"_s,
                                      u"200"_s, u"--trace"_s, trace},
                                     120000);
    QVERIFY2(run.exitCode == 2, run.err.constData());
    const QString expected = QDir::toNativeSeparators(trace) + u": cannot write the trace: File too large"_s;
    QVERIFY2(QString::fromUtf8(run.err).contains(expected), run.err.constData());
}

void TestSimCli::printsWhatIsSafeForATerminal()
{
    // a name with escape sequences (which could recolour or rewrite a terminal) is printed with
    // them shown, \u001b, not sent
    core::SceneDesc scene = testScene();
    scene.name = "\x1b[31mred\x1b[0m\x07";
    const QString file = path(u"escapes.json"_s);
    QVERIFY(io::saveScene(file, scene).ok());
    const Run run = sim({file, u"--steps"_s, u"2"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.out.contains("(\"\\u001b[31mred\\u001b[0m\\u0007\")"), run.out.constData());
    QVERIFY(!run.out.contains('\x1b') && !run.out.contains('\x07'));
}

void TestSimCli::summaryThatCannotBeWrittenFails()
{
    // stdout on a full device: the summary is lost, so the run is not a success
    if (!QFileInfo::exists(u"/dev/full"_s))
        QSKIP("no /dev/full here");
    const Run run = test::runProgram(u"/bin/sh"_s,
                                     {u"-c"_s, u"exec \"$0\" \"$@\" > /dev/full"_s, QStringLiteral(SPRINGLAB_SIM),
                                      path(u"scene.json"_s), u"--steps"_s, u"2"_s},
                                     60000);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("cannot write to the standard output: No space left on device"), run.err.constData());
}

void TestSimCli::linkLoopIsNamed()
{
    // two links that lead to each other are not "no such file"
    const QString first = path(u"loop-a.json"_s), second = path(u"loop-b.json"_s);
    QVERIFY(QFile::link(second, first));
    QVERIFY(QFile::link(first, second));
    const Run run = sim({first});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("cannot open: Too many levels of symbolic links"), run.err.constData());
}

void TestSimCli::energyGrowthIsAWarning()
{
    // explicit Euler on an undamped spring gains 1 + (hω)² of its energy a step: 7× in 200 steps,
    // far from a blow-up; the summary must not say "warnings none"
    core::OscillatorOptions options;
    options.stiffness = 100.0;
    options.damping = 0.0;
    core::SceneDesc scene = core::makeOscillator(options);
    scene.settings.integrator = core::Integrator::ExplicitEuler;
    scene.settings.timeStep = 0.01;
    const QString file = path(u"growing.json"_s);
    QVERIFY(io::saveScene(file, scene).ok());
    const Run run = sim({file, u"--steps"_s, u"200"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.err.contains("explicit-euler is unstable at this step"), run.err.constData());
    QVERIFY2(run.out.contains("warnings   1 (above)"), run.out.constData());

    // symplectic Euler on the same spring keeps its energy: no warning
    scene.settings.integrator = core::Integrator::SymplecticEuler;
    QVERIFY(io::saveScene(file, scene).ok());
    const Run steady = sim({file, u"--steps"_s, u"200"_s});
    QVERIFY2(steady.out.contains("warnings   none"), steady.out.constData());
}

void TestSimCli::energyThatRunsAwayIsABlowup()
{
    // just over symplectic Euler's limit (ω h = 2.02), undamped: the swing grows a little each
    // step, every value finite for hundreds of steps; past a thousandfold the start's energy with
    // no work done, the run stops as blown up, as the editor's does, and writes no --output
    core::OscillatorOptions options;
    options.stiffness = std::pow(2.02 / 0.01, 2.0);
    options.damping = 0.0;
    core::SceneDesc scene = core::makeOscillator(options);
    scene.settings.integrator = core::Integrator::SymplecticEuler;
    scene.settings.timeStep = 0.01;
    scene.settings.substeps = 1;
    const QString file = path(u"runaway.json"_s);
    QVERIFY(io::saveScene(file, scene).ok());
    const QString out = path(u"runaway-out.json"_s);
    QFile::remove(out);
    const Run run = sim({file, u"--steps"_s, u"2000"_s, u"--output"_s, out});
    QCOMPARE(run.exitCode, 3);
    QVERIFY2(run.err.contains("The total energy grew from 5.1e+03 J to "), run.err.constData());
    QVERIFY2(run.err.contains("the stability limit"), run.err.constData());
    QVERIFY2(run.out.contains("(stopped: blew up)"), run.out.constData());
    QVERIFY(!QFileInfo::exists(out));
    // well before the world's bound: the editor's runner stops the same spring by step 64
    const QRegularExpression ran(u"ran +(\\d+) of 2000 steps"_s);
    const QRegularExpressionMatch match = ran.match(QString::fromUtf8(run.out));
    QVERIFY2(match.hasMatch(), run.out.constData());
    QVERIFY2(match.captured(1).toInt() <= 200, run.out.constData());
}

void TestSimCli::autoSubstepsSaysWhatRan()
{
    // the summary gives the count that ran, and --output keeps it for the run resumed from there
    const QString half = path(u"chain-half.json"_s);
    const Run run = sim({path(u"chain-auto.json"_s), u"--steps"_s, u"100"_s, u"--output"_s, half});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.out.contains("4 substeps (auto: for the stability limit, at least 1)"), run.out.constData());
    const io::LoadResult loaded = io::loadScene(half);
    QVERIFY2(loaded.scene, qPrintable(loaded.error));
    QCOMPARE(loaded.scene->settings.substeps, 4);
    QVERIFY(loaded.scene->settings.autoSubsteps);
}

void TestSimCli::runLeavingTheFileRangeBlowsUp()
{
    // a particle falling freely for 15 000 s passes 1e9 m, past what a scene file may hold: the
    // run stops there as a blow-up (exit 3) and writes no --output, rather than a file that the
    // loader refuses
    const QString output = path(u"fell-too-far.json"_s);
    const Run run = test::runProgram(QStringLiteral(SPRINGLAB_SIM),
                                     {QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/particles.json"),
                                      u"--time-step"_s, u"0.1"_s, u"--duration"_s, u"15000"_s, u"--output"_s, output},
                                     120000);
    QVERIFY2(run.exitCode == 3, run.err.constData());
    QVERIFY2(run.err.contains("(no --output written)"), run.err.constData());
    QVERIFY(!QFileInfo::exists(output));

    // 14 000 s stays inside the range: the output is written, and it loads
    const Run within = test::runProgram(QStringLiteral(SPRINGLAB_SIM),
                                        {QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/particles.json"),
                                         u"--time-step"_s, u"0.1"_s, u"--duration"_s, u"14000"_s, u"--output"_s, output},
                                        120000);
    QVERIFY2(within.exitCode == 0, within.err.constData());
    const io::LoadResult loaded = io::loadScene(output);
    QVERIFY2(loaded.scene, qPrintable(loaded.error));
}

void TestSimCli::outputsMustNotNameTheInputOrEachOther()
{
    // --trace or --output onto the scene file (also by another spelling of its path), or --trace
    // and --output onto one file: exit 2 before the run, naming the clash, and every file as it was
    const QString scene = path(u"scene.json"_s);
    const QByteArray before = readAll(scene);
    const QString otherSpelling = m_dir.path() + u"/./scene.json"_s;
    const QString both = path(u"both.out"_s);
    const struct {
        QStringList arguments;
        QString says;
    } cases[] = {
        {{scene, u"--trace"_s, scene}, u"overwrite what it reads"_s},
        {{scene, u"--output"_s, otherSpelling}, u"overwrite what it reads"_s},
        {{scene, u"--output"_s, both, u"--trace"_s, both}, u"one would overwrite the other"_s},
    };
    for (const auto &[arguments, says] : cases) {
        const Run run = test::runProgram(QStringLiteral(SPRINGLAB_SIM), arguments + QStringList{u"--steps"_s, u"5"_s}, 60000);
        QVERIFY2(run.exitCode == 2, run.err.constData());
        QVERIFY2(QString::fromUtf8(run.err).contains(says), run.err.constData());
        QCOMPARE(readAll(scene), before);
        QVERIFY(!QFileInfo::exists(both));
    }
}

void TestSimCli::resumeEqualsUninterrupted_data()
{
    QTest::addColumn<QString>("scene");  // "" for the test scene
    QTest::addColumn<int>("first");
    QTest::addColumn<int>("second");
    QTest::addColumn<QStringList>("extra");
    QTest::newRow("test scene") << QString() << 137 << 263 << QStringList();
    QTest::newRow("test scene, overridden")
        << QString() << 50 << 70 << QStringList{u"--time-step"_s, u"0.003"_s, u"--substeps"_s, u"4"_s};
    QTest::newRow("test scene, explicit euler")
        << QString() << 20 << 20 << QStringList{u"--integrator"_s, u"explicit-euler"_s};
    // under a sanitizer the examples resume after a tenth of the steps: the same files and the same
    // code, which is what that stage checks, in a tenth of its time (7 of its 11 minutes were here)
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    constexpr int shorter = 10;
#else
    constexpr int shorter = 1;
#endif
    for (const QString &file : exampleFiles())
        QTest::newRow(qPrintable(QFileInfo(file).fileName())) << file << 60 / shorter << 90 / shorter << QStringList();
    // auto substeps: the count the run chose at its start goes on (4 here, for ω = 654 rad/s)
    QTest::newRow("chain, auto substeps") << path(u"chain-auto.json"_s) << 100 << 100 << QStringList();
    // the adaptive step size goes on from where it was (settings.adaptiveStep)
    QTest::newRow("tearable-cloth, adaptive-rk45")
        << QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/tearable-cloth.json") << 300 / shorter
        << 200 / shorter << QStringList{u"--integrator"_s, u"adaptive-rk45"_s};
}

void TestSimCli::resumeEqualsUninterrupted()
{
    QFETCH(QString, scene);
    QFETCH(int, first);
    QFETCH(int, second);
    QFETCH(QStringList, extra);
    if (scene.isEmpty())
        scene = path(u"scene.json"_s);
    const QString whole = path(u"whole.json"_s);
    const QString half = path(u"half.json"_s);
    const QString resumed = path(u"resumed.json"_s);

    // one run of first + second steps
    Run run = sim(
        QStringList{scene, u"--steps"_s, QString::number(first + second), u"--output"_s, whole, u"--quiet"_s} + extra);
    QVERIFY2(run.exitCode == 0, run.err.constData());

    // first steps, stop, then second steps from the saved state
    run = sim(QStringList{scene, u"--steps"_s, QString::number(first), u"--output"_s, half, u"--quiet"_s} + extra);
    QVERIFY2(run.exitCode == 0, run.err.constData());
    run = sim({half, u"--steps"_s, QString::number(second), u"--output"_s, resumed, u"--quiet"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());

    // the state at step 0, to tell a scene that moves from one at rest (the pool's balls lie still)
    const QString initial = path(u"initial.json"_s);
    run = sim(QStringList{scene, u"--steps"_s, u"0"_s, u"--output"_s, initial, u"--quiet"_s} + extra);
    QVERIFY2(run.exitCode == 0, run.err.constData());

    // the same file, byte for byte; the files hold every double's bits (see test_scene_file)
    const QByteArray expected = readAll(whole);
    QVERIFY(!expected.isEmpty());
    // a moving scene: the halfway particles differ from the end's (the pool's lie still, though
    // their contact impulses are saved once they have run)
    const auto particles = [](const QString &file) {
        return QJsonDocument::fromJson(readAll(file)).object().value(u"particles"_s);
    };
    if (particles(initial) != particles(whole))
        QVERIFY(particles(half) != particles(whole));
    QCOMPARE(readAll(resumed), expected);
}

void TestSimCli::replayRunsARecordingToItsBits()
{
    // a session of the editor's runner: a tilt and a parameter change while it runs
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{std::make_shared<const core::SceneDesc>(testScene()), ui::SceneChange::Replace});
    runner.apply(ui::StartRecording{});
    runner.apply(ui::Play{});
    runner.advance(0.2, 1e9);
    runner.apply(ui::TiltEdit{7, 1.0});
    auto changed = std::make_shared<core::SceneDesc>(*runner.scene());
    changed->settings.viscosity = 0.3;
    runner.apply(ui::SetSceneEdit{changed, ui::SceneChange::Parameters});
    runner.advance(0.2, 1e9);
    runner.apply(ui::StopRecording{1});
    const std::optional<ui::RecordingReply> stopped = ui::findReply<ui::RecordingReply>(runner.takeReplies());
    QVERIFY(stopped);
    const auto recording = stopped->recording;
    QVERIFY(recording && recording->steps > 0);
    const QString session = path(u"session.replay.json"_s);
    QCOMPARE(ui::saveRecording(session, *recording), QString());

    // replayed: the recorded bits, and its final state written as a scene to run on from
    const Run replayed = sim({session, u"--replay"_s, u"--output"_s, path(u"replayed.json"_s)});
    QCOMPARE(replayed.exitCode, 0);
    const QString hash = QString::number(recording->finalHash, 16).rightJustified(16, u'0');
    QVERIFY2(replayed.out.contains(("final state " + hash + ", as recorded").toUtf8()), replayed.out.constData());
    const io::LoadResult final = io::loadScene(path(u"replayed.json"_s));
    QVERIFY2(final.ok(), qPrintable(final.error));
    core::SceneDesc expected = *changed;
    core::storeState(runner.state(), expected);
    QVERIFY(final.scene->particles == expected.particles);

    // a recording whose end does not match: exit 4, both hashes named
    QByteArray tampered = readAll(session);
    tampered.replace(hash.toUtf8(), QByteArray("0123456789abcdef"));
    QFile file(path(u"tampered.replay.json"_s));
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write(tampered) == tampered.size());
    file.close();
    const Run differs = sim({path(u"tampered.replay.json"_s), u"--replay"_s});
    QCOMPARE(differs.exitCode, 4);
    QVERIFY2(differs.err.contains("but the recording ended with 0123456789abcdef"), differs.err.constData());

    // nothing may change a replay
    const Run refused = sim({session, u"--replay"_s, u"--steps"_s, u"5"_s});
    QCOMPARE(refused.exitCode, 2);
    QVERIFY2(refused.err.contains("--steps cannot change it"), refused.err.constData());
}

void TestSimCli::tearableClothTears()
{
    // the ball tears through the sheet: the summary counts the breaks, the final file has fewer
    // springs, and the ball lies on the floor under the sheet's height
    const QString scene = QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/tearable-cloth.json");
    const QString out = path(u"torn.json"_s);
    const Run run = sim({scene, u"--duration"_s, u"2"_s, u"--output"_s, out});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const QRegularExpressionMatch match =
        QRegularExpression(u"breaks     (\\d+) of (\\d+) springs broke, the first in step (\\d+)"_s)
            .match(QString::fromUtf8(run.out));
    QVERIFY2(match.hasMatch(), run.out.constData());
    const int broken = match.captured(1).toInt();
    const int springs = match.captured(2).toInt();
    QVERIFY(broken > 10);
    const io::LoadResult torn = io::loadScene(out);
    QVERIFY2(torn.ok(), qPrintable(torn.error));
    QCOMPARE(int(torn.scene->springs.size()), springs - broken);
    const core::ParticleDesc &ball = torn.scene->particles.back();
    QVERIFY2(ball.position.y() < 0.5, qPrintable(QString("the ball is at y = %1").arg(ball.position.y())));
}

QTEST_GUILESS_MAIN(TestSimCli)
#include "test_sim_cli.moc"
