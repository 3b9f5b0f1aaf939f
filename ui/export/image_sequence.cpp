#include "image_sequence.h"

#include "core/io/file_identity.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QObject>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {

// k / (fps · h) is computed in floating point: a value this close to a whole number is that number
// (3 / (30 · 0.01) is 10.000000000000002), so that a frame time that falls on a step takes it
constexpr double kWholeTolerance = 1e-9;

// ceil(x), taking x within the tolerance of a whole number as that number
double ceilOfNearlyWhole(double x)
{
    const double nearest = std::round(x);
    return std::abs(x - nearest) <= kWholeTolerance * std::max(1.0, std::abs(x)) ? nearest : std::ceil(x);
}

// a frame's name: frame-00042.png
constexpr const char *kFrameName = "^frame-\\d{5,}\\.png$";

}  // namespace

int sequenceFrameCount(double fps, double duration)
{
    return std::max(1, static_cast<int>(ceilOfNearlyWhole(duration * fps)));
}

std::vector<std::uint64_t> sequenceFrameSteps(double fps, int count, double timeStep)
{
    std::vector<std::uint64_t> steps;
    steps.reserve(static_cast<std::size_t>(std::max(count, 0)));
    for (int k = 0; k < count; ++k)
        steps.push_back(static_cast<std::uint64_t>(ceilOfNearlyWhole(k / (fps * timeStep))));
    return steps;
}

QString sequenceFramePath(const QString &folder, int index)
{
    return QDir(folder).filePath(QString::asprintf(kSequenceFramePattern, index));
}

QStringList sequenceFramesIn(const QString &folder)
{
    static const QRegularExpression name{QLatin1StringView(kFrameName)};
    QStringList frames;
    const QDir directory(folder);
    for (const QString &file : directory.entryList({QStringLiteral("frame-*.png")}, QDir::Files, QDir::Name))
        if (name.match(file).hasMatch())
            frames << directory.filePath(file);
    return frames;
}

QString removeSequenceFrames(const QString &folder)
{
    for (const QString &frame : sequenceFramesIn(folder))
        if (!QFile::remove(frame))
            return QObject::tr("cannot remove %1, left from an earlier sequence").arg(QDir::toNativeSeparators(frame));
    return {};
}

bool isSequenceFrame(const QString &path, const QString &folder)
{
    // the path as given (a link there would be removed) and the file a link leads to (which
    // would be written through)
    static const QRegularExpression name(QLatin1StringView(kFrameName), QRegularExpression::CaseInsensitiveOption);
    const auto inFolder = [&](const QFileInfo &file) {
        return name.match(file.fileName()).hasMatch() && io::sameFile(file.path(), folder);
    };
    const QFileInfo given(path);
    return inFolder(given) || (given.exists() && inFolder(QFileInfo(given.canonicalFilePath())));
}

}  // namespace ui
