// Takes the pictures of the editor in docs/images/, by hand, outside the test run. Three kinds:
//   editor_screenshot SCENE STEPS [SCRUB] OUT.png   the whole window on a scene (a file or an
//                                                   example's name) after STEPS steps, optionally
//                                                   scrubbed back to step SCRUB on the timeline
//   editor_screenshot --generate-dialog OUT.png     Edit › Generate… on a soft ball of 200 points
//   editor_screenshot --plots FOLDER                the plots dock after 2.5 s of the springs
//                                                   example: plots-energies.png and
//                                                   plots-particle-velocity.png
// Needs a display; under none, run it as, e.g.
//   xvfb-run -a -s "-screen 0 1600x1000x24" build/release/tools/editor_screenshot tearable-cloth 60 45 out.png
//   xvfb-run -a -s "-screen 0 1600x1000x24" build/release/tools/editor_screenshot --generate-dialog docs/images/generate-dialog.png
//   xvfb-run -a -s "-screen 0 1600x1000x24" build/release/tools/editor_screenshot --plots docs/images
#include "ui/viewport/edit_tools.h"
#include "ui/dialogs/generate_dialog.h"
#include "ui/dialogs/generate_preview.h"
#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/panels/plots_widget.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "session/simulation_frame.h"
#include "ui/viewport/viewport.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QDeadlineTimer>
#include <QSettings>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QThread>
#include <cstdio>

namespace {

// runs the event loop until done() or timeoutMs; false on timeout
template <typename Done>
bool waitFor(Done &&done, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    while (!done() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return done();
}

// the newest frame once every edit so far is applied, or null after ten minutes
std::shared_ptr<const ui::SimulationFrame> settled(ui::SimulationController &controller)
{
    const std::uint64_t sequence = controller.sync();
    const auto applied = [&] { return controller.frame() && controller.frame()->appliedMessage >= sequence; };
    return waitFor(applied, 600000) ? controller.frame() : nullptr;
}

// a few more turns of the event loop, so that the view and the docks have painted the frame
void letItPaint()
{
    for (int i = 0; i < 20; ++i) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(10);
    }
}

int fail(const QString &why)
{
    std::fprintf(stderr, "editor_screenshot: %s\n", qPrintable(why));
    return 1;
}

int save(const QPixmap &picture, const QString &path)
{
    if (!picture.save(path, "PNG"))
        return fail(QStringLiteral("cannot write ") + path);
    std::printf("wrote %s\n", qPrintable(path));
    return 0;
}

// the whole window on a scene, after `steps` steps, scrubbed back to step `scrub` if not negative
int windowPicture(ui::MainWindow &window, const QString &scene, int steps, qlonglong scrub, const QString &out)
{
    window.resize(1400, 860);
    window.show();
    QString error;
    const bool opened = scene.endsWith(QStringLiteral(".json")) ? window.files()->openScene(scene, &error)
                                                                : window.files()->openExample(scene, &error);
    if (!opened)
        return fail(error);
    ui::SimulationController &controller = *window.controller();
    for (int i = 0; i < steps; ++i)
        controller.stepOnce();
    if (scrub >= 0)
        controller.scrub(std::uint64_t(scrub));
    if (!settled(controller))
        return fail(QStringLiteral("no frame from the worker"));
    letItPaint();
    return save(window.grab(), out);
}

// Edit › Generate… on a soft ball of 200 points of radius 15 mm, once its preview shows them
int generateDialogPicture(ui::MainWindow &window, const QString &out)
{
    window.show();
    if (!settled(*window.controller()))
        return fail(QStringLiteral("no frame from the worker"));
    auto *generate = window.findChild<QAction *>(QStringLiteral("actionGenerate"));
    if (!generate)
        return fail(QStringLiteral("no Edit › Generate… action"));
    generate->trigger();
    ui::GenerateDialog *dialog = window.generateDialog();
    if (!dialog || !waitFor([&] { return dialog->isVisible(); }, 10000))
        return fail(QStringLiteral("the Generate dialog did not open"));
    dialog->kindBox()->setCurrentIndex(int(ui::GenerateDialog::Kind::SoftBall));
    auto *points = dialog->findChild<QSpinBox *>(QStringLiteral("generate-softBall-points"));
    auto *radius = dialog->findChild<QDoubleSpinBox *>(QStringLiteral("generate-softBall-radius"));
    if (!points || !radius)
        return fail(QStringLiteral("no soft ball fields in the Generate dialog"));
    points->setValue(200);
    radius->setValue(0.015);  // m
    // the points and the centre
    if (!waitFor([&] { return dialog->preview()->drawnParticles() == 201; }, 10000))
        return fail(QStringLiteral("the preview never drew the soft ball"));
    letItPaint();
    return save(dialog->grab(), out);
}

// the plots dock on the springs example after 250 steps, each step a sample: the energies and the
// middle particle's velocity
int plotsPictures(ui::MainWindow &window, const QString &folder)
{
    window.resize(1000, 760);
    window.show();
    QString error;
    if (!window.files()->openExample(QStringLiteral("springs"), &error))
        return fail(error);
    ui::SimulationController &controller = *window.controller();
    if (!settled(controller))
        return fail(QStringLiteral("no frame from the worker"));
    auto *showPlots = window.findChild<QAction *>(QStringLiteral("actionPlots"));
    if (!showPlots)
        return fail(QStringLiteral("no View › Plots action"));
    showPlots->trigger();
    const int middle = int(window.document()->scene().particles.size() / 2);
    window.editTools()->setSelection({{middle}, {}});
    // step by step, so that every step is a sample even where the window draws slowly
    for (int i = 0; i < 250; ++i) {
        controller.stepOnce();
        if (!settled(controller))
            return fail(QStringLiteral("no frame from the worker"));
    }
    letItPaint();
    if (!QDir().mkpath(folder))
        return fail(QStringLiteral("cannot make ") + folder);
    for (const auto &[group, name] : {std::pair{ui::PlotGroup::Energies, "plots-energies.png"},
                                      std::pair{ui::PlotGroup::Velocity, "plots-particle-velocity.png"}}) {
        window.plots()->setGroup(group);
        letItPaint();
        if (const int failed = save(window.plots()->grab(), QDir(folder).filePath(QString::fromLatin1(name))))
            return failed;
    }
    return 0;
}

int usage(const QString &program)
{
    std::fprintf(stderr,
                 "usage: %s SCENE STEPS [SCRUB] OUT.png\n"
                 "       %s --generate-dialog OUT.png\n"
                 "       %s --plots FOLDER\n",
                 qPrintable(program), qPrintable(program), qPrintable(program));
    return 2;
}

}  // namespace

int main(int argc, char *argv[])
{
    QSurfaceFormat::setDefaultFormat(ui::Viewport::requestedFormat());
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    const QStringList arguments = app.arguments();
    const bool special = arguments.size() == 3 && arguments[1].startsWith(QStringLiteral("--"));
    if (!special && arguments.size() != 4 && arguments.size() != 5)
        return usage(arguments.front());
    // the settings of a throwaway folder: a picture shows the default layout, not the user's
    QTemporaryDir settings;
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings.path());

    ui::MainWindow window;
    if (arguments[1] == QStringLiteral("--generate-dialog") && special)
        return generateDialogPicture(window, arguments[2]);
    if (arguments[1] == QStringLiteral("--plots") && special)
        return plotsPictures(window, arguments[2]);
    if (special)
        return usage(arguments.front());
    const qlonglong scrub = arguments.size() == 5 ? arguments[3].toLongLong() : -1;
    return windowPicture(window, arguments[1], arguments[2].toInt(), scrub, arguments.back());
}
