// Loading a scene file needs memory in proportion to the file: at most 3 times its size for a file
// that loads (the bytes themselves and the scene made of them, never a tree of the document), and
// little more than the bytes for a file refused for a list over its limit, which is refused before
// anything is made for the list; past 100 warnings, unknown keys are counted rather than listed.
// Each load runs in a process of its own (load_peak), whose peak resident memory (VmHWM) is the
// load's.

#include "tests/test_files.h"
#include "core/io/scene_file.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

namespace {

using test::writeAll;

struct Peak {
    double rssKib = 0.0;   // before loading
    double peakKib = 0.0;  // after
    QString outcome;       // "ok" or the message
};

// runs load_peak on path
Peak loadInChild(const QString &path)
{
    QProcess process;
    process.start(QStringLiteral(SPRINGLAB_LOAD_PEAK), {path});
    Peak peak;
    if (!process.waitForFinished(60000) || process.exitCode() != 0)
        return peak;
    const QList<QByteArray> lines = process.readAllStandardOutput().trimmed().split('\n');
    const QList<QByteArray> numbers = lines.value(0).split(' ');
    peak.rssKib = numbers.value(1).toDouble();
    peak.peakKib = numbers.value(3).toDouble();
    peak.outcome = QString::fromUtf8(lines.value(1));
    return peak;
}

// AddressSanitizer's red zones and quarantine inflate every peak several times over: under it the
// loads still run (and are checked for memory errors), but the ratios mean nothing
#if defined(SPRINGLAB_UNDER_ASAN)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

}  // namespace

class TestSceneMemory : public QObject {
    Q_OBJECT

private slots:
    void loadWithinThreeTimesTheFile();
    void listOverItsLimitRefusedBeforeMaking();
    void largeTextThatIsNotJsonRefusedInProportion();
    void manyUnknownKeysCounted();
};

void TestSceneMemory::loadWithinThreeTimesTheFile()
{
    // a chain of 100 000 particles and 200 000 springs, about 28 MB as saved
    core::SceneDesc scene;
    constexpr int kParticles = 100'000;
    for (int i = 0; i < kParticles; ++i) {
        core::ParticleDesc particle;
        particle.position = {0.1 * i, 0.001 * (i % 7), -0.002 * (i % 11)};
        particle.mass = 1.0 + 1e-6 * i;
        particle.radius = 0.01;
        scene.particles.push_back(particle);
    }
    for (int i = 0; i + 2 < kParticles; ++i)
        for (int step : {1, 2})
            scene.springs.push_back({i, i + step, 1000.0, 0.5, 0.1 * step, 0.0});
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"chain.json"_s);
    const QByteArray json = io::sceneToJson(scene);
    QVERIFY(writeAll(path, json));
    scene = {};

    const Peak peak = loadInChild(path);
    QCOMPARE(peak.outcome, u"ok"_s);
    const double fileKib = json.size() / 1024.0;
    const double ratio = (peak.peakKib - peak.rssKib) / fileKib;
    qInfo("file %.1f MB, peak %.1f MB over %.1f MB at the start: %.2f times the file", json.size() / 1e6,
          peak.peakKib / 1024.0, peak.rssKib / 1024.0, ratio);
    if (kSanitized)
        QSKIP("the peak under AddressSanitizer is not the loader's");
    QVERIFY2(ratio <= 3.0, qPrintable(QString::number(ratio)));
}

void TestSceneMemory::listOverItsLimitRefusedBeforeMaking()
{
    // one particle over the limit, each the smallest element there is: 30 MB of "{}," that a
    // tree of the document would need gigabytes for
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"too-many.json"_s);
    QByteArray json = R"({"format": "springlab-scene", "version": 1, "name": "n", "particles": [)";
    json += QByteArray("{},").repeated(io::kMaxParticles);
    json += R"({}], "springs": [], "planes": []})";
    QVERIFY(writeAll(path, json));

    const Peak peak = loadInChild(path);
    QCOMPARE(peak.outcome, path + u": particles: too many particles: 10000001, more than the limit of 10000000"_s);
    const double ratio = (peak.peakKib - peak.rssKib) / (json.size() / 1024.0);
    qInfo("refused with a peak of %.2f times the file", ratio);
    if (kSanitized)
        QSKIP("the peak under AddressSanitizer is not the loader's");
    QVERIFY2(ratio <= 1.5, qPrintable(QString::number(ratio)));
}

void TestSceneMemory::largeTextThatIsNotJsonRefusedInProportion()
{
    // 300 000 particles with a fault in the last (21 MB): QJsonDocument, asked for the message,
    // built a tree of everything before the fault, 216 MB (10 times the file). Past 16 MiB the
    // reader's own place of the fault is the message.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"cut.json"_s);
    QByteArray json = R"({"format": "springlab-scene", "version": 1, "particles": [)";
    json += QByteArray(R"({"position": [0.125, 1.5, -2.25], "velocity": [0, 0, 0], "mass": 1},)"
                       "\n")
                .repeated(300000);
    json += R"({"position": [0, 0, 0], "mass": 1 1}]})"
            "\n";
    QVERIFY(writeAll(path, json));

    const Peak peak = loadInChild(path);
    QCOMPARE(peak.outcome,
             path + u": particles[300000].mass: not valid JSON (a fault in the text at byte %1, line 300001, column 35)"_s
                        .arg(json.size() - 5));
    const double ratio = (peak.peakKib - peak.rssKib) / (json.size() / 1024.0);
    qInfo("refused with a peak of %.2f times the file", ratio);
    if (kSanitized)
        QSKIP("the peak under AddressSanitizer is not the loader's");
    QVERIFY2(ratio <= 3.0, qPrintable(QString::number(ratio)));
}

void TestSceneMemory::manyUnknownKeysCounted()
{
    // a warning is longer than the key it names: past the first 100 they are only counted
    QByteArray json = R"({"format": "springlab-scene", "version": 1, "name": "n", "particles": [)";
    for (int i = 0; i < 150; ++i)
        json += (i == 0 ? "" : ",") + QByteArray(R"({"position": [0, 0, 0], "mass": 1, "radius": 1, "x": 0})");
    json += R"(], "springs": [], "planes": [], "y": 0})";
    const io::LoadResult result = io::parseScene(json, u"many.json"_s);
    QVERIFY2(result.ok(), qPrintable(result.error));
    QCOMPARE(result.warnings.size(), 101);
    QCOMPARE(result.warnings.first(), u"many.json: particles[0].x: unknown key, ignored"_s);
    QCOMPARE(result.warnings.last(), u"many.json: 51 more unknown keys, ignored"_s);
}

QTEST_GUILESS_MAIN(TestSceneMemory)
#include "test_scene_memory.moc"
