#pragma once
// How a parameter's slider maps positions to values. The parameter table (core/model/parameters.h)
// gives the safe range and the scale; a slider spans the useful part of that range (a gravity of
// ±10⁴ m/s² is safe, but a slider over it could not set 9.81), so the table also gives each
// parameter a slider range. A log slider whose safe range starts at 0 keeps its first position for
// exactly 0 ("off"). Qt-free, for the unit tests.

#include "core/model/parameters.h"

namespace ui {

struct SliderScale {
    double minimum = 0.0;  // value at the first position (or the second, with zeroAtStart)
    double maximum = 1.0;  // value at the last position
    core::Scale scale = core::Scale::Linear;
    bool zeroAtStart = false;  // log scale only: the first position means exactly 0
    int positions = 1000;      // the slider runs from 0 to positions

    // the value at a slider position, rounded: a linear scale to the power of ten below one
    // position's width, a log scale to three significant digits
    double valueAt(int position) const;
    // the position nearest to a value (clamped to the slider)
    int positionOf(double value) const;
};

SliderScale sliderScale(const core::ParameterInfo &info);

// value rounded to `digits` significant digits
double roundSignificant(double value, int digits);

}  // namespace ui
