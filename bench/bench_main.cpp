// springlab-bench: the benchmark programs, one per first argument.
//   springlab-bench accuracy [--out DIR] [--quick]   error against run time (docs/benchmarks.md)
//   springlab-bench stability [--out DIR] [--quick]  largest stable time step against theory
//   springlab-bench throughput [--out DIR] [--quick] run time per step against references and the
//                                                    memory bandwidth bound
//   springlab-bench contacts [--out DIR] [--quick]   stacks, piles and a heap beside Bullet's rigid
//                                                    spheres: what stands, what settles, the cost
//   springlab-bench cloth-contacts [--out DIR] [--quick] [--size N]... [--seconds S]
//   springlab-bench rolling [--out DIR]              single balls against their closed forms, and
//                                                    as Bullet's rotating spheres
//                                                    a sheet crumpling and one draping, with the
//                                                    core's triangle collisions, without them and
//                                                    as Bullet's soft-body cloth: crossings, cost
//   springlab-bench stiff [--out DIR] [--quick]      a stiff cloth: the sub-steps and cost each of
//                                                    symplectic Euler, implicit Euler and xpbd needs
//                                                    to stay within 1% stretch
//   springlab-bench stiff ... [--size N]... [--stiffness K]...   only those rows of it
//   springlab-bench xpbd-substep [--size N] [--stiffness K] [--substeps S] [--runs R] [--drape SECONDS]
//                                                    one xpbd sub-step's cost: the core's pass beside
//                                                    the colour-by-colour pass it replaced
//   springlab-bench pause --scene FILE [--runs R] [--timeline-mb M] [--busy] [--window]
//                                                    how long a Pause takes to stop a big scene's
//                                                    step and to make the snapshot answering it;
//                                                    then a Step and a scrub, paused; --window: in
//                                                    the editor's window, from the key to the
//                                                    picture (under xvfb-run without a display);
//                                                    --busy: with a loop keeping a core busy
//   springlab-bench mesh-import [--out DIR] [--runs R] [--frames N] [--quick]
//                                                    reading, making and compiling a model of
//                                                    100 000 triangles as each kind of body, and
//                                                    a streamed PC2 export's peak memory
//   springlab-bench write-references DIR             the reference problems as scene files
//
// The plots are painted into images, which needs an application for the fonts but no display:
// the program picks Qt's offscreen platform unless QT_QPA_PLATFORM says otherwise, or the mode
// opens the editor's window (pause --window), which needs a display.

#include "accuracy.h"
#include "cloth_contacts.h"
#include "mesh_import.h"
#include "rolling.h"
#include "contacts.h"
#include "pause_latency.h"
#include "pause_on_screen.h"
#include "reference_problems.h"
#include "stability.h"
#include "stiff.h"
#include "throughput.h"
#include "xpbd_substep.h"

#include "core/io/scene_file.h"
#include "ui/viewport/viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QSurfaceFormat>
#include <QTextStream>

#include <algorithm>
#include <optional>
#include <string_view>

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitBadArguments = 2;

const char *const kUsage =
    "usage: springlab-bench accuracy [--out DIR] [--quick]\n"
    "       springlab-bench stability [--out DIR] [--quick]\n"
    "       springlab-bench throughput [--out DIR] [--quick]\n"
    "       springlab-bench contacts [--out DIR] [--quick]\n"
    "       springlab-bench cloth-contacts [--out DIR] [--quick] [--size N]... [--seconds S]\n"
    "       springlab-bench rolling [--out DIR]\n"
    "       springlab-bench stiff [--out DIR] [--quick] [--size N]... [--stiffness K]...\n"
    "       springlab-bench xpbd-substep [--size N] [--stiffness K] [--substeps S] [--runs R] [--drape SECONDS]\n"
    "       springlab-bench pause --scene FILE [--runs R] [--timeline-mb M] [--busy] [--window]\n"
    "       springlab-bench mesh-import [--out DIR] [--runs R] [--frames N] [--quick]\n"
    "       springlab-bench write-references DIR\n";

int badArguments(QTextStream &err, const QString &message)
{
    err << "springlab-bench: " << message << '\n' << kUsage;
    return kExitBadArguments;
}

// parses a mode's arguments: nullopt to go on, else the exit code (bad arguments, or the help printed)
std::optional<int> parseMode(QCommandLineParser &parser, const QStringList &arguments, QTextStream &out,
                             QTextStream &err, const QString &mode)
{
    if (!parser.parse(arguments))
        return badArguments(err, parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out << parser.helpText();
        return kExitOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return badArguments(err, QStringLiteral("%1 takes no file names").arg(mode));
    return std::nullopt;
}

// a mode that takes --out DIR and --quick and nothing else: parses them and calls
// run(outDir, quick)
template <typename Run>
int sweepMode(const QStringList &arguments, QTextStream &out, QTextStream &err, const QString &mode,
              const QString &description, const QString &outHelp, const QString &quickHelp, Run run)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(description);
    parser.addHelpOption();
    const QCommandLineOption outOption(QStringLiteral("out"), outHelp, QStringLiteral("DIR"), QStringLiteral("."));
    const QCommandLineOption quickOption(QStringLiteral("quick"), quickHelp);
    parser.addOptions({outOption, quickOption});
    if (const std::optional<int> done = parseMode(parser, arguments, out, err, mode))
        return *done;
    return run(parser.value(outOption), parser.isSet(quickOption));
}

int accuracy(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    return sweepMode(arguments, out, err, QStringLiteral("accuracy"),
                     QStringLiteral("Error against run time for every integrator on the reference problems."),
                     QStringLiteral("Folder for the CSVs and plots (default: .)."),
                     QStringLiteral("A tiny sweep: a smoke test only."),
                     [&](const QString &dir, bool quick) { return bench::runAccuracy({dir, quick}, out); });
}

int stability(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    return sweepMode(
        arguments, out, err, QStringLiteral("stability"),
        QStringLiteral("Largest stable time step of the explicit integrators on spring chains, against theory."),
        QStringLiteral("Folder for the CSV and plot (default: .)."),
        QStringLiteral("A small grid, short trials: a smoke test only."),
        [&](const QString &dir, bool quick) { return bench::runStability({dir, quick}, out); });
}

int throughput(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    return sweepMode(
        arguments, out, err, QStringLiteral("throughput"),
        QStringLiteral("Run time per step of the core against plain and naive references and the memory bandwidth bound."),
        QStringLiteral("Folder for the CSV and plot (default: .)."),
        QStringLiteral("The smallest scenes, short timings: a smoke test only."),
        [&](const QString &dir, bool quick) { return bench::runThroughput({dir, quick}, out); });
}

int contacts(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    return sweepMode(
        arguments, out, err, QStringLiteral("contacts"),
        QStringLiteral("A column, a pyramid, piles and a heap of balls in the core and beside Bullet's rigid spheres."),
        QStringLiteral("Folder for the CSV and plot (default: .)."),
        QStringLiteral("Short runs and a small heap: a smoke test only."),
        [&](const QString &dir, bool quick) { return bench::runContacts({dir, quick}, out); });
}

int rolling(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Single balls struck on felt, rolling and sliding down slopes and struck with backspin: the "
                       "core and Bullet's rotating spheres beside the closed forms."));
    parser.addHelpOption();
    const QCommandLineOption outOption(QStringLiteral("out"), QStringLiteral("Folder for the CSV (default: .)."),
                                       QStringLiteral("DIR"), QStringLiteral("."));
    parser.addOptions({outOption});
    if (const std::optional<int> done = parseMode(parser, arguments, out, err, QStringLiteral("rolling")))
        return *done;
    return bench::runRolling(parser.value(outOption), out);
}

int meshImport(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("A sheet and a closed sphere of about 100 000 triangles: each read from OBJ, PLY, STL and glTF, "
                       "made into each kind of body and compiled, the median wall time of several runs; then the peak "
                       "memory of a PC2 export of a 200 x 200 sheet at 100 frames and at many."));
    parser.addHelpOption();
    const QCommandLineOption outOption(QStringLiteral("out"), QStringLiteral("Folder for the CSV (default: .)."),
                                       QStringLiteral("DIR"), QStringLiteral("."));
    const QCommandLineOption runsOption(QStringLiteral("runs"), QStringLiteral("Timed runs of each row (default 5)."),
                                        QStringLiteral("R"), QStringLiteral("5"));
    const QCommandLineOption quickOption(QStringLiteral("quick"),
                                         QStringLiteral("Meshes of about 2 000 triangles, one run: a smoke test only."));
    const QCommandLineOption framesOption(QStringLiteral("frames"),
                                          QStringLiteral("The long export's frames (default 2000; the short one has 100)."),
                                          QStringLiteral("N"), QStringLiteral("2000"));
    parser.addOptions({outOption, runsOption, quickOption, framesOption});
    if (const std::optional<int> done = parseMode(parser, arguments, out, err, QStringLiteral("mesh-import")))
        return *done;
    bool ok = false;
    const int runs = parser.value(runsOption).toInt(&ok);
    if (!ok || runs < 1 || runs > 1000)
        return badArguments(err, QStringLiteral("mesh-import: --runs must be a whole number from 1 to 1000, not \"%1\"")
                                     .arg(parser.value(runsOption)));
    const int frames = parser.value(framesOption).toInt(&ok);
    if (!ok || frames < 100 || frames > 100000)
        return badArguments(err, QStringLiteral("mesh-import: --frames must be a whole number from 100 to 100000, not \"%1\"")
                                     .arg(parser.value(framesOption)));
    return bench::runMeshImport({parser.value(outOption), runs, parser.isSet(quickOption), frames}, out);
}

int clothContacts(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("A sheet crumpling on the floor and one draping over a ball, with the core's triangle "
                       "collisions, with colliding beads instead and as Bullet's soft-body cloth: crossings and time a step."));
    parser.addHelpOption();
    const QCommandLineOption outOption(QStringLiteral("out"), QStringLiteral("Folder for the CSV (default: .)."),
                                       QStringLiteral("DIR"), QStringLiteral("."));
    const QCommandLineOption quickOption(QStringLiteral("quick"),
                                         QStringLiteral("A 16 x 16 sheet for 0.1 s: a smoke test only."));
    const QCommandLineOption sizeOption(QStringLiteral("size"),
                                        QStringLiteral("Only this sheet size (particles a side, 2 to 1000); repeatable."),
                                        QStringLiteral("N"));
    const QCommandLineOption secondsOption(
        QStringLiteral("seconds"), QStringLiteral("Simulated seconds a run (default: 2 at 64 a side and under, else 0.5)."),
        QStringLiteral("S"));
    parser.addOptions({outOption, quickOption, sizeOption, secondsOption});
    if (const std::optional<int> done = parseMode(parser, arguments, out, err, QStringLiteral("cloth-contacts")))
        return *done;
    bench::ClothContactsOptions options;
    options.outDir = parser.value(outOption);
    options.quick = parser.isSet(quickOption);
    for (const QString &text : parser.values(sizeOption)) {
        bool ok = false;
        const int size = text.toInt(&ok);
        if (!ok || size < 2 || size > 1000)
            return badArguments(err, QStringLiteral("--size: expected a whole number from 2 to 1000, got \"%1\"").arg(text));
        options.sizes.push_back(size);
    }
    if (parser.isSet(secondsOption)) {
        bool ok = false;
        options.seconds = parser.value(secondsOption).toDouble(&ok);
        if (!ok || !(options.seconds > 0.0) || options.seconds > 3600.0)
            return badArguments(err, QStringLiteral("--seconds: expected a number of seconds above 0 and up to 3600, got \"%1\"")
                                         .arg(parser.value(secondsOption)));
    }
    return bench::runClothContacts(options, out);
}

int stiff(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("A stiff cloth draping: the sub-steps and cost symplectic Euler, implicit Euler and xpbd need "
                       "to keep it within 1% stretch, against a fine reference."));
    parser.addHelpOption();
    const QCommandLineOption outOption(QStringLiteral("out"),
                                       QStringLiteral("Folder for the CSV, the summary and the plot (default: .)."),
                                       QStringLiteral("DIR"), QStringLiteral("."));
    const QCommandLineOption quickOption(QStringLiteral("quick"),
                                         QStringLiteral("A tiny cloth at two stiffnesses: a smoke test only."));
    const QCommandLineOption sizeOption(QStringLiteral("size"),
                                        QStringLiteral("Only this cloth size (particles a side); repeatable."),
                                        QStringLiteral("N"));
    const QCommandLineOption stiffnessOption(
        QStringLiteral("stiffness"), QStringLiteral("Only this structural stiffness (N/m); repeatable."),
        QStringLiteral("K"));
    parser.addOptions({outOption, quickOption, sizeOption, stiffnessOption});
    if (const std::optional<int> done = parseMode(parser, arguments, out, err, QStringLiteral("stiff")))
        return *done;
    bench::StiffOptions options{parser.value(outOption), parser.isSet(quickOption), {}, {}};
    for (const QString &text : parser.values(sizeOption)) {
        bool ok = false;
        const int size = text.toInt(&ok);
        if (!ok || size < 2)
            return badArguments(err, QStringLiteral("--size: expected a whole number from 2, got \"%1\"").arg(text));
        options.sizes.push_back(size);
    }
    for (const QString &text : parser.values(stiffnessOption)) {
        bool ok = false;
        const double k = text.toDouble(&ok);
        if (!ok || !(k > 0.0))
            return badArguments(err, QStringLiteral("--stiffness: expected a positive number, got \"%1\"").arg(text));
        options.stiffness.push_back(k);
    }
    return bench::runStiff(options, out);
}

int xpbdSubStep(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("The cost of one xpbd sub-step on the stiff cloth: the core's pass beside the colour-by-colour "
                       "pass it replaced and symplectic Euler's sub-step, on 1 and 2 threads."));
    parser.addHelpOption();
    const bench::XpbdSubStepOptions defaults;
    const QCommandLineOption size(QStringLiteral("size"), QStringLiteral("Particles a side."), QStringLiteral("N"),
                                  QString::number(defaults.size));
    const QCommandLineOption stiffness(QStringLiteral("stiffness"), QStringLiteral("Structural stiffness, N/m."),
                                       QStringLiteral("K"), QString::number(defaults.stiffness));
    const QCommandLineOption substeps(QStringLiteral("substeps"), QStringLiteral("Sub-steps a 0.01 s step."),
                                      QStringLiteral("S"), QString::number(defaults.substeps));
    const QCommandLineOption runs(QStringLiteral("runs"), QStringLiteral("Timed runs of each variant."),
                                  QStringLiteral("R"), QString::number(defaults.runs));
    const QCommandLineOption drape(QStringLiteral("drape"),
                                   QStringLiteral("Seconds of draping to read the stretch over (0: none)."),
                                   QStringLiteral("SECONDS"), QString::number(defaults.drape));
    parser.addOptions({size, stiffness, substeps, runs, drape});
    if (const std::optional<int> done = parseMode(parser, arguments, out, err, QStringLiteral("xpbd-substep")))
        return *done;
    bench::XpbdSubStepOptions options;
    bool ok[5] = {};
    options.size = parser.value(size).toInt(&ok[0]);
    options.stiffness = parser.value(stiffness).toDouble(&ok[1]);
    options.substeps = parser.value(substeps).toInt(&ok[2]);
    options.runs = parser.value(runs).toInt(&ok[3]);
    options.drape = parser.value(drape).toDouble(&ok[4]);
    if (!(ok[0] && ok[1] && ok[2] && ok[3] && ok[4]) || options.size < 2 || !(options.stiffness > 0.0) ||
        options.substeps < 1 || options.runs < 1 || !(options.drape >= 0.0))
        return badArguments(err, QStringLiteral("xpbd-substep: a value is not a number in its range"));
    return bench::runXpbdSubStep(options, out);
}

int pause(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("How long a Pause takes on a scene, without the window: the step cut short and put back, "
                       "and the snapshot of the state it stopped at; with --window, in the editor's window from "
                       "the key to the picture of Pause, Step and Step Back."));
    parser.addHelpOption();
    const bench::PauseLatencyOptions defaults;
    const QCommandLineOption scene(QStringLiteral("scene"), QStringLiteral("The scene file to play."),
                                   QStringLiteral("FILE"));
    const QCommandLineOption runs(QStringLiteral("runs"), QStringLiteral("Pauses timed."), QStringLiteral("R"),
                                  QString::number(defaults.runs));
    const QCommandLineOption timeline(QStringLiteral("timeline-mb"),
                                      QStringLiteral("The recording's budget, MB (the editor's default: 512)."),
                                      QStringLiteral("M"), QString::number(defaults.timelineMegabytes));
    const QCommandLineOption busy(QStringLiteral("busy"), QStringLiteral("Keep one core busy all along."));
    const QCommandLineOption window(QStringLiteral("window"),
                                    QStringLiteral("In the editor's window, from the key to the picture (needs a "
                                                   "display: run under xvfb-run)."));
    parser.addOptions({scene, runs, timeline, busy, window});
    if (const std::optional<int> done = parseMode(parser, arguments, out, err, QStringLiteral("pause")))
        return *done;
    bench::PauseLatencyOptions options;
    bool ok = false, timelineOk = false;
    options.scene = parser.value(scene);
    options.runs = parser.value(runs).toInt(&ok);
    options.timelineMegabytes = parser.value(timeline).toInt(&timelineOk);
    if (options.scene.isEmpty())
        return badArguments(err, QStringLiteral("pause: --scene FILE is needed"));
    if (!ok || options.runs < 1)
        return badArguments(err, QStringLiteral("pause: --runs must be a whole number of at least 1"));
    if (!timelineOk || options.timelineMegabytes < 0 || options.timelineMegabytes > (1 << 20))
        return badArguments(err, QStringLiteral("pause: --timeline-mb must be a whole number from 0 to 1048576"));
    options.busy = parser.isSet(busy);
    options.window = parser.isSet(window);
    return options.window ? bench::runPauseOnScreen(options, out, err) : bench::runPauseLatency(options, out, err);
}

// every reference problem's scene, saved as DIR/<name>.json
int writeReferences(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    if (arguments.size() != 2)
        return badArguments(err, QStringLiteral("write-references takes one folder"));
    const QDir dir(arguments[1]);
    if (!dir.mkpath(QStringLiteral(".")))
        return badArguments(err, QStringLiteral("cannot create the folder %1").arg(arguments[1]));
    for (const bench::ReferenceProblem &problem : bench::referenceProblems()) {
        const QString path = dir.filePath(QString::fromStdString(problem.name) + QStringLiteral(".json"));
        const io::SaveResult saved = io::saveScene(path, problem.scene);
        if (!saved.ok()) {
            err << "springlab-bench: " << saved.error << '\n';
            return kExitFailed;
        }
        out << "wrote " << path << '\n';
    }
    return kExitOk;
}

}  // namespace

int main(int argc, char *argv[])
{
    // painting text needs a platform, not a display; the editor's window needs both, and OpenGL
    // set up as the editor's main() sets it, before the application exists
    const bool window = argc > 1 && std::string_view(argv[1]) == "pause" &&
                        std::any_of(argv + 2, argv + argc, [](const char *a) { return std::string_view(a) == "--window"; });
    if (window) {
        QSurfaceFormat::setDefaultFormat(ui::Viewport::requestedFormat());
        QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    } else if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    QApplication app(argc, argv);
    QTextStream out(stdout);
    QTextStream err(stderr);

    // the first argument names the benchmark; the rest are its own
    QStringList arguments = QApplication::arguments();
    if (arguments.size() < 2)
        return badArguments(err, QStringLiteral("which benchmark?"));
    const QString name = arguments[1];
    arguments.removeAt(1);
    if (name == QStringLiteral("accuracy"))
        return accuracy(arguments, out, err);
    if (name == QStringLiteral("stability"))
        return stability(arguments, out, err);
    if (name == QStringLiteral("throughput"))
        return throughput(arguments, out, err);
    if (name == QStringLiteral("contacts"))
        return contacts(arguments, out, err);
    if (name == QStringLiteral("cloth-contacts"))
        return clothContacts(arguments, out, err);
    if (name == QStringLiteral("rolling"))
        return rolling(arguments, out, err);
    if (name == QStringLiteral("mesh-import"))
        return meshImport(arguments, out, err);
    if (name == QStringLiteral("stiff"))
        return stiff(arguments, out, err);
    if (name == QStringLiteral("xpbd-substep"))
        return xpbdSubStep(arguments, out, err);
    if (name == QStringLiteral("pause"))
        return pause(arguments, out, err);
    if (name == QStringLiteral("write-references"))
        return writeReferences(arguments, out, err);
    if (name == QStringLiteral("--help") || name == QStringLiteral("-h")) {
        out << kUsage;
        return kExitOk;
    }
    return badArguments(err, QStringLiteral("unknown benchmark \"%1\"").arg(name));
}
