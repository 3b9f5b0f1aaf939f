// The MP4 of an image sequence: ffmpeg's arguments (frame rate, the frames' pattern, yuv420p with
// even sides); with no ffmpeg on PATH, a clear "ffmpeg not found" and no process; where ffmpeg is
// installed, an MP4 made from three small frames of an odd size.

#include "ui/export/image_sequence.h"
#include "ui/export/video_encoder.h"

#include <QFileInfo>
#include <QImage>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

class TestVideoEncoder : public QObject {
    Q_OBJECT

private slots:
    void argumentsReadTheSequence();
    void saysClearlyWhenFfmpegIsNotInstalled();
    void makesAnMp4WhereFfmpegIsInstalled();
};

void TestVideoEncoder::argumentsReadTheSequence()
{
    const QStringList arguments = ui::VideoEncoder::arguments(
        24.0, QStringLiteral("/tmp/run"), QStringLiteral("/tmp/run/run.mp4"), QStringLiteral("mpeg4"));
    const QString all = arguments.join(QLatin1Char(' '));
    QVERIFY2(all.contains(QStringLiteral("-framerate 24 -i /tmp/run/frame-%05d.png")), qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("-pix_fmt yuv420p -c:v mpeg4")), qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("pad=ceil(iw/2)*2:ceil(ih/2)*2")), qPrintable(all));
    QCOMPARE(arguments.last(), QStringLiteral("/tmp/run/run.mp4"));
    QCOMPARE(arguments.first(), QStringLiteral("-y"));
}

void TestVideoEncoder::saysClearlyWhenFfmpegIsNotInstalled()
{
    // a PATH with nothing on it, whether or not this machine has ffmpeg
    QTemporaryDir empty;
    const QByteArray path = qgetenv("PATH");
    qputenv("PATH", empty.path().toLocal8Bit());
    const QString found = ui::VideoEncoder::findFfmpeg();
    ui::VideoEncoder encoder;
    QString error;
    const bool started = encoder.start(30.0, empty.path(), empty.filePath(QStringLiteral("x.mp4")), &error);
    qputenv("PATH", path);

    QVERIFY(found.isEmpty());
    QVERIFY(!started);
    QVERIFY(!encoder.isRunning());
    QVERIFY2(error.startsWith(QStringLiteral("ffmpeg not found")), qPrintable(error));
    QCOMPARE(error, ui::VideoEncoder::missingText());
}

void TestVideoEncoder::makesAnMp4WhereFfmpegIsInstalled()
{
    if (ui::VideoEncoder::findFfmpeg().isEmpty())
        QSKIP("ffmpeg is not installed here; the test without it is saysClearlyWhenFfmpegIsNotInstalled");
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    for (int k = 0; k < 3; ++k) {
        QImage frame(33, 21, QImage::Format_RGB32);
        frame.fill(QColor::fromHsv(100 * k, 200, 200));
        QVERIFY(frame.save(ui::sequenceFramePath(dir.path(), k), "PNG"));
    }
    ui::VideoEncoder encoder;
    QSignalSpy finished(&encoder, &ui::VideoEncoder::finished);
    const QString output = dir.filePath(QStringLiteral("run.mp4"));
    QString error;
    QVERIFY2(encoder.start(30.0, dir.path(), output, &error), qPrintable(error));
    QVERIFY(finished.wait(60000));
    QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
    QVERIFY(QFileInfo(output).size() > 0);
}

QTEST_GUILESS_MAIN(TestVideoEncoder)
#include "test_video_encoder.moc"
