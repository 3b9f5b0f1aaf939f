// springlab: the editor. `springlab [SCENE.json]` opens the scene, or the springs example without
// one; a file that cannot be opened is reported and the editor opens on the example instead. A
// session that crashed with unsaved changes is offered back first. `--play` starts the run at
// once; `--exit-after SECONDS` ends the editor after that long and prints the steps/s and
// frames/s it reached (ui/window/timed_play.h), to compare machines and for the benchmark.

#include "ui/document/document_files.h"
#include "ui/document/recent_files.h"
#include "ui/window/main_window.h"
#include "ui/window/timed_play.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <cstdio>

int main(int argc, char *argv[])
{
    // OpenGL settings must be in place before the application exists
    QSurfaceFormat::setDefaultFormat(ui::Viewport::requestedFormat());
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);

    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("Springlab"));
    QCoreApplication::setApplicationName(QStringLiteral("Springlab"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SPRINGLAB_VERSION));

    // the command line: an optional scene file, and the timed run
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Editor for particle and mass-spring physics."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("scene"),
                                 QStringLiteral("Scene file to open (default: the springs example)."),
                                 QStringLiteral("[SCENE.json]"));
    const QCommandLineOption play(QStringLiteral("play"), QStringLiteral("Start the simulation once the scene is open."));
    const QCommandLineOption exitAfter(
        QStringLiteral("exit-after"),
        QStringLiteral("Quit after SECONDS of wall time, printing the steps/s and frames/s reached since the start."),
        QStringLiteral("SECONDS"));
    parser.addOptions({play, exitAfter});
    parser.process(app);
    const QStringList arguments = parser.positionalArguments();
    if (arguments.size() > 1) {
        std::fprintf(stderr, "springlab: expected at most one scene file, got %d\n", int(arguments.size()));
        return 2;
    }
    double seconds = 0.0;
    if (parser.isSet(exitAfter)) {
        bool ok = false;
        seconds = parser.value(exitAfter).toDouble(&ok);
        if (!ok || !(seconds > 0.0) || seconds > 86400.0) {
            std::fprintf(stderr, "springlab: --exit-after takes a number of seconds above 0 and at most 86400, got \"%s\"\n",
                         qPrintable(parser.value(exitAfter)));
            return 2;
        }
    }

    ui::MainWindow window;
    window.show();
    // a timed run measures the machine; the scenes it opens are not the user's recent files
    if (parser.isSet(exitAfter))
        window.files()->recentFiles()->setRemembering(false);

    // work a crash left behind is offered first; a scene that cannot be opened is reported (here
    // and in a message), and the example stays open
    QString error;
    if (!window.files()->start(arguments.isEmpty() ? QString() : arguments.front(), &error))
        std::fprintf(stderr, "springlab: %s\n", qPrintable(error));

    // the timed run, or just the run
    if (parser.isSet(exitAfter)) {
        auto *timed = new ui::TimedPlay(window, parser.isSet(play), seconds, &window);
        timed->start();
    } else if (parser.isSet(play)) {
        window.controller()->play();
    }
    return app.exec();
}
