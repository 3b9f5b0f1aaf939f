#pragma once
// PlotSeries: the samples of one plot, a few curves against time, at most one sample per step of
// the simulation. The worker samples every step (session/step_samples.h); a sample at the step
// already last replaces it (an edit while paused changes the values, not the time), and a step or
// time before the last one means the run started over (a reset, another scene), so the old
// samples go. Values are doubles, so that a plotted energy is the core's to the bit. Qt-free.
//
// Memory stays bounded however long the run, and the samples stay evenly spaced in steps: the
// series keeps the steps that are multiples of its stride, 1 at first. When it is full, every
// other sample goes (those off a multiple of twice the stride) and the stride doubles; so a run of
// any length keeps its whole history, from capacity / 2 to capacity samples, one every stride steps.

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
    // every step of 200 s at the default 10 ms step before the first halving
    static constexpr std::size_t kDefaultCapacity = 20000;

    explicit PlotSeries(std::vector<PlotCurve> curves, std::size_t capacity = kDefaultCapacity);

    // Skipped: a step off the stride, not kept
    enum class Added { Appended, Replaced, StartedOver, Skipped };
    // one value per curve
    Added add(std::uint64_t step, double time, const std::vector<double> &values);
    void clear();
    // drops the samples after step: the run went on from there (the timeline's resume)
    void dropAfter(std::uint64_t step);

    const std::vector<PlotCurve> &curves() const { return m_curves; }
    std::size_t curveCount() const { return m_curves.size(); }
    std::size_t capacity() const { return m_capacity; }
    // the steps kept are the multiples of this: 1, then 2, 4, … as the series fills up
    std::uint64_t stride() const { return m_stride; }
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
    // written so that it reads back to the same double: a row every stride() steps
    std::string csv() const;

private:
    // keeps every other sample, those at multiples of twice the stride, which doubles
    void halve();

    std::vector<PlotCurve> m_curves;
    std::size_t m_capacity;
    std::uint64_t m_stride = 1;
    std::deque<std::uint64_t> m_steps;
    std::deque<double> m_times;
    std::vector<std::deque<double>> m_values;  // per curve
};

}  // namespace ui
