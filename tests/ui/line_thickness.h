#pragma once
// How thick a line is in a picture of the view, in pixels: for the tests of the line widths.

#include "ui/viewport/render_data.h"

#include <QColor>
#include <QImage>

#include <algorithm>
#include <cstdlib>

namespace test {

// the line across column x near row y (within reach rows): the rows' differences from the
// background summed, over the largest of them, so that the edges the multisampling blends count
// as the part of a pixel they cover; 0 when no pixel there clearly differs
inline double lineThickness(const QImage &image, int x, int y, int reach)
{
    const QColor background =
        QColor::fromRgbF(ui::kBackgroundColour[0], ui::kBackgroundColour[1], ui::kBackgroundColour[2]);
    auto contrast = [&](int row) {
        const QColor c = image.pixelColor(x, row);
        return std::max({std::abs(c.red() - background.red()), std::abs(c.green() - background.green()),
                         std::abs(c.blue() - background.blue())});
    };
    const int first = std::max(0, y - reach), last = std::min(image.height() - 1, y + reach);
    int peak = 0, sum = 0;
    for (int row = first; row <= last; ++row) {
        peak = std::max(peak, contrast(row));
        sum += contrast(row);
    }
    return peak < 40 ? 0.0 : double(sum) / peak;
}

}  // namespace test
