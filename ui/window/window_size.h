#pragma once
// The editor window's first size: 1200 × 800, or less on a screen too small for it (a laptop with
// its scale factor at 150% has 1066 × 666 logical pixels), so that the window never opens larger
// than the screen.

#include <QSize>

namespace ui {

inline constexpr QSize kDefaultWindowSize{1200, 800};

// room left around the window on the screen, for its frame and title bar, px
inline constexpr int kScreenMargin = 64;

// the default size within the screen's available area less the margin, each side on its own
inline QSize defaultWindowSize(QSize available)
{
    if (!available.isValid() || available.isEmpty())
        return kDefaultWindowSize;
    return kDefaultWindowSize.boundedTo(available - QSize(kScreenMargin, kScreenMargin));
}

}  // namespace ui
