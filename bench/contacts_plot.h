#pragma once
// The contacts benchmark's picture, drawn with QPainter into an image: above, grouped bars of the
// milliseconds per step of each engine on each scene (log scale, the figure on each bar); below, a
// table of what each engine did with each scene (stands, settles, overlap, repose angle); and the
// run's note at the foot. Needs a QGuiApplication for the text (the offscreen platform will do).

#include <QImage>
#include <QSize>
#include <QString>

#include <optional>
#include <vector>

namespace bench {

inline constexpr QSize kContactsPlotSize{1200, 980};  // pixels

// one row of contacts.csv: one scene run in one engine
struct ContactRow {
    QString scene;   // column, pyramid, pile, pile-4sub, heap
    QString engine;  // springlab, bullet, bullet-norot
    int balls = 0;
    int substeps = 1;
    double duration = 0.0;         // s simulated
    std::optional<bool> stands;    // the column and the pyramid: moved less than 1% of r
    std::optional<double> movedMm;  // mm, the column's top ball, or the pyramid's ball that moved most
    std::optional<double> movedDownMm;    // mm, of that, along gravity
    std::optional<double> movedAcrossMm;  // mm, of that, across gravity
    bool settled = false;           // kinetic energy below the threshold all through the run's last second
    // s, from when on the kinetic energy stayed below the threshold to the end; empty: not settled
    std::optional<double> settleSeconds;
    double kineticEnd = 0.0;        // J, at the end
    double kineticPeak = 0.0;       // J, the largest over the run's last second
    double kineticThreshold = 0.0;  // J, 1e-3 N m g r
    double overlapMm = 0.0;         // mm, the deepest overlap over the run's last second
    std::optional<double> reposeFitDegrees;   // the heap: the fitted slope of its surface
    std::optional<double> reposeConeDegrees;  // the heap: atan(height / base radius)
    std::optional<double> heapHeight;         // m, the heap's highest ball top
    std::optional<double> heapBaseRadius;     // m, the radius within which 95% of its balls lie, plus r
    double msPerStep = 0.0;  // ms, CPU time per step of h (all its sub-steps), median of the repetitions
    bool blewUp = false;     // the core stopped: a value not finite or not bounded
};

// `note` is written under the table (the machine, the load, what differs between the engines)
QImage drawContacts(const QString &title, const std::vector<ContactRow> &rows, const QString &note,
                    const QSize &size = kContactsPlotSize);

}  // namespace bench
