#pragma once
// VideoEncoder: an MP4 from an image sequence (image_sequence.h), made by ffmpeg where it is
// installed: H.264 (libx264) in yuv420p, which every player reads, or MPEG-4 part 2 where this
// ffmpeg lacks libx264. yuv420p needs even sides, so an odd width or height gets one black row
// or column. ffmpeg runs as a child process; the window never waits for it.

#include <QObject>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace ui {

class VideoEncoder : public QObject {
    Q_OBJECT

public:
    explicit VideoEncoder(QObject *parent = nullptr);
    // an ffmpeg still running (the window closed meanwhile) is stopped
    ~VideoEncoder() override;

    // ffmpeg's path, found on PATH; empty when it is not installed
    static QString findFfmpeg();
    // what to say when it is not
    static QString missingText();
    // the arguments that make output from folder's frames at fps with the codec
    static QStringList arguments(double fps, const QString &folder, const QString &output, const QString &codec);

    // starts ffmpeg on folder's frames; false (and error) if ffmpeg is not found or does not start
    bool start(double fps, const QString &folder, const QString &output, QString *error = nullptr);
    void cancel();
    bool isRunning() const { return m_process.state() != QProcess::NotRunning; }
    QString codec() const { return m_codec; }

signals:
    // ok with the output written, or the reason it was not (ffmpeg's last words included)
    void finished(bool ok, const QString &message);

private:
    QString chooseCodec(const QString &ffmpeg);
    void processFinished(int exitCode, QProcess::ExitStatus status);

    QProcess m_process;
    QString m_output;
    QString m_codec;
    bool m_cancelled = false;
};

}  // namespace ui
