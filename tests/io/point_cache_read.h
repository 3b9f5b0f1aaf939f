#pragma once
// A PC2 point cache read back by a reader written from the format's description (a 12-byte
// signature "POINTCACHE2\0"; int32 version 1, int32 points, float32 start frame, float32 sampling,
// int32 samples, all little-endian; then per sample every point's x, y, z as float32), shared by
// the tests of the export in the core, the simulator and the editor.

#include <QByteArray>
#include <QDataStream>

#include <vector>

namespace test {

struct PointCache {
    QByteArray signature;
    qint32 version = 0, points = 0, samples = 0;
    float start = 0.0f, sampling = 0.0f;
    std::vector<std::vector<float>> frames;  // per sample, 3 × points
    bool wholeFile = false;                  // the bytes were exactly the header and the samples
};

inline PointCache readPointCache(const QByteArray &bytes)
{
    PointCache cache;
    QDataStream in(bytes);
    in.setByteOrder(QDataStream::LittleEndian);
    in.setFloatingPointPrecision(QDataStream::SinglePrecision);
    cache.signature = bytes.left(12);
    in.skipRawData(12);
    in >> cache.version >> cache.points >> cache.start >> cache.sampling >> cache.samples;
    for (qint32 s = 0; s < cache.samples && cache.points >= 0 && in.status() == QDataStream::Ok; ++s) {
        std::vector<float> frame(static_cast<std::size_t>(3 * cache.points));
        for (float &value : frame)
            in >> value;
        cache.frames.push_back(std::move(frame));
    }
    cache.wholeFile = in.status() == QDataStream::Ok && in.atEnd();
    return cache;
}

}  // namespace test
