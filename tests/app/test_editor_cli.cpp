// springlab --play --exit-after, end to end under a virtual X server: the editor plays the scene
// for that long, then prints one line with the steps and frames it reached and ends; the figures
// agree with each other and with the scene (the run never gets ahead of the wall clock), and the
// scene stays out of the recent files; without --play nothing steps; a duration that is not one
// is refused with exit code 2.

#include "program_run.h"

#include <QFile>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

namespace {

struct Line {
    double seconds = 0.0;
    double steps = 0.0;
    double stepsPerSecond = 0.0;
    double frames = 0.0;
    double framesPerSecond = 0.0;
    double pauseSeconds = 0.0;
    double shownSeconds = 0.0;
};

// "springlab: 10.022 s: 976 steps (97.39 steps/s), 151 frames (15.07 frames/s), paused in 0.044 s,
// shown in 0.044 s"
std::optional<Line> parseLine(const QByteArray &out)
{
    static const QRegularExpression line(
        uR"(^springlab: ([0-9.]+) s: ([0-9]+) steps \(([0-9.]+) steps/s\), ([0-9]+) frames \(([0-9.]+) frames/s\), paused in ([0-9.]+) s, shown in ([0-9.]+) s$)"_s,
        QRegularExpression::MultilineOption);
    const QRegularExpressionMatch match = line.match(QString::fromUtf8(out));
    if (!match.hasMatch())
        return std::nullopt;
    return Line{match.captured(1).toDouble(), match.captured(2).toDouble(), match.captured(3).toDouble(),
                match.captured(4).toDouble(), match.captured(5).toDouble(), match.captured(6).toDouble(),
                match.captured(7).toDouble()};
}

}  // namespace

class TestEditorCli : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void playsForTheTimeGivenAndSaysHowFast();
    void withoutPlayNothingSteps();
    void refusesADurationThatIsNotOne();

private:
    test::ProgramRun editor(const QStringList &arguments) const
    {
        return test::runProgram(QStringLiteral(SPRINGLAB_EDITOR), arguments, 120000, m_environment);
    }
    QString scene() const { return m_dir.filePath(u"particles.json"_s); }

    QTemporaryDir m_dir;
    QProcessEnvironment m_environment;
};

void TestEditorCli::initTestCase()
{
    // the particles example: two particles thrown and falling, 0.5 ms steps; the editor's
    // settings, autosaves and recent files in a folder of the test's own
    QVERIFY(m_dir.isValid());
    QVERIFY(QFile::copy(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/particles.json"), scene()));
    QVERIFY(!qEnvironmentVariableIsEmpty("DISPLAY"));  // run_ui_test.sh gives it one
    m_environment = QProcessEnvironment::systemEnvironment();
    m_environment.insert(u"QT_QPA_PLATFORM"_s, u"xcb"_s);
    m_environment.insert(u"HOME"_s, m_dir.path());
    for (const char *name : {"XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME"})
        m_environment.insert(QString::fromLatin1(name), m_dir.filePath(QString::fromLatin1(name)));
}

void TestEditorCli::playsForTheTimeGivenAndSaysHowFast()
{
    const test::ProgramRun run = editor({scene(), u"--play"_s, u"--exit-after"_s, u"1.5"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const std::optional<Line> line = parseLine(run.out);
    QVERIFY2(line, run.out.constData());

    // at least the time asked for; it stepped and drew
    QVERIFY2(line->seconds >= 1.5 && line->seconds < 60.0, run.out.constData());
    QVERIFY(line->steps > 0.0);
    QVERIFY(line->frames > 0.0);
    // the rates are the counts over that time (to the rounding of the figures printed)
    QVERIFY2(std::abs(line->stepsPerSecond - line->steps / line->seconds) <= 1e-3 * line->stepsPerSecond + 0.01,
             run.out.constData());
    QVERIFY2(std::abs(line->framesPerSecond - line->frames / line->seconds) <= 1e-3 * line->framesPerSecond + 0.01,
             run.out.constData());
    // the editor never runs ahead of real time: 0.5 ms steps, so at most 2000 a second (and the
    // one tick of up to 0.1 s that may end after the clock stopped)
    QVERIFY2(line->steps * 0.0005 <= line->seconds + 0.1, run.out.constData());
    // the picture of the step it paused at comes with the answer or after it, never before
    QVERIFY2(line->shownSeconds >= line->pauseSeconds, run.out.constData());

    // a timed run is not the user's: the scene stays out of File › Open Recent, while the
    // window's other settings (its size, written on closing) were saved in the same file
    const QString settings = m_dir.filePath(u"XDG_CONFIG_HOME/Springlab/Springlab.conf"_s);
    QVERIFY2(QFile::exists(settings), qPrintable(settings));
    const QSettings stored(settings, QSettings::IniFormat);
    QVERIFY2(!stored.allKeys().isEmpty(), qPrintable(settings));
    QVERIFY2(stored.value(u"files/recent"_s).toStringList().isEmpty(),
             qPrintable(stored.value(u"files/recent"_s).toStringList().join(u", "_s)));
}

void TestEditorCli::withoutPlayNothingSteps()
{
    const test::ProgramRun run = editor({scene(), u"--exit-after"_s, u"0.5"_s});
    QVERIFY2(run.exitCode == 0, run.err.constData());
    const std::optional<Line> line = parseLine(run.out);
    QVERIFY2(line, run.out.constData());
    QCOMPARE(line->steps, 0.0);
    QVERIFY(line->seconds >= 0.5);
}

void TestEditorCli::refusesADurationThatIsNotOne()
{
    for (const QString &bad : {u"0"_s, u"-1"_s, u"soon"_s}) {
        const test::ProgramRun run = editor({scene(), u"--play"_s, u"--exit-after"_s, bad});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("--exit-after takes a number of seconds"), run.err.constData());
        QVERIFY(run.out.isEmpty());
    }
}

QTEST_GUILESS_MAIN(TestEditorCli)
#include "test_editor_cli.moc"
