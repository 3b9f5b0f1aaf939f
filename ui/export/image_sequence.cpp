#include "image_sequence.h"

#include <QDir>
#include <QFile>
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
    static const QRegularExpression name(QStringLiteral("^frame-\\d{5,}\\.png$"));
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

}  // namespace ui
