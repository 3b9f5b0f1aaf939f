// Session recordings: a runner records a session full of edits (tilts, steering, the mouse spring,
// a strike with spin, parameter and structure changes, a step, a reset, a blow-up that the runner takes back) and a
// replay on a fresh runner ends with the same bits, straight from memory and through a file; a
// recording changed by one step no longer matches; a damaged file is refused with its path.

#include "session/session_file.h"
#include "tests/session/runner_with.h"
#include "session/simulation_runner.h"

#include "core/model/generators.h"
#include "core/io/scene_file.h"
#include "core/model/state_hash.h"

#include <QTemporaryDir>
#include <QtTest>

namespace {

constexpr double kNoBudgetLimit = 1e9;  // s

// a small net on a floor, falling and bouncing: springs, contacts, gravity and drag all at work
std::shared_ptr<const core::SceneDesc> netScene()
{
    core::ClothOptions options;
    options.rows = 4;
    options.cols = 5;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.timeStep = 0.005;
    scene.settings.viscosity = 0.05;
    scene.settings.particleCollisions = true;
    scene.settings.planeCollisions = true;
    scene.settings.friction = 0.3;  // so that it turns, and a strike's spin is kept
    return std::make_shared<const core::SceneDesc>(scene);
}

using test::runnerWith;

// the recording a StopRecording handed back, and the request it answers
std::shared_ptr<const ui::SessionRecording> stoppedRecording(ui::SimulationRunner &runner, std::uint64_t *request = nullptr)
{
    const std::optional<ui::RecordingReply> reply = ui::findReply<ui::RecordingReply>(runner.takeReplies());
    if (request)
        *request = reply ? reply->request : 0;
    return reply ? reply->recording : nullptr;
}

// the runner's own session: every kind of edit, some mid-run, and a tick that blows up
std::shared_ptr<const ui::SessionRecording> recordSession(ui::SimulationRunner &runner, std::uint64_t *request = nullptr)
{
    runner.apply(ui::SetSceneEdit{netScene(), ui::SceneChange::Replace});
    runner.apply(ui::Play{});
    runner.advance(0.1, kNoBudgetLimit);  // recording starts mid-run, with the steering on
    runner.apply(ui::SteerEdit{3, Eigen::Vector3d(0.5, 0.0, -0.25)});
    runner.advance(0.05, kNoBudgetLimit);
    runner.apply(ui::StartRecording{});
    runner.advance(0.07, kNoBudgetLimit);
    runner.apply(ui::TiltEdit{42, 1.5});
    runner.advance(0.031, kNoBudgetLimit);
    runner.apply(ui::StrikeEdit{5, Eigen::Vector3d(0.4, 0.2, 0.0), Eigen::Vector3d(0.0, 30.0, -10.0)});
    runner.advance(0.02, kNoBudgetLimit);
    runner.apply(ui::GrabEdit{7, Eigen::Vector3d(0.3, 1.2, -0.1)});
    runner.advance(0.04, kNoBudgetLimit);
    runner.apply(ui::GrabEdit{7, Eigen::Vector3d(0.5, 1.0, 0.2)});
    runner.advance(0.02, kNoBudgetLimit);
    runner.apply(ui::GrabEdit{-1, Eigen::Vector3d::Zero()});
    runner.apply(ui::Sync{});  // changes nothing: not recorded
    auto stiffer = std::make_shared<core::SceneDesc>(*runner.scene());
    for (core::SpringDesc &spring : stiffer->springs)
        spring.stiffness *= 1.5;
    runner.apply(ui::SetSceneEdit{stiffer, ui::SceneChange::Parameters});
    runner.advance(0.05, kNoBudgetLimit);
    runner.apply(ui::StepOnce{});
    runner.apply(ui::Play{});
    auto added = std::make_shared<core::SceneDesc>(*runner.scene());
    core::ParticleDesc extra;
    extra.position = {0.0, 2.0, 0.0};
    added->particles.push_back(extra);
    added->springs.push_back({0, int(added->particles.size()) - 1, 50.0, 0.5, 1.0});
    runner.apply(ui::SetSceneEdit{added, ui::SceneChange::Structure});
    runner.advance(0.06, kNoBudgetLimit);
    // far too stiff for the step: the tick blows up and the runner goes back to its start
    auto wild = std::make_shared<core::SceneDesc>(*runner.scene());
    for (core::SpringDesc &spring : wild->springs)
        spring.stiffness = 1e9;
    runner.apply(ui::SetSceneEdit{wild, ui::SceneChange::Parameters});
    const std::uint64_t before = runner.stepsTaken();
    runner.advance(0.05, kNoBudgetLimit);
    if (runner.isRunning() || runner.stepsTaken() != before)
        qWarning("the wild tick did not blow up");
    runner.takeBlowupMessage();
    runner.apply(ui::SetSceneEdit{added, ui::SceneChange::Parameters});
    runner.apply(ui::Play{});
    runner.advance(0.04, kNoBudgetLimit);
    runner.apply(ui::Reset{});
    runner.advance(0.03, kNoBudgetLimit);
    runner.apply(ui::StopRecording{1});
    runner.advance(0.05, kNoBudgetLimit);  // after the end: not part of it
    return stoppedRecording(runner, request);
}

}  // namespace

class TestSessionRecording : public QObject {
    Q_OBJECT

private slots:
    void replayEndsWithTheRecordedBits();
    void replayThroughAFileToo();
    void aRecordingChangedByOneStepNoLongerMatches();
    void damagedFilesAreRefusedWithTheirPath();
    void indexIntoAnEmptySceneIsNamed();
    void nothingIsRecordedWithoutAStart();
    void replayAfterSpringsBroke();
    void damagedBreaksAreRefused();
    void damagedContactImpulsesAreRefused();
    void negativeZeroKeepsItsSign();
    void endlessFileIsRefused();
};

void TestSessionRecording::replayEndsWithTheRecordedBits()
{
    ui::SimulationRunner runner;
    std::uint64_t request = 0;
    const auto recording = recordSession(runner, &request);
    QVERIFY(recording);
    QCOMPARE(request, std::uint64_t(1));
    QVERIFY(!runner.isRecording());
    // every kind of edit is in it, Sync is not; the steering held from before starts it
    QCOMPARE(recording->entries.size(), std::size_t(14));
    QVERIFY(std::holds_alternative<ui::SteerEdit>(recording->entries.front().message));
    QVERIFY(std::any_of(recording->entries.begin(), recording->entries.end(), [](const auto &entry) {
        return std::holds_alternative<ui::StrikeEdit>(entry.message);
    }));
    // the net turns, so the strike's spin is part of the run replayed
    QVERIFY(runnerWith(netScene()).state().angularVelocity.cols() > 0);
    QCOMPARE(recording->entries.front().steps, std::uint64_t(0));
    for (const auto &entry : recording->entries)
        QVERIFY(!std::holds_alternative<ui::Sync>(entry.message));
    QVERIFY(recording->steps > 50);
    QVERIFY(recording->start.time > 0.0);  // it started mid-run

    const ui::ReplayResult replayed = ui::replay(*recording);
    QVERIFY2(replayed.error.empty(), replayed.error.c_str());
    QCOMPARE(replayed.hash, recording->finalHash);
    QVERIFY(replayed.hash != 0);
}

void TestSessionRecording::replayThroughAFileToo()
{
    ui::SimulationRunner runner;
    const auto recording = recordSession(runner);
    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("session.replay.json"));
    QCOMPARE(ui::saveRecording(path, *recording), QString());
    const ui::RecordingLoad loaded = ui::loadRecording(path);
    QVERIFY2(loaded.recording, qPrintable(loaded.error));
    QCOMPARE(loaded.recording->entries.size(), recording->entries.size());
    QCOMPARE(loaded.recording->steps, recording->steps);
    QVERIFY(loaded.recording->start.position.cwiseEqual(recording->start.position).all());
    QVERIFY(loaded.recording->start.velocity.cwiseEqual(recording->start.velocity).all());
    QVERIFY(*loaded.recording->scene == *recording->scene);
    // writing what was read gives the same bytes
    QCOMPARE(ui::recordingToJson(*loaded.recording), ui::recordingToJson(*recording));
    const ui::ReplayResult replayed = ui::replay(*loaded.recording);
    QVERIFY2(replayed.error.empty(), replayed.error.c_str());
    QCOMPARE(replayed.hash, recording->finalHash);
}

void TestSessionRecording::aRecordingChangedByOneStepNoLongerMatches()
{
    ui::SimulationRunner runner;
    auto changed = std::make_shared<ui::SessionRecording>(*recordSession(runner));
    // the reset, the last edit, one step later
    QVERIFY(std::holds_alternative<ui::Reset>(changed->entries.back().message));
    changed->entries.back().steps += 1;
    const ui::ReplayResult replayed = ui::replay(*changed);
    QVERIFY2(replayed.error.empty(), replayed.error.c_str());
    QVERIFY(replayed.hash != changed->finalHash);
}

void TestSessionRecording::damagedFilesAreRefusedWithTheirPath()
{
    ui::SimulationRunner runner;
    const QByteArray good = ui::recordingToJson(*recordSession(runner));
    const auto refused = [](QByteArray json, const char *expected) {
        const ui::RecordingLoad loaded = ui::parseRecording(json, QStringLiteral("s.json"));
        if (loaded.recording || !loaded.error.startsWith(QStringLiteral("s.json: ")) ||
            !loaded.error.contains(QString::fromUtf8(expected))) {
            qWarning("%s", qPrintable(loaded.error));
            return false;
        }
        return true;
    };
    QVERIFY(refused(good.left(good.size() / 2), "the file ends too early: is it truncated?"));
    QVERIFY(refused(QByteArray(), "the file is empty"));
    QVERIFY(refused(QByteArray(good).replace("\"version\": 1", "\"version\": 1.5"), "version 1.5 is not supported"));
    QVERIFY(refused(QByteArray(good).replace("springlab-replay", "springlab-scene"), "not a Springlab replay"));
    QVERIFY(refused(QByteArray(good).replace("\"edit\": \"tilt\"", "\"edit\": \"twist\""), "unknown edit \"twist\""));
    QVERIFY(refused(QByteArray(good).replace("\"particle\": 7", "\"particle\": 700"), "expected -1 or a particle"));
    QVERIFY(refused(QByteArray(good).replace("\"hash\": \"", "\"hash\": \"zz"), "hash"));
    QVERIFY(refused(QByteArray(good).replace("\"positions\": [", "\"positions\": [1, "), "start.positions"));
}

void TestSessionRecording::indexIntoAnEmptySceneIsNamed()
{
    // a scene with no particles: the range "(0 to -1)" (or 2^64 - 1) would mean nothing
    auto empty = std::make_shared<core::SceneDesc>();
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{empty, ui::SceneChange::Replace});
    runner.apply(ui::StartRecording{});
    runner.apply(ui::SteerEdit{-1, Eigen::Vector3d::Zero()});
    runner.apply(ui::StopRecording{1});
    const auto recording = stoppedRecording(runner);
    QVERIFY(recording);
    const QByteArray json = ui::recordingToJson(*recording);
    QVERIFY(json.contains("\"particle\": -1"));
    const ui::RecordingLoad loaded = ui::parseRecording(QByteArray(json).replace("\"particle\": -1", "\"particle\": 3"),
                                                        QStringLiteral("s.json"));
    QVERIFY(!loaded.recording);
    QVERIFY2(loaded.error.contains(QStringLiteral("expected -1: the scene has no particles")), qPrintable(loaded.error));

    // and a break of a spring in a scene with none: no range "(0 to -1)" either
    QVERIFY(json.contains("\"positions\": "));
    const ui::RecordingLoad broken = ui::parseRecording(
        QByteArray(json).replace("\"positions\": ", "\"breaks\": [{\"spring\": 0, \"step\": 1, \"time\": 0}], \"positions\": "),
        QStringLiteral("s.json"));
    QVERIFY(!broken.recording);
    QVERIFY2(broken.error.contains(QStringLiteral(".spring: expected a spring of the scene, which has none")),
             qPrintable(broken.error));
}

void TestSessionRecording::nothingIsRecordedWithoutAStart()
{
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{netScene(), ui::SceneChange::Replace});
    runner.apply(ui::Play{});
    runner.advance(0.05, kNoBudgetLimit);
    runner.apply(ui::StopRecording{5});
    std::uint64_t request = 0;
    QVERIFY(!stoppedRecording(runner, &request));
    QCOMPARE(request, std::uint64_t(5));
}

// the tearable cloth run past its first break, then 50 steps recorded
std::shared_ptr<const ui::SessionRecording> recordAfterABreak(ui::SimulationRunner &runner)
{
    const io::LoadResult loaded = io::loadScene(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/tearable-cloth.json"));
    if (!loaded.ok())
        return nullptr;
    auto scene = std::make_shared<const core::SceneDesc>(*loaded.scene);
    runner.apply(ui::SetSceneEdit{scene, ui::SceneChange::Replace});
    runner.apply(ui::Play{});
    const double h = scene->settings.timeStep;
    // after the first break, and at a step where a contact carries an impulse to the next (the
    // ball on the floor: at a step where it bounces there is none to carry)
    for (int tick = 0; tick < 2000 && (runner.state().breaks.empty() || runner.state().contactImpulses.empty()); ++tick)
        runner.advance(h, kNoBudgetLimit);
    if (runner.state().breaks.empty() || runner.state().contactImpulses.empty())
        return nullptr;
    runner.apply(ui::StartRecording{});
    const std::uint64_t from = runner.stepsTaken();
    while (runner.stepsTaken() < from + 50)
        runner.advance(h, kNoBudgetLimit);
    runner.apply(ui::StopRecording{1});
    return stoppedRecording(runner);
}

// a recording that starts after springs have broken carries them: its replay, from memory and
// through a file, ends with the recorded bits and the same springs broken (it used to start with
// every spring whole, and the replay went astray)
void TestSessionRecording::replayAfterSpringsBroke()
{
    ui::SimulationRunner runner;
    const auto recording = recordAfterABreak(runner);
    QVERIFY(recording);
    QCOMPARE(recording->steps, std::uint64_t(50));
    QVERIFY(!recording->start.breaks.empty());
    QCOMPARE(recording->start.springBroken.size(), recording->scene->springs.size());

    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("torn.replay.json"));
    QCOMPARE(ui::saveRecording(path, *recording), QString());
    const ui::RecordingLoad loaded = ui::loadRecording(path);
    QVERIFY2(loaded.recording, qPrintable(loaded.error));
    QVERIFY(loaded.recording->start.springBroken == recording->start.springBroken);
    QVERIFY(loaded.recording->start.breaks == recording->start.breaks);
    for (const ui::SessionRecording *r : {recording.get(), loaded.recording.get()}) {
        const ui::ReplayResult replayed = ui::replay(*r);
        QVERIFY2(replayed.error.empty(), replayed.error.c_str());
        QCOMPARE(replayed.hash, recording->finalHash);
        QVERIFY(replayed.state.springBroken == runner.state().springBroken);
        QVERIFY(replayed.state.breaks == runner.state().breaks);
    }
}

void TestSessionRecording::damagedBreaksAreRefused()
{
    ui::SimulationRunner runner;
    const auto recording = recordAfterABreak(runner);
    QVERIFY(recording);
    const QByteArray good = ui::recordingToJson(*recording);
    const int spring = recording->start.breaks.front().spring;
    const QByteArray entry = "{\"spring\": " + QByteArray::number(spring) + ",";
    QVERIFY(good.contains(entry));
    const auto error = [&](const QByteArray &json) {
        return ui::parseRecording(json, QStringLiteral("s.json")).error;
    };
    const QString beyond = error(QByteArray(good).replace(entry, "{\"spring\": 99999,"));
    QVERIFY2(beyond.contains(QStringLiteral("start.breaks[0].spring: expected a spring of the scene")), qPrintable(beyond));
    const QString twice = error(QByteArray(good).replace("\"breaks\": [", "\"breaks\": [" + entry + " \"step\": 1, \"time\": 0}, "));
    QVERIFY2(twice.contains(QStringLiteral("broke twice")), qPrintable(twice));
}

void TestSessionRecording::damagedContactImpulsesAreRefused()
{
    // the start state's contact impulses (the net rests on the floor) get the scene file's checks
    // and messages, with their path
    ui::SimulationRunner runner;
    const auto recording = recordAfterABreak(runner);
    QVERIFY(recording);
    QVERIFY(!recording->start.contactImpulses.empty());
    const QByteArray good = ui::recordingToJson(*recording);
    const QByteArray list = "\"contactImpulses\": [";
    QCOMPARE(good.count(list), qsizetype(1));
    const auto error = [&](const QByteArray &first) {
        return ui::parseRecording(QByteArray(good).replace(list, list + first + ", "), QStringLiteral("s.json")).error;
    };
    const QString plane = error("[0, -99, 0.1, 0, 0, 0]");
    QVERIFY2(plane.contains(QStringLiteral("start.contactImpulses[0].plane: plane index 98 is out of range")),
             qPrintable(plane));
    const QString pulls = error("[0, 1, -0.1, 0, 0, 0]");
    QVERIFY2(pulls.contains(QStringLiteral("start.contactImpulses[0].normal: must be from 0")), qPrintable(pulls));
    const QString half = error("[0.5, 1, 0.1, 0, 0, 0]");
    QVERIFY2(half.contains(QStringLiteral("start.contactImpulses[0][0]: expected a particle or plane index")),
             qPrintable(half));
}

void TestSessionRecording::negativeZeroKeepsItsSign()
{
    // a pinned particle at x = -0 keeps that bit to the end, so the recorded hash holds it: read
    // back as +0 (Qt's parser), the replay would end with other bits than the recorded run
    auto scene = std::make_shared<core::SceneDesc>(*netScene());
    core::ParticleDesc post;
    post.position = {-0.0, 1.5, -0.0};
    post.pinned = true;
    scene->particles.push_back(post);
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{scene, ui::SceneChange::Replace});
    runner.apply(ui::StartRecording{});
    runner.apply(ui::Play{});
    runner.advance(0.05, kNoBudgetLimit);
    runner.apply(ui::StopRecording{1});
    const auto recording = stoppedRecording(runner);
    QVERIFY(recording);
    QVERIFY(std::signbit(recording->start.position(0, Eigen::Index(scene->particles.size()) - 1)));

    QTemporaryDir folder;
    const QString path = folder.filePath(QStringLiteral("zero.replay.json"));
    QCOMPARE(ui::saveRecording(path, *recording), QString());
    const ui::RecordingLoad loaded = ui::loadRecording(path);
    QVERIFY2(loaded.recording, qPrintable(loaded.error));
    QVERIFY(std::signbit(loaded.recording->start.position(0, Eigen::Index(scene->particles.size()) - 1)));
    const ui::ReplayResult replayed = ui::replay(*loaded.recording);
    QVERIFY2(replayed.error.empty(), replayed.error.c_str());
    QCOMPARE(replayed.hash, recording->finalHash);
}

void TestSessionRecording::endlessFileIsRefused()
{
    // a device that never ends is read only up to the limit, and refused with the scene files' message
    if (!QFile::exists(QStringLiteral("/dev/zero")))
        QSKIP("no /dev/zero here");
    const ui::RecordingLoad loaded = ui::loadRecording(QStringLiteral("/dev/zero"), 1000);
    QVERIFY(!loaded.recording);
    QCOMPARE(loaded.error, QStringLiteral("/dev/zero: the file is too large: more than the limit of 1000 bytes"));
}

QTEST_APPLESS_MAIN(TestSessionRecording)
#include "test_session_recording.moc"
