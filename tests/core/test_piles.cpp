// The pile target, on the contacts benchmark's own pile (bench/contact_scenes.h): 1000
// balls (r = 0.05 m, 0.1 kg, e = 0.5, μ = 0.5) dropped into a box 1 m wide settle within 10 s
// (kinetic energy below 1e-3 N m g r), the total energy never rises over any 1 s window from the
// start, and the resting overlap stays below 1% of r. Labelled stress: 10 s of the pile takes
// about 3 s at one sub-step and 7 s at three.

#include "bench/contact_measures.h"
#include "bench/contact_scenes.h"
#include "pile_checks.h"
#include "scene_builder.h"

#include <QtTest>

#include <algorithm>
#include <vector>

class TestPiles : public QObject {
    Q_OBJECT
private slots:
    void thousandBallsSettle_data();
    void thousandBallsSettle();
};

void TestPiles::thousandBallsSettle_data()
{
    QTest::addColumn<int>("substeps");
    QTest::addColumn<double>("maxOverlap");  // m
    QTest::addColumn<bool>("settles");       // under the bar from some time before 10 s on
    // at 3 sub-steps, every target. At one sub-step of 10 ms, the known gap of docs/physics.md
    // ("Piles", which gives the pile at 1 to 8 sub-steps): the pile comes to rest, but its kinetic
    // energy stays at a fifth to a half of the bar, so a late slip of a ball held by friction
    // alone takes it over the bar or not by chance, and a 10 ms step leaves 2–5 mm of overlap
    // (g h² is 1 mm a step, on each of some 20 levels). There the test asks for the median over
    // the last second under the bar, and the overlap under 10% of r
    QTest::newRow("1 sub-step") << 1 << 0.1 * bench::kBallRadius << false;
    QTest::newRow("3 sub-steps") << 3 << 0.01 * bench::kBallRadius << true;
}

void TestPiles::thousandBallsSettle()
{
    QFETCH(int, substeps);
    QFETCH(double, maxOverlap);
    QFETCH(bool, settles);
    const bench::ContactScene pile = bench::contactPile(1000, substeps, 10.0);
    test::Sim sim = test::compile(pile.scene);
    const double bar = test::settleThreshold(sim, bench::kBallRadius);
    std::vector<double> energies{test::totalEnergy(sim)};
    double lastUnsettled = 0.0;  // s, the end of the last step with the kinetic energy at or above the bar
    std::vector<double> lastSecond;  // J, the kinetic energy after each step of the last second
    for (int i = 1; i <= 1000; ++i) {
        QVERIFY(sim.step());
        energies.push_back(test::totalEnergy(sim));
        const double kinetic = bench::kineticEnergy(sim.state.velocity, sim.model->mass);
        if (kinetic >= bar)
            lastUnsettled = 0.01 * i;
        if (i > 900)
            lastSecond.push_back(kinetic);
    }
    std::nth_element(lastSecond.begin(), lastSecond.begin() + 50, lastSecond.end());
    const double median = lastSecond[50];
    const double overlap = bench::deepestOverlap(sim.state.position, sim.model->radius, pile.scene.planes);
    qInfo("settled from %.2f s; median kinetic energy over the last second %.3g J (bar %.3g J); deepest "
          "overlap at 10 s %.3g mm",
          lastUnsettled, median, bar, 1e3 * overlap);
    if (settles)
        QVERIFY2(lastUnsettled < 10.0, qPrintable(QString::number(lastUnsettled)));
    else
        QVERIFY2(median < bar, qPrintable(QString::number(median)));
    const int rise = test::firstRise(energies, 100, 100, 1e-7);
    QVERIFY2(rise < 0, qPrintable(QString("the energy rose in the second ending at step %1").arg(rise)));
    QVERIFY2(overlap < maxOverlap, qPrintable(QString::number(overlap)));
}

QTEST_MAIN(TestPiles)
#include "test_piles.moc"
