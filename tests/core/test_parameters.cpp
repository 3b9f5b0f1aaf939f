// The parameter table: complete, in enum order, sane ranges, and clear refusals.
#include "core/model/parameters.h"

#include <QtTest>
#include <limits>

class TestParameters : public QObject {
    Q_OBJECT

private slots:
    void tableIsCompleteAndOrdered();
    void refusals_data();
    void refusals();
};

void TestParameters::tableIsCompleteAndOrdered()
{
    const auto table = core::parameterTable();
    QCOMPARE(int(table.size()), core::kParameterCount);
    for (std::size_t i = 0; i < table.size(); ++i) {
        const core::ParameterInfo &info = table[i];
        QCOMPARE(int(info.parameter), int(i));
        QVERIFY(info.minimum < info.maximum);
        // a slider spans part of the safe range, never beyond it
        QVERIFY(info.sliderMinimum < info.sliderMaximum);
        QVERIFY(info.sliderMinimum >= info.minimum && info.sliderMaximum <= info.maximum);
        QVERIFY(!info.key.empty() && !info.label.empty() && !info.tooltip.empty());
        QVERIFY2(!core::checkParameter(info.parameter, info.defaultValue), info.key.data());
        if (info.scale == core::Scale::Log)  // a log slider needs a positive lower end to map from
            QVERIFY(info.maximum > 0.0);
    }
}

void TestParameters::refusals_data()
{
    QTest::addColumn<int>("parameter");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("reason");  // empty: accepted
    QTest::newRow("mass ok") << int(core::Parameter::Mass) << 2.5 << "";
    QTest::newRow("mass zero") << int(core::Parameter::Mass) << 0.0 << "must be greater than 0 kg (got 0 kg)";
    // found by fuzzing: the smallest double is positive, but 1 / m overflows
    QTest::newRow("mass denormal") << int(core::Parameter::Mass) << 5e-324
                                   << "is too small: 1 / mass is infinite (got 5e-324 kg)";
    QTest::newRow("substeps huge") << int(core::Parameter::Substeps) << 2147483647.0
                                   << "must be at most 10000 (got 2147483647)";
    QTest::newRow("restitution 1") << int(core::Parameter::Restitution) << 1.0 << "";
    QTest::newRow("restitution 2") << int(core::Parameter::Restitution) << 2.0 << "must be at most 1 (got 2)";
    QTest::newRow("time step NaN") << int(core::Parameter::TimeStep) << std::numeric_limits<double>::quiet_NaN()
                                   << "is not a number (NaN)";
    QTest::newRow("stiffness inf") << int(core::Parameter::Stiffness) << std::numeric_limits<double>::infinity()
                                   << "must be finite (got infinity)";
}

void TestParameters::refusals()
{
    QFETCH(int, parameter);
    QFETCH(double, value);
    QFETCH(QString, reason);
    const auto refusal = core::checkParameter(static_cast<core::Parameter>(parameter), value);
    QCOMPARE(refusal ? QString::fromStdString(*refusal) : QString(), reason);
}

QTEST_APPLESS_MAIN(TestParameters)
#include "test_parameters.moc"
