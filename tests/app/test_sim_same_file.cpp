// springlab-sim never writes over the file it reads, nor one output over another, when the two
// are one file under different names: a hard link, a symbolic link, "./x" beside "x", a bind mount
// of the scene's folder, a frame of --render. Each is refused before the run with exit code 2 and
// a message naming the file, and the scene's bytes are as they were.

#include "sim_run.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <cstring>
#include <memory>

#include <unistd.h>

using namespace Qt::Literals::StringLiterals;

namespace {

using test::sim;
using test::readAll;

using Run = test::ProgramRun;

// springlab-sim run in folder, so that its relative paths are taken from there
Run simIn(const QString &folder, const QStringList &arguments)
{
    QProcess process;
    process.setProcessEnvironment(test::offscreenEnvironment());
    process.setWorkingDirectory(folder);
    process.start(QStringLiteral(SPRINGLAB_SIM), arguments);
    Run run;
    if (!process.waitForFinished(120000) || process.exitStatus() != QProcess::NormalExit)
        return run;
    run.exitCode = process.exitCode();
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

bool hardLink(const QString &existing, const QString &alias)
{
    return ::link(QFile::encodeName(existing).constData(), QFile::encodeName(alias).constData()) == 0;
}

}  // namespace

class TestSimSameFile : public QObject {
    Q_OBJECT

private slots:
    void init();

    void distinctFilesStillRun();
    void hardLinkOfTheSceneIsRefused_data();
    void hardLinkOfTheSceneIsRefused();
    void symbolicLinkOfTheSceneIsRefused();
    void dotSlashNamesTheSceneToo();
    void outputsThatAreHardLinksOfEachOtherAreRefused();
    void recordingIsNotWrittenOverByItsReplay();
    void bindMountOfTheScenesFolderIsRefused();
    void renderFramesNeverReplaceTheScene();

private:
    QString path(const QString &name) const { return m_dir->filePath(name); }
    // why run is not a refusal (exit code 2, with says among its words, the scene as it was);
    // empty when it is
    QString whyNotRefused(const Run &run, const QString &says) const;

    std::unique_ptr<QTemporaryDir> m_dir;
    QString m_scene;     // scenes/scene.json in m_dir
    QByteArray m_bytes;  // what it holds
};

void TestSimSameFile::init()
{
    // a fresh folder with an example scene in a folder of its own, for each test
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    QVERIFY(QDir(m_dir->path()).mkdir(u"scenes"_s));
    m_scene = path(u"scenes/scene.json"_s);
    QVERIFY(QFile::copy(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/particles.json"), m_scene));
    m_bytes = readAll(m_scene);
    QVERIFY(!m_bytes.isEmpty());
}

QString TestSimSameFile::whyNotRefused(const Run &run, const QString &says) const
{
    if (run.exitCode != 2)
        return u"exit code %1, not 2: "_s.arg(run.exitCode) + QString::fromUtf8(run.err);
    if (!QString::fromUtf8(run.err).contains(says))
        return u"expected \""_s + says + u"\" in: "_s + QString::fromUtf8(run.err);
    if (readAll(m_scene) != m_bytes)
        return u"the scene's file was changed"_s;
    return QString();
}

void TestSimSameFile::distinctFilesStillRun()
{
    // a copy of the scene is another file: writing it is allowed, and the scene stays as it was
    const QString copy = path(u"scenes/copy.json"_s);
    QVERIFY(QFile::copy(m_scene, copy));
    const Run run = sim({m_scene, u"--steps"_s, u"5"_s, u"--output"_s, copy, u"--trace"_s, path(u"trace.csv"_s),
                         u"--summary-json"_s, path(u"summary.json"_s), u"--quiet"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    QCOMPARE(readAll(m_scene), m_bytes);
    QVERIFY(readAll(copy) != m_bytes);
    QVERIFY(readAll(path(u"trace.csv"_s)).startsWith("step,time,particle"));
}

void TestSimSameFile::hardLinkOfTheSceneIsRefused_data()
{
    QTest::addColumn<QString>("option");
    QTest::newRow("--trace") << u"--trace"_s;
    QTest::newRow("--summary-json") << u"--summary-json"_s;
    QTest::newRow("--summary-csv") << u"--summary-csv"_s;
    QTest::newRow("--output") << u"--output"_s;
}

void TestSimSameFile::hardLinkOfTheSceneIsRefused()
{
    // another name of the scene's inode, in another folder and with another suffix
    QFETCH(QString, option);
    const QString alias = path(u"alias.csv"_s);
    QVERIFY2(hardLink(m_scene, alias), std::strerror(errno));
    const Run run = sim({m_scene, u"--steps"_s, u"5"_s, option, alias});
    const QString why = whyNotRefused(run, option + u' ' + QDir::toNativeSeparators(alias) + u" names the scene's file"_s);
    QVERIFY2(why.isEmpty(), qPrintable(why));
    QCOMPARE(readAll(alias), m_bytes);
}

void TestSimSameFile::symbolicLinkOfTheSceneIsRefused()
{
    const QString link = path(u"link.csv"_s);
    QVERIFY(QFile::link(m_scene, link));
    for (const QString &option : {u"--trace"_s, u"--output"_s, u"--summary-csv"_s}) {
        const Run run = sim({m_scene, u"--steps"_s, u"5"_s, option, link});
        const QString why = whyNotRefused(run, option + u' ' + QDir::toNativeSeparators(link) + u" names the scene's file"_s);
        QVERIFY2(why.isEmpty(), qPrintable(why));
    }
    // the scene read through a link to its folder, written by its plain path
    QVERIFY(QFile::link(path(u"scenes"_s), path(u"elsewhere"_s)));
    const Run run = sim({path(u"elsewhere/scene.json"_s), u"--steps"_s, u"5"_s, u"--trace"_s, m_scene});
    const QString why = whyNotRefused(run, u"names the scene's file"_s);
    QVERIFY2(why.isEmpty(), qPrintable(why));
}

void TestSimSameFile::dotSlashNamesTheSceneToo()
{
    // relative paths, taken from the working folder
    const QString folder = path(u"scenes"_s);
    const struct {
        QStringList arguments;
        QString says;
    } cases[] = {
        {{u"scene.json"_s, u"--output"_s, u"./scene.json"_s}, u"--output ./scene.json names the scene's file"_s},
        {{u"./scene.json"_s, u"--trace"_s, u"scene.json"_s}, u"--trace scene.json names the scene's file"_s},
        {{u"scene.json"_s, u"--summary-json"_s, u"../scenes/scene.json"_s},
         u"--summary-json ../scenes/scene.json names the scene's file"_s},
    };
    for (const auto &[arguments, says] : cases) {
        const Run run = simIn(folder, arguments + QStringList{u"--steps"_s, u"5"_s});
        const QString why = whyNotRefused(run, says);
        QVERIFY2(why.isEmpty(), qPrintable(why));
    }
}

void TestSimSameFile::outputsThatAreHardLinksOfEachOtherAreRefused()
{
    // two names of one file, neither the scene: the second output would overwrite the first
    const QString first = path(u"first.csv"_s);
    const QString second = path(u"scenes/second.json"_s);
    QFile file(first);
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write("kept\n") == 5);
    file.close();
    QVERIFY2(hardLink(first, second), std::strerror(errno));
    const Run run = sim({m_scene, u"--steps"_s, u"5"_s, u"--trace"_s, first, u"--summary-json"_s, second});
    const QString why = whyNotRefused(run, u"--trace and --summary-json name one file, "_s + QDir::toNativeSeparators(first));
    QVERIFY2(why.isEmpty(), qPrintable(why));
    QCOMPARE(readAll(first), QByteArray("kept\n"));
}

void TestSimSameFile::recordingIsNotWrittenOverByItsReplay()
{
    // refused before the recording is read, so any file will do as one
    const QString alias = path(u"final.json"_s);
    QVERIFY2(hardLink(m_scene, alias), std::strerror(errno));
    const Run run = sim({m_scene, u"--replay"_s, u"--output"_s, alias});
    const QString why = whyNotRefused(run, u"--output "_s + QDir::toNativeSeparators(alias) + u" names the recording's file"_s);
    QVERIFY2(why.isEmpty(), qPrintable(why));
}

void TestSimSameFile::bindMountOfTheScenesFolderIsRefused()
{
    // the scene's folder mounted again at mounted/, in a mount namespace of the run's own: one
    // inode under two paths that no link explains. That needs unshare(1) and the right to mount
    // (root, or CAP_SYS_ADMIN); where either is missing the case is skipped
    const QString mounted = path(u"mounted"_s);
    QVERIFY(QDir(m_dir->path()).mkdir(u"mounted"_s));
    const auto inMount = [&](const QStringList &command) {
        return test::runProgram(u"unshare"_s,
                                QStringList{u"--mount"_s, u"--propagation"_s, u"private"_s, u"sh"_s, u"-c"_s,
                                            uR"(mount --bind "$1" "$2" || exit 99; shift 2; exec "$@")"_s, u"sh"_s,
                                            path(u"scenes"_s), mounted} + command,
                                120000);
    };
    const Run probe = inMount({u"test"_s, u"-f"_s, mounted + u"/scene.json"_s});
    if (probe.exitCode != 0)
        QSKIP(qPrintable(u"no bind mount here (exit %1): %2"_s.arg(probe.exitCode).arg(QString::fromUtf8(probe.err))));

    const QString through = mounted + u"/scene.json"_s;
    for (const QString &option : {u"--output"_s, u"--trace"_s}) {
        const Run run = inMount({QStringLiteral(SPRINGLAB_SIM), m_scene, u"--steps"_s, u"5"_s, option, through});
        const QString why = whyNotRefused(run, option + u' ' + QDir::toNativeSeparators(through) + u" names the scene's file"_s);
        QVERIFY2(why.isEmpty(), qPrintable(why));
    }
    // and nothing stays mounted
    QVERIFY(!QFile::exists(through));
}

void TestSimSameFile::renderFramesNeverReplaceTheScene()
{
    // --render DIR removes DIR/frame-*.png and writes new ones: a scene or an output among them
    // would be lost. The refusal comes before any drawing, but --render needs an X display to
    // start at all (xvfb-run -a); without one the case is skipped
#if defined(SPRINGLAB_UNDER_ASAN)
    // (under LeakSanitizer the X client library's connection, which Qt never frees, is reported
    // when the refused program exits, and turns its exit code 2 into 1)
    QSKIP("--render opens an X connection that LeakSanitizer reports at exit");
#endif
    QVERIFY(QDir(m_dir->path()).mkdir(u"frames"_s));
    const QString frames = path(u"frames"_s);
    const QString sceneAsFrame = path(u"frames/frame-00000.png"_s);
    QVERIFY(QFile::rename(m_scene, sceneAsFrame));
    m_scene = sceneAsFrame;
    const Run run = sim({m_scene, u"--steps"_s, u"5"_s, u"--render"_s, frames});
    if (run.exitCode == 2 && run.err.contains("needs an X display"))
        QSKIP("--render has no X display here: run under xvfb-run -a");
    QString why = whyNotRefused(run, u"--render "_s + QDir::toNativeSeparators(frames) + u" would replace the scene's file"_s);
    QVERIFY2(why.isEmpty(), qPrintable(why));

    // the folder by a link to it
    QVERIFY(QFile::link(frames, path(u"frames-link"_s)));
    why = whyNotRefused(sim({m_scene, u"--steps"_s, u"5"_s, u"--render"_s, path(u"frames-link"_s)}),
                        u"would replace the scene's file"_s);
    QVERIFY2(why.isEmpty(), qPrintable(why));

    // an output among the frames, in another case: one on a file system that ignores case
    const QString other = path(u"other.json"_s);
    QVERIFY(QFile::copy(m_scene, other));
    const QString trace = path(u"frames/FRAME-00003.PNG"_s);
    why = whyNotRefused(sim({other, u"--steps"_s, u"5"_s, u"--render"_s, frames, u"--trace"_s, trace}),
                        u"--trace "_s + QDir::toNativeSeparators(trace) + u" is one of the frames of --render"_s);
    QVERIFY2(why.isEmpty(), qPrintable(why));
    QVERIFY(!QFile::exists(trace));
}

QTEST_GUILESS_MAIN(TestSimSameFile)
#include "test_sim_same_file.moc"
