#pragma once
// The axes of a plot: a range that shows all the data with a little room, ticks at round values
// (1, 2 or 5 times a power of ten) within it, and their labels. Qt-free.

#include <string>
#include <vector>

namespace ui {

struct AxisRange {
    double low = 0.0;
    double high = 1.0;
    double span() const { return high - low; }
};

// the range of the data, widened a little on both sides so that no curve runs along the frame; a
// single value (or none that is finite) gets a range around it
AxisRange paddedRange(double low, double high, double padding = 0.05);

// the time axis of samples from first to last (s): all of it, with no room; a single sample at t
// shows t to t + 1 s, so that time never reads below the run's start (not -1 … 1 s)
AxisRange timeRange(double first, double last);

struct AxisTicks {
    std::vector<double> values;  // from low to high
    double step = 0.0;           // between two of them
};

// round values from low to high, about `target` of them, evenly spaced (none for an empty range)
AxisTicks niceTicks(const AxisRange &range, int target = 5);

// a tick's label with as many decimals as the step needs ("0.4", "15000"), or in scientific
// notation for very large or very small steps
std::string tickLabel(double value, double step);

}  // namespace ui
