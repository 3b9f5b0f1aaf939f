// editor_throughput: the editor's steps per second beside springlab-sim's on the same scene and
// machine. It writes the scene a user gets from File › New and Edit › Generate › Cloth (rows ×
// cols, the generator's 20 sub-steps of the 10 ms step, centred at (0, 1, 0) over the floor), then
// runs, alternating, `springlab SCENE --play --exit-after SECONDS` (the editor drawing as it runs)
// and `springlab-sim SCENE --steps N` for as many steps as that editor run reached (the same
// stretch of the same run), several times each, and prints every run, the medians and their
// ratio. The editor needs a display: run it under a virtual X server, as docs/benchmarks.md does:
//   xvfb-run -a -s "-screen 0 1280x1024x24" build/release/bench/editor_throughput
// With --no-contacts the scene's plane and particle contacts are off (a faster step, where what
// the editor adds to each one weighs more); with --write-scene FILE it only writes the scene (any
// size, 1000 × 1000 for 10⁶ particles). With --busy a loop keeps one core busy, and each program
// runs with the threads it chooses beside the same with OMP_NUM_THREADS=1.

#include "bench_common.h"

#include "ui/document/document_files.h"
#include "ui/document/scene_edits.h"

#include "core/model/generators.h"
#include "core/io/scene_file.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QThread>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTextStream>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <optional>
#include <thread>
#include <vector>

namespace {

// the scene as the editor makes it: a new scene (its floor and default settings) with the cloth
// generated into it where the Generate dialog puts it by default
core::SceneDesc generatedCloth(int rows, int cols, bool contacts)
{
    core::ClothOptions options;
    options.rows = rows;
    options.cols = cols;
    core::SceneDesc scene = ui::DocumentFiles::newScene();
    ui::addGenerated(scene, core::makeCloth(options), Eigen::Vector3d(0.0, 1.0, 0.0));
    scene.name = QStringLiteral("cloth-%1x%2").arg(rows).arg(cols).toStdString();
    scene.settings.planeCollisions = scene.settings.particleCollisions = contacts;
    return scene;
}

struct EditorRun {
    double seconds = 0.0;
    double steps = 0.0;
    double frames = 0.0;
    double pauseSeconds = 0.0;  // from the Pause at the end to its frame
    double shownSeconds = 0.0;  // from the Pause to the frame with the snapshot of its step
};

// the line `springlab --exit-after` prints (ui/window/timed_play.h)
std::optional<EditorRun> parseEditorLine(const QString &output)
{
    static const QRegularExpression line(
        QStringLiteral(R"(springlab: ([0-9.]+) s: ([0-9]+) steps \([0-9.]+ steps/s\), ([0-9]+) frames \([0-9.]+ frames/s\), paused in ([0-9.]+) s, shown in ([0-9.]+) s)"));
    const QRegularExpressionMatch match = line.match(output);
    if (!match.hasMatch())
        return std::nullopt;
    return EditorRun{match.captured(1).toDouble(), match.captured(2).toDouble(), match.captured(3).toDouble(),
                     match.captured(4).toDouble(), match.captured(5).toDouble()};
}

// runs a program to its end; its standard output, or nothing (and why, in error). threads: with
// OMP_NUM_THREADS set to it (1: what a user would set by hand on a busy machine; every core: what
// OpenMP did before Springlab chose), 0: the program chooses
std::optional<QString> run(const QString &program, const QStringList &arguments, int timeoutMs, QString &error,
                           int threads = 0)
{
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove(QStringLiteral("OMP_NUM_THREADS"));
    if (threads > 0)
        environment.insert(QStringLiteral("OMP_NUM_THREADS"), QString::number(threads));
    process.setProcessEnvironment(environment);
    process.start(program, arguments);
    if (!process.waitForFinished(timeoutMs) || process.exitStatus() != QProcess::NormalExit ||
        process.exitCode() != 0) {
        error = QStringLiteral("%1 %2 failed: %3").arg(program, arguments.join(QLatin1Char(' ')),
                                                       QString::fromLocal8Bit(process.readAllStandardError()));
        process.kill();
        process.waitForFinished();
        return std::nullopt;
    }
    return QString::fromLocal8Bit(process.readAllStandardOutput());
}

// --busy: the editor and springlab-sim with the threads they choose beside the same with one
// thread and with every core (OMP_NUM_THREADS), a loop keeping one core busy all along; runs
// alternate
int compareWithOneThread(const QString &editorPath, const QString &simPath, const QString &scene, int runs,
                         double seconds, const QString &dir)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    const bench::BusyCore busy;
    const int every = std::max(2, QThread::idealThreadCount());
    out << "with a loop keeping one core busy all along; steps/s with the threads chosen, with one, with "
        << every << "\n\n"
        << "| run | springlab: chosen | one | " << every << " | one / chosen | springlab-sim: chosen | one | " << every
        << " | one / chosen |\n"
        << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    out.flush();
    const int timeoutMs = static_cast<int>(seconds * 1000.0) + 600000;
    std::vector<double> editorRatios, simRatios;
    std::vector<double> editorRates[3], simRates[3];
    const int counts[3] = {0, 1, every};
    for (int i = 0; i < runs; ++i) {
        double editorRate[3] = {0.0, 0.0, 0.0};
        double simRate[3] = {0.0, 0.0, 0.0};
        for (int c = 0; c < 3; ++c) {
            QString error;
            const std::optional<QString> output =
                run(editorPath, {scene, QStringLiteral("--play"), QStringLiteral("--exit-after"), QString::number(seconds)},
                    timeoutMs, error, counts[c]);
            const std::optional<EditorRun> editor = output ? parseEditorLine(*output) : std::nullopt;
            if (!editor || editor->steps < 1.0) {
                err << "editor_throughput: " << (error.isEmpty() ? QStringLiteral("no steps from the editor") : error) << '\n';
                return 1;
            }
            editorRate[c] = editor->steps / editor->seconds;
            // the simulator over as many steps as the chosen threads' editor run took
            const QString summary = dir + QStringLiteral("/summary.json");
            const double steps = std::max(1.0, std::round(editorRate[0] * seconds));
            if (!run(simPath, {scene, QStringLiteral("--steps"), QString::number(steps), QStringLiteral("--quiet"),
                               QStringLiteral("--summary-json"), summary},
                     timeoutMs, error, counts[c])) {
                err << "editor_throughput: " << error << '\n';
                return 1;
            }
            QFile file(summary);
            file.open(QIODevice::ReadOnly);
            simRate[c] = QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("stepsPerSecond")).toDouble();
            editorRates[c].push_back(editorRate[c]);
            simRates[c].push_back(simRate[c]);
        }
        editorRatios.push_back(editorRate[1] / editorRate[0]);
        simRatios.push_back(simRate[1] / simRate[0]);
        out << "| " << i + 1;
        for (int c = 0; c < 3; ++c)
            out << " | " << QString::number(editorRate[c], 'f', 1);
        out << " | " << QString::number(editorRatios.back(), 'f', 2);
        for (int c = 0; c < 3; ++c)
            out << " | " << QString::number(simRate[c], 'f', 1);
        out << " | " << QString::number(simRatios.back(), 'f', 2) << " |\n";
        out.flush();
    }
    using bench::median;
    out << "| median";
    for (int c = 0; c < 3; ++c)
        out << " | " << QString::number(median(editorRates[c]), 'f', 1);
    out << " | " << QString::number(median(editorRatios), 'f', 2);
    for (int c = 0; c < 3; ++c)
        out << " | " << QString::number(median(simRates[c]), 'f', 1);
    out << " | " << QString::number(median(simRatios), 'f', 2) << " |\n\n"
        << "one / chosen: one thread's steps/s over the chosen threads' (1.2 at most is the target); load average "
           "at the end "
        << bench::loadText() << '\n';
    return 0;
}

}  // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("The editor's steps/s beside springlab-sim's on a generated cloth, runs alternating."));
    parser.addHelpOption();
    const QCommandLineOption rowsOption(QStringLiteral("rows"), QStringLiteral("Cloth rows (default 200)."),
                                        QStringLiteral("N"), QStringLiteral("200"));
    const QCommandLineOption colsOption(QStringLiteral("cols"), QStringLiteral("Cloth columns (default 200)."),
                                        QStringLiteral("N"), QStringLiteral("200"));
    const QCommandLineOption runsOption(QStringLiteral("runs"), QStringLiteral("Runs of each (default 5)."),
                                        QStringLiteral("N"), QStringLiteral("5"));
    const QCommandLineOption secondsOption(QStringLiteral("seconds"),
                                           QStringLiteral("Wall time of each editor run (default 10)."),
                                           QStringLiteral("S"), QStringLiteral("10"));
    const QCommandLineOption editorOption(QStringLiteral("editor"), QStringLiteral("The editor to run."),
                                          QStringLiteral("PATH"), QStringLiteral(SPRINGLAB_EDITOR));
    const QCommandLineOption simOption(QStringLiteral("sim"), QStringLiteral("The headless simulator to run."),
                                       QStringLiteral("PATH"), QStringLiteral(SPRINGLAB_SIM));
    const QCommandLineOption writeOption(QStringLiteral("write-scene"),
                                         QStringLiteral("Only write the scene to FILE and exit."),
                                         QStringLiteral("FILE"));
    const QCommandLineOption noContactsOption(QStringLiteral("no-contacts"),
                                              QStringLiteral("Turn the scene's plane and particle contacts off."));
    const QCommandLineOption busyOption(
        QStringLiteral("busy"), QStringLiteral("Keep one core busy, and compare the threads the programs choose with one thread."));
    parser.addOptions({rowsOption, colsOption, runsOption, secondsOption, editorOption, simOption, writeOption,
                       noContactsOption, busyOption});
    parser.process(app);
    QTextStream out(stdout);
    QTextStream err(stderr);

    const int rows = std::max(2, parser.value(rowsOption).toInt());
    const int cols = std::max(2, parser.value(colsOption).toInt());
    const int runs = std::max(1, parser.value(runsOption).toInt());
    const double seconds = std::max(1.0, parser.value(secondsOption).toDouble());

    // the scene, in a file of its own
    const core::SceneDesc scene = generatedCloth(rows, cols, !parser.isSet(noContactsOption));
    QTemporaryDir dir;
    const QString path =
        parser.isSet(writeOption) ? parser.value(writeOption) : dir.filePath(QStringLiteral("cloth.json"));
    if (const io::SaveResult saved = io::saveScene(path, scene); !saved.ok()) {
        err << "editor_throughput: " << saved.error << '\n';
        return 1;
    }
    const double subStep = scene.settings.timeStep / scene.settings.substeps;
    out << "cloth " << rows << " x " << cols << ": " << scene.particles.size() << " particles, "
        << scene.springs.size() << " springs, " << scene.settings.substeps << " sub-steps of " << subStep * 1e3
        << " ms, contacts " << (scene.settings.particleCollisions ? "on" : "off") << "\n";
    if (parser.isSet(writeOption)) {
        out << "wrote " << path << '\n';
        return 0;
    }
    out << bench::machineDescription() << ", load average " << bench::loadText() << "\n" << runs
        << " runs of each, alternating, the editor for " << seconds << " s a run\n\n";
    if (parser.isSet(busyOption))
        return compareWithOneThread(parser.value(editorOption), parser.value(simOption), path, runs, seconds, dir.path());
    out << "| run | springlab-sim steps/s | springlab steps/s | springlab frames/s | editor / sim | pause answered | its step shown |\n"
        << "|---:|---:|---:|---:|---:|---:|---:|\n";
    out.flush();

    // editor, then the simulator over the same steps
    const int timeoutMs = static_cast<int>(seconds * 1000.0) + 600000;
    std::vector<double> simRates, editorRates, frameRates, ratios, pauses, shown;
    for (int i = 0; i < runs; ++i) {
        QString error;
        const std::optional<QString> editorOutput =
            run(parser.value(editorOption), {path, QStringLiteral("--play"), QStringLiteral("--exit-after"),
                                             QString::number(seconds)},
                timeoutMs, error);
        const std::optional<EditorRun> editor = editorOutput ? parseEditorLine(*editorOutput) : std::nullopt;
        if (!editor || editor->steps < 1.0) {
            err << "editor_throughput: " << (error.isEmpty() ? QStringLiteral("no steps from the editor") : error)
                << '\n';
            return 1;
        }
        const QString summary = dir.filePath(QStringLiteral("summary.json"));
        if (!run(parser.value(simOption),
                 {path, QStringLiteral("--steps"), QString::number(editor->steps), QStringLiteral("--quiet"),
                  QStringLiteral("--summary-json"), summary},
                 timeoutMs, error)) {
            err << "editor_throughput: " << error << '\n';
            return 1;
        }
        QFile file(summary);
        file.open(QIODevice::ReadOnly);
        const double simRate = QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("stepsPerSecond")).toDouble();
        const double editorRate = editor->steps / editor->seconds;
        const double frameRate = editor->frames / editor->seconds;
        simRates.push_back(simRate);
        editorRates.push_back(editorRate);
        frameRates.push_back(frameRate);
        ratios.push_back(simRate > 0.0 ? editorRate / simRate : 0.0);
        pauses.push_back(editor->pauseSeconds);
        shown.push_back(editor->shownSeconds);
        out << "| " << i + 1 << " | " << QString::number(simRate, 'f', 1) << " | "
            << QString::number(editorRate, 'f', 1) << " | " << QString::number(frameRate, 'f', 1) << " | "
            << QString::number(ratios.back(), 'f', 2) << " | " << QString::number(1e3 * pauses.back(), 'f', 0)
            << " ms | " << QString::number(1e3 * shown.back(), 'f', 0) << " ms |\n";
        out.flush();
    }
    using bench::median;
    out << "| median | " << QString::number(median(simRates), 'f', 1) << " | "
        << QString::number(median(editorRates), 'f', 1) << " | " << QString::number(median(frameRates), 'f', 1)
        << " | " << QString::number(median(ratios), 'f', 2) << " | "
        << QString::number(1e3 * median(pauses), 'f', 0) << " ms | " << QString::number(1e3 * median(shown), 'f', 0)
        << " ms |\n\n";
    out << "ratio of the medians: " << QString::number(median(editorRates) / median(simRates), 'f', 2)
        << "; load average at the end " << bench::loadText() << '\n';
    return 0;
}
