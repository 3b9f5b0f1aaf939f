#pragma once
// PlotSeries: the samples of one plot, a few curves against time, at most one sample per step of
// the simulation. Frames reach the editor at display rate, so steps are skipped or seen twice: a
// sample at the step already last replaces it (an edit while paused changes the values, not the
// time), and a step or time before the last one means the run started over (a reset, another
// scene), so the old samples go. Past the capacity the oldest sample goes. Values are doubles, so
// that a plotted energy is the core's to the bit. Qt-free.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ui {

struct PlotCurve {
    std::string name;  // the legend's entry, "kinetic"
    std::string unit;  // "J"
};

class PlotSeries {
public:
    // about five minutes at 60 frames a second
    static constexpr std::size_t kDefaultCapacity = 20000;

    explicit PlotSeries(std::vector<PlotCurve> curves, std::size_t capacity = kDefaultCapacity);

    enum class Added { Appended, Replaced, StartedOver };
    // one value per curve
    Added add(std::uint64_t step, double time, const std::vector<double> &values);
    void clear();
    // drops the samples after step: the run went on from there (the timeline's resume)
    void dropAfter(std::uint64_t step);

    const std::vector<PlotCurve> &curves() const { return m_curves; }
    std::size_t curveCount() const { return m_curves.size(); }
    std::size_t capacity() const { return m_capacity; }
    std::size_t size() const { return m_steps.size(); }
    bool empty() const { return m_steps.empty(); }

    // sample i, oldest first
    std::uint64_t step(std::size_t i) const { return m_steps[i]; }
    double time(std::size_t i) const { return m_times[i]; }   // s
    double value(std::size_t curve, std::size_t i) const { return m_values[curve][i]; }
    // the sample of this step, if it is kept
    std::optional<std::size_t> indexOfStep(std::uint64_t step) const;
    // the smallest and largest finite value of all curves (nullopt when there is none)
    std::optional<std::pair<double, double>> valueRange() const;

    // a header (step, time, then each curve with its unit), then one row per sample, every value
    // written so that it reads back to the same double
    std::string csv() const;

private:
    std::vector<PlotCurve> m_curves;
    std::size_t m_capacity;
    std::deque<std::uint64_t> m_steps;
    std::deque<double> m_times;
    std::vector<std::deque<double>> m_values;  // per curve
};

}  // namespace ui
