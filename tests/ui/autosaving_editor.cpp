// The editor's main window in a process of its own, for test_crash_recovery to kill: it opens a
// scene, changes it twice through the undo stack as the editor's commands do, waits for autosave
// to write the recovery file, saves the scene it expects to be recovered, prints "autosaved" and
// then runs until it is killed.
//
//   autosaving_editor SETTINGS_DIR SCENE.json EXPECTED.json

#include "ui/document/autosave.h"
#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "ui/viewport/viewport.h"

#include "core/io/scene_file.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTimer>
#include <cstdio>

#include "editor_test_setup.h"

namespace {

// waits (running the event loop) until done() or timeoutMs; false on timeout
template <typename Done>
bool waitFor(Done &&done, int timeoutMs)
{
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (clock.elapsed() > timeoutMs)
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    }
    return true;
}

}  // namespace

int main(int argc, char *argv[])
{
    test::prepareOpenGL();
    QApplication app(argc, argv);
    if (argc != 4) {
        std::fprintf(stderr, "usage: autosaving_editor SETTINGS_DIR SCENE.json EXPECTED.json\n");
        return 2;
    }
    // the settings the test wrote: its recovery folder and a one-second autosave
    test::useSettingsIn(QString::fromLocal8Bit(argv[1]), QStringLiteral("test_crash_recovery"));

    ui::MainWindow window;
    window.show();
    QString error;
    if (!window.files()->start(QString::fromLocal8Bit(argv[2]), &error)) {
        std::fprintf(stderr, "autosaving_editor: %s\n", qPrintable(error));
        return 1;
    }

    // two changes, as the parameters panel makes them
    ui::SceneDocument &document = *window.document();
    for (double viscosity : {0.5, 0.75}) {
        core::Settings settings = document.scene().settings;
        settings.viscosity = viscosity;
        document.undoStack()->push(
            new ui::SettingsCommand(document, QStringLiteral("viscosity"), QString(), settings));
    }
    const QString recovery = window.files()->autosave()->recoveryPath();
    if (!waitFor([&] { return QFileInfo::exists(recovery); }, 30000)) {
        std::fprintf(stderr, "autosaving_editor: no recovery file after 30 s\n");
        return 1;
    }
    const io::SaveResult saved = io::saveScene(QString::fromLocal8Bit(argv[3]), document.scene());
    if (!saved.ok()) {
        std::fprintf(stderr, "autosaving_editor: %s\n", qPrintable(saved.error));
        return 1;
    }
    std::printf("autosaved %s\n", qPrintable(recovery));
    std::fflush(stdout);
    return app.exec();
}
