#include "plot_series.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>

namespace ui {

namespace {

// the shortest text that reads back to the same double
void appendNumber(std::string &out, double value)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

}  // namespace

PlotSeries::PlotSeries(std::vector<PlotCurve> curves, std::size_t capacity)
    : m_curves(std::move(curves)), m_capacity(capacity), m_values(m_curves.size())
{
    assert(capacity > 1);
}

PlotSeries::Added PlotSeries::add(std::uint64_t step, double time, const std::vector<double> &values)
{
    assert(values.size() == m_curves.size());

    // the same step again: its newest values
    if (!empty() && step == m_steps.back() && time == m_times.back()) {
        for (std::size_t c = 0; c < values.size(); ++c)
            m_values[c].back() = values[c];
        return Added::Replaced;
    }

    // back in step or time: the run started over
    const bool startedOver = !empty() && (step <= m_steps.back() || time < m_times.back());
    if (startedOver)
        clear();

    // only the steps on the stride; when full, half of them go to make room
    if (step % m_stride != 0)
        return Added::Skipped;
    // (a series with gaps may need more than one halving)
    while (size() >= m_capacity)
        halve();
    if (step % m_stride != 0)
        return Added::Skipped;
    m_steps.push_back(step);
    m_times.push_back(time);
    for (std::size_t c = 0; c < values.size(); ++c)
        m_values[c].push_back(values[c]);
    return startedOver ? Added::StartedOver : Added::Appended;
}

void PlotSeries::dropAfter(std::uint64_t step)
{
    while (!empty() && m_steps.back() > step) {
        m_steps.pop_back();
        m_times.pop_back();
        for (std::deque<double> &curve : m_values)
            curve.pop_back();
    }
}

void PlotSeries::halve()
{
    m_stride *= 2;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < size(); ++i) {
        if (m_steps[i] % m_stride != 0)
            continue;
        m_steps[kept] = m_steps[i];
        m_times[kept] = m_times[i];
        for (std::deque<double> &curve : m_values)
            curve[kept] = curve[i];
        ++kept;
    }
    m_steps.resize(kept);
    m_times.resize(kept);
    for (std::deque<double> &curve : m_values)
        curve.resize(kept);
}

void PlotSeries::clear()
{
    m_stride = 1;
    m_steps.clear();
    m_times.clear();
    for (std::deque<double> &curve : m_values)
        curve.clear();
}

std::optional<std::size_t> PlotSeries::indexOfStep(std::uint64_t step) const
{
    // steps only increase within a series
    const auto found = std::lower_bound(m_steps.begin(), m_steps.end(), step);
    if (found == m_steps.end() || *found != step)
        return std::nullopt;
    return static_cast<std::size_t>(found - m_steps.begin());
}

std::optional<std::pair<double, double>> PlotSeries::valueRange() const
{
    std::optional<std::pair<double, double>> range;
    for (const std::deque<double> &curve : m_values)
        for (double value : curve) {
            if (!std::isfinite(value))
                continue;
            if (!range)
                range.emplace(value, value);
            range->first = std::min(range->first, value);
            range->second = std::max(range->second, value);
        }
    return range;
}

std::string PlotSeries::csv() const
{
    // header: names with units in brackets
    std::string out = "step,time [s]";
    for (const PlotCurve &curve : m_curves)
        out += "," + curve.name + " [" + curve.unit + "]";
    out += "\n";

    // one row per sample
    for (std::size_t i = 0; i < size(); ++i) {
        out += std::to_string(m_steps[i]);
        out += ",";
        appendNumber(out, m_times[i]);
        for (const std::deque<double> &curve : m_values) {
            out += ",";
            appendNumber(out, curve[i]);
        }
        out += "\n";
    }
    return out;
}

}  // namespace ui
