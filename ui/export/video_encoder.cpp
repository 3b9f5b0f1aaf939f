#include "video_encoder.h"

#include "image_sequence.h"

#include <QDir>
#include <QStandardPaths>

namespace ui {

namespace {

// how long listing ffmpeg's encoders may take, ms
constexpr int kEncoderListMs = 10000;
// how much of what ffmpeg said is shown when it fails, characters
constexpr int kErrorTail = 600;

}  // namespace

VideoEncoder::VideoEncoder(QObject *parent) : QObject(parent)
{
    m_process.setProcessChannelMode(QProcess::MergedChannels);
    connect(&m_process, &QProcess::finished, this, &VideoEncoder::processFinished);
}

VideoEncoder::~VideoEncoder()
{
    disconnect(&m_process, nullptr, this, nullptr);
    if (isRunning()) {
        m_process.kill();
        m_process.waitForFinished();
    }
}

QString VideoEncoder::findFfmpeg()
{
    return QStandardPaths::findExecutable(QStringLiteral("ffmpeg"));
}

QString VideoEncoder::missingText()
{
    return tr("ffmpeg not found: it is not installed (or not on PATH), so no MP4 can be made; only the PNG "
              "frames are written");
}

QStringList VideoEncoder::arguments(double fps, const QString &folder, const QString &output, const QString &codec)
{
    return {QStringLiteral("-y"),
            QStringLiteral("-hide_banner"),
            QStringLiteral("-loglevel"),
            QStringLiteral("error"),
            QStringLiteral("-framerate"),
            QString::number(fps, 'g', 10),
            QStringLiteral("-i"),
            QDir(folder).filePath(QString::fromLatin1(kSequenceFramePattern)),
            QStringLiteral("-vf"),
            QStringLiteral("pad=ceil(iw/2)*2:ceil(ih/2)*2"),
            QStringLiteral("-pix_fmt"),
            QStringLiteral("yuv420p"),
            QStringLiteral("-c:v"),
            codec,
            output};
}

QString VideoEncoder::chooseCodec(const QString &ffmpeg)
{
    // libx264 if this ffmpeg was built with it, else its own MPEG-4 encoder
    QProcess list;
    list.start(ffmpeg, {QStringLiteral("-hide_banner"), QStringLiteral("-encoders")});
    if (list.waitForFinished(kEncoderListMs) && list.readAllStandardOutput().contains("libx264"))
        return QStringLiteral("libx264");
    return QStringLiteral("mpeg4");
}

bool VideoEncoder::start(double fps, const QString &folder, const QString &output, QString *error)
{
    const QString ffmpeg = findFfmpeg();
    if (ffmpeg.isEmpty()) {
        if (error)
            *error = missingText();
        return false;
    }
    m_codec = chooseCodec(ffmpeg);
    m_output = output;
    m_cancelled = false;
    m_process.start(ffmpeg, arguments(fps, folder, output, m_codec));
    if (!m_process.waitForStarted()) {
        if (error)
            *error = tr("ffmpeg (%1) did not start: %2").arg(ffmpeg, m_process.errorString());
        return false;
    }
    return true;
}

void VideoEncoder::cancel()
{
    if (!isRunning())
        return;
    m_cancelled = true;
    m_process.kill();
}

void VideoEncoder::processFinished(int exitCode, QProcess::ExitStatus status)
{
    const QString output = QDir::toNativeSeparators(m_output);
    if (m_cancelled) {
        emit finished(false, tr("the MP4 was cancelled; %1 may be incomplete").arg(output));
        return;
    }
    if (status == QProcess::NormalExit && exitCode == 0) {
        emit finished(true, tr("made %1 with ffmpeg (%2)").arg(output, m_codec));
        return;
    }
    const QString said = QString::fromLocal8Bit(m_process.readAll()).trimmed().right(kErrorTail);
    emit finished(false, tr("ffmpeg could not make %1 (exit code %2): %3").arg(output).arg(exitCode).arg(said));
}

}  // namespace ui
