// springlab-bench: the benchmark programs, one per first argument.
//   springlab-bench accuracy [--out DIR] [--quick]   error against run time (docs/benchmarks.md)
//   springlab-bench stability [--out DIR] [--quick]  largest stable time step against theory
//   springlab-bench throughput [--out DIR] [--quick] run time per step against references and the
//                                                    memory bandwidth bound
//   springlab-bench contacts [--out DIR] [--quick]   stacks, piles and a heap beside Bullet's rigid
//                                                    spheres: what stands, what settles, the cost
//   springlab-bench stiff [--out DIR] [--quick]      a stiff cloth: the sub-steps and cost each of
//                                                    symplectic Euler, implicit Euler and xpbd needs
//                                                    to stay within 1% stretch
//   springlab-bench write-references DIR             the reference problems as scene files
//
// The plots are painted into images, which needs a QGuiApplication for the fonts but no display:
// the program picks Qt's offscreen platform unless QT_QPA_PLATFORM says otherwise.

#include "accuracy.h"
#include "contacts.h"
#include "reference_problems.h"
#include "stability.h"
#include "stiff.h"
#include "throughput.h"

#include "core/io/scene_file.h"

#include <QCommandLineParser>
#include <QDir>
#include <QGuiApplication>
#include <QTextStream>

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitBadArguments = 2;

const char *const kUsage =
    "usage: springlab-bench accuracy [--out DIR] [--quick]\n"
    "       springlab-bench stability [--out DIR] [--quick]\n"
    "       springlab-bench throughput [--out DIR] [--quick]\n"
    "       springlab-bench contacts [--out DIR] [--quick]\n"
    "       springlab-bench stiff [--out DIR] [--quick]\n"
    "       springlab-bench write-references DIR\n";

int badArguments(QTextStream &err, const QString &message)
{
    err << "springlab-bench: " << message << '\n' << kUsage;
    return kExitBadArguments;
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
    if (!parser.parse(arguments))
        return badArguments(err, parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out << parser.helpText();
        return kExitOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return badArguments(err, QStringLiteral("%1 takes no file names").arg(mode));
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

int stiff(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    return sweepMode(
        arguments, out, err, QStringLiteral("stiff"),
        QStringLiteral("A stiff cloth draping: the sub-steps and cost symplectic Euler, implicit Euler and xpbd need "
                       "to keep it within 1% stretch, against a fine reference."),
        QStringLiteral("Folder for the CSV, the summary and the plot (default: .)."),
        QStringLiteral("A tiny cloth at two stiffnesses: a smoke test only."),
        [&](const QString &dir, bool quick) { return bench::runStiff({dir, quick}, out); });
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
    // painting text needs a platform, not a display
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    QTextStream out(stdout);
    QTextStream err(stderr);

    // the first argument names the benchmark; the rest are its own
    QStringList arguments = QGuiApplication::arguments();
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
    if (name == QStringLiteral("stiff"))
        return stiff(arguments, out, err);
    if (name == QStringLiteral("write-references"))
        return writeReferences(arguments, out, err);
    if (name == QStringLiteral("--help") || name == QStringLiteral("-h")) {
        out << kUsage;
        return kExitOk;
    }
    return badArguments(err, QStringLiteral("unknown benchmark \"%1\"").arg(name));
}
