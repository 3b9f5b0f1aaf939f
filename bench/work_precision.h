#pragma once
// Work-precision data: for each integrator, the runs of one sweep as (error, cost) points, and the
// cost read off such a curve at a given error.

#include "core/integrators/integrator.h"

#include <optional>
#include <vector>

namespace bench {

// one run of the sweep
struct WorkPrecisionPoint {
    double timeStep = 0.0;   // s, the scene's time step
    int substeps = 1;        // the integration step is timeStep / substeps
    double tolerance = 0.0;  // adaptive-rk45's tolerance; 0 for the fixed-step integrators
    double error = 0.0;      // m, RMS position error at the end time; infinite for a blow-up
    double cost = 0.0;       // CPU seconds per simulated second (not measured for a blow-up)

    bool blewUp() const;
};

// the runs of one integrator, in sweep order: coarse to fine, so cost rises along it
struct WorkPrecisionCurve {
    core::Integrator integrator = core::Integrator::SymplecticEuler;
    std::vector<WorkPrecisionPoint> points;
};

// the cost at which a curve first gets down to `error`
struct CostAtError {
    double cost = 0.0;    // CPU s per simulated s
    bool atMost = false;  // the curve's first usable run is already there: the cost is an upper bound
};

// the cost from which on the curve stays at or below `error`: the last run above it and the next
// run are interpolated linearly in log(error) and log(cost). A curve that dips below the error by
// luck and comes back above it (a contact that happens to fall near a step boundary) is not
// counted as there until it stays there. nullopt when the sweep never gets there for good
std::optional<CostAtError> costToReach(const WorkPrecisionCurve &curve, double error);

}  // namespace bench
