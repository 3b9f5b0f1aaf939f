#include "sim_render.h"

#include "ui/export/image_sequence.h"
#include "ui/viewport/viewport.h"

#include "core/model/snapshot.h"

#include <QApplication>
#include <QDir>
#include <QSurfaceFormat>

#include <algorithm>
#include <cstring>
#include <chrono>
#include <dlfcn.h>
#include <thread>

namespace app {

using namespace Qt::Literals::StringLiterals;

bool asksToRender(int argc, char *argv[])
{
    // --render DIR or --render=DIR, before any "--" that ends the options
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--") == 0)
            return false;
        if (std::strcmp(argv[i], "--render") == 0 || std::strncmp(argv[i], "--render=", 9) == 0)
            return true;
    }
    return false;
}

namespace {

// Whether an X server answers at DISPLAY. Qt's xcb platform aborts the program when none does, so
// the connection is tried first, with the library that platform loads anyway (libxcb), opened at
// run time so that building needs no X headers. Empty when it answers, else why not.
QString displayProblem()
{
    // (never unloaded: Qt's xcb platform loads the same library next, and unmapping it under
    // anything it registered made the program crash at exit now and then)
    void *xcb = dlopen("libxcb.so.1", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (!xcb)
        return u"libxcb.so.1, which Qt's xcb platform draws through, cannot be loaded"_s;
    using Connect = void *(*)(const char *, int *);
    using HasError = int (*)(void *);
    using Disconnect = void (*)(void *);
    const auto connect = reinterpret_cast<Connect>(dlsym(xcb, "xcb_connect"));
    const auto hasError = reinterpret_cast<HasError>(dlsym(xcb, "xcb_connection_has_error"));
    const auto disconnect = reinterpret_cast<Disconnect>(dlsym(xcb, "xcb_disconnect"));
    QString problem;
    if (!connect || !hasError || !disconnect) {
        problem = u"libxcb.so.1 lacks xcb_connect"_s;
    } else {
        // A connection that answered stays open for the program's life: closing the server's last
        // client makes an X server reset (Xvfb under xvfb-run does), and Qt's own connection,
        // made a moment later, then failed now and then and aborted. (A failed connection is
        // still an object to disconnect.)
        // A server that is resetting (its last client just left) refuses for a moment: a few
        // tries, 50 ms apart, before it counts as absent.
        void *connection = connect(nullptr, nullptr);
        for (int attempt = 1; attempt < 5 && hasError(connection) != 0; ++attempt) {
            disconnect(connection);
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            connection = connect(nullptr, nullptr);
        }
        if (hasError(connection) != 0) {
            problem = u"no X server answers at DISPLAY=%1"_s.arg(qEnvironmentVariable("DISPLAY"));
            disconnect(connection);
        }
    }
    return problem;
}

}  // namespace

std::unique_ptr<QCoreApplication> makeApplication(int &argc, char *argv[], bool render, QString *error)
{
    if (!render)
        return std::make_unique<QCoreApplication>(argc, argv);

    // Qt's xcb platform: the offscreen one cannot host the view's QOpenGLWidget; and xcb without
    // a display would abort, so that is checked first
    if (qEnvironmentVariableIsEmpty("DISPLAY")) {
        *error = u"--render draws with OpenGL and needs an X display, but DISPLAY is not set; run it under a "
                 "virtual X server: xvfb-run -a springlab-sim SCENE.json --render DIR"_s;
        return nullptr;
    }
    if (const QString problem = displayProblem(); !problem.isEmpty()) {
        *error = u"--render draws with OpenGL and needs an X display, but "_s + problem +
                 u"; run it under a virtual X server: xvfb-run -a springlab-sim SCENE.json --render DIR"_s;
        return nullptr;
    }
    qputenv("QT_QPA_PLATFORM", "xcb");
    QSurfaceFormat::setDefaultFormat(ui::Viewport::requestedFormat());
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    return std::make_unique<QApplication>(argc, argv);
}

FrameRenderer::FrameRenderer() = default;
FrameRenderer::~FrameRenderer() = default;

QString FrameRenderer::open(const QString &folder, QSize size, double fps, const core::SceneDesc &scene,
                            std::uint64_t totalSteps)
{
    // the folder, without frames left from an earlier sequence
    m_folder = folder;
    m_size = size;
    if (!QDir().mkpath(folder))
        return u"--render: cannot create the folder "_s + QDir::toNativeSeparators(folder);
    m_removed = static_cast<int>(ui::sequenceFramesIn(folder).size());
    if (const QString failure = ui::removeSequenceFrames(folder); !failure.isEmpty())
        return u"--render: "_s + failure;

    // frames over the run's simulated time, none past its end
    const double timeStep = scene.settings.timeStep;
    const int count = ui::sequenceFrameCount(fps, static_cast<double>(totalSteps) * timeStep);
    m_steps = ui::sequenceFrameSteps(fps, count, timeStep);
    for (std::uint64_t &step : m_steps)
        step = std::min(step, totalSteps);

    // the editor's view, never on screen, at the frames' size so that framing fits them
    m_viewport = std::make_unique<ui::Viewport>();
    m_viewport->setAttribute(Qt::WA_DontShowOnScreen);
    m_viewport->setMinimumSize(1, 1);
    m_viewport->resize(size);
    m_viewport->setPlanes(scene.planes);
    m_viewport->show();
    if (m_viewport->maxImageSide() == 0)
        return u"--render: no OpenGL 3.3 on this display (Mesa's llvmpipe under xvfb-run has it)"_s;
    if (size.width() > m_viewport->maxImageSide() || size.height() > m_viewport->maxImageSide())
        return u"--size: %1x%2 is larger than this OpenGL driver can draw: at most %3 px a side"_s.arg(size.width())
            .arg(size.height())
            .arg(m_viewport->maxImageSide());
    return {};
}

std::uint64_t FrameRenderer::nextStep(std::uint64_t totalSteps) const
{
    return m_next < frameCount() ? m_steps[static_cast<std::size_t>(m_next)] : totalSteps;
}

QString FrameRenderer::renderDue(const core::Model &model, const core::State &state)
{
    if (m_next >= frameCount() || m_steps[static_cast<std::size_t>(m_next)] != state.step)
        return {};

    // the first frame frames the view on the particles; later ones keep that camera
    m_viewport->setSnapshot(core::makeSnapshot(model, state));
    QString error;
    const QImage image = m_viewport->renderImage(m_size, &error);
    if (image.isNull())
        return u"--render: frame %1: "_s.arg(m_next) + error;

    // every frame due at this step (several when a step is longer than a frame)
    for (; m_next < frameCount() && m_steps[static_cast<std::size_t>(m_next)] == state.step; ++m_next) {
        const QString path = ui::sequenceFramePath(m_folder, m_next);
        if (!image.save(path, "PNG"))
            return u"--render: cannot write "_s + QDir::toNativeSeparators(path);
    }
    return {};
}

}  // namespace app
