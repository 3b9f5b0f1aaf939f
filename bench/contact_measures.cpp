#include "contact_measures.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace bench {

double kineticEnergy(const Eigen::Matrix3Xd &velocity, const Eigen::VectorXd &mass)
{
    double energy = 0.0;
    for (Eigen::Index i = 0; i < velocity.cols(); ++i)
        energy += 0.5 * mass[i] * velocity.col(i).squaredNorm();
    return energy;
}

double deepestOverlap(const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius,
                      const std::vector<core::PlaneDesc> &planes)
{
    const Eigen::Index n = position.cols();
    double deepest = 0.0;
    if (n == 0)
        return deepest;

    // the planes: r minus the distance in front
    for (Eigen::Index i = 0; i < n; ++i)
        for (const core::PlaneDesc &plane : planes)
            deepest = std::max(deepest, radius[i] - (plane.normal.dot(position.col(i)) - plane.offset));

    // the pairs: a sweep along x, each ball against those less than two largest radii further on
    std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), Eigen::Index{0});
    std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return position(0, a) < position(0, b); });
    const double reach = 2.0 * radius.maxCoeff();
    for (std::size_t a = 0; a < order.size(); ++a) {
        const Eigen::Index i = order[a];
        for (std::size_t b = a + 1; b < order.size() && position(0, order[b]) - position(0, i) < reach; ++b) {
            const Eigen::Index j = order[b];
            deepest = std::max(deepest, radius[i] + radius[j] - (position.col(i) - position.col(j)).norm());
        }
    }
    return deepest;
}

Repose reposeAngle(const Eigen::Matrix3Xd &position, const Eigen::VectorXd &radius, const Eigen::Vector2d &axis)
{
    Repose repose;
    const Eigen::Index n = position.cols();
    if (n == 0)
        return repose;
    const double r = radius.maxCoeff();

    // each ball's distance from the axis and its top; the bins' highest tops
    std::vector<double> distance(static_cast<std::size_t>(n));
    std::map<int, double> highest;  // bin of one diameter → the highest top in it, m
    for (Eigen::Index i = 0; i < n; ++i) {
        const double rho = std::hypot(position(0, i) - axis.x(), position(2, i) - axis.y());
        const double top = position(1, i) + radius[i];
        distance[static_cast<std::size_t>(i)] = rho;
        repose.height = std::max(repose.height, top);
        double &bin = highest[static_cast<int>(rho / (2.0 * r))];
        bin = std::max(bin, top);
    }

    // the cone: height over the radius that holds 95% of the balls
    const auto percentile = distance.begin() + static_cast<std::ptrdiff_t>(distance.size() * 95 / 100);
    std::nth_element(distance.begin(), percentile, distance.end());
    repose.baseRadius = *percentile + r;
    repose.coneDegrees = std::atan2(repose.height, repose.baseRadius) * 180.0 / M_PI;

    // the flank: bins 1, 2, ... while each holds a ball above the first layer
    std::vector<std::pair<double, double>> flank;  // (bin's middle, m; its highest top, m)
    for (int b = 1;; ++b) {
        const auto found = highest.find(b);
        if (found == highest.end() || found->second <= 3.0 * r)
            break;
        flank.emplace_back((b + 0.5) * 2.0 * r, found->second);
    }
    repose.flankBins = static_cast<int>(flank.size());
    if (flank.size() < 3)
        return repose;

    // least squares: top = a + slope × distance
    double meanX = 0.0, meanY = 0.0;
    for (const auto &[x, y] : flank) {
        meanX += x;
        meanY += y;
    }
    meanX /= static_cast<double>(flank.size());
    meanY /= static_cast<double>(flank.size());
    double sxy = 0.0, sxx = 0.0;
    for (const auto &[x, y] : flank) {
        sxy += (x - meanX) * (y - meanY);
        sxx += (x - meanX) * (x - meanX);
    }
    repose.fitDegrees = std::atan(-sxy / sxx) * 180.0 / M_PI;
    return repose;
}

}  // namespace bench
