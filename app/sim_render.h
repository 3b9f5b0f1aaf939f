#pragma once
// springlab-sim --render: the run drawn into PNG frames (ui/image_sequence.h) by the editor's own
// 3D view, offscreen, framed on the scene as View › Frame All frames it. Drawing needs OpenGL, so
// --render alone makes a QApplication, on the xcb platform, and needs an X display: without one
// it stops with exit code 2 and says to run it under a virtual X server (xvfb-run -a). Every
// other mode of springlab-sim runs without a display.

#include "core/model/model.h"
#include "core/model/scene.h"
#include "core/model/state.h"

#include <QCoreApplication>
#include <QSize>
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

namespace ui {
class Viewport;
}

namespace app {

// whether the command line asks for --render (looked at before any application exists)
bool asksToRender(int argc, char *argv[]);

// the application: a QApplication for --render, a QCoreApplication otherwise; null, with the
// message in error, when --render has no display to draw on
std::unique_ptr<QCoreApplication> makeApplication(int &argc, char *argv[], bool render, QString *error);

class FrameRenderer {
public:
    FrameRenderer();
    ~FrameRenderer();

    // makes the folder (removing frames of an earlier sequence) and the view, for frames at fps
    // over a run of totalSteps steps; empty on success, else the message
    QString open(const QString &folder, QSize size, double fps, const core::SceneDesc &scene,
                 std::uint64_t totalSteps);

    // the step of the next frame due (the run should stop there), or totalSteps when none is left
    std::uint64_t nextStep(std::uint64_t totalSteps) const;
    // draws and writes every frame due at the state's step; empty on success, else the message
    QString renderDue(const core::Model &model, const core::State &state);

    int frameCount() const { return static_cast<int>(m_steps.size()); }
    int framesWritten() const { return m_next; }
    int framesRemoved() const { return m_removed; }

private:
    std::unique_ptr<ui::Viewport> m_viewport;
    QString m_folder;
    QSize m_size;
    std::vector<std::uint64_t> m_steps;  // the frames' steps
    int m_next = 0;                      // the next frame to write
    int m_removed = 0;                   // frames of an earlier sequence removed from the folder
};

}  // namespace app
