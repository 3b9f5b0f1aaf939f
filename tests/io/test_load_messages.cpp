// What a load says when a file is not what it should be, for scenes and recordings alike: text in
// another encoding (UTF-16, UTF-32) or no text at all (a zero byte, /dev/zero) is named as such,
// a cut file says it ends too early whatever its size, running out of memory names the process's
// limit, and a save that fails names the read-only file system or the temporary file it could not
// make (issue 37).

#include "core/io/json_pull.h"
#include "core/io/load_checks.h"
#include "core/io/safe_write.h"
#include "core/io/scene_file.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "session/session_file.h"
#include "tests/address_space_cap.h"
#include "tests/spring_pair.h"
#include "tests/test_files.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QStringEncoder>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <system_error>

#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

using namespace Qt::Literals::StringLiterals;

namespace {

using test::encoded;
using test::readAll;
using test::writeAll;

// a scene of many particles, its text over the 16 MiB past which a syntax error's place is the
// reader's own rather than QJsonDocument's
QByteArray largeSceneText(int particles)
{
    QByteArray json = R"({"format": "springlab-scene", "version": 1, "name": "many", "particles": [)";
    json += QByteArray(R"({"position": [0.125, 1.5, -2.25], "velocity": [0, 0, 0], "mass": 1, "radius": 0.1},)"
                       "\n")
                .repeated(particles - 1);
    json += R"({"position": [0, 0, 0], "mass": 1, "radius": 0.1}], "springs": [], "planes": []})"
            "\n";
    return json;
}

// whether the process has no limit a shell's ulimit could set on its memory
bool memoryUnlimited()
{
    rlimit as{};
    rlimit data{};
    return getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur == RLIM_INFINITY && getrlimit(RLIMIT_DATA, &data) == 0 &&
           data.rlim_cur == RLIM_INFINITY;
}

const QString kNotText = u"not a text file (byte %1 is a zero byte): a Springlab file is JSON text in UTF-8"_s;
const QString kTooEarly = u"the file ends too early: is it truncated?"_s;

}  // namespace

class TestLoadMessages : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void otherEncodingsAreNamed_data();
    void otherEncodingsAreNamed();
    void utf8ByteOrderMarkIsRead();
    void zeroByteIsNotText_data();
    void zeroByteIsNotText();
    void endlessDeviceStopsAtItsFirstZero();
    void cutTextEndsTooEarlyAtAnySize_data();
    void cutTextEndsTooEarlyAtAnySize();
    void largeCutRecordingEndsTooEarly();
    void deepRecordingIsRefusedUnread();
    void recordingKeysAndEscapesAreCheckedAsAScenes();
    void checkedStringsReadAsQtReadsThem_data();
    void checkedStringsReadAsQtReadsThem();
    void outOfMemoryNamesTheProcessLimit();
    void memoryShortfallWithoutALimit();
    void readOnlyFileSystemIsNamed();
    void failedTemporaryFileIsNamed();
};

void TestLoadMessages::initTestCase()
{
    // large blocks always get their own mapping, given back when freed: the memory a cap is set
    // over (tests/address_space_cap.h) is then the memory in use, not what the heap kept of the
    // test's earlier large texts
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 1 << 17);
#endif
}

void TestLoadMessages::otherEncodingsAreNamed_data()
{
    QTest::addColumn<int>("encoding");  // QStringConverter::Encoding
    QTest::addColumn<bool>("mark");
    QTest::addColumn<QString>("reason");
    using E = QStringConverter::Encoding;
    QTest::newRow("UTF-16 little-endian, marked")
        << int(E::Utf16LE) << true << u"the file is UTF-16 text (it starts with the byte order mark FF FE): save it as UTF-8"_s;
    QTest::newRow("UTF-16 big-endian, marked")
        << int(E::Utf16BE) << true << u"the file is UTF-16 text (it starts with the byte order mark FE FF): save it as UTF-8"_s;
    QTest::newRow("UTF-32 little-endian, marked")
        << int(E::Utf32LE) << true
        << u"the file is UTF-32 text (it starts with the byte order mark FF FE 00 00): save it as UTF-8"_s;
    QTest::newRow("UTF-32 big-endian, marked")
        << int(E::Utf32BE) << true
        << u"the file is UTF-32 text (it starts with the byte order mark 00 00 FE FF): save it as UTF-8"_s;
    QTest::newRow("UTF-16 little-endian")
        << int(E::Utf16LE) << false
        << u"the file looks like UTF-16 text (little-endian, with no byte order mark): save it as UTF-8"_s;
    QTest::newRow("UTF-16 big-endian")
        << int(E::Utf16BE) << false
        << u"the file looks like UTF-16 text (big-endian, with no byte order mark): save it as UTF-8"_s;
    QTest::newRow("UTF-32 little-endian")
        << int(E::Utf32LE) << false
        << u"the file looks like UTF-32 text (little-endian, with no byte order mark): save it as UTF-8"_s;
}

void TestLoadMessages::otherEncodingsAreNamed()
{
    QFETCH(int, encoding);
    QFETCH(bool, mark);
    QFETCH(QString, reason);
    const auto as = static_cast<QStringConverter::Encoding>(encoding);
    const core::SceneDesc scene = test::springPairScene();
    const QByteArray sceneText = encoded(io::sceneToJson(scene), as, mark);
    const QByteArray recordingText = encoded(ui::recordingToJson(test::playedRecording(scene, 10)), as, mark);

    // from memory: Qt's "illegal value at byte 1" was all it said
    QCOMPARE(io::parseScene(sceneText, u"s.json"_s).error, u"s.json: "_s + reason);
    QCOMPARE(ui::parseRecording(recordingText, u"r.json"_s).error, u"r.json: "_s + reason);

    // and from files
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString scenePath = dir.filePath(u"scene.json"_s);
    const QString recordingPath = dir.filePath(u"session.replay.json"_s);
    QVERIFY(writeAll(scenePath, sceneText));
    QVERIFY(writeAll(recordingPath, recordingText));
    QCOMPARE(io::loadScene(scenePath).error, QDir::toNativeSeparators(scenePath) + u": "_s + reason);
    QCOMPARE(ui::loadRecording(recordingPath).error, recordingPath + u": "_s + reason);
}

void TestLoadMessages::utf8ByteOrderMarkIsRead()
{
    // UTF-8 with a byte order mark is UTF-8: both kinds of file read as without it
    const core::SceneDesc scene = test::springPairScene();
    const QByteArray mark = "\xEF\xBB\xBF";
    const io::LoadResult loaded = io::parseScene(mark + io::sceneToJson(scene), u"s.json"_s);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    QVERIFY(*loaded.scene == scene);

    const ui::SessionRecording recording = test::playedRecording(scene, 10);
    const ui::RecordingLoad read = ui::parseRecording(mark + ui::recordingToJson(recording), u"r.json"_s);
    QVERIFY2(read.recording, qPrintable(read.error));
    QVERIFY(*read.recording->scene == scene);
    QCOMPARE(ui::recordingToJson(*read.recording), ui::recordingToJson(recording));
}

void TestLoadMessages::zeroByteIsNotText_data()
{
    QTest::addColumn<int>("at");  // where the zero byte goes, counted from the end when negative
    QTest::newRow("first byte") << 0;
    QTest::newRow("in a string") << 50;
    QTest::newRow("last byte") << -1;
}

void TestLoadMessages::zeroByteIsNotText()
{
    QFETCH(int, at);
    const core::SceneDesc scene = test::springPairScene();
    QByteArray sceneText = io::sceneToJson(scene);
    QByteArray recordingText = ui::recordingToJson(test::playedRecording(scene, 10));
    const qsizetype sceneOffset = at >= 0 ? at : sceneText.size() + at;
    const qsizetype recordingOffset = at >= 0 ? at : recordingText.size() + at;
    sceneText[sceneOffset] = '\0';
    recordingText[recordingOffset] = '\0';
    QCOMPARE(io::parseScene(sceneText, u"s.json"_s).error, u"s.json: "_s + kNotText.arg(sceneOffset));
    QCOMPARE(ui::parseRecording(recordingText, u"r.json"_s).error, u"r.json: "_s + kNotText.arg(recordingOffset));
}

void TestLoadMessages::endlessDeviceStopsAtItsFirstZero()
{
    // /dev/zero has no size and no end: read in pieces, it stops at the first, which holds zero
    // bytes, well before the limit of 1 GiB (which it took gigabytes of memory to reach)
    if (!QFile::exists(u"/dev/zero"_s))
        QSKIP("no /dev/zero here");
    QCOMPARE(io::loadScene(u"/dev/zero"_s).error, u"/dev/zero: "_s + kNotText.arg(0));
    QCOMPARE(ui::loadRecording(u"/dev/zero"_s).error, u"/dev/zero: "_s + kNotText.arg(0));
}

void TestLoadMessages::cutTextEndsTooEarlyAtAnySize_data()
{
    QTest::addColumn<int>("particles");
    QTest::addColumn<QByteArray>("cutAfter");  // the text is cut after the last of these
    QTest::addColumn<QString>("path");         // the JSON path the message names, after "particles[N]"
    // 3 particles is a small text; 250 000 (21 MB) is past 16 MiB
    for (const int particles : {3, 250000}) {
        const QByteArray size = particles < 1000 ? "small" : "large";
        QTest::newRow(size + ", after a comma") << particles << QByteArray("},\n") << QString();
        QTest::newRow(size + ", in a number") << particles << QByteArray("[0.12") << u".position[0]"_s;
        QTest::newRow(size + ", in a key") << particles << QByteArray("\"veloc") << QString();
        QTest::newRow(size + ", after a colon") << particles << QByteArray("\"mass\":") << u".mass"_s;
    }
}

void TestLoadMessages::cutTextEndsTooEarlyAtAnySize()
{
    QFETCH(int, particles);
    QFETCH(QByteArray, cutAfter);
    QFETCH(QString, path);
    const QByteArray whole = largeSceneText(particles);
    const qsizetype cut = whole.lastIndexOf(cutAfter, whole.lastIndexOf("{\"position\": [0.125") + 80) + cutAfter.size();
    QVERIFY(cut > cutAfter.size());
    const QByteArray text = whole.left(cut);

    // the same words whichever way the message is made (QJsonDocument's under 16 MiB, the
    // reader's own over it); over 16 MiB it said "not valid JSON (a fault at byte N)", N the end
    const QString error = io::parseScene(text, u"cut.json"_s).error;
    const QString at = u"cut.json: particles[%1]"_s.arg(particles - 2) + path + u": "_s;
    QVERIFY2(error.startsWith(at + kTooEarly), qPrintable(error));
}

void TestLoadMessages::largeCutRecordingEndsTooEarly()
{
    // a recording of a scene over 16 MiB, cut in the scene's text
    core::SceneDesc scene;
    scene.name = "many";
    scene.particles.resize(200000);
    // particles 1 mm apart with 10 cm radii overlap two hundred neighbours each: only the file's
    // size matters here, so nothing collides and the ten steps cost little even under the sanitizers
    scene.settings.particleCollisions = false;
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        scene.particles[i].position = {0.001 * double(i), 1.0 + 1e-7 * double(i), -0.5};
    const QByteArray whole = ui::recordingToJson(test::playedRecording(scene, 10));
    QVERIFY(whole.size() > (qsizetype(16) << 20));
    const QString error = ui::parseRecording(whole.left(whole.indexOf("\"start\"") / 2), u"r.json"_s).error;
    QVERIFY2(error.startsWith(u"r.json: scene: "_s + kTooEarly), qPrintable(error));
}

void TestLoadMessages::deepRecordingIsRefusedUnread()
{
    // a million arrays open at once: refused by its depth, as a scene file is, before a reader
    // keeps anything for each level
    const QByteArray deep = R"({"format": "springlab-replay", "version": 1, "edits": )" + QByteArray(1000000, '[') +
                            QByteArray(1000000, ']') + "}";
    const QString error = ui::parseRecording(deep, u"r.json"_s).error;
    QVERIFY2(error.startsWith(u"r.json: edits"_s) &&
                 error.contains(u": nested too deeply: more than the limit of 32 levels of arrays and objects (at byte "_s),
             qPrintable(error));
}

void TestLoadMessages::recordingKeysAndEscapesAreCheckedAsAScenes()
{
    // which of two values was meant cannot be known, and half a UTF-16 pair is no character: a
    // recording is refused for either, in a scene file's words
    const QByteArray good = ui::recordingToJson(test::playedRecording(test::springPairScene(), 10));
    QVERIFY(ui::parseRecording(good, u"r.json"_s).recording);
    const QString twice = ui::parseRecording(QByteArray(good).replace("\"steps\": 10", "\"steps\": 10, \"steps\": 11"),
                                             u"r.json"_s)
                              .error;
    QCOMPARE(twice, u"r.json: steps: this key comes twice in its object: keep one"_s);
    const QString half = ui::parseRecording(QByteArray(good).replace("\"edit\": \"play\"", "\"edit\": \"pl\\ud800ay\""),
                                            u"r.json"_s)
                             .error;
    QCOMPARE(half, u"r.json: edits[0].edit: a \\u escape is half of a UTF-16 pair (a lone surrogate), which is no character"_s);
}

void TestLoadMessages::checkedStringsReadAsQtReadsThem_data()
{
    // a recording's strings are checked by the pull reader and decoded only when asked for (a
    // scene's text, megabytes long); what it accepts and the text it gives must be QJsonDocument's
    QTest::addColumn<QByteArray>("written");  // between the quotes
    QTest::newRow("escapes") << QByteArray(R"(a\"b\\c\/d\b\f\n\r\t)");
    QTest::newRow("unicode escapes") << QByteArray(R"(\u00e9\u20AC\ud83d\ude00)");
    QTest::newRow("UTF-8") << QByteArray("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
    QTest::newRow("raw tab and line break") << QByteArray("a\tb\nc");
    QTest::newRow("unknown escape") << QByteArray(R"(\a\x\0)");
    QTest::newRow("short unicode escape") << QByteArray(R"(\u12)");
    QTest::newRow("unicode escape, not hex") << QByteArray(R"(\u12g4)");
    QTest::newRow("bad UTF-8") << QByteArray("a\xC3(b");
    QTest::newRow("cut UTF-8") << QByteArray("a\xE2\x82");
    QTest::newRow("UTF-8 of a surrogate") << QByteArray("a\xED\xA0\x80");
    QTest::newRow("half a pair") << QByteArray(R"(a\ud800b)");
}

void TestLoadMessages::checkedStringsReadAsQtReadsThem()
{
    QFETCH(QByteArray, written);
    const QByteArray text = "[\"" + written + "\"]";
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(text, &error);
    const bool qtReads = error.error == QJsonParseError::NoError;

    io::JsonPull pull(text, io::JsonStrings::Check);
    const bool pulled = pull.next() == io::JsonToken::BeginArray && pull.next() == io::JsonToken::String;
    const QByteArray utf8 = pulled ? pull.utf8() : QByteArray();
    const bool whole = pulled && pull.next() == io::JsonToken::EndArray && pull.next() == io::JsonToken::End;
    QCOMPARE(whole, qtReads);
    // half a UTF-16 pair is noted, for the recording to be refused (Qt's text keeps the half,
    // which UTF-8 cannot hold)
    QCOMPARE(!pull.loneSurrogate().isNull(), written.contains("\\ud800"));
    if (qtReads && pull.loneSurrogate().isNull())
        QCOMPARE(utf8, document.array().at(0).toString().toUtf8());
}

void TestLoadMessages::outOfMemoryNamesTheProcessLimit()
{
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    QSKIP("the sanitizers reserve terabytes of address space: a cap on it cannot be set");
#endif
    // a scene of 250 000 particles (21 MB) and a recording of it, with 8 MB more than the test
    // has mapped: the loads run out of memory and say which limit it was, as the step does
    // ("more memory than is free" was said with gigabytes free)
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString scenePath = dir.filePath(u"big.json"_s);
    const QString recordingPath = dir.filePath(u"big.replay.json"_s);
    const QByteArray sceneText = largeSceneText(250000);
    QVERIFY(writeAll(scenePath, sceneText));
    {
        io::LoadResult loaded = io::parseScene(sceneText, u"big.json"_s);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        // the particles all lie in one place: only the recording's size matters, so they do not
        // collide (a quarter of a million overlapping pairs took minutes to step)
        loaded.scene->settings.particleCollisions = false;
        QVERIFY(writeAll(recordingPath, ui::recordingToJson(test::playedRecording(*loaded.scene, 10))));
    }
    const QByteArray recordingText = readAll(recordingPath);
    QVERIFY(!recordingText.isEmpty());

    io::LoadResult scene;
    ui::RecordingLoad recording;
    ui::RecordingLoad parsed;
    {
        const test::AddressSpaceCap cap(8u << 20);
        QVERIFY(cap.capped());
        scene = io::loadScene(scenePath);
        recording = ui::loadRecording(recordingPath);
        parsed = ui::parseRecording(recordingText, u"in memory"_s);
    }
    const QString needs = u": cannot load: out of memory: reading it needs more memory than this process may use "
                          "(its address space is limited to "_s;
    const QString seeUlimit = u": see ulimit -v)"_s;
    QVERIFY(!scene.ok());
    QVERIFY2(scene.error.startsWith(QDir::toNativeSeparators(scenePath) + needs) && scene.error.endsWith(seeUlimit),
             qPrintable(scene.error));
    QVERIFY(!recording.recording);
    QVERIFY(recording.outOfMemory);
    QVERIFY2(recording.error.startsWith(recordingPath + needs) && recording.error.endsWith(seeUlimit),
             qPrintable(recording.error));
    QVERIFY(!parsed.recording);
    QVERIFY(parsed.outOfMemory);
    QVERIFY2(parsed.error.startsWith(u"in memory"_s + needs) && parsed.error.endsWith(seeUlimit), qPrintable(parsed.error));

    // with the memory back, both load
    QVERIFY2(io::loadScene(scenePath).ok(), "the scene did not load with the memory back");
    const ui::RecordingLoad fed = ui::loadRecording(recordingPath);
    QVERIFY2(fed.recording, qPrintable(fed.error));
    QCOMPARE(fed.recording->scene->particles.size(), std::size_t(250000));
}

void TestLoadMessages::memoryShortfallWithoutALimit()
{
    // with no limit set, the machine's memory is what ran out
    if (!memoryUnlimited())
        QSKIP("this process runs under a memory limit (ulimit -v or -d)");
    QCOMPARE(io::memoryShortfall(), u"more memory than is free"_s);
    QCOMPARE(io::cannotLoadForMemory(u"x.json"_s), u"x.json: cannot load: out of memory: reading it needs more memory than is free"_s);
}

void TestLoadMessages::readOnlyFileSystemIsNamed()
{
    // EROFS: no permission bit is to blame, and none would help
    QCOMPARE(io::systemReason(EROFS, u"Qt's reason"_s), u"read-only file system: nothing on it can be written"_s);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"scene.json"_s);
    QVERIFY(writeAll(path, "{}"));
    QCOMPARE(io::explainFailure(path, true, EROFS, u"Qt's reason"_s),
             u"read-only file system: "_s + QDir::toNativeSeparators(dir.path()) + u" is on a file system mounted read-only"_s);
    // other errors keep the system's words
    QCOMPARE(io::systemReason(ENOSPC, u"Qt's reason"_s), QString::fromStdString(std::generic_category().message(ENOSPC)));
    QCOMPARE(io::systemReason(0, u"Qt's reason"_s), u"Qt's reason"_s);
}

void TestLoadMessages::failedTemporaryFileIsNamed()
{
    // a file whose name is one short of the limit: its temporary twin (name + suffix) cannot be
    // made. The system's "File name too long" alone would seem to be about the file itself
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString name(250, u'a');
    QVERIFY(writeAll(dir.filePath(name), "old"));
    // (with O_TMPFILE, Linux's nameless temporary file, the name is only needed at the rename)
    const QString failure = io::writeFileAtomically(dir.filePath(name), "{}");
    const QString tooLong = QString::fromStdString(std::generic_category().message(ENAMETOOLONG));
    QVERIFY2(failure == u"cannot create the temporary file beside it in "_s + QDir::toNativeSeparators(dir.path()) +
                            u" (a save writes one there, then renames it over the file): "_s + tooLong ||
                 failure == u"cannot rename the temporary file over it: "_s + tooLong,
             qPrintable(failure));
    QCOMPARE(readAll(dir.filePath(name)), QByteArray("old"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot), QStringList{name});

    // /proc takes no new files: where /proc/version looks writable (as root), its temporary file
    // is what fails ("No such file or directory" was all it said)
    if (!QFileInfo(u"/proc/version"_s).isWritable())
        QSKIP("/proc/version is read-only to this user: the file itself is refused first");
    const QString proc = io::writeFileAtomically(u"/proc/version"_s, "{}");
    QVERIFY2(proc.startsWith(u"cannot create the temporary file beside it in /proc (a save writes one there, then "
                             "renames it over the file): "_s),
             qPrintable(proc));
}

QTEST_GUILESS_MAIN(TestLoadMessages)
#include "test_load_messages.moc"
