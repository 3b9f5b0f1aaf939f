#pragma once
// The throughput plot, drawn with QPainter into an image: milliseconds per step against particle
// count on log-log axes, one coloured line per variant and thread count (solid with dots for the
// cloths, dash-dot with squares for the boxes), and the bandwidth bound per thread count in grey.
// Needs a QGuiApplication for the text (the offscreen platform will do).

#include <QImage>
#include <QSize>
#include <QString>
#include <vector>

namespace bench {

inline constexpr QSize kThroughputPlotSize{1100, 720};  // pixels

enum class SceneKind { Cloth, Box };

// one measured row of throughput.csv
struct ThroughputRow {
    QString scene;  // "cloth-256", "box-100000"
    SceneKind kind = SceneKind::Cloth;
    long long particles = 0;
    long long springs = 0;
    int threads = 1;
    QString variant;             // springlab, plain, naive, bullet
    double msPerStep = 0.0;      // ms, median of the repetitions
    double boundMs = 0.0;        // ms, the bytes a step must move over the measured bandwidth
    double ratioToBound() const { return msPerStep / boundMs; }
};

// `note` is written under the legend (the machine and its bandwidth)
QImage drawThroughput(const QString &title, const std::vector<ThroughputRow> &rows, const QString &note,
                      const QSize &size = kThroughputPlotSize);

}  // namespace bench
