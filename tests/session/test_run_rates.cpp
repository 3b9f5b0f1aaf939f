// The rates of a playing run: averaged over a window of wall time, which stays open until it
// holds a step, so that a run of slow steps reads its true rate and never 0 while it steps.

#include "session/run_rates.h"

#include <QtTest>

class TestRunRates : public QObject {
    Q_OBJECT

private slots:
    void averagesOverTheWindow();
    void slowStepsNeverReadZero();
    void startForgetsTheRates();
};

void TestRunRates::averagesOverTheWindow()
{
    // 30 steps of 10 ms in 0.6 s, all kept up with: 50 steps/s at half real time
    ui::RunRates rates;
    rates.start();
    QVERIFY(!rates.add(10, 0.2, 0.2));
    QVERIFY(!rates.add(10, 0.2, 0.4));
    QCOMPARE(rates.stepsPerSecond(), 0.0);  // not measured yet
    QVERIFY(rates.add(10, 0.2, 0.6));
    QCOMPARE(rates.stepsPerSecond(), 50.0);
    QCOMPARE(rates.realTimeFactor(), 1.0);

    // the next window starts empty
    QVERIFY(rates.add(5, 0.25, 0.5));
    QCOMPARE(rates.stepsPerSecond(), 10.0);
    QCOMPARE(rates.realTimeFactor(), 0.5);
}

void TestRunRates::slowStepsNeverReadZero()
{
    // one step every 2.5 s: ticks without a step leave the window open, and the rate shown stays
    // the last one measured
    ui::RunRates rates;
    rates.start();
    QVERIFY(rates.add(1, 0.01, 2.5));
    QCOMPARE(rates.stepsPerSecond(), 0.4);
    for (double t : {0.6, 1.2, 1.8, 2.4})
        QVERIFY(!rates.add(0, 0.0, t));
    QCOMPARE(rates.stepsPerSecond(), 0.4);
    QVERIFY(rates.add(1, 0.01, 2.5));
    QCOMPARE(rates.stepsPerSecond(), 0.4);
    QCOMPARE(rates.realTimeFactor(), 0.004);
}

void TestRunRates::startForgetsTheRates()
{
    ui::RunRates rates;
    rates.start();
    QVERIFY(rates.add(10, 0.1, 1.0));
    rates.start();
    QCOMPARE(rates.stepsPerSecond(), 0.0);
    QCOMPARE(rates.realTimeFactor(), 0.0);
    QVERIFY(!rates.add(0, 0.0, 0.7));
}

QTEST_APPLESS_MAIN(TestRunRates)
#include "test_run_rates.moc"
