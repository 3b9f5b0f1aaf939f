// A plot's axes: ticks at 1, 2 or 5 times a power of ten, evenly spaced and inside the range, and
// ranges with room around the data, even for a single value.

#include "ui/panels/plot_axis.h"

#include <QtTest>

#include <cmath>
#include <limits>

class TestPlotAxis : public QObject {
    Q_OBJECT

private slots:
    void ticks_data();
    void ticks();
    void noTicksForAnEmptyRange();
    void paddedRange();
    void timeRange();
    void labels_data();
    void labels();
};

void TestPlotAxis::ticks_data()
{
    QTest::addColumn<double>("low");
    QTest::addColumn<double>("high");
    QTest::addColumn<int>("target");
    QTest::addColumn<double>("step");
    QTest::addColumn<int>("count");
    QTest::newRow("unit") << 0.0 << 1.0 << 5 << 0.2 << 6;
    QTest::newRow("across zero") << -3.0 << 7.0 << 5 << 2.0 << 5;
    QTest::newRow("small") << 0.0013 << 0.0091 << 4 << 0.002 << 4;
    QTest::newRow("large") << -12000.0 << 31000.0 << 5 << 10000.0 << 5;
    QTest::newRow("energies") << -61.3 << -58.7 << 5 << 0.5 << 5;
}

void TestPlotAxis::ticks()
{
    QFETCH(double, low);
    QFETCH(double, high);
    QFETCH(int, target);
    QFETCH(double, step);
    QFETCH(int, count);
    const ui::AxisTicks found = ui::niceTicks({low, high}, target);
    QCOMPARE(found.step, step);
    const std::vector<double> &ticks = found.values;
    QCOMPARE(int(ticks.size()), count);
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        // inside the range, a whole number of steps, the same distance apart
        QVERIFY(ticks[i] >= low && ticks[i] <= high);
        const double steps = ticks[i] / step;
        QVERIFY2(std::abs(steps - std::round(steps)) < 1e-9, qPrintable(QString::number(ticks[i])));
        if (i > 0)
            QVERIFY(std::abs(ticks[i] - ticks[i - 1] - step) < 1e-9 * step);
    }
}

void TestPlotAxis::noTicksForAnEmptyRange()
{
    QVERIFY(ui::niceTicks({1.0, 1.0}).values.empty());
    QVERIFY(ui::niceTicks({2.0, 1.0}).values.empty());
    QVERIFY(ui::niceTicks({0.0, std::numeric_limits<double>::infinity()}).values.empty());
}

void TestPlotAxis::timeRange()
{
    // all the time kept; one sample at the start reads 0 … 1 s, never -1 … 1 s
    const ui::AxisRange run = ui::timeRange(0.5, 2.0);
    QCOMPARE(run.low, 0.5);
    QCOMPARE(run.high, 2.0);
    const ui::AxisRange one = ui::timeRange(0.0, 0.0);
    QCOMPARE(one.low, 0.0);
    QCOMPARE(one.high, 1.0);
    const ui::AxisRange later = ui::timeRange(3.25, 3.25);
    QCOMPARE(later.low, 3.25);
    QCOMPARE(later.high, 4.25);
}

void TestPlotAxis::paddedRange()
{
    // room on both sides
    const ui::AxisRange wide = ui::paddedRange(0.0, 10.0);
    QCOMPARE(wide.low, -0.5);
    QCOMPARE(wide.high, 10.5);

    // one value: a tenth of it either side, or 1 around zero
    const ui::AxisRange one = ui::paddedRange(-20.0, -20.0);
    QCOMPARE(one.low, -22.0);
    QCOMPARE(one.high, -18.0);
    const ui::AxisRange zero = ui::paddedRange(0.0, 0.0);
    QCOMPARE(zero.low, -1.0);
    QCOMPARE(zero.high, 1.0);

    // nothing finite: the unit range
    const ui::AxisRange none = ui::paddedRange(std::numeric_limits<double>::quiet_NaN(), 1.0);
    QCOMPARE(none.low, 0.0);
    QCOMPARE(none.high, 1.0);
}

void TestPlotAxis::labels_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<double>("step");
    QTest::addColumn<QString>("label");
    QTest::newRow("tenths") << 0.4 << 0.2 << "0.4";
    QTest::newRow("whole") << 15000.0 << 5000.0 << "15000";
    QTest::newRow("negative") << -60.5 << 0.5 << "-60.5";
    QTest::newRow("thousandths") << 0.006 << 0.002 << "0.006";
    QTest::newRow("zero with decimals") << 0.0 << 0.05 << "0.00";
    QTest::newRow("huge") << 2e7 << 1e7 << "2e+07";
    QTest::newRow("tiny") << 3e-6 << 1e-6 << "3e-06";
}

void TestPlotAxis::labels()
{
    QFETCH(double, value);
    QFETCH(double, step);
    QFETCH(QString, label);
    QCOMPARE(QString::fromStdString(ui::tickLabel(value, step)), label);
}

QTEST_APPLESS_MAIN(TestPlotAxis)
#include "test_plot_axis.moc"
