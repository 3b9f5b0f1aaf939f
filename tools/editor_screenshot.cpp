// Takes the pictures of the editor in docs/images/: opens a scene (a file or an example's name),
// takes STEPS steps, optionally scrubs back to step SCRUB on the timeline, and saves the whole
// window as a PNG. Needs a display; under none, run it as
//   xvfb-run -a -s "-screen 0 1600x1000x24" build/release/tools/editor_screenshot tearable-cloth 60 45 out.png
#include "ui/main_window.h"
#include "ui/simulation_controller.h"
#include "ui/simulation_frame.h"
#include "ui/viewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QThread>
#include <cstdio>

namespace {

// the newest frame once every edit so far is applied, or null after ten minutes
std::shared_ptr<const ui::SimulationFrame> settled(ui::SimulationController &controller)
{
    const std::uint64_t sequence = controller.sync();
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 600000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        const auto frame = controller.frame();
        if (frame && frame->appliedEdit >= sequence)
            return frame;
    }
    return nullptr;
}

}  // namespace

int main(int argc, char *argv[])
{
    QSurfaceFormat::setDefaultFormat(ui::Viewport::requestedFormat());
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    const QStringList arguments = app.arguments();
    if (arguments.size() != 4 && arguments.size() != 5) {
        std::fprintf(stderr, "usage: %s SCENE STEPS [SCRUB] OUT.png\n", qPrintable(arguments.front()));
        return 2;
    }
    // the settings of a throwaway folder: a picture shows the default layout, not the user's
    QTemporaryDir settings;
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings.path());

    ui::MainWindow window;
    window.resize(1400, 860);
    window.show();
    const QString scene = arguments[1];
    QString error;
    const bool opened = scene.endsWith(QStringLiteral(".json")) ? window.openScene(scene, &error)
                                                                  : window.openExample(scene, &error);
    if (!opened) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    ui::SimulationController &controller = *window.controller();
    const int steps = arguments[2].toInt();
    for (int i = 0; i < steps; ++i)
        controller.stepOnce();
    if (arguments.size() == 5)
        controller.scrub(arguments[3].toULongLong());
    if (!settled(controller)) {
        std::fprintf(stderr, "no frame from the worker\n");
        return 1;
    }
    // a few more turns of the event loop so that the view and the docks have painted the frame
    for (int i = 0; i < 20; ++i) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(10);
    }
    const QString out = arguments.back();
    if (!window.grab().save(out, "PNG")) {
        std::fprintf(stderr, "cannot write %s\n", qPrintable(out));
        return 1;
    }
    std::printf("wrote %s\n", qPrintable(out));
    return 0;
}
