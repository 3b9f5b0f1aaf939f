// The status bar's words: the real-time factor says when the run falls behind the wall clock; the
// steps and frames per second, a slow rate never read as 0; the local error and the energy drift
// in short figures; what the accuracy planner picked and why.

#include "ui/panels/status_text.h"

#include <QtTest>

class TestStatusText : public QObject {
    Q_OBJECT

private slots:
    void rate_data();
    void rate();
    void figures();
    void scientific_data();
    void scientific();
    void localError();
    void drift_data();
    void drift();
    void plan();
    void selection();
    void distance();
    void stability();
};

void TestStatusText::rate_data()
{
    QTest::addColumn<bool>("running");
    QTest::addColumn<double>("factor");
    QTest::addColumn<double>("speed");
    QTest::addColumn<QString>("text");
    QTest::newRow("paused") << false << 1.0 << 1.0 << "paused";
    QTest::newRow("not measured yet") << true << 0.0 << 1.0 << "×…";
    QTest::newRow("real time") << true << 1.0 << 1.0 << "×1.00";
    QTest::newRow("rounds to real time") << true << 0.996 << 1.0 << "×1.00";
    QTest::newRow("slower") << true << 0.35 << 1.0 << "×0.35 — slower than real time";
    QTest::newRow("just slower") << true << 0.99 << 1.0 << "×0.99 — slower than real time";
    // a step of 10 ms every 4.8 s: not ×0.00
    QTest::newRow("far slower") << true << 0.0021 << 1.0 << "×0.0021 — slower than real time";
    QTest::newRow("a tenth") << true << 0.1 << 1.0 << "×0.10 — slower than real time";
    // another speed chosen: measured against it
    QTest::newRow("a quarter, kept up") << true << 0.25 << 0.25 << "×0.25";
    QTest::newRow("four times, kept up") << true << 3.99 << 4.0 << "×3.99";
    QTest::newRow("four times, behind") << true << 2.5 << 4.0 << "×2.50 — slower than the ×4 asked";
    QTest::newRow("a half, behind") << true << 0.3 << 0.5 << "×0.30 — slower than the ×½ asked";
    QTest::newRow("as fast as it goes") << true << 37.204 << 0.0 << "×37.20 — as fast as it goes";
}

void TestStatusText::rate()
{
    QFETCH(bool, running);
    QFETCH(double, factor);
    QFETCH(double, speed);
    QFETCH(QString, text);
    QCOMPARE(ui::rateText(running, factor, speed), text);
}

void TestStatusText::figures()
{
    QCOMPARE(ui::timeText(1.25), QStringLiteral("t = 1.250 s"));
    QCOMPARE(ui::stepsText(true, 849.6), QStringLiteral("850 steps/s"));
    QCOMPARE(ui::stepsText(false, 849.6), QString());
    QCOMPARE(ui::stepsText(false, 0.0, 1), QStringLiteral("taking a step…"));
    QCOMPARE(ui::stepsText(false, 0.0, 3), QStringLiteral("taking 3 steps…"));
    QCOMPARE(ui::stepsText(true, 12.4, 1), QStringLiteral("12 steps/s"));
    // slow runs keep two significant digits, never "0 steps/s"; 0 is "not measured yet"
    QCOMPARE(ui::stepsText(true, 12.4), QStringLiteral("12 steps/s"));
    QCOMPARE(ui::stepsText(true, 4.24), QStringLiteral("4.2 steps/s"));
    QCOMPARE(ui::stepsText(true, 0.19), QStringLiteral("0.19 steps/s"));
    QCOMPARE(ui::stepsText(true, 0.0), QStringLiteral("… steps/s"));
    QCOMPARE(ui::framesText(true, 59.7), QStringLiteral("60 frames/s"));
    QCOMPARE(ui::framesText(true, 0.8), QStringLiteral("0.8 frames/s"));
    QCOMPARE(ui::framesText(true, 0.0), QStringLiteral("… frames/s"));
    QCOMPARE(ui::framesText(false, 30.0), QString());
    QCOMPARE(ui::energyText(-12.5), QStringLiteral("E = -12.5 J"));
    // round-off is 0: a scene at rest (9.76e-27 J), parts that cancel to a billionth
    QCOMPARE(ui::energyText(core::Energies{9.76215e-27, 0.0, 0.0}), QStringLiteral("E = 0 J"));
    QCOMPARE(ui::energyText(core::Energies{0.0, 3.0, -3.0 + 1e-15}), QStringLiteral("E = 0 J"));
    // a small energy that is not round-off stays
    QCOMPARE(ui::energyText(core::Energies{2.5e-9, 0.0, 0.0}), QStringLiteral("E = 2.5e-09 J"));
    QCOMPARE(ui::energyText(core::Energies{1.0, 2.0, 0.5}), QStringLiteral("E = 3.5 J"));
}

void TestStatusText::scientific_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("text");
    QTest::newRow("small") << 3.2e-6 << "3.2e-6";
    QTest::newRow("rounded") << 3.249e-6 << "3.2e-6";
    QTest::newRow("large") << 12500.0 << "1.3e4";
    QTest::newRow("whole") << 2.0 << "2";
    QTest::newRow("trailing zero") << 1e-6 << "1e-6";
    QTest::newRow("two-digit exponent") << 4.5e-12 << "4.5e-12";
}

void TestStatusText::scientific()
{
    QFETCH(double, value);
    QFETCH(QString, text);
    QCOMPARE(ui::scientificText(value), text);
}

void TestStatusText::localError()
{
    QCOMPARE(ui::localErrorText(3.2e-6), QStringLiteral("local error ≈ 3.2e-6 m/step"));
    QCOMPARE(ui::localErrorText(std::nullopt), QStringLiteral("local error ≈ ?"));
    QCOMPARE(ui::durationText(8e-4), QStringLiteral("0.8 ms"));
    QCOMPARE(ui::durationText(1.24e-5), QStringLiteral("12 µs"));
    QCOMPARE(ui::durationText(3.1e-4), QStringLiteral("310 µs"));
    QCOMPARE(ui::durationText(2.0), QStringLiteral("2 s"));
}

void TestStatusText::drift_data()
{
    QTest::addColumn<double>("kinetic");
    QTest::addColumn<double>("gravitational");
    QTest::addColumn<double>("spring");
    QTest::addColumn<double>("current");
    QTest::addColumn<QString>("text");
    QTest::newRow("none") << 1.0 << 2.0 << 3.0 << 6.0 << "ΔE = 0 %";
    QTest::newRow("gain") << 0.0 << 100.0 << 0.0 << 100.4 << "ΔE = +0.4 %";
    QTest::newRow("loss, of a negative total") << 0.0 << -200.0 << 0.0 << -230.0 << "ΔE = -15 %";
    QTest::newRow("tiny") << 0.0 << 10.0 << 0.0 << 10.0002 << "ΔE = +0.002 %";
    QTest::newRow("zero total: joules") << 0.0 << 0.0 << 0.0 << 0.012 << "ΔE = +0.012 J";
    QTest::newRow("parts cancel: joules") << 5.0 << -5.0 << 0.0 << -0.26 << "ΔE = -0.3 J";
    // the springs example: a start of rounding noise, with parts of the same size
    QTest::newRow("noise start: joules") << 0.0 << 3.7e-31 << 0.0 << -1.36 << "ΔE = -1.4 J";
    QTest::newRow("a thousandfold change: joules") << 0.0 << 0.001 << 0.0 << 2.0 << "ΔE = +2.0 J";
}

void TestStatusText::drift()
{
    QFETCH(double, kinetic);
    QFETCH(double, gravitational);
    QFETCH(double, spring);
    QFETCH(double, current);
    QFETCH(QString, text);
    core::Energies initial;
    initial.kinetic = kinetic;
    initial.gravitational = gravitational;
    initial.spring = spring;
    QCOMPARE(ui::driftText(initial, current), text);
}

void TestStatusText::selection()
{
    QCOMPARE(ui::selectionText(121, 220), QStringLiteral("121 particles and 220 springs selected"));
    QCOMPARE(ui::selectionText(1, 0), QStringLiteral("1 particle selected"));
    QCOMPARE(ui::selectionText(0, 1), QStringLiteral("1 spring selected"));
    QCOMPARE(ui::selectionText(0, 0), QStringLiteral("Nothing selected"));
}

void TestStatusText::distance()
{
    // the view's label: four digits; the status bar and inspector: six, with the parts
    QCOMPARE(ui::lengthText(1.2247448), QStringLiteral("1.225 m"));
    QCOMPARE(ui::lengthText(0.0005), QStringLiteral("0.0005 m"));
    QCOMPARE(ui::distanceText({1.0, 0.5, -0.5}), QStringLiteral("1.22474 m (Δx 1, Δy 0.5, Δz -0.5)"));
    QCOMPARE(ui::distanceText(Eigen::Vector3d::Zero()), QStringLiteral("0 m (Δx 0, Δy 0, Δz 0)"));
}

void TestStatusText::plan()
{
    // two rows meet the tolerance; rk4 is the cheaper
    core::AccuracyPlan plan;
    plan.tolerance = 1e-6;
    plan.timeStep = 0.01;
    core::PlanCandidate euler;
    euler.substeps = 120;
    euler.localError = 9e-7;
    euler.secondsPerSimulatedSecond = 1.5e-3;
    euler.feasible = true;
    core::PlanCandidate rk4;
    rk4.integrator = core::Integrator::Rk4;
    rk4.substeps = 3;
    rk4.localError = 2.1e-7;
    rk4.secondsPerSimulatedSecond = 8e-4;
    rk4.feasible = true;
    core::PlanCandidate unstable;
    unstable.integrator = core::Integrator::ExplicitEuler;
    unstable.reason = "unstable";
    plan.candidates = {euler, unstable, rk4};
    plan.chosen = 2;
    QCOMPARE(ui::planText(plan), QStringLiteral("rk4 with 3 substeps: ≈ 2.1e-7 m/step at 0.8 ms per simulated "
                                                "second, the cheapest of 2 integrators that meet 1e-6 m/step"));

    // nothing meets it
    plan.chosen = -1;
    QVERIFY(ui::planText(plan).startsWith(QStringLiteral("No fixed-step integrator meets 1e-6 m/step")));
}

void TestStatusText::stability()
{
    using core::Integrator;
    const double infinity = std::numeric_limits<double>::infinity();

    // well inside, near (from 80%), past: the limit, the sub-step, and past it the substeps that fix it
    ui::StabilityNote note = ui::stabilityNote(0.004, 0.001, 0.001, Integrator::SymplecticEuler);
    QCOMPARE(note.level, ui::StabilityLevel::Safe);
    QCOMPARE(note.text, QStringLiteral("Stable sub-step ≤ 4 ms; each is 1 ms (25 % of it)"));
    note = ui::stabilityNote(0.004, 0.0032, 0.0032, Integrator::SymplecticEuler);
    QCOMPARE(note.level, ui::StabilityLevel::Near);
    QCOMPARE(note.text, QStringLiteral("Stable sub-step ≤ 4 ms; each is 3.2 ms (80 % of it)"));
    note = ui::stabilityNote(0.0031, 0.01, 0.01, Integrator::SymplecticEuler);
    QCOMPARE(note.level, ui::StabilityLevel::Past);
    // 0.01 / (0.9 × 0.0031) = 3.58 → 4
    QCOMPARE(note.text, QStringLiteral("Stable sub-step ≤ 3.1 ms; each is 10 ms, 3.2× over: use ≥ 4 substeps or "
                                       "projective"));

    // no limit, or no stable step at all
    note = ui::stabilityNote(infinity, 0.01, 0.01, Integrator::ImplicitEuler);
    QCOMPARE(note.level, ui::StabilityLevel::Safe);
    QCOMPARE(note.text, QStringLiteral("implicit-euler is stable at any time step"));
    note = ui::stabilityNote(infinity, 0.01, 0.01, Integrator::Rk4);
    QCOMPARE(note.text, QStringLiteral("No springs: no stability limit on the time step"));
    note = ui::stabilityNote(0.0, 0.01, 0.01, Integrator::ExplicitEuler);
    QCOMPARE(note.level, ui::StabilityLevel::Past);
    QVERIFY(note.text.startsWith(QStringLiteral("explicit-euler is unstable at any time step")));
}

QTEST_APPLESS_MAIN(TestStatusText)
#include "test_status_text.moc"
