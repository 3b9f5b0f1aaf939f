// The status bar's words: the real-time factor says when the run falls behind the wall clock.

#include "ui/status_text.h"

#include <QtTest>

class TestStatusText : public QObject {
    Q_OBJECT

private slots:
    void rate_data();
    void rate();
    void figures();
};

void TestStatusText::rate_data()
{
    QTest::addColumn<bool>("running");
    QTest::addColumn<double>("factor");
    QTest::addColumn<QString>("text");
    QTest::newRow("paused") << false << 1.0 << "paused";
    QTest::newRow("not measured yet") << true << 0.0 << "×…";
    QTest::newRow("real time") << true << 1.0 << "×1.00";
    QTest::newRow("rounds to real time") << true << 0.996 << "×1.00";
    QTest::newRow("slower") << true << 0.35 << "×0.35 — slower than real time";
    QTest::newRow("just slower") << true << 0.99 << "×0.99 — slower than real time";
}

void TestStatusText::rate()
{
    QFETCH(bool, running);
    QFETCH(double, factor);
    QFETCH(QString, text);
    QCOMPARE(ui::rateText(running, factor), text);
}

void TestStatusText::figures()
{
    QCOMPARE(ui::timeText(1.25), QStringLiteral("t = 1.250 s"));
    QCOMPARE(ui::stepsText(true, 849.6), QStringLiteral("850 steps/s"));
    QCOMPARE(ui::stepsText(false, 849.6), QString());
    QCOMPARE(ui::energyText(-12.5), QStringLiteral("E = -12.5 J"));
}

QTEST_APPLESS_MAIN(TestStatusText)
#include "test_status_text.moc"
