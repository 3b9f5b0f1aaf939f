#include "export_dialog.h"

#include "image_sequence.h"
#include "video_encoder.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <utility>

namespace ui {

namespace {

// the boxes' ranges
constexpr double kMaxFps = 1000.0;
constexpr double kMaxDuration = 1.0e6;  // s
constexpr int kMaxEvery = 1000000000;
constexpr int kMaxSide = 16384;          // px, the most this editor draws
constexpr int kMaxTypedSide = 999999999;  // px, what a side's box takes: any number a user types

// a side in pixels. Its box takes any whole number, and the dialog says when one is too large:
// a box with the real maximum refuses the keystroke that passes it, so 20000 typed against a
// maximum of 16384 silently became 2000
QSpinBox *sideBox(const char *name, QWidget *parent)
{
    auto *box = new QSpinBox(parent);
    box->setObjectName(QString::fromLatin1(name));
    box->setRange(1, kMaxTypedSide);
    box->setSuffix(QStringLiteral(" px"));
    return box;
}

QDoubleSpinBox *numberBox(const char *name, double minimum, double maximum, double value, const QString &suffix,
                          QWidget *parent)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setObjectName(QString::fromLatin1(name));
    box->setDecimals(3);
    box->setRange(minimum, maximum);
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}

}  // namespace

ExportDialog::ExportDialog(Kind kind, BrowseFunction browse, QWidget *parent)
    : QDialog(parent), m_kind(kind), m_browse(std::move(browse)), m_path(new QLineEdit(this)),
      m_summary(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setObjectName(QStringLiteral("exportDialog"));
    const SequenceExport defaults;
    auto *form = new QFormLayout;

    // how long, and how often: a sequence's frame rate, a trace's every K steps
    const MeshAnimationExport animationDefaults;
    if (kind == Kind::Sequence || kind == Kind::Animation) {
        setWindowTitle(kind == Kind::Sequence ? tr("Export Image Sequence") : tr("Export Animation"));
        m_fps = numberBox("exportFps", 0.001, kMaxFps, kind == Kind::Sequence ? defaults.fps : animationDefaults.fps,
                          tr(" frames/s"), this);
        m_fps->setToolTip(tr("Frames per simulated second; frame k shows the first step at or after k / rate"));
        form->addRow(tr("Frame rate"), m_fps);
    }
    if (kind != Kind::Image) {
        m_duration = numberBox("exportDuration", 0.0, kMaxDuration,
                               kind == Kind::Trace       ? TraceExport{}.duration
                               : kind == Kind::Animation ? animationDefaults.duration
                                                         : defaults.duration,
                               tr(" s"), this);
        m_duration->setToolTip(tr("Simulated time to run from the current state"));
        if (kind == Kind::Animation) {
            // a run on from here, or the run already recorded: what was seen, replayed to the bit
            m_source = new QComboBox(this);
            m_source->setObjectName(QStringLiteral("exportSource"));
            m_source->addItems({tr("A run on from the current state"), tr("The recorded run (timeline)")});
            m_source->setToolTip(tr("The recorded run is replayed from the timeline's keyframes, exactly as it ran, "
                                    "and the run is left where it was recorded"));
            form->addRow(tr("Frames of"), m_source);
        }
        form->addRow(tr("Duration"), m_duration);
        if (kind == Kind::Animation) {
            m_from = numberBox("exportFrom", 0.0, kMaxDuration, 0.0, tr(" s"), this);
            m_to = numberBox("exportTo", 0.0, kMaxDuration, 0.0, tr(" s"), this);
            m_from->setToolTip(tr("The recorded run's time of the first frame"));
            m_to->setToolTip(tr("The recorded run's time of the last frame, at most"));
            auto *range = new QHBoxLayout;
            range->addWidget(m_from);
            range->addWidget(new QLabel(tr("to"), this));
            range->addWidget(m_to);
            form->addRow(tr("Recorded from"), range);
            connect(m_source, &QComboBox::currentIndexChanged, this, &ExportDialog::updateSummary);
            for (QDoubleSpinBox *box : {m_from, m_to})
                connect(box, &QDoubleSpinBox::valueChanged, this, &ExportDialog::updateSummary);
            setTimeline(false, 0.0, 0.0, tr("nothing is recorded yet"));
        }
    }
    if (kind == Kind::Trace) {
        setWindowTitle(tr("Export Trace CSV"));
        m_every = new QSpinBox(this);
        m_every->setObjectName(QStringLiteral("exportEvery"));
        m_every->setRange(1, kMaxEvery);
        m_every->setToolTip(tr("One set of rows every K steps, the current step first"));
        form->addRow(tr("Rows every"), m_every);
        m_every->setSuffix(tr(" steps"));
    }

    // the picture's size, for an image and a sequence
    if (kind == Kind::Image || kind == Kind::Sequence) {
        if (kind == Kind::Image)
            setWindowTitle(tr("Export Image"));
        m_width = sideBox("exportWidth", this);
        m_height = sideBox("exportHeight", this);
        auto *size = new QHBoxLayout;
        size->addWidget(m_width);
        size->addWidget(new QLabel(QStringLiteral("×"), this));
        size->addWidget(m_height);
        form->addRow(tr("Size"), size);
    }

    // where: a file, or a folder for the frames
    m_path->setObjectName(QStringLiteral("exportPath"));
    auto *browseButton = new QPushButton(tr("&Browse..."), this);
    browseButton->setObjectName(QStringLiteral("exportBrowse"));
    connect(browseButton, &QPushButton::clicked, this, &ExportDialog::browse);
    auto *where = new QHBoxLayout;
    where->addWidget(m_path, 1);
    where->addWidget(browseButton);
    form->addRow(kind == Kind::Sequence ? tr("Folder") : kind == Kind::Animation ? tr("PC2 cache") : tr("File"), where);

    // an animation's other outputs, each optional
    if (kind == Kind::Animation) {
        m_path->setToolTip(tr("The point cache Blender's Mesh Cache modifier reads; the OBJ of its first frame is "
                              "written beside it. Empty: no cache"));
        m_objFolder = new QLineEdit(this);
        m_objFolder->setObjectName(QStringLiteral("exportObjFolder"));
        m_objFolder->setToolTip(tr("A folder for an OBJ a frame (NAME_00000.obj on); empty: none"));
        form->addRow(tr("OBJ frames folder"), m_objFolder);
        m_meshPath = new QLineEdit(this);
        m_meshPath->setObjectName(QStringLiteral("exportMeshPath"));
        m_meshPath->setToolTip(tr("The last frame, in the format its extension names (.glb, .gltf, .ply, .stl, .obj, "
                                  "...); empty: none"));
        form->addRow(tr("Last frame as"), m_meshPath);
        m_fileSpace = new QCheckBox(tr("Where the imported files have their vertices"), this);
        m_fileSpace->setObjectName(QStringLiteral("exportFileSpace"));
        m_fileSpace->setChecked(animationDefaults.fileSpace);
        m_fileSpace->setToolTip(tr("On: each imported mesh in its own file's coordinates (its scale, up axis and "
                                   "placement undone), so the cache fits the file. Off: in the scene's metres, y up"));
        form->addRow(QString(), m_fileSpace);
        for (QLineEdit *edit : {m_objFolder, m_meshPath})
            connect(edit, &QLineEdit::textChanged, this, &ExportDialog::updateSummary);
    }

    // the MP4, offered where ffmpeg is installed
    if (kind == Kind::Sequence) {
        m_video = new QCheckBox(tr("Also make an &MP4 from the frames (ffmpeg)"), this);
        m_video->setObjectName(QStringLiteral("exportVideo"));
        m_ffmpegNote = new QLabel(this);
        m_ffmpegNote->setObjectName(QStringLiteral("exportFfmpegNote"));
        m_ffmpegNote->setWordWrap(true);
        form->addRow(QString(), m_video);
        form->addRow(QString(), m_ffmpegNote);
        setFfmpegFound(false);
    }

    // what will be written; OK only once there is somewhere to write it
    m_summary->setObjectName(QStringLiteral("exportSummary"));
    m_summary->setWordWrap(true);
    auto *ok = m_buttons->button(QDialogButtonBox::Ok);
    ok->setText(tr("&Export"));
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_path, &QLineEdit::textChanged, this, &ExportDialog::updateSummary);
    for (QDoubleSpinBox *box : {m_fps, m_duration})
        if (box)
            connect(box, &QDoubleSpinBox::valueChanged, this, &ExportDialog::updateSummary);
    for (QSpinBox *box : {m_every, m_width, m_height})
        if (box)
            connect(box, &QSpinBox::valueChanged, this, &ExportDialog::updateSummary);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_summary);
    layout->addWidget(m_buttons);
    updateSummary();
}

void ExportDialog::setPath(const QString &path)
{
    m_path->setText(path);
}

void ExportDialog::setImageSize(QSize size)
{
    if (m_width) {
        m_width->setValue(size.width());
        m_height->setValue(size.height());
    }
}

void ExportDialog::setMaximumSide(int side)
{
    if (side <= 0)
        return;
    m_maxSide = std::min(side, kMaxSide);
    for (QSpinBox *box : {m_width, m_height})
        if (box)
            box->setToolTip(tr("At most %1 px, the largest this OpenGL driver draws").arg(m_maxSide));
    updateSummary();
}

void ExportDialog::setFfmpegFound(bool found)
{
    if (!m_video)
        return;
    m_video->setEnabled(found);
    m_video->setChecked(found);
    m_ffmpegNote->setText(found ? tr("The MP4 goes into the folder, named after it.")
                                : VideoEncoder::missingText());
}

void ExportDialog::setTimeStep(double timeStep)
{
    m_timeStep = timeStep;
    updateSummary();
}

ImageExport ExportDialog::image() const
{
    return {m_path->text().trimmed(), m_width ? QSize(m_width->value(), m_height->value()) : QSize()};
}

SequenceExport ExportDialog::sequence() const
{
    SequenceExport settings;
    settings.folder = m_path->text().trimmed();
    if (m_fps) {
        settings.fps = m_fps->value();
        settings.duration = m_duration->value();
        settings.size = QSize(m_width->value(), m_height->value());
        settings.video = m_video->isEnabled() && m_video->isChecked();
    }
    return settings;
}

MeshAnimationExport ExportDialog::animation() const
{
    MeshAnimationExport settings;
    settings.pc2Path = m_path->text().trimmed();
    if (m_objFolder) {
        settings.objFolder = m_objFolder->text().trimmed();
        settings.meshPath = m_meshPath->text().trimmed();
        settings.fps = m_fps->value();
        settings.duration = m_duration->value();
        settings.fileSpace = m_fileSpace->isChecked();
        settings.fromTimeline = m_source->currentIndex() == 1;
        settings.from = m_from->value();
        settings.to = m_to->value();
    }
    return settings;
}

void ExportDialog::setTimeline(bool available, double first, double last, const QString &unavailable)
{
    if (!m_source)
        return;
    m_timelineUnavailable = available ? QString() : unavailable;
    for (QDoubleSpinBox *box : {m_from, m_to}) {
        const QSignalBlocker quiet(box);
        box->setRange(available ? first : 0.0, available ? last : 0.0);
    }
    {
        const QSignalBlocker quiet(m_from);
        m_from->setValue(first);
    }
    const QSignalBlocker quiet(m_to);
    m_to->setValue(last);
    updateSummary();
}

void ExportDialog::setSurfaces(const QString &surfaces)
{
    m_surfaces = surfaces;
    updateSummary();
}

void ExportDialog::setAnimation(const MeshAnimationExport &settings)
{
    if (!m_objFolder)
        return;
    m_objFolder->setText(settings.objFolder);
    m_meshPath->setText(settings.meshPath);
    m_fps->setValue(settings.fps);
    m_duration->setValue(settings.duration);
    m_fileSpace->setChecked(settings.fileSpace);
    m_source->setCurrentIndex(settings.fromTimeline ? 1 : 0);
}

TraceExport ExportDialog::trace() const
{
    TraceExport settings;
    settings.path = m_path->text().trimmed();
    if (m_every) {
        settings.duration = m_duration->value();
        settings.every = m_every->value();
    }
    return settings;
}

void ExportDialog::browse()
{
    if (!m_browse)
        return;
    const QString chosen = m_browse(m_path->text().trimmed());
    if (!chosen.isEmpty())
        m_path->setText(chosen);
}

void ExportDialog::updateSummary()
{
    const bool somewhere = !m_path->text().trimmed().isEmpty() ||
                           (m_objFolder && (!m_objFolder->text().trimmed().isEmpty() ||
                                            !m_meshPath->text().trimmed().isEmpty()));
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(somewhere);
    // a side typed out of range: said, and nothing exported until it is mended
    if (m_width) {
        for (const auto &[box, name] : {std::pair{m_width, tr("Width")}, std::pair{m_height, tr("Height")}})
            if (box->value() > m_maxSide) {
                m_summary->setText(tr("%1 must be from 1 to %2 px (%3); %4 px cannot be used.")
                                       .arg(name)
                                       .arg(m_maxSide)
                                       .arg(m_maxSide == kMaxSide ? tr("the largest this editor draws")
                                                                  : tr("the largest this OpenGL driver draws"))
                                       .arg(box->value()));
                m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
                return;
            }
    }
    switch (m_kind) {
    case Kind::Image:
        m_summary->setText(tr("The 3D view as it is, drawn at %1 × %2 px into a PNG.")
                               .arg(m_width->value())
                               .arg(m_height->value()));
        break;
    case Kind::Sequence: {
        const int frames = sequenceFrameCount(m_fps->value(), m_duration->value());
        m_summary->setText(tr("%1 frames (frame-00000.png on), run from the current state; frame k shows the first "
                              "step at or after k / %2 s. Cancel stops after the frame being written.")
                               .arg(frames)
                               .arg(m_fps->value(), 0, 'g', 6));
        break;
    }
    case Kind::Trace: {
        const QString steps = m_timeStep > 0.0
                                  ? tr("%1 steps").arg(std::llround(m_duration->value() / m_timeStep))
                                  : tr("the steps");
        m_summary->setText(tr("step,time,particle,x,y,z,vx,vy,vz, as springlab-sim --trace writes it, for %1 "
                              "from the current state, every %2 steps (floats, as the view has them).")
                               .arg(steps)
                               .arg(m_every->value()));
        break;
    }
    case Kind::Animation: {
        const bool recorded = m_source->currentIndex() == 1;
        m_duration->setEnabled(!recorded);
        m_from->setEnabled(recorded && m_timelineUnavailable.isEmpty());
        m_to->setEnabled(recorded && m_timelineUnavailable.isEmpty());
        if (m_surfaces.isEmpty()) {
            m_summary->setText(tr("The scene has no surface to export: import a mesh, or make a cloth."));
            m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
        } else if (recorded && !m_timelineUnavailable.isEmpty()) {
            m_summary->setText(tr("The recorded run cannot be exported: %1.").arg(m_timelineUnavailable));
            m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
        } else if (recorded) {
            // frame k at from + k / rate, up to `to`
            const double span = std::max(0.0, m_to->value() - m_from->value());
            const int frames = int(std::floor(span * m_fps->value() * (1.0 + 1e-12) + 1e-9)) + 1;
            m_summary->setText(tr("%1 frames of %2 from the recorded run, %3 s to %4 s, replayed from the timeline "
                                  "exactly as it ran; frame k holds the first step at or after %3 + k / %5 s. Cancel "
                                  "stops after the frame being written and keeps those written.")
                                   .arg(frames)
                                   .arg(m_surfaces)
                                   .arg(m_from->value(), 0, 'g', 6)
                                   .arg(m_to->value(), 0, 'g', 6)
                                   .arg(m_fps->value(), 0, 'g', 6));
        } else {
            const int frames = sequenceFrameCount(m_fps->value(), m_duration->value());
            m_summary->setText(tr("%1 frames of %2, run from the current state; frame k holds the first step at "
                                  "or after k / %3 s. Frames are written as the run goes, never held. Cancel "
                                  "stops after the frame being written and keeps those written.")
                                   .arg(frames)
                                   .arg(m_surfaces)
                                   .arg(m_fps->value(), 0, 'g', 6));
        }
        break;
    }
    }
}

}  // namespace ui
