// springlab-sim's --set and the summary's status, end to end (issue 37): a --set that reaches no
// element of the scene is refused, with its value judged all the same; a number no double holds
// is named in the scene loader's words; an index is shown as it was typed; and a run that ran out
// of memory or could not write what it was asked to is filed under a status of its own, not as
// "bad-input" (refused, nothing ran).

#include "core/io/scene_file.h"
#include "core/model/parameters.h"
#include "sim_run.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

namespace {

using test::sim;
using test::readAll;
using test::readJson;

using Run = test::ProgramRun;

// the first line springlab-sim wrote to stderr, less its name
QString firstError(const Run &run)
{
    return QString::fromUtf8(run.err).section(u'\n', 0, 0).remove(0, QStringLiteral("springlab-sim: ").size());
}

// the words of the range check the loader and --set share: "must be at most 10 (got 99)"
QString rangeWords(core::Parameter parameter, double value)
{
    return QString::fromStdString(core::checkParameter(parameter, value).value_or("(in range)"));
}

// a row of free particles, one metre apart, and nothing else: no springs, no planes
core::SceneDesc particlesOnly(int count)
{
    core::SceneDesc scene;
    scene.name = "particles only";
    scene.settings.timeStep = 0.01;
    for (int i = 0; i < count; ++i) {
        core::ParticleDesc particle;
        particle.position = {1.0 * i, 1.0, 0.0};
        particle.velocity = {0.0, 0.5, 0.1 * i};
        particle.mass = 0.5;
        particle.radius = 0.05;
        scene.particles.push_back(particle);
    }
    return scene;
}

// three particles, one spring between the first two, and a floor
core::SceneDesc springAndFloor()
{
    core::SceneDesc scene = particlesOnly(3);
    scene.name = "spring and floor";
    scene.springs.push_back({0, 1, 200.0, 0.5, 1.0});
    scene.planes.push_back({{0.0, 1.0, 0.0}, 0.0});
    return scene;
}

// a scene whose values are each written once in its file, so that one can be replaced by text
core::SceneDesc marked()
{
    core::SceneDesc scene = particlesOnly(3);
    scene.name = "marked";
    scene.settings.timeStep = 0.0123456;
    scene.settings.substeps = 37;
    scene.settings.gravity = {0.111111, -9.333333, 0.555555};
    scene.particles[0].mass = 0.777777;
    scene.particles[0].velocity = {0.2222, 0.4444, 0.6666};
    return scene;
}

}  // namespace

class TestSimOverrides : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void setThatMatchesNothingIsRefused_data();
    void setThatMatchesNothingIsRefused();
    void setThatMatchesRuns_data();
    void setThatMatchesRuns();
    void unholdableNumberInTheLoadersWords_data();
    void unholdableNumberInTheLoadersWords();
    void indexShownAsTyped_data();
    void indexShownAsTyped();
    void outOfMemoryInAStepHasItsStatus();
    void writeThatFailedHasItsStatus_data();
    void writeThatFailedHasItsStatus();

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }

    QTemporaryDir m_dir;
};

void TestSimOverrides::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_SIM)).isExecutable());
    QVERIFY(m_dir.isValid());
    QVERIFY(io::saveScene(path(u"three.json"_s), particlesOnly(3)).ok());
    QVERIFY(io::saveScene(path(u"spring.json"_s), springAndFloor()).ok());
    QVERIFY(io::saveScene(path(u"marked.json"_s), marked()).ok());
}

void TestSimOverrides::setThatMatchesNothingIsRefused_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("argument");
    QTest::addColumn<QString>("message");  // the whole of it, after "springlab-sim: "

    const auto nothing = [](const QString &argument, const QString &why) {
        return u"--set "_s + argument + u": "_s + why;
    };
    // the issue's case: out of range, and nothing to change
    QTest::newRow("planes.friction=99, no planes")
        << u"three.json"_s << u"planes.friction=99"_s
        << nothing(u"planes.friction=99"_s, u"planes.friction: matches nothing: the scene has no planes; and "
                                             "planes.friction: "_s + rangeWords(core::Parameter::Friction, 99.0));
    QTest::newRow("planes.friction=0.5, no planes")
        << u"three.json"_s << u"planes.friction=0.5"_s
        << nothing(u"planes.friction=0.5"_s, u"planes.friction: matches nothing: the scene has no planes"_s);
    QTest::newRow("planes.normal=[0,0,0], no planes")
        << u"three.json"_s << u"planes.normal=[0,0,0]"_s
        << nothing(u"planes.normal=[0,0,0]"_s, u"planes.normal: matches nothing: the scene has no planes; and "
                                                "planes.normal: is zero: a plane needs a direction"_s);
    QTest::newRow("springs.stiffness=500, no springs")
        << u"three.json"_s << u"springs.stiffness=500"_s
        << nothing(u"springs.stiffness=500"_s, u"springs.stiffness: matches nothing: the scene has no springs"_s);
    QTest::newRow("springs.stiffness=-5, no springs")
        << u"three.json"_s << u"springs.stiffness=-5"_s
        << nothing(u"springs.stiffness=-5"_s, u"springs.stiffness: matches nothing: the scene has no springs; and "
                                               "springs.stiffness: "_s + rangeWords(core::Parameter::Stiffness, -5.0));
    // a strain is judged against a rest length: the stand-in spring has one
    QTest::newRow("springs.breakStrain=0.5, no springs")
        << u"three.json"_s << u"springs.breakStrain=0.5"_s
        << nothing(u"springs.breakStrain=0.5"_s, u"springs.breakStrain: matches nothing: the scene has no springs"_s);
    QTest::newRow("particles[5].mass=2, 3 particles")
        << u"three.json"_s << u"particles[5].mass=2"_s
        << nothing(u"particles[5].mass=2"_s, u"particles[5]: index 5 is out of range (the scene has 3 particles)"_s);
    QTest::newRow("particles[5].mass=-1, 3 particles")
        << u"three.json"_s << u"particles[5].mass=-1"_s
        << nothing(u"particles[5].mass=-1"_s, u"particles[5]: index 5 is out of range (the scene has 3 particles); "
                                               "and particles[5].mass: "_s + rangeWords(core::Parameter::Mass, -1.0));
    QTest::newRow("particles[3].position out of range, 3 particles")
        << u"three.json"_s << u"particles[3].position=[0,2e9,0]"_s
        << nothing(u"particles[3].position=[0,2e9,0]"_s,
                   u"particles[3]: index 3 is out of range (the scene has 3 particles); and particles[3].position[1]: "_s +
                       rangeWords(core::Parameter::Coordinate, 2e9));
    QTest::newRow("springs[1].damping=1, 1 spring")
        << u"spring.json"_s << u"springs[1].damping=1"_s
        << nothing(u"springs[1].damping=1"_s, u"springs[1]: index 1 is out of range (the scene has 1 springs)"_s);
    QTest::newRow("planes[0].offset=1, no planes")
        << u"three.json"_s << u"planes[0].offset=1"_s
        << nothing(u"planes[0].offset=1"_s, u"planes[0]: index 0 is out of range (the scene has 0 planes)"_s);
}

void TestSimOverrides::setThatMatchesNothingIsRefused()
{
    QFETCH(QString, scene);
    QFETCH(QString, argument);
    QFETCH(QString, message);
    const QString summaryPath = path(u"nothing.json"_s);
    const QString output = path(u"nothing-final.json"_s);
    QFile::remove(summaryPath);
    QFile::remove(output);

    // refused before the run: exit 2, the message on stderr, nothing printed or written
    const Run run = sim({path(scene), u"--steps"_s, u"5"_s, u"--set"_s, argument, u"--output"_s, output,
                         u"--summary-json"_s, summaryPath});
    QVERIFY2(run.exitCode == 2, run.err.constData());
    QCOMPARE(firstError(run), message);
    QVERIFY(run.out.isEmpty());
    QVERIFY(!QFile::exists(output));

    // the summary says so: the override as asked, not run, and why
    const QJsonObject summary = readJson(summaryPath);
    QCOMPARE(summary[u"status"_s].toString(), u"bad-input"_s);
    QCOMPARE(summary[u"exitCode"_s].toInt(-1), 2);
    QVERIFY(summary[u"steps"_s].isNull());
    QCOMPARE(summary[u"error"_s].toString(), message);
    const QString key = argument.section(u'=', 0, 0);
    QVERIFY2(summary[u"overrides"_s].toObject().contains(key), qPrintable(key));
}

void TestSimOverrides::setThatMatchesRuns_data()
{
    QTest::addColumn<QString>("argument");
    QTest::addColumn<QString>("changed");  // what the final scene holds, as its file writes it

    QTest::newRow("every plane") << u"planes.friction=0.5"_s << u"\"friction\": 0.5"_s;
    QTest::newRow("every spring") << u"springs.stiffness=500"_s << u"\"stiffness\": 500"_s;
    QTest::newRow("the last particle") << u"particles[2].mass=2"_s << u"\"mass\": 2,"_s;
    QTest::newRow("the one spring") << u"springs[0].breakStrain=0.5"_s << u"\"breakStrain\": 0.5"_s;
}

void TestSimOverrides::setThatMatchesRuns()
{
    // the same keys on a scene that has the elements they name run, and change them
    QFETCH(QString, argument);
    QFETCH(QString, changed);
    const QString output = path(u"matched-final.json"_s);
    QFile::remove(output);
    const Run run = sim({path(u"spring.json"_s), u"--steps"_s, u"5"_s, u"--quiet"_s, u"--set"_s, argument,
                         u"--output"_s, output});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    const QString final = QString::fromUtf8(readAll(output));
    QVERIFY2(final.contains(changed), qPrintable(final));
    QVERIFY(!QString::fromUtf8(io::sceneToJson(springAndFloor())).contains(changed));
}

void TestSimOverrides::unholdableNumberInTheLoadersWords_data()
{
    QTest::addColumn<QString>("argument");
    QTest::addColumn<QByteArray>("marker");   // the value's text in marked.json
    QTest::addColumn<QByteArray>("literal");  // the text written in its place

    QTest::newRow("time step 1e400") << u"settings.timeStep=1e400"_s << "0.0123456"_ba << "1e400"_ba;
    QTest::newRow("time step -1e400") << u"settings.timeStep=-1e400"_s << "0.0123456"_ba << "-1e400"_ba;
    QTest::newRow("time step 1e-400") << u"settings.timeStep=1e-400"_s << "0.0123456"_ba << "1e-400"_ba;
    QTest::newRow("time step nan") << u"settings.timeStep=nan"_s << "0.0123456"_ba << "nan"_ba;
    QTest::newRow("time step NaN") << u"settings.timeStep=NaN"_s << "0.0123456"_ba << "NaN"_ba;
    QTest::newRow("time step inf") << u"settings.timeStep=inf"_s << "0.0123456"_ba << "inf"_ba;
    QTest::newRow("time step -inf") << u"settings.timeStep=-inf"_s << "0.0123456"_ba << "-inf"_ba;
    QTest::newRow("time step Infinity") << u"settings.timeStep=Infinity"_s << "0.0123456"_ba << "Infinity"_ba;
    QTest::newRow("substeps 1e400") << u"settings.substeps=1e400"_s << "\"substeps\": 37"_ba
                                    << "\"substeps\": 1e400"_ba;
    QTest::newRow("gravity x 1e400") << u"settings.gravity=[1e400,0,0]"_s << "0.111111"_ba << "1e400"_ba;
    QTest::newRow("gravity y nan") << u"settings.gravity=[0.111111, nan, 0.555555]"_s << "-9.333333"_ba << "nan"_ba;
    QTest::newRow("mass 1e400") << u"particles[0].mass=1e400"_s << "0.777777"_ba << "1e400"_ba;
    QTest::newRow("velocity z -inf") << u"particles[0].velocity=[0,0,-inf]"_s << "0.6666"_ba << "-inf"_ba;
}

void TestSimOverrides::unholdableNumberInTheLoadersWords()
{
    QFETCH(QString, argument);
    QFETCH(QByteArray, marker);
    QFETCH(QByteArray, literal);

    // the file with the literal in the value's place, and the loader's words for it
    QByteArray text = io::sceneToJson(marked());
    QCOMPARE(text.count(marker), 1);
    text.replace(marker, literal);
    const QString file = path(u"literal.json"_s);
    QFile out(file);
    QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QCOMPARE(out.write(text), text.size());
    out.close();
    const io::LoadResult loaded = io::loadScene(file);
    QVERIFY(!loaded.ok());
    // less the file's name before, and the place in the text after
    QString fileWords = loaded.error.mid(QDir::toNativeSeparators(file).size() + 2);
    fileWords.truncate(fileWords.lastIndexOf(u" ("_s));
    QVERIFY2(fileWords.contains(QString::fromLatin1(literal.mid(literal.lastIndexOf(' ') + 1))), qPrintable(fileWords));

    // --set says the same of the same literal, and does not call it a string
    const QString summaryPath = path(u"literal-summary.json"_s);
    QFile::remove(summaryPath);
    const Run run = sim({path(u"marked.json"_s), u"--steps"_s, u"3"_s, u"--set"_s, argument, u"--summary-json"_s,
                         summaryPath});
    QVERIFY2(run.exitCode == 2, run.err.constData());
    const QString prefix = u"--set "_s + argument + u": "_s;
    const QString error = firstError(run);
    QVERIFY2(error.startsWith(prefix), qPrintable(error));
    QCOMPARE(error.mid(prefix.size()), fileWords);
    QVERIFY(!error.contains(u"a string"_s));

    const QJsonObject summary = readJson(summaryPath);
    QCOMPARE(summary[u"status"_s].toString(), u"bad-input"_s);
    QCOMPARE(summary[u"error"_s].toString(), error);
}

void TestSimOverrides::indexShownAsTyped_data()
{
    QTest::addColumn<QString>("argument");
    QTest::addColumn<QString>("message");

    QTest::newRow("20 digits") << u"particles[99999999999999999999].mass=2"_s
                               << u"--set particles[99999999999999999999].mass=2: particles[99999999999999999999]: "
                                  "index 99999999999999999999 is out of range (the scene has 3 particles)"_s;
    QTest::newRow("one past a signed 64-bit count")
        << u"particles[9223372036854775808].radius=0.1"_s
        << u"--set particles[9223372036854775808].radius=0.1: particles[9223372036854775808]: "
           "index 9223372036854775808 is out of range (the scene has 3 particles)"_s;
    QTest::newRow("2 to the 64, no planes") << u"planes[18446744073709551616].offset=1"_s
                                            << u"--set planes[18446744073709551616].offset=1: "
                                               "planes[18446744073709551616]: index 18446744073709551616 is out "
                                               "of range (the scene has 0 planes)"_s;
    QTest::newRow("leading zeros") << u"particles[007].mass=2"_s
                                   << u"--set particles[007].mass=2: particles[007]: index 007 is out of range "
                                      "(the scene has 3 particles)"_s;
    QTest::newRow("huge, and a bad value") << u"springs[123456789012345678901234567890].stiffness=-1"_s
                                           << u"--set springs[123456789012345678901234567890].stiffness=-1: "
                                              "springs[123456789012345678901234567890]: index "
                                              "123456789012345678901234567890 is out of range (the scene has 0 "
                                              "springs); and springs[123456789012345678901234567890].stiffness: "_s +
                                                  rangeWords(core::Parameter::Stiffness, -1.0);
}

void TestSimOverrides::indexShownAsTyped()
{
    QFETCH(QString, argument);
    QFETCH(QString, message);
    const Run run = sim({path(u"three.json"_s), u"--steps"_s, u"3"_s, u"--set"_s, argument});
    QVERIFY2(run.exitCode == 2, run.err.constData());
    QCOMPARE(firstError(run), message);
    // no count the program made up in place of what was typed
    QVERIFY2(!run.err.contains("9223372036854775807"), run.err.constData());
}

void TestSimOverrides::outOfMemoryInAStepHasItsStatus()
{
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    QSKIP("the sanitizers reserve terabytes of address space: ulimit -v cannot be set under them");
#endif
    // 20 000 particles on one spot: the first step's contacts need far more than a 200 MB address
    // space holds (test_sim_cli's outOfMemoryIsAMessage), while loading the file does not
    core::SceneDesc crowd;
    crowd.name = "crowd";
    crowd.settings.particleCollisions = true;
    crowd.settings.contactSolver = core::ContactSolver::Iterative;
    crowd.particles.assign(20000, core::ParticleDesc{});
    const QString scene = path(u"crowd.json"_s);
    QVERIFY(io::saveScene(scene, crowd).ok());
    const QString json = path(u"crowd-summary.json"_s);
    const QString csv = path(u"crowd-summary.csv"_s);
    const Run run = test::runProgram(u"/bin/sh"_s,
                                     {u"-c"_s, u"ulimit -v 204800 && exec \"$0\" \"$@\""_s, QStringLiteral(SPRINGLAB_SIM),
                                      scene, u"--steps"_s, u"2"_s, u"--quiet"_s, u"--summary-json"_s, json,
                                      u"--summary-csv"_s, csv},
                                     120000);
    QVERIFY2(run.exitCode == 2, qPrintable(u"exit %1: %2"_s.arg(run.exitCode).arg(QString::fromUtf8(run.err))));

    // its own status, not "refused, nothing ran"; the run's figures up to the step that failed
    const QJsonObject summary = readJson(json);
    QCOMPARE(summary[u"status"_s].toString(), u"out-of-memory"_s);
    QCOMPARE(summary[u"exitCode"_s].toInt(-1), 2);
    QVERIFY2(summary[u"error"_s].toString().contains(u"out of memory in step 1"_s),
             qPrintable(summary[u"error"_s].toString()));
    QCOMPARE(summary[u"stepsRequested"_s].toInt(-1), 2);
    QCOMPARE(summary[u"steps"_s].toInt(-1), 0);
    QVERIFY(summary[u"kineticStart"_s].isDouble());
    QVERIFY(summary[u"kineticEnd"_s].isNull());  // half-way through a step: not known
    QVERIFY(QString::fromUtf8(readAll(csv)).contains(u",out-of-memory,"_s));
}

void TestSimOverrides::writeThatFailedHasItsStatus_data()
{
    QTest::addColumn<QString>("how");        // "", "limit": every file at most 4096 bytes, "full": stdout on /dev/full
    QTest::addColumn<QStringList>("extra");  // "@" stands for the temporary folder
    QTest::addColumn<QString>("stderrHas");

    QTest::newRow("--output in a folder that is not there")
        << QString() << QStringList{u"--output"_s, u"@/no-such-folder/final.json"_s}
        << QDir::toNativeSeparators(u"/no-such-folder/final.json: cannot save"_s);
    QTest::newRow("--output onto a full disk") << u"limit"_s << QStringList{u"--output"_s, u"@/full-final.json"_s}
                                              << u"full-final.json: cannot save: File too large"_s;
    QTest::newRow("--trace onto a full disk") << u"limit"_s << QStringList{u"--trace"_s, u"@/full-trace.csv"_s}
                                             << u"full-trace.csv: cannot write the trace: File too large"_s;
    QTest::newRow("the printed report onto a full device")
        << u"full"_s << QStringList() << u"cannot write to the standard output: No space left on device"_s;
}

void TestSimOverrides::writeThatFailedHasItsStatus()
{
    QFETCH(QString, how);
    QFETCH(QStringList, extra);
    QFETCH(QString, stderrHas);
    if (how == u"full"_s && !QFileInfo::exists(u"/dev/full"_s))
        QSKIP("no /dev/full here");
    for (QString &argument : extra)
        argument.replace(u'@', m_dir.path());

    // sixty particles: a final scene and a trace well past 4096 bytes, a summary well under it
    constexpr int kLimit = 4096;
    const QString scene = path(u"sixty.json"_s);
    QVERIFY(io::saveScene(scene, particlesOnly(60)).ok());
    QVERIFY(io::sceneToJson(particlesOnly(60)).size() > kLimit);
    const QString json = path(u"write-summary.json"_s);
    QFile::remove(json);
    const QStringList arguments =
        QStringList{scene, u"--steps"_s, u"200"_s, u"--summary-json"_s, json} + extra;

    Run run;
    if (how == u"limit"_s)
        run = test::runProgram(QStringLiteral(SPRINGLAB_WITH_FILE_LIMIT),
                               QStringList{QString::number(kLimit), QStringLiteral(SPRINGLAB_SIM)} + arguments, 120000);
    else if (how == u"full"_s)
        run = test::runProgram(u"/bin/sh"_s,
                               QStringList{u"-c"_s, u"exec \"$0\" \"$@\" > /dev/full"_s, QStringLiteral(SPRINGLAB_SIM)} +
                                   arguments,
                               120000);
    else
        run = sim(arguments);
    QVERIFY2(run.exitCode == 2, qPrintable(u"exit %1: %2"_s.arg(run.exitCode).arg(QString::fromUtf8(run.err))));
    QVERIFY2(QString::fromUtf8(run.err).contains(stderrHas), run.err.constData());

    // the run went to its end, and the summary keeps its figures; what failed is the write
    const QJsonObject summary = readJson(json);
    QCOMPARE(summary[u"status"_s].toString(), u"write-failed"_s);
    QCOMPARE(summary[u"exitCode"_s].toInt(-1), 2);
    QVERIFY2(summary[u"error"_s].toString().contains(stderrHas), qPrintable(summary[u"error"_s].toString()));
    QCOMPARE(summary[u"stepsRequested"_s].toInt(-1), 200);
    QCOMPARE(summary[u"steps"_s].toInt(-1), 200);
    QVERIFY(summary[u"kineticEnd"_s].isDouble());
    QVERIFY(summary[u"kineticEnd"_s].toDouble() != summary[u"kineticStart"_s].toDouble());
}

QTEST_MAIN(TestSimOverrides)
#include "test_sim_overrides.moc"
