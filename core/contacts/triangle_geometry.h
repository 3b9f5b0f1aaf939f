#pragma once
// Distances and times of impact between a point and a triangle and between two edges, for the
// triangle collisions (triangle_collisions.cpp). Everything is a distance: no cubic for the time of
// coplanarity, so that coplanar, parallel and degenerate configurations (a zero-area triangle, an
// edge of zero length, parallel edges) need no special case beyond the distance's own, and the time
// of impact has no false negatives (docs/physics.md, "Triangle collisions").

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>

namespace core {

// the closest points of a pair: on the first feature (a point, or edge a's point (1-s) a0 + s a1)
// and on the second (the triangle's point Σ b_k t_k, or edge b's (1-t) b0 + t b1)
struct ClosestPoints {
    double squaredDistance = 0.0;
    // weights of the four vertices in the relative position: first feature minus second, so that
    // Σ weight_k x_k is the vector from the second feature's closest point to the first's
    std::array<double, 4> weight{};
};

// the closest points of segments p0 p1 and q0 q1 (parameters clamped to [0, 1]; a segment of zero
// length or two parallel segments give one of the closest pairs)
inline void closestOnSegments(const Eigen::Vector3d &p0, const Eigen::Vector3d &p1, const Eigen::Vector3d &q0,
                              const Eigen::Vector3d &q1, double &s, double &t)
{
    const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    constexpr double tiny = std::numeric_limits<double>::min();
    if (a <= tiny && e <= tiny) {
        s = t = 0.0;
        return;
    }
    if (a <= tiny) {
        s = 0.0;
        t = std::clamp(f / e, 0.0, 1.0);
        return;
    }
    const double c = d1.dot(r);
    if (e <= tiny) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
        return;
    }
    const double b = d1.dot(d2);
    const double denom = a * e - b * b;  // >= 0; 0 when parallel
    s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
    t = (b * s + f) / e;
    if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
    }
}

inline ClosestPoints edgeEdge(const Eigen::Vector3d &a0, const Eigen::Vector3d &a1, const Eigen::Vector3d &b0,
                              const Eigen::Vector3d &b1)
{
    double s = 0.0, t = 0.0;
    closestOnSegments(a0, a1, b0, b1, s, t);
    ClosestPoints c;
    c.weight = {1.0 - s, s, -(1.0 - t), -t};
    c.squaredDistance = ((1.0 - s) * a0 + s * a1 - (1.0 - t) * b0 - t * b1).squaredNorm();
    return c;
}

// point p against triangle t0 t1 t2, by the Voronoi regions of the triangle's features; a
// triangle too thin for its face region falls back to the nearest of its three sides
inline ClosestPoints pointTriangle(const Eigen::Vector3d &p, const Eigen::Vector3d &t0, const Eigen::Vector3d &t1,
                                   const Eigen::Vector3d &t2)
{
    ClosestPoints c;
    auto set = [&](double b0, double b1, double b2) {
        c.weight = {1.0, -b0, -b1, -b2};
        c.squaredDistance = (p - b0 * t0 - b1 * t1 - b2 * t2).squaredNorm();
        return c;
    };
    const Eigen::Vector3d ab = t1 - t0, ac = t2 - t0, ap = p - t0;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0)
        return set(1, 0, 0);
    const Eigen::Vector3d bp = p - t1;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3)
        return set(0, 1, 0);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 - d3 > 0.0 ? d1 / (d1 - d3) : 0.0;
        return set(1 - v, v, 0);
    }
    const Eigen::Vector3d cp = p - t2;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6)
        return set(0, 0, 1);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double w = d2 - d6 > 0.0 ? d2 / (d2 - d6) : 0.0;
        return set(1 - w, 0, w);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
        const double w = (d4 - d3) + (d5 - d6) > 0.0 ? (d4 - d3) / ((d4 - d3) + (d5 - d6)) : 0.0;
        return set(0, 1 - w, w);
    }
    const double sum = va + vb + vc;
    if (sum > 1e-14 * ab.squaredNorm() * ac.squaredNorm() && std::isfinite(1.0 / sum)) {
        const double v = vb / sum, w = vc / sum;
        return set(1 - v - w, v, w);
    }
    // degenerate: the nearest side
    double s = 0.0;
    ClosestPoints best;
    best.squaredDistance = std::numeric_limits<double>::infinity();
    const std::array<const Eigen::Vector3d *, 3> corner{&t0, &t1, &t2};
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d &u = *corner[std::size_t(k)], &w = *corner[std::size_t((k + 1) % 3)];
        const Eigen::Vector3d e = w - u;
        const double l2 = e.squaredNorm();
        s = l2 > 0.0 ? std::clamp((p - u).dot(e) / l2, 0.0, 1.0) : 0.0;
        const double d = (p - (1 - s) * u - s * w).squaredNorm();
        if (d < best.squaredDistance) {
            best.squaredDistance = d;
            best.weight = {1.0, 0.0, 0.0, 0.0};
            best.weight[std::size_t(k) + 1] = -(1 - s);
            best.weight[std::size_t((k + 1) % 3) + 1] = -s;
        }
    }
    return best;
}

enum class PairKind : std::uint8_t { PointTriangle, EdgeEdge };

inline ClosestPoints closest(PairKind kind, const std::array<Eigen::Vector3d, 4> &x)
{
    return kind == PairKind::PointTriangle ? pointTriangle(x[0], x[1], x[2], x[3]) : edgeEdge(x[0], x[1], x[2], x[3]);
}

// The first fraction t of a linear motion x + t d (t in [0, 1]) at which the pair's distance falls
// to within `distance`, by additive conservative advancement (Li, Kaufman and Kavan 2021, as
// codimensional IPC uses it): with the displacements taken relative to their mean, the distance
// changes no faster than l = |d_first| + |d_second| (the largest of each feature's), so advancing
// by 0.9 (gap) / l never steps past the touch. It stops once the gap is down to a tenth of the
// start's (startGap, > 0) or of `distance`, whichever is less, and reports that time: the pair is
// still apart there, and closer than 1.1 `distance`. Returns
// a value above 1 when the pair stays farther apart than that for the whole motion. It has no false
// negatives: a pair it passes never came within `distance`.
inline double additiveImpact(PairKind kind, const std::array<Eigen::Vector3d, 4> &x, std::array<Eigen::Vector3d, 4> d,
                             double distance, double startGap)
{
    const Eigen::Vector3d mean = 0.25 * (d[0] + d[1] + d[2] + d[3]);
    for (Eigen::Vector3d &v : d)
        v -= mean;
    const double l = kind == PairKind::PointTriangle
                         ? d[0].norm() + std::max({d[1].norm(), d[2].norm(), d[3].norm()})
                         : std::max(d[0].norm(), d[1].norm()) + std::max(d[2].norm(), d[3].norm());
    if (!(l > 0.0))
        return 2.0;  // no relative motion: the distance cannot change
    if (!std::isfinite(l))
        return 0.0;  // no bound on the motion: an impact at once
    const double stop = 0.1 * std::min(startGap, distance);
    double t = 0.0;
    double advance = 0.9 * startGap / l;
    constexpr int kMostSteps = 256;
    for (int step = 0; step < kMostSteps; ++step) {
        const double next = t + advance;
        if (next > 1.0)
            return 2.0;
        std::array<Eigen::Vector3d, 4> y;
        for (std::size_t k = 0; k < 4; ++k)
            y[k] = x[k] + next * d[k];
        const double gap = std::sqrt(closest(kind, y).squaredDistance) - distance;
        if (!(gap >= stop))
            return t;
        t = next;
        advance = 0.9 * gap / l;
    }
    return t;  // a slow, grazing approach: reported as an impact where the search stopped
}

}  // namespace core
