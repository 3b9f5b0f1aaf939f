#pragma once
// Exporter: File › Export. The view as a PNG of any size (an offscreen framebuffer), an image
// sequence of the run with an MP4 of it where ffmpeg is installed, the run's trace as CSV, and
// (File › Export Animation) the deforming surfaces for Blender: a PC2 cache and OBJ frames.
// The sequence and the trace step the worker's run from where it is (ExportRun), with a progress
// dialog over the window that can cancel them; the run is left paused at the last step exported.
// None of them writes over the open scene's file, by its path or any other name of it.

#include "export_settings.h"

#include <QObject>
#include <QString>
#include <array>
#include <functional>
#include <optional>

class QMenu;
class QProgressDialog;
class QWidget;

namespace ui {

class ExportRun;
class Prompts;
class SceneDocument;
class SimulationController;
class VideoEncoder;
class Viewport;

class Exporter : public QObject {
    Q_OBJECT

public:
    // folder: where the dialogs suggest writing (the window's screenshot folder)
    Exporter(SceneDocument &document, SimulationController &controller, Viewport &viewport, const Prompts &prompts,
             std::function<QString()> folder, QWidget *window);

    // File › Export's submenu, under file
    void addMenu(QMenu *file);
    void showDialog(ExportKind kind);

    // the view drawn at any size into a PNG; false and the reason if not written
    bool exportImage(const ImageExport &settings, QString *error = nullptr);
    // an image sequence of the run from its current state, then an MP4 of it if asked for and
    // ffmpeg is installed; a trace of the run as CSV. Both run on, with a progress dialog that
    // can cancel them, and end with finished; false (and error) if they cannot start
    bool startSequenceExport(const SequenceExport &settings, QString *error = nullptr);
    bool startTraceExport(const TraceExport &settings, QString *error = nullptr);
    // the deforming surfaces as a PC2 cache, OBJ frames and a last frame, run on from here with
    // the same progress dialog; false (and error) if it cannot start
    bool startAnimationExport(const MeshAnimationExport &settings, QString *error = nullptr);
    bool isExporting() const { return m_run != nullptr || m_encoder != nullptr; }
    // cancels what is being exported, as the progress dialog's Cancel does
    void cancel();

signals:
    // a sequence or trace ended: ok when everything asked for was written; the message says what
    // was written, or why not (cancelled, failed, ffmpeg not found)
    void finished(bool ok, const QString &message);
    // what the status bar should say for ms milliseconds
    void statusMessage(const QString &message, int ms);

private:
    // what an export wrote, told once it ends: frames is how many export steps were handled;
    // error is set if writing failed at the end
    using Summary = std::function<QString(int frames, QString *error)>;
    bool begin(ExportRun *run, const QString &label, Summary summary, std::optional<SequenceExport> video = std::nullopt);
    void encodeVideo(const SequenceExport &settings, const QString &written);
    void finish(bool ok, const QString &message);

    SceneDocument &m_document;
    SimulationController &m_controller;
    Viewport &m_viewport;
    const Prompts &m_prompts;
    std::function<QString()> m_folder;
    // what the last export of each kind was given, so that the next dialog of the kind starts there
    std::array<QString, 4> m_lastPath;  // by ExportKind
    std::array<QString, 4> m_lastPathScene;  // the scene file each was made from: another scene
                                             // starts beside its own file again
    MeshAnimationExport m_lastAnimation;
    QSize m_lastImageSize;
    QWidget *m_window;
    ExportRun *m_run = nullptr;                  // the sequence or trace being exported
    VideoEncoder *m_encoder = nullptr;           // ffmpeg making the MP4 after a sequence
    QProgressDialog *m_progress = nullptr;       // while either runs
};

}  // namespace ui
