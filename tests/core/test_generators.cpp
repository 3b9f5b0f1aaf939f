// Scene generators: counts, rest lengths, pins, and that every generated scene is valid.
#include "core/generators.h"
#include "core/validate.h"

#include <QtTest>

class TestGenerators : public QObject {
    Q_OBJECT

private slots:
    void netIsTheHandoutsSpringsScene();
    void clothHasStructuralShearAndBendSprings();
    void chainHangsFromItsFirstParticle();
};

void TestGenerators::netIsTheHandoutsSpringsScene()
{
    const core::SceneDesc net = core::makeNet({});
    QVERIFY(!core::findProblem(net));
    QCOMPARE(net.particles.size(), std::size_t(121));
    QCOMPARE(net.springs.size(), std::size_t(2 * 11 * 10));
    int pinned = 0;
    for (const auto &p : net.particles)
        pinned += p.pinned ? 1 : 0;
    QCOMPARE(pinned, 22);
    for (const auto &s : net.springs) {
        QVERIFY(std::abs(s.restLength - 0.4) < 1e-12);
        QCOMPARE(s.stiffness, 4000.0);
    }
}

void TestGenerators::clothHasStructuralShearAndBendSprings()
{
    core::ClothOptions options;
    options.rows = 4;
    options.cols = 5;
    const core::SceneDesc cloth = core::makeCloth(options);
    QVERIFY(!core::findProblem(cloth));
    QCOMPARE(cloth.particles.size(), std::size_t(20));
    // structural 4·4 + 3·5, shear 2·3·4, bend 4·3 + 2·5
    const std::size_t structural = 16 + 15, shear = 24, bend = 12 + 10;
    QCOMPARE(cloth.springs.size(), structural + shear + bend);
    QVERIFY(cloth.particles[0].pinned);
    QVERIFY(cloth.particles[4].pinned);
    QVERIFY(!cloth.particles[5].pinned);
    QVERIFY(std::abs(cloth.springs[structural].restLength - options.spacing * std::sqrt(2.0)) < 1e-12);
    QCOMPARE(cloth.springs[structural].stiffness, options.shearStiffness);
    QVERIFY(std::abs(cloth.springs.back().restLength - 2 * options.spacing) < 1e-12);
    QCOMPARE(cloth.springs.back().stiffness, options.bendStiffness);
}

void TestGenerators::chainHangsFromItsFirstParticle()
{
    const core::SceneDesc chain = core::makeChain({});
    QVERIFY(!core::findProblem(chain));
    QCOMPARE(chain.particles.size(), std::size_t(11));
    QCOMPARE(chain.springs.size(), std::size_t(10));
    QVERIFY(chain.particles[0].pinned);
    QVERIFY(!chain.particles[1].pinned);
}

QTEST_APPLESS_MAIN(TestGenerators)
#include "test_generators.moc"
