// Slider scales: every position of every parameter's slider gives a value the parameter table
// accepts, positions and values round-trip, and log sliders keep 0 at their start where 0 is
// allowed.

#include "ui/panels/slider_scale.h"

#include <QtTest>

Q_DECLARE_METATYPE(core::Parameter)

class TestSliderScale : public QObject {
    Q_OBJECT

private slots:
    void everyPositionIsAccepted_data();
    void everyPositionIsAccepted();
    void positionsRoundTrip_data();
    void positionsRoundTrip();
    void logStartsAtZeroWhereZeroIsAllowed();
    void timeStepNeverReachesZero();
    void valuesOutsideTheSliderPinToItsEnds();
    void roundsToThreeSignificantDigits();
};

void TestSliderScale::everyPositionIsAccepted_data()
{
    QTest::addColumn<core::Parameter>("parameter");
    for (const core::ParameterInfo &info : core::parameterTable())
        QTest::newRow(std::string(info.key).c_str()) << info.parameter;
}

void TestSliderScale::everyPositionIsAccepted()
{
    QFETCH(core::Parameter, parameter);
    const ui::SliderScale scale = ui::sliderScale(core::parameterInfo(parameter));
    for (int position = 0; position <= scale.positions; ++position) {
        const double value = scale.valueAt(position);
        if (const auto problem = core::checkParameter(parameter, value))
            QFAIL(qPrintable(QStringLiteral("position %1 gives %2, which %3")
                                 .arg(position)
                                 .arg(value)
                                 .arg(QString::fromStdString(*problem))));
    }
}

void TestSliderScale::positionsRoundTrip_data()
{
    everyPositionIsAccepted_data();
}

void TestSliderScale::positionsRoundTrip()
{
    // three significant digits are enough to find the position again, give or take one
    QFETCH(core::Parameter, parameter);
    const ui::SliderScale scale = ui::sliderScale(core::parameterInfo(parameter));
    for (int position = 0; position <= scale.positions; position += 7)
        QVERIFY(std::abs(scale.positionOf(scale.valueAt(position)) - position) <= 1);
}

void TestSliderScale::logStartsAtZeroWhereZeroIsAllowed()
{
    const ui::SliderScale stiffness = ui::sliderScale(core::parameterInfo(core::Parameter::Stiffness));
    QCOMPARE(stiffness.scale, core::Scale::Log);
    QVERIFY(stiffness.zeroAtStart);
    QCOMPARE(stiffness.valueAt(0), 0.0);
    QCOMPARE(stiffness.valueAt(1), stiffness.minimum);
    QCOMPARE(stiffness.valueAt(stiffness.positions), stiffness.maximum);
    QCOMPARE(stiffness.positionOf(0.0), 0);

    // one decade is the same number of positions wherever it is
    const int low = stiffness.positionOf(10.0) - stiffness.positionOf(1.0);
    const int high = stiffness.positionOf(1e5) - stiffness.positionOf(1e4);
    QVERIFY(std::abs(low - high) <= 1);
}

void TestSliderScale::timeStepNeverReachesZero()
{
    const ui::SliderScale timeStep = ui::sliderScale(core::parameterInfo(core::Parameter::TimeStep));
    QVERIFY(!timeStep.zeroAtStart);
    QVERIFY(timeStep.valueAt(0) > 0.0);
}

void TestSliderScale::valuesOutsideTheSliderPinToItsEnds()
{
    const ui::SliderScale gravity = ui::sliderScale(core::parameterInfo(core::Parameter::Gravity));
    QCOMPARE(gravity.positionOf(-1000.0), 0);
    QCOMPARE(gravity.positionOf(1000.0), gravity.positions);
    QCOMPARE(gravity.positionOf(0.0), gravity.positions / 2);
}

void TestSliderScale::roundsToThreeSignificantDigits()
{
    QCOMPARE(ui::roundSignificant(1234.5678, 3), 1230.0);
    QCOMPARE(ui::roundSignificant(-0.0098765, 3), -0.00988);
    QCOMPARE(ui::roundSignificant(0.0, 3), 0.0);
}

QTEST_APPLESS_MAIN(TestSliderScale)
#include "test_slider_scale.moc"
