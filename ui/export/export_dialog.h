#pragma once
// ExportDialog: File › Export's small dialog, for an image (width, height, file), an image sequence
// (frame rate, duration, width, height, folder, and an MP4 where ffmpeg is installed, else a
// clear note that it is not), a trace (duration, every K steps, file) or an animation (frame
// rate, a run on for a duration or the recorded run from one time to another, a PC2 file, a folder
// of OBJ frames, a last-frame mesh, the files' coordinates). Browse asks the window for a path,
// through the same hook as every file dialog, so tests answer it without a modal dialog.

#include "export_settings.h"

#include <QDialog>

#include <functional>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace ui {

class ExportDialog : public QDialog {
    Q_OBJECT

public:
    using Kind = ExportKind;
    // asked for a path when Browse is clicked, with the one typed so far; empty: cancelled
    using BrowseFunction = std::function<QString(const QString &current)>;

    ExportDialog(Kind kind, BrowseFunction browse, QWidget *parent = nullptr);

    Kind kind() const { return m_kind; }
    void setPath(const QString &path);
    void setImageSize(QSize size);
    // the largest side the view can draw (Viewport::maxImageSide); the size boxes stop there
    void setMaximumSide(int side);
    // whether the MP4 can be offered; if not, the dialog says that ffmpeg is not installed
    void setFfmpegFound(bool found);
    // s: the scene's time step, for the summary of what will be written
    void setTimeStep(double timeStep);

    ImageExport image() const;
    SequenceExport sequence() const;
    TraceExport trace() const;
    MeshAnimationExport animation() const;
    // the surfaces an animation writes and their vertices, for its summary ("flag, 3 402 vertices")
    void setSurfaces(const QString &surfaces);
    // an animation's other outputs, shown as they were last time
    void setAnimation(const MeshAnimationExport &settings);
    // the run the timeline holds, from first to last s, which an animation may be taken from;
    // unavailable (with the reason shown) when it holds none or a session is being recorded
    void setTimeline(bool available, double first, double last, const QString &unavailable = QString());

private:
    void browse();
    void updateSummary();

    Kind m_kind;
    BrowseFunction m_browse;
    double m_timeStep = 0.0;
    QSpinBox *m_width = nullptr;
    QSpinBox *m_height = nullptr;
    int m_maxSide = 16384;  // px, the largest side the view can be drawn at (setMaximumSide)
    QDoubleSpinBox *m_fps = nullptr;
    QDoubleSpinBox *m_duration = nullptr;
    QSpinBox *m_every = nullptr;
    QLineEdit *m_path = nullptr;
    QCheckBox *m_video = nullptr;
    QLineEdit *m_objFolder = nullptr;   // an animation's OBJ frames
    QLineEdit *m_meshPath = nullptr;    // and its last frame
    QCheckBox *m_fileSpace = nullptr;
    QComboBox *m_source = nullptr;      // an animation of a run on, or of the recorded run
    QDoubleSpinBox *m_from = nullptr;   // the recorded run's part, s
    QDoubleSpinBox *m_to = nullptr;
    QString m_timelineUnavailable;      // why the recorded run cannot be chosen; empty: it can
    QString m_surfaces;
    QLabel *m_ffmpegNote = nullptr;
    QLabel *m_summary = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

}  // namespace ui
