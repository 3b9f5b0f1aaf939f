#include "work_precision.h"

#include <cmath>

namespace bench {

bool WorkPrecisionPoint::blewUp() const
{
    return !std::isfinite(error);
}

std::optional<CostAtError> costToReach(const WorkPrecisionCurve &curve, double error)
{
    // the last run above the error (a blow-up counts as above), and the first usable one after it
    const WorkPrecisionPoint *above = nullptr;
    const WorkPrecisionPoint *within = nullptr;
    for (const WorkPrecisionPoint &point : curve.points) {
        // runs without a positive error and cost have no place on a log-log curve
        const bool usable = !point.blewUp() && point.error > 0.0 && point.cost > 0.0;
        if (point.blewUp() || (usable && point.error > error)) {
            above = usable ? &point : nullptr;
            within = nullptr;
        } else if (usable && within == nullptr) {
            within = &point;
        }
    }
    if (within == nullptr)
        return std::nullopt;

    // already there at the first usable run (or the first after a blow-up): an upper bound
    if (above == nullptr)
        return CostAtError{within->cost, true};

    // else interpolate between the two runs that bracket the error
    const double fraction =
        (std::log(error) - std::log(above->error)) / (std::log(within->error) - std::log(above->error));
    const double logCost = std::log(above->cost) + fraction * (std::log(within->cost) - std::log(above->cost));
    return CostAtError{std::exp(logCost), false};
}

}  // namespace bench
