// A plot's samples: one per step, the same step replacing its values, a step or time going back
// starting over, a full series halved to every other step (its whole length kept, evenly spaced),
// and CSV that reads back to the same doubles.

#include "ui/panels/plot_series.h"

#include <QtTest>

#include <charconv>
#include <cmath>
#include <limits>

namespace {

ui::PlotSeries twoCurves(std::size_t capacity = ui::PlotSeries::kDefaultCapacity)
{
    return ui::PlotSeries({{"kinetic", "J"}, {"total", "J"}}, capacity);
}

// the comma-separated fields of one line
QStringList fields(const std::string &line)
{
    return QString::fromStdString(line).split(QLatin1Char(','));
}

}  // namespace

class TestPlotSeries : public QObject {
    Q_OBJECT

private slots:
    void oneSamplePerStep();
    void theSameStepReplacesItsValues();
    void aStepBackStartsOver();
    void aTimeBackStartsOver();
    void dropAfterKeepsWhatCameBefore();
    void aFullSeriesKeepsEveryOtherStep();
    void valueRangeSkipsWhatIsNotFinite();
    void csvHasAHeaderAndOneRowPerSample();
};

void TestPlotSeries::oneSamplePerStep()
{
    ui::PlotSeries series = twoCurves();
    QVERIFY(series.empty());
    QCOMPARE(series.add(0, 0.0, {1.0, 2.0}), ui::PlotSeries::Added::Appended);
    QCOMPARE(series.add(3, 0.03, {1.5, 2.5}), ui::PlotSeries::Added::Appended);
    QCOMPARE(series.size(), std::size_t(2));
    QCOMPARE(series.curveCount(), std::size_t(2));
    QCOMPARE(series.step(1), std::uint64_t(3));
    QCOMPARE(series.time(1), 0.03);
    QCOMPARE(series.value(0, 1), 1.5);
    QCOMPARE(series.value(1, 0), 2.0);
    QCOMPARE(series.indexOfStep(3), std::optional<std::size_t>(1));
    QVERIFY(!series.indexOfStep(2));
}

void TestPlotSeries::theSameStepReplacesItsValues()
{
    // a paused edit: the frame has the same step with other values
    ui::PlotSeries series = twoCurves();
    series.add(5, 0.05, {1.0, 2.0});
    QCOMPARE(series.add(5, 0.05, {7.0, 8.0}), ui::PlotSeries::Added::Replaced);
    QCOMPARE(series.size(), std::size_t(1));
    QCOMPARE(series.value(0, 0), 7.0);
    QCOMPARE(series.value(1, 0), 8.0);
}

void TestPlotSeries::aStepBackStartsOver()
{
    // a reset: back to step 0
    ui::PlotSeries series = twoCurves();
    for (std::uint64_t s = 0; s < 4; ++s)
        series.add(s, 0.01 * double(s), {double(s), 0.0});
    QCOMPARE(series.add(0, 0.0, {9.0, 9.0}), ui::PlotSeries::Added::StartedOver);
    QCOMPARE(series.size(), std::size_t(1));
    QCOMPARE(series.step(0), std::uint64_t(0));
    QCOMPARE(series.value(0, 0), 9.0);

    // and the same step at another time is a new run too
    series.add(1, 0.01, {1.0, 1.0});
    QCOMPARE(series.add(1, 0.5, {2.0, 2.0}), ui::PlotSeries::Added::StartedOver);
    QCOMPARE(series.size(), std::size_t(1));
}

void TestPlotSeries::aTimeBackStartsOver()
{
    // another scene with a shorter step, seen first at a later step but an earlier time
    ui::PlotSeries series = twoCurves();
    series.add(10, 0.1, {1.0, 1.0});
    QCOMPARE(series.add(20, 0.02, {2.0, 2.0}), ui::PlotSeries::Added::StartedOver);
    QCOMPARE(series.size(), std::size_t(1));
    QCOMPARE(series.time(0), 0.02);
}

void TestPlotSeries::dropAfterKeepsWhatCameBefore()
{
    // the run went on from step 3 of 0..7: 0..3 stay, and step 3 again replaces its values
    ui::PlotSeries series = twoCurves();
    for (std::uint64_t s = 0; s < 8; ++s)
        series.add(s, 0.01 * double(s), {double(s), 0.0});
    series.dropAfter(3);
    QCOMPARE(series.size(), std::size_t(4));
    QCOMPARE(series.step(3), std::uint64_t(3));
    QCOMPARE(series.add(3, 0.03, {5.0, 5.0}), ui::PlotSeries::Added::Replaced);
    QCOMPARE(series.add(4, 0.04, {6.0, 6.0}), ui::PlotSeries::Added::Appended);
    QCOMPARE(series.size(), std::size_t(5));
    QCOMPARE(series.value(0, 4), 6.0);
}

void TestPlotSeries::aFullSeriesKeepsEveryOtherStep()
{
    // capacity 4: steps 0..3 all, then every 2nd step, then every 4th
    ui::PlotSeries series = twoCurves(4);
    QCOMPARE(series.capacity(), std::size_t(4));
    for (std::uint64_t s = 0; s < 4; ++s)
        QCOMPARE(series.add(s, 0.5 * double(s), {double(s), -double(s)}), ui::PlotSeries::Added::Appended);
    QCOMPARE(series.stride(), std::uint64_t(1));
    // full: step 4 halves it to 0, 2 and itself; 5 is off the stride
    QCOMPARE(series.add(4, 2.0, {4.0, -4.0}), ui::PlotSeries::Added::Appended);
    QCOMPARE(series.stride(), std::uint64_t(2));
    QCOMPARE(series.size(), std::size_t(3));
    QCOMPARE(series.add(5, 2.5, {5.0, -5.0}), ui::PlotSeries::Added::Skipped);
    QCOMPARE(series.size(), std::size_t(3));

    // a long run: the whole of it, every stride steps from step 0, within the capacity
    for (std::uint64_t s = 5; s <= 1000; ++s)
        series.add(s, 0.5 * double(s), {double(s), -double(s)});
    QCOMPARE_LE(series.size(), series.capacity());
    QCOMPARE_GE(series.size(), series.capacity() / 2);
    QCOMPARE(series.step(0), std::uint64_t(0));
    for (std::size_t i = 0; i < series.size(); ++i) {
        QCOMPARE(series.step(i), std::uint64_t(i) * series.stride());
        QCOMPARE(series.time(i), 0.5 * double(series.step(i)));
        QCOMPARE(series.value(1, i), -double(series.step(i)));
    }
    QCOMPARE_GT(series.step(series.size() - 1) + series.stride(), std::uint64_t(1000));
    QCOMPARE(series.indexOfStep(series.stride()), std::optional<std::size_t>(1));

    // a reset starts over at every step
    QCOMPARE(series.add(0, 0.0, {0.0, 0.0}), ui::PlotSeries::Added::StartedOver);
    QCOMPARE(series.stride(), std::uint64_t(1));
    QCOMPARE(series.add(1, 0.5, {1.0, -1.0}), ui::PlotSeries::Added::Appended);
}

void TestPlotSeries::valueRangeSkipsWhatIsNotFinite()
{
    ui::PlotSeries series = twoCurves();
    QVERIFY(!series.valueRange());
    series.add(0, 0.0, {std::numeric_limits<double>::quiet_NaN(), 3.0});
    series.add(1, 0.1, {-2.0, std::numeric_limits<double>::infinity()});
    series.add(2, 0.2, {0.5, 4.0});
    const auto range = series.valueRange();
    QVERIFY(range);
    QCOMPARE(range->first, -2.0);
    QCOMPARE(range->second, 4.0);
}

void TestPlotSeries::csvHasAHeaderAndOneRowPerSample()
{
    ui::PlotSeries series = twoCurves();
    const double awkward = 0.1 + 0.2;  // not 0.3: it must come back exactly
    series.add(0, 0.0, {awkward, -1e-300});
    series.add(7, 0.07, {1.0 / 3.0, 12345.678});
    const std::string csv = series.csv();

    std::vector<std::string> lines;
    for (std::size_t at = 0, next; at < csv.size(); at = next + 1) {
        next = csv.find('\n', at);
        QVERIFY2(next != std::string::npos, "the last line has no newline");
        lines.push_back(csv.substr(at, next - at));
    }
    QCOMPARE(lines.size(), std::size_t(3));
    QCOMPARE(QString::fromStdString(lines[0]), QStringLiteral("step,time [s],kinetic [J],total [J]"));
    QCOMPARE(fields(lines[1]).size(), 4);
    QCOMPARE(fields(lines[2]).front(), QStringLiteral("7"));

    // every number reads back to the double it was
    for (std::size_t row = 0; row < 2; ++row) {
        const QStringList values = fields(lines[row + 1]);
        const double expected[] = {series.time(row), series.value(0, row), series.value(1, row)};
        for (int column = 1; column < 4; ++column) {
            const std::string text = values[column].toStdString();
            double read = 0.0;
            const auto result = std::from_chars(text.data(), text.data() + text.size(), read);
            QVERIFY2(result.ec == std::errc() && result.ptr == text.data() + text.size(), text.c_str());
            QCOMPARE(read, expected[column - 1]);
        }
    }
}

QTEST_APPLESS_MAIN(TestPlotSeries)
#include "test_plot_series.moc"
