#include "slider_scale.h"

#include <algorithm>
#include <cmath>

namespace ui {

double roundSignificant(double value, int digits)
{
    if (value == 0.0 || !std::isfinite(value))
        return value;
    const double magnitude = std::floor(std::log10(std::abs(value)));
    const double unit = std::pow(10.0, magnitude - (digits - 1));
    return std::round(value / unit) * unit;
}

SliderScale sliderScale(const core::ParameterInfo &info)
{
    SliderScale scale;
    scale.scale = info.scale;
    scale.minimum = std::max(info.sliderMinimum, info.minimum);
    scale.maximum = std::min(info.sliderMaximum, info.maximum);
    if (scale.scale == core::Scale::Log) {
        // a log scale cannot reach 0: start a few decades below the top, and keep 0 at the start
        // when the safe range allows it
        scale.zeroAtStart = info.minimum == 0.0 && !info.minimumExclusive;
        if (scale.minimum <= 0.0)
            scale.minimum = scale.maximum * 1e-6;
    }
    return scale;
}

double SliderScale::valueAt(int position) const
{
    position = std::clamp(position, 0, positions);
    if (scale == core::Scale::Linear) {
        // rounded to the power of ten below one position's width: a gravity of -9.8, not -9.7999
        const double t = static_cast<double>(position) / positions;
        const double value = minimum + t * (maximum - minimum);
        const double exponent = std::floor(std::log10((maximum - minimum) / positions));
        // dividing by a whole power of ten gives the double nearest the decimal (14.14, not 14.140000000000001)
        if (exponent < 0.0) {
            const double perUnit = std::pow(10.0, -exponent);
            return std::round(value * perUnit) / perUnit;
        }
        const double unit = std::pow(10.0, exponent);
        return std::round(value / unit) * unit;
    }
    if (zeroAtStart && position == 0)
        return 0.0;
    const int first = zeroAtStart ? 1 : 0;
    const double t = static_cast<double>(position - first) / (positions - first);
    return roundSignificant(minimum * std::pow(maximum / minimum, t), 3);
}

int SliderScale::positionOf(double value) const
{
    if (!std::isfinite(value))
        return value > 0 ? positions : 0;
    double t = 0.0;
    int first = 0;
    if (scale == core::Scale::Linear) {
        t = (value - minimum) / (maximum - minimum);
    } else {
        if (zeroAtStart && value <= 0.0)
            return 0;
        if (value <= 0.0)
            return 0;
        first = zeroAtStart ? 1 : 0;
        t = std::log(value / minimum) / std::log(maximum / minimum);
    }
    t = std::clamp(t, 0.0, 1.0);
    return first + static_cast<int>(std::lround(t * (positions - first)));
}

}  // namespace ui
