#include "plot_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ui {

AxisRange paddedRange(double low, double high, double padding)
{
    // nothing finite to show: the unit range
    if (!std::isfinite(low) || !std::isfinite(high) || low > high)
        return {};
    // one value: a range as wide as a tenth of it (or 1 around zero)
    if (low == high) {
        const double half = low == 0.0 ? 1.0 : 0.1 * std::abs(low);
        return {low - half, high + half};
    }
    const double room = padding * (high - low);
    return {low - room, high + room};
}

AxisRange timeRange(double first, double last)
{
    if (!std::isfinite(first) || !std::isfinite(last) || last < first)
        return {};
    return last > first ? AxisRange{first, last} : AxisRange{first, first + 1.0};
}

AxisTicks niceTicks(const AxisRange &range, int target)
{
    AxisTicks ticks;
    const double span = range.span();
    if (!(span > 0.0) || !std::isfinite(span) || target < 1)
        return ticks;

    // the round step nearest span / target: 1, 2 or 5 times a power of ten
    const double rough = span / target;
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    const double fraction = rough / power;
    const double step = (fraction < 1.5 ? 1.0 : fraction < 3.5 ? 2.0 : fraction < 7.5 ? 5.0 : 10.0) * power;
    ticks.step = step;

    // every multiple of it in the range; a tick within rounding of zero is zero
    for (double k = std::ceil(range.low / step); k * step <= range.high + 1e-9 * step; k += 1.0) {
        const double tick = k * step;
        ticks.values.push_back(std::abs(tick) < 1e-9 * step ? 0.0 : tick);
    }
    return ticks;
}

std::string tickLabel(double value, double step)
{
    // the decimals of the step: 0.2 needs one, 5000 none; past a million or under 1e-4, 1.5e+07
    char text[64];
    const double magnitude = std::max(std::abs(value), step);
    if (step > 0.0 && step >= 1e-4 && magnitude < 1e6) {
        const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
        std::snprintf(text, sizeof text, "%.*f", decimals, value);
    } else {
        std::snprintf(text, sizeof text, "%.3g", value);
    }
    return text;
}

}  // namespace ui
