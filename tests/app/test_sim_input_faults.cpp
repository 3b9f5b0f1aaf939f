// springlab-sim end to end, through QProcess, on input and output that is not what it should be
// (issue 37): a device with no end, a recording too large for the memory the process may use,
// text in another encoding, a cut file over 16 MiB, an --output where no temporary file can be
// made or on a read-only file system. Each is a message and exit 2, never an abort (134).

#include "core/io/scene_file.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "sim_run.h"
#include "session/session_file.h"
#include "session/session_recording.h"
#include "tests/spring_pair.h"
#include "tests/test_files.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QStringEncoder>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

namespace {

using test::encoded;
using test::sim;
using test::writeAll;

using Run = test::ProgramRun;

// springlab-sim under an address-space limit in KiB, as `ulimit -v` sets it
Run simWithin(int kib, const QStringList &arguments)
{
    return test::runProgram(u"/bin/sh"_s,
                            QStringList{u"-c"_s, u"ulimit -v %1 && exec \"$0\" \"$@\""_s.arg(kib),
                                        QStringLiteral(SPRINGLAB_SIM)} +
                                arguments,
                            120000);
}

QString said(const Run &run)
{
    return u"exit %1: %2"_s.arg(run.exitCode).arg(QString::fromUtf8(run.err));
}

// a particle as a scene file holds it, one to a line
const QByteArray kParticle =
    R"({"position": [0.125, 1.5, -2.25], "velocity": [0, 0, 0], "mass": 1, "radius": 0.1, "pinned": false})";

// a scene of that many particles, written line by line
bool writeLargeScene(const QString &path, int particles, bool whole)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return false;
    file.write(R"({"format": "springlab-scene", "version": 1, "name": "many", "particles": [)");
    for (int i = 0; i < particles; ++i)
        file.write((i ? ",\n" : "\n") + kParticle);
    if (whole)
        file.write("], \"springs\": [], \"planes\": []}\n");
    return file.flush();
}

// a recording of a scene of that many particles, as recordingToJson() writes one, line by line:
// the scene's text (a JSON string), the start state, no edits
bool writeLargeRecording(const QString &path, int particles)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return false;
    QByteArray escaped = kParticle;
    escaped.replace("\"", "\\\"");
    file.write("{\n    \"format\": \"springlab-replay\",\n    \"version\": 1,\n    \"scene\": \"{\\n    \\\"format\\\": "
               "\\\"springlab-scene\\\",\\n    \\\"version\\\": 1,\\n    \\\"name\\\": \\\"many\\\",\\n    "
               "\\\"particles\\\": [");
    for (int i = 0; i < particles; ++i)
        file.write((i ? ",\\n        " : "\\n        ") + escaped);
    file.write("\\n    ],\\n    \\\"springs\\\": [],\\n    \\\"planes\\\": []\\n}\\n\",\n    \"start\": {\"time\": 0, "
               "\"step\": 0, \"adaptiveStep\": 0,\n        \"positions\": [");
    for (int i = 0; i < particles; ++i)
        file.write(i ? ", 0.125, 1.5, -2.25" : "0.125, 1.5, -2.25");
    file.write("],\n        \"velocities\": [");
    for (int i = 0; i < particles; ++i)
        file.write(i ? ", 0, 0, 0" : "0, 0, 0");
    file.write("]},\n    \"edits\": [],\n    \"steps\": 0,\n    \"hash\": \"0000000000000000\"\n}\n");
    return file.flush();
}

}  // namespace

class TestSimInputFaults : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void endlessDeviceIsRefused_data();
    void endlessDeviceIsRefused();
    void largeReplayWithinALimitIsAMessage();
    void sceneWithinALimitNamesIt();
    void otherEncodingsAreNamed_data();
    void otherEncodingsAreNamed();
    void utf8ByteOrderMarkReplays();
    void largeCutSceneEndsTooEarly();
    void outputWhereNoTemporaryFileCanBeMade();
    void outputOnAReadOnlyMount_data();
    void outputOnAReadOnlyMount();

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }

    QTemporaryDir m_dir;
};

void TestSimInputFaults::initTestCase()
{
    QVERIFY(QFileInfo(QStringLiteral(SPRINGLAB_SIM)).isExecutable());
    QVERIFY(m_dir.isValid());
    QVERIFY(io::saveScene(path(u"pair.json"_s), test::springPairScene()).ok());
    QCOMPARE(ui::saveRecording(path(u"pair.replay.json"_s), test::playedRecording(test::springPairScene(), 20)), QString());
}

void TestSimInputFaults::endlessDeviceIsRefused_data()
{
    QTest::addColumn<bool>("replay");
    QTest::addColumn<int>("kib");  // the address-space limit; 0: none
    for (const bool replay : {true, false})
        for (const int kib : {0, 3000000, 1500000, 500000})
            QTest::newRow(qPrintable(u"%1, %2"_s.arg(replay ? u"--replay"_s : u"scene"_s)
                                         .arg(kib ? u"ulimit -v %1"_s.arg(kib) : u"no limit"_s)))
                << replay << kib;
}

void TestSimInputFaults::endlessDeviceIsRefused()
{
    // /dev/zero has no size and never ends: a replay of it read on until std::bad_alloc (134),
    // the scene loader until its limit or the memory ran out. Both stop at its first zero byte.
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    QSKIP("the sanitizers reserve terabytes of address space: ulimit -v cannot be set under them");
#endif
    QFETCH(bool, replay);
    QFETCH(int, kib);
    if (!QFile::exists(u"/dev/zero"_s))
        QSKIP("no /dev/zero here");
    const QStringList arguments = replay ? QStringList{u"--replay"_s, u"/dev/zero"_s} : QStringList{u"/dev/zero"_s};
    const Run run = kib ? simWithin(kib, arguments) : sim(arguments);
    QVERIFY2(run.exitCode == 2, qPrintable(said(run)));
    QVERIFY2(QString::fromUtf8(run.err).contains(
                 u"/dev/zero: not a text file (byte 0 is a zero byte): a Springlab file is JSON text in UTF-8"_s),
             qPrintable(said(run)));
}

void TestSimInputFaults::largeReplayWithinALimitIsAMessage()
{
    // a recording of 2 000 000 particles (about 300 MB) under a 600 MB address space: a load that
    // needs more than the limit says so, naming it; it ended in std::bad_alloc (134)
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    QSKIP("the sanitizers reserve terabytes of address space: ulimit -v cannot be set under them");
#endif
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString recording = dir.filePath(u"big.replay.json"_s);
    QVERIFY(writeLargeRecording(recording, 2000000));
    QVERIFY(QFileInfo(recording).size() > 290'000'000);
    const Run run = simWithin(600000, {u"--replay"_s, recording, u"--quiet"_s});
    QFile::remove(recording);
    // it may load one day in that space; it may never abort
    QVERIFY2(run.exitCode == 2 || run.exitCode == 4, qPrintable(said(run)));
    if (run.exitCode == 2)
        QVERIFY2(QString::fromUtf8(run.err).contains(
                     recording + u": cannot load: out of memory: reading it needs more memory than this process may "
                                 "use (its address space is limited to 585.9 MiB: see ulimit -v)"_s),
                 qPrintable(said(run)));
}

void TestSimInputFaults::sceneWithinALimitNamesIt()
{
    // a scene of 1 200 000 particles (120 MB) under a 200 MB address space: it said "more memory
    // than is free" with gigabytes free; the limit is the process's, and the message names it as
    // the step's does ("see ulimit -v")
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    QSKIP("the sanitizers reserve terabytes of address space: ulimit -v cannot be set under them");
#endif
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString scene = dir.filePath(u"big.json"_s);
    QVERIFY(writeLargeScene(scene, 1200000, true));
    const Run run = simWithin(200000, {scene, u"--steps"_s, u"1"_s, u"--quiet"_s});
    QFile::remove(scene);
    QVERIFY2(run.exitCode == 2, qPrintable(said(run)));
    const QString expected = QDir::toNativeSeparators(scene) +
                             u": cannot load: out of memory: reading it needs more memory than this process may use "
                             "(its address space is limited to 195.3 MiB: see ulimit -v)"_s;
    QVERIFY2(QString::fromUtf8(run.err).contains(expected), qPrintable(said(run)));
}

void TestSimInputFaults::otherEncodingsAreNamed_data()
{
    QTest::addColumn<bool>("replay");
    QTest::addColumn<int>("encoding");  // QStringConverter::Encoding
    QTest::addColumn<QString>("reason");
    using E = QStringConverter::Encoding;
    for (const bool replay : {false, true}) {
        const QString kind = replay ? u"--replay, "_s : u"scene, "_s;
        QTest::newRow(qPrintable(kind + u"UTF-16 FF FE"_s))
            << replay << int(E::Utf16LE)
            << u"the file is UTF-16 text (it starts with the byte order mark FF FE): save it as UTF-8"_s;
        QTest::newRow(qPrintable(kind + u"UTF-16 FE FF"_s))
            << replay << int(E::Utf16BE)
            << u"the file is UTF-16 text (it starts with the byte order mark FE FF): save it as UTF-8"_s;
        QTest::newRow(qPrintable(kind + u"UTF-32 FF FE 00 00"_s))
            << replay << int(E::Utf32LE)
            << u"the file is UTF-32 text (it starts with the byte order mark FF FE 00 00): save it as UTF-8"_s;
        QTest::newRow(qPrintable(kind + u"UTF-32 00 00 FE FF"_s))
            << replay << int(E::Utf32BE)
            << u"the file is UTF-32 text (it starts with the byte order mark 00 00 FE FF): save it as UTF-8"_s;
    }
}

void TestSimInputFaults::otherEncodingsAreNamed()
{
    // "illegal value at byte 1" was all a UTF-16 file got
    QFETCH(bool, replay);
    QFETCH(int, encoding);
    QFETCH(QString, reason);
    QFile source(path(replay ? u"pair.replay.json"_s : u"pair.json"_s));
    QVERIFY(source.open(QIODevice::ReadOnly));
    const QString file = path(u"encoded.json"_s);
    QVERIFY(writeAll(file, encoded(source.readAll(), static_cast<QStringConverter::Encoding>(encoding), true)));
    const Run run = sim(replay ? QStringList{u"--replay"_s, file} : QStringList{file, u"--steps"_s, u"1"_s});
    QVERIFY2(run.exitCode == 2, qPrintable(said(run)));
    QVERIFY2(QString::fromUtf8(run.err).contains(QDir::toNativeSeparators(file) + u": "_s + reason), qPrintable(said(run)));
}

void TestSimInputFaults::utf8ByteOrderMarkReplays()
{
    // UTF-8 with a byte order mark is UTF-8: the scene runs and the recording replays to its bits
    for (const QString &name : {u"pair.json"_s, u"pair.replay.json"_s}) {
        QFile source(path(name));
        QVERIFY(source.open(QIODevice::ReadOnly));
        QVERIFY(writeAll(path(u"marked-"_s + name), "\xEF\xBB\xBF" + source.readAll()));
    }
    const Run scene = sim({path(u"marked-pair.json"_s), u"--steps"_s, u"5"_s, u"--quiet"_s});
    QVERIFY2(scene.exitCode == 0, qPrintable(said(scene)));
    const Run replayed = sim({u"--replay"_s, path(u"marked-pair.replay.json"_s)});
    QVERIFY2(replayed.exitCode == 0, qPrintable(said(replayed)));
    QVERIFY2(replayed.out.contains(", as recorded"), replayed.out.constData());
}

void TestSimInputFaults::largeCutSceneEndsTooEarly()
{
    // cut after its 250 000th particle (25 MB, over 16 MiB): it said "not valid JSON (a fault in
    // the text at byte N)" with N the end of the file; a small file so cut says it ends too early
    const QString cut = path(u"cut.json"_s);
    QVERIFY(writeLargeScene(cut, 250000, false));
    QVERIFY(QFileInfo(cut).size() > (qint64(16) << 20));
    const Run run = sim({cut});
    QFile::remove(cut);
    QVERIFY2(run.exitCode == 2, qPrintable(said(run)));
    QVERIFY2(QString::fromUtf8(run.err).contains(QDir::toNativeSeparators(cut) +
                                                 u": particles[249999]: the file ends too early: is it truncated?"_s),
             qPrintable(said(run)));
}

void TestSimInputFaults::outputWhereNoTemporaryFileCanBeMade()
{
    // /proc takes no new files: as root /proc/version looks writable, and the save failed at the
    // temporary file beside it, which "No such file or directory" did not say
    if (!QFileInfo(u"/proc/version"_s).isWritable())
        QSKIP("/proc/version is read-only to this user: the file itself is refused first");
    const Run run = sim({path(u"pair.json"_s), u"--steps"_s, u"2"_s, u"--quiet"_s, u"--output"_s, u"/proc/version"_s});
    QVERIFY2(run.exitCode == 2, qPrintable(said(run)));
    QVERIFY2(QString::fromUtf8(run.err).contains(u"/proc/version: cannot save: cannot create the temporary file beside "
                                                 "it in /proc (a save writes one there, then renames it over the file): "_s),
             qPrintable(said(run)));
}

void TestSimInputFaults::outputOnAReadOnlyMount_data()
{
    QTest::addColumn<bool>("existing");  // an old file is there
    QTest::newRow("new file") << false;
    QTest::newRow("existing file") << true;
}

void TestSimInputFaults::outputOnAReadOnlyMount()
{
    // a folder mounted read-only (a file system of its own in a mount namespace of the run's own,
    // where unshare may make one): the file was said to be read-only, as if a permission were to blame
    QFETCH(bool, existing);
    if (QStandardPaths::findExecutable(u"unshare"_s).isEmpty())
        QSKIP("no unshare here");
    const QString folder = path(u"mounted"_s);
    QVERIFY(QDir().mkpath(folder));
    const QString output = QDir(folder).filePath(u"out.json"_s);
    // 77: the mount could not be made (no user namespaces here, say)
    const QString mount = existing ? u"mount -t tmpfs tmpfs \"$1\" && echo old > \"$1/out.json\" && "
                                     "mount -o remount,ro \"$1\""_s
                                   : u"mount -t tmpfs -o ro tmpfs \"$1\""_s;
    const Run run = test::runProgram(
        u"unshare"_s,
        {u"--user"_s, u"--map-root-user"_s, u"--mount"_s, u"/bin/sh"_s, u"-c"_s,
         u"("_s + mount + u") 2>/dev/null || exit 77; shift; exec \"$@\""_s, u"sh"_s, folder, QStringLiteral(SPRINGLAB_SIM),
         path(u"pair.json"_s), u"--steps"_s, u"2"_s, u"--quiet"_s, u"--output"_s, output},
        120000);
    if (run.exitCode == 77 || (run.exitCode == 1 && run.err.contains("unshare")))
        QSKIP("a read-only mount cannot be made here");
    QVERIFY2(run.exitCode == 2, qPrintable(said(run)));
    QVERIFY2(QString::fromUtf8(run.err).contains(QDir::toNativeSeparators(output) + u": cannot save: read-only file system: "_s +
                                                 QDir::toNativeSeparators(folder) + u" is on a file system mounted read-only"_s),
             qPrintable(said(run)));
}

QTEST_GUILESS_MAIN(TestSimInputFaults)
#include "test_sim_input_faults.moc"
