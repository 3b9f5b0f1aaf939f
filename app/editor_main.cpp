// springlab: the editor. `springlab [SCENE.json]` opens the scene, or the springs example without
// one; a file that cannot be opened is reported and the editor opens on the example instead. A
// session that crashed with unsaved changes is offered back first.

#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
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

    // the command line: an optional scene file
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Editor for particle and mass-spring physics."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("scene"),
                                 QStringLiteral("Scene file to open (default: the springs example)."),
                                 QStringLiteral("[SCENE.json]"));
    parser.process(app);
    const QStringList arguments = parser.positionalArguments();
    if (arguments.size() > 1) {
        std::fprintf(stderr, "springlab: expected at most one scene file, got %d\n", int(arguments.size()));
        return 2;
    }

    ui::MainWindow window;
    window.show();

    // work a crash left behind is offered first; a scene that cannot be opened is reported (here
    // and in a message), and the example stays open
    QString error;
    if (!window.files()->start(arguments.isEmpty() ? QString() : arguments.front(), &error))
        std::fprintf(stderr, "springlab: %s\n", qPrintable(error));
    return app.exec();
}
