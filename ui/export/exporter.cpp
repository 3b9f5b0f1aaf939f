#include "exporter.h"

#include "export_dialog.h"
#include "export_run.h"
#include "image_sequence.h"
#include "video_encoder.h"

#include "ui/dialogs/prompts.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include "core/io/animation_export.h"
#include "core/io/file_identity.h"
#include "core/io/trace_writer.h"
#include "core/meshes/mesh_surface.h"
#include "core/model/snapshot.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QProgressDialog>

#include <cmath>
#include <limits>

namespace ui {

namespace {

// how long the status bar shows what an export wrote, ms
constexpr int kExportMessageMs = 15000;

QString nativePath(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

// false, with the reason in error
bool failWith(QString *error, const QString &reason)
{
    if (error)
        *error = reason;
    return false;
}

// the MP4 of a sequence: in its folder, named after it
QString videoPath(const QString &folder)
{
    const QString name = QFileInfo(QDir::cleanPath(folder)).fileName();
    return QDir(folder).filePath((name.isEmpty() ? QStringLiteral("sequence") : name) + QStringLiteral(".mp4"));
}

// an export written over the open scene's file would destroy it; an image or a trace truncates
// its file in place, so a hard link to the scene is as much the scene as its own path
bool isSceneFile(const QString &path, const SceneDocument &document)
{
    return io::sameFile(path, document.filePath());
}

}  // namespace

Exporter::Exporter(SceneDocument &document, SimulationController &controller, Viewport &viewport, const Prompts &prompts,
                   std::function<QString()> folder, QWidget *window)
    : QObject(window), m_document(document), m_controller(controller), m_viewport(viewport), m_prompts(prompts),
      m_folder(std::move(folder)), m_window(window)
{
}

void Exporter::addMenu(QMenu *file)
{
    QAction *animation = file->addAction(tr("Export &Animation..."), this, [this] { showDialog(ExportKind::Animation); });
    animation->setObjectName(QStringLiteral("actionExportAnimation"));
    animation->setStatusTip(tr("Run on from here and save the moving surfaces for Blender: a PC2 point cache, OBJ "
                               "frames, a last frame as glTF, PLY or STL"));
    QMenu *menu = file->addMenu(tr("E&xport"));
    menu->setObjectName(QStringLiteral("exportMenu"));
    QAction *image = menu->addAction(tr("&Image..."), this, [this] { showDialog(ExportKind::Image); });
    image->setObjectName(QStringLiteral("actionExportImage"));
    image->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F2));
    image->setStatusTip(tr("Save the 3D view as a PNG of any size (drawn again offscreen, same camera)"));
    QAction *sequence =
        menu->addAction(tr("Image &Sequence..."), this, [this] { showDialog(ExportKind::Sequence); });
    sequence->setObjectName(QStringLiteral("actionExportSequence"));
    sequence->setStatusTip(tr("Run on from here and save a PNG per frame, and an MP4 where ffmpeg is installed"));
    QAction *trace = menu->addAction(tr("&Trace CSV..."), this, [this] { showDialog(ExportKind::Trace); });
    trace->setObjectName(QStringLiteral("actionExportTrace"));
    trace->setStatusTip(tr("Run on from here and save positions and velocities as springlab-sim --trace does"));
}

void Exporter::showDialog(ExportKind kind)
{
    if (isExporting()) {
        m_prompts.ask(QMessageBox::Information, tr("Export"), tr("An export is running; cancel it or wait for it first."));
        return;
    }

    // the path through the window's file dialog (the tests' hook), with the right filter
    // beside the scene's file, or in the screenshot folder before it has one; the last export of
    // the kind, when there was one, is where the dialog starts, at the size it had
    const QString folder = m_document.filePath().isEmpty() ? m_folder() : m_document.folder();
    const QString stem = QDir(folder).filePath(m_document.displayName());
    auto browse = [this, kind](const QString &current) {
        switch (kind) {
        case ExportKind::Image:
            return m_prompts.chooseFile(Prompts::FileDialogMode::Save, tr("Export image"), current, tr("PNG images (*.png)"));
        case ExportKind::Sequence:
            return m_prompts.chooseFile(Prompts::FileDialogMode::Folder, tr("Folder for the frames"), current);
        case ExportKind::Trace:
            return m_prompts.chooseFile(Prompts::FileDialogMode::Save, tr("Export trace"), current, tr("CSV files (*.csv)"));
        case ExportKind::Animation:
            return m_prompts.chooseFile(Prompts::FileDialogMode::Save, tr("Export animation"), current,
                                        tr("PC2 point caches (*.pc2)"));
        }
        return QString();
    };
    auto *dialog = new ExportDialog(kind, browse, m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    const QSize viewSize = m_viewport.size() * m_viewport.devicePixelRatio();
    dialog->setImageSize(kind == ExportKind::Image && m_lastImageSize.isValid() ? m_lastImageSize
                         : kind == ExportKind::Image                           ? 2 * viewSize
                                                                               : viewSize);
    dialog->setMaximumSide(m_viewport.maxImageSide());
    dialog->setFfmpegFound(!VideoEncoder::findFfmpeg().isEmpty());
    dialog->setTimeStep(m_document.scene().settings.timeStep);
    const QString last = m_lastPathScene[std::size_t(kind)] == m_document.filePath() ? m_lastPath[std::size_t(kind)]
                                                                                          : QString();
    dialog->setPath(!last.isEmpty() ? last
                    : stem + (kind == ExportKind::Image       ? QStringLiteral(".png")
                              : kind == ExportKind::Trace     ? QStringLiteral(".csv")
                              : kind == ExportKind::Animation ? QStringLiteral(".pc2")
                                                              : QStringLiteral("-frames")));
    if (kind == ExportKind::Animation) {
        dialog->setAnimation(m_lastAnimation);
        QStringList surfaces;
        for (const core::MeshDesc &mesh : core::exportedMeshes(m_document.scene()))
            surfaces << tr("%1 (%n vertices)", nullptr, mesh.vertexCount()).arg(QString::fromStdString(mesh.name));
        dialog->setSurfaces(surfaces.join(QStringLiteral(", ")));
        const std::shared_ptr<const SimulationFrame> frame = m_controller.frame();
        if (!frame || frame->timeline.empty)
            dialog->setTimeline(false, 0.0, 0.0, tr("nothing is recorded yet: play the run first"));
        else if (frame->timeline.locked)
            dialog->setTimeline(false, 0.0, 0.0, tr("a session is being recorded: stop it first (Ctrl+R)"));
        else
            dialog->setTimeline(true, frame->timeline.firstTime, frame->timeline.lastTime);
    }

    // shown without a nested event loop; what was asked for starts when it is accepted
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        QString error;
        bool ok = false;
        switch (dialog->kind()) {
        case ExportKind::Image:
            m_lastPath[std::size_t(ExportKind::Image)] = dialog->image().path;
            m_lastPathScene[std::size_t(ExportKind::Image)] = m_document.filePath();
            m_lastImageSize = dialog->image().size;
            ok = exportImage(dialog->image(), &error);
            break;
        case ExportKind::Sequence:
            m_lastPath[std::size_t(ExportKind::Sequence)] = dialog->sequence().folder;
            m_lastPathScene[std::size_t(ExportKind::Sequence)] = m_document.filePath();
            ok = startSequenceExport(dialog->sequence(), &error);
            break;
        case ExportKind::Trace:
            m_lastPath[std::size_t(ExportKind::Trace)] = dialog->trace().path;
            m_lastPathScene[std::size_t(ExportKind::Trace)] = m_document.filePath();
            ok = startTraceExport(dialog->trace(), &error);
            break;
        case ExportKind::Animation:
            m_lastAnimation = dialog->animation();
            m_lastPath[std::size_t(ExportKind::Animation)] = m_lastAnimation.pc2Path;
            m_lastPathScene[std::size_t(ExportKind::Animation)] = m_document.filePath();
            ok = startAnimationExport(m_lastAnimation, &error);
            break;
        }
        if (!ok && !error.isEmpty())
            m_prompts.ask(QMessageBox::Warning, dialog->windowTitle(), error);
    });
    dialog->open();
}

bool Exporter::exportImage(const ImageExport &settings, QString *error)
{
    if (isSceneFile(settings.path, m_document))
        return failWith(error, tr("Export image: %1 is the open scene's file, %2; export to another file")
                                   .arg(nativePath(settings.path), nativePath(m_document.filePath())));
    QString why;
    const QImage image = m_viewport.renderImage(settings.size, &why);
    if (image.isNull())
        return failWith(error, tr("Export image: %1").arg(why));
    if (!image.save(settings.path, "PNG"))
        return failWith(error, tr("Export image: cannot write %1").arg(nativePath(settings.path)));
    emit statusMessage(tr("Saved a %1 × %2 px image to %3")
                           .arg(image.width())
                           .arg(image.height())
                           .arg(nativePath(settings.path)),
                       kExportMessageMs);
    return true;
}

bool Exporter::startSequenceExport(const SequenceExport &settings, QString *error)
{
    if (isExporting())
        return failWith(error, tr("Export image sequence: an export is running already"));
    const double timeStep = m_document.scene().settings.timeStep;
    if (!(settings.fps > 0.0) || !(settings.duration >= 0.0) || !std::isfinite(settings.fps * settings.duration))
        return failWith(error, tr("Export image sequence: the frame rate must be above 0 and the duration at least 0"));
    // the frames already in the folder are removed and new ones written, then the MP4 beside them
    const QString scene = m_document.filePath();
    if (!scene.isEmpty() && isSequenceFrame(scene, settings.folder))
        return failWith(error, tr("Export image sequence: the open scene's file, %1, is among the frames in %2, "
                                  "which the sequence would replace; choose another folder")
                                   .arg(nativePath(scene), nativePath(settings.folder)));
    if (settings.video && isSceneFile(videoPath(settings.folder), m_document))
        return failWith(error, tr("Export image sequence: the MP4, %1, would be written over the open scene's file; "
                                  "choose another folder")
                                   .arg(nativePath(videoPath(settings.folder))));
    // one frame drawn now proves that the size can be drawn at all
    if (QString why; m_viewport.renderImage(settings.size, &why).isNull())
        return failWith(error, tr("Export image sequence: %1").arg(why));

    // the folder, without frames left from an earlier sequence (ffmpeg would append them)
    const QString folder = settings.folder;
    if (folder.isEmpty() || !QDir().mkpath(folder))
        return failWith(error, tr("Export image sequence: cannot create the folder %1").arg(nativePath(folder)));
    if (const QStringList old = sequenceFramesIn(folder); !old.isEmpty()) {
        if (m_prompts.ask(QMessageBox::Question, tr("Export image sequence"),
                tr("%1 already holds %2 frames (frame-*.png). Replace them?").arg(nativePath(folder)).arg(old.size()),
                QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel) != QMessageBox::Yes)
            return failWith(error, QString());
        if (const QString failure = removeSequenceFrames(folder); !failure.isEmpty())
            return failWith(error, tr("Export image sequence: %1").arg(failure));
    }

    // each frame drawn offscreen at the size asked for, with the view's camera
    const int count = sequenceFrameCount(settings.fps, settings.duration);
    auto *run = new ExportRun(
        m_controller, sequenceFrameSteps(settings.fps, count, timeStep),
        [this, settings](const std::shared_ptr<const core::Snapshot> &snapshot, int index) {
            m_viewport.setSnapshot(snapshot);
            QString why;
            const QImage image = m_viewport.renderImage(settings.size, &why);
            const QString path = sequenceFramePath(settings.folder, index);
            if (image.isNull())
                return tr("frame %1: %2").arg(index).arg(why);
            if (!image.save(path, "PNG"))
                return tr("cannot write %1").arg(nativePath(path));
            return QString();
        },
        this);
    return begin(run, tr("Writing the frames..."), [settings](int frames, QString *) {
        const QString written = tr("%n frame(s) of %1 × %2 px at %3 frames/s in %4", nullptr, frames)
                                    .arg(settings.size.width())
                                    .arg(settings.size.height())
                                    .arg(settings.fps, 0, 'g', 6)
                                    .arg(nativePath(settings.folder));
        return written;
    }, settings.video ? std::optional<SequenceExport>(settings) : std::nullopt);
}

bool Exporter::startTraceExport(const TraceExport &settings, QString *error)
{
    if (isExporting())
        return failWith(error, tr("Export trace: an export is running already"));
    const double timeStep = m_document.scene().settings.timeStep;
    const double steps = std::round(settings.duration / timeStep);
    if (!(settings.duration >= 0.0) || !(steps <= double(std::numeric_limits<int>::max())) || settings.every < 1)
        return failWith(error, tr("Export trace: %1 s at a time step of %2 s is not a duration that can be run")
                        .arg(settings.duration)
                        .arg(timeStep));

    if (isSceneFile(settings.path, m_document))
        return failWith(error, tr("Export trace: %1 is the open scene's file, %2; export to another file")
                                   .arg(nativePath(settings.path), nativePath(m_document.filePath())));

    // rows at steps 0, K, 2K, ... up to the duration's steps
    auto trace = std::make_shared<io::TraceWriter>();
    if (const QString failure = trace->open(settings.path); !failure.isEmpty())
        return failWith(error, tr("Export trace: %1").arg(failure));
    std::vector<std::uint64_t> rowSteps;
    for (std::uint64_t step = 0; step <= static_cast<std::uint64_t>(steps); step += std::uint64_t(settings.every))
        rowSteps.push_back(step);
    auto *run = new ExportRun(
        m_controller, std::move(rowSteps),
        [trace](const std::shared_ptr<const core::Snapshot> &snapshot, int) {
            trace->writeRows(*snapshot);
            return QString();
        },
        this);
    const QString path = settings.path;
    return begin(run, tr("Writing the trace..."), [trace, path](int, QString *error) {
        *error = trace->close();
        return tr("%n row(s) of step,time,particle,x,y,z,vx,vy,vz in %1", nullptr, int(trace->rowCount()))
            .arg(nativePath(path));
    });
}

bool Exporter::startAnimationExport(const MeshAnimationExport &settings, QString *error)
{
    const QString title = tr("Export animation");
    if (isExporting())
        return failWith(error, tr("%1: an export is running already").arg(title));
    const core::SceneDesc &scene = m_document.scene();
    const double timeStep = scene.settings.timeStep;
    double steps = std::round(settings.duration / timeStep);
    if (settings.fromTimeline) {
        // the recorded run's steps are its own, time = step × h: checked, as an edit of the time
        // step during the run breaks it
        const std::shared_ptr<const SimulationFrame> frame = m_controller.frame();
        if (!frame || frame->timeline.empty)
            return failWith(error, tr("%1: the timeline holds no recorded run: play the run first").arg(title));
        const TimelineInfo &timeline = frame->timeline;
        if (timeline.locked)
            return failWith(error, tr("%1: a session is being recorded; stop it first (Ctrl+R)").arg(title));
        const auto atItsStep = [timeStep](double time, std::uint64_t step) {
            return std::abs(time - double(step) * timeStep) <= 1e-9 * std::max(1.0, std::abs(time));
        };
        if (!atItsStep(timeline.firstTime, timeline.firstStep) || !atItsStep(timeline.lastTime, timeline.lastStep))
            return failWith(error, tr("%1: the time step was changed during the recorded run, so its times are not "
                                      "its steps × %2 s; export a run on from the current state instead")
                                       .arg(title)
                                       .arg(timeStep));
        const double slack = 0.5 * timeStep;
        if (!(settings.from >= timeline.firstTime - slack) || !(settings.to <= timeline.lastTime + slack) ||
            !(settings.to >= settings.from))
            return failWith(error, tr("%1: the timeline holds the run from %2 s to %3 s; %4 s to %5 s is not within it")
                                       .arg(title)
                                       .arg(timeline.firstTime)
                                       .arg(timeline.lastTime)
                                       .arg(settings.from)
                                       .arg(settings.to));
        steps = double(timeline.lastStep);
    }
    if (!(settings.duration >= 0.0) || !(steps <= double(std::numeric_limits<int>::max())))
        return failWith(error, tr("%1: %2 s at a time step of %3 s is not a duration that can be run")
                                   .arg(title)
                                   .arg(settings.duration)
                                   .arg(timeStep));
    for (const QString &path : {settings.pc2Path, settings.meshPath})
        if (!path.isEmpty() && isSceneFile(path, m_document))
            return failWith(error, tr("%1: %2 is the open scene's file, %3; export to another file")
                                       .arg(title, nativePath(path), nativePath(m_document.filePath())));

    // the outputs opened (and checked against the scene) before the run moves
    io::ExportOptions options;
    options.pc2Path = settings.pc2Path;
    options.objFolder = settings.objFolder;
    options.meshPath = settings.meshPath;
    options.fps = settings.fps;
    options.space = settings.fileSpace ? core::MeshSpace::File : core::MeshSpace::Scene;
    if (settings.fromTimeline) {
        options.from = std::max(0.0, settings.from);
        options.to = settings.to;
    }
    auto exported = std::make_shared<io::AnimationExport>();
    if (const QString failure = exported->open(options, scene, timeStep, std::uint64_t(steps)); !failure.isEmpty())
        return failWith(error, tr("%1: %2").arg(title, failure));
    if (settings.fromTimeline && exported->frameSteps().front() < m_controller.frame()->timeline.firstStep) {
        exported->cancel();
        return failWith(error, tr("%1: the first frame's step is before the timeline's first").arg(title));
    }
    auto *run = new ExportRun(
        m_controller, exported->frameSteps(),
        [exported, positions = std::make_shared<Eigen::Matrix3Xd>()](
            const std::shared_ptr<const core::Snapshot> &snapshot, int index) {
            // the view's floats are what the cache stores (float32) and what the user saw
            const int n = snapshot->particleCount();
            positions->resize(3, n);
            for (int i = 0; i < n; ++i)
                for (int a = 0; a < 3; ++a)
                    (*positions)(a, i) = double(snapshot->positions[3 * std::size_t(i) + std::size_t(a)]);
            return exported->writeDue(exported->frameSteps()[std::size_t(index)], *positions);
        },
        this, settings.fromTimeline ? ExportRun::Source::Timeline : ExportRun::Source::RunOn);
    return begin(run, tr("Writing the animation..."), [exported](int, QString *failure) {
        // a cancelled export keeps the frames written, in complete files
        *failure = exported->finish();
        const QStringList &files = exported->files();
        return tr("%n frame(s) in ", nullptr, exported->framesWritten()) +
               (files.isEmpty()       ? tr("no file")
                : files.size() == 1 ? nativePath(files.first())
                                    : tr("%1 files, from %2 to %3")
                                          .arg(files.size())
                                          .arg(nativePath(files.first()), nativePath(files.last())));
    });
}

bool Exporter::begin(ExportRun *run, const QString &label, Summary summary, std::optional<SequenceExport> video)
{
    // a progress dialog over the window (no nested event loop), whose Cancel stops the run
    m_run = run;
    m_progress = new QProgressDialog(label, tr("Cancel"), 0, run->frameCount(), m_window);
    m_progress->setObjectName(QStringLiteral("exportProgress"));
    m_progress->setWindowTitle(tr("Export"));
    m_progress->setWindowModality(Qt::WindowModal);
    m_progress->setMinimumDuration(0);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    m_progress->setValue(0);
    connect(m_progress, &QProgressDialog::canceled, this, &Exporter::cancel);
    connect(run, &ExportRun::progressed, m_progress, &QProgressDialog::setValue);

    // at the end: what was written, then the MP4 if one was asked for and the frames are all there
    connect(run, &ExportRun::finished, this,
            [this, run, summary, video](ExportRun::Outcome outcome, const QString &message) {
                m_run = nullptr;
                run->deleteLater();
                QString error;
                const QString written = summary(run->framesDone(), &error);
                if (!error.isEmpty())
                    finish(false, tr("Export failed: %1").arg(error));
                else if (outcome == ExportRun::Outcome::Cancelled)
                    finish(false, tr("Export cancelled; wrote %1").arg(written));
                else if (outcome == ExportRun::Outcome::Failed)
                    finish(false, tr("Export stopped: %1; wrote %2").arg(message, written));
                else if (video)
                    encodeVideo(*video, written);
                else
                    finish(true, tr("Exported %1").arg(written));
            });
    m_progress->show();
    run->start();
    return true;
}

void Exporter::encodeVideo(const SequenceExport &settings, const QString &written)
{
    // ffmpeg joins the frames; the dialog waits on it, and Cancel kills it
    m_encoder = new VideoEncoder(this);
    QString error;
    if (!m_encoder->start(settings.fps, settings.folder, videoPath(settings.folder), &error)) {
        m_encoder->deleteLater();
        m_encoder = nullptr;
        finish(false, tr("Exported %1, but no MP4: %2").arg(written, error));
        return;
    }
    m_progress->setLabelText(tr("Making the MP4 with ffmpeg (%1)...").arg(m_encoder->codec()));
    m_progress->setRange(0, 0);
    connect(m_encoder, &VideoEncoder::finished, this, [this, written](bool ok, const QString &message) {
        m_encoder->deleteLater();
        m_encoder = nullptr;
        finish(ok, tr("Exported %1; %2").arg(written, message));
    });
}

void Exporter::cancel()
{
    if (m_run)
        m_run->cancel();
    else if (m_encoder)
        m_encoder->cancel();
}

void Exporter::finish(bool ok, const QString &message)
{
    if (m_progress) {
        m_progress->hide();
        m_progress->deleteLater();
        m_progress = nullptr;
    }
    emit statusMessage(message, kExportMessageMs);
    emit finished(ok, message);
}

}  // namespace ui
