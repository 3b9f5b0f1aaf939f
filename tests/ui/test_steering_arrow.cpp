// The steering arrow's lines, without GL: a shaft from the steered particle's centre along the
// push, reaching past the ball in proportion to its strength, two barbs at the tip that face the
// eye, all in the steering colour; nothing without a push, a particle or a direction.

#include "ui/viewport/steering_arrow.h"

#include <QtTest>

#include <cmath>

namespace {

// a ball of radius 0.5 at (1, 0.5, 0), as the pool's, and one more
core::Snapshot twoBalls()
{
    core::Snapshot s;
    s.positions = {1.0f, 0.5f, 0.0f, -2.0f, 0.5f, 0.0f};
    s.radii = {0.5f, 0.5f};
    s.pinned = {0, 0};
    return s;
}

QVector3D vertex(const std::vector<float> &v, int i)
{
    const std::size_t at = std::size_t(i) * ui::kVertexFloats;
    return {v[at], v[at + 1], v[at + 2]};
}

}  // namespace

class TestSteeringArrow : public QObject {
    Q_OBJECT

private slots:
    void shaftGrowsWithThePush();
    void barbsFaceTheEye();
    void nothingWithoutAPush();
};

void TestSteeringArrow::shaftGrowsWithThePush()
{
    const core::Snapshot s = twoBalls();
    const QVector3D eye(1.0f, 10.0f, 0.0f);  // from above
    for (const float strength : {0.05f, 0.5f, 1.0f}) {
        const std::vector<float> v = ui::packSteeringArrow({0, QVector3D(0.0f, 0.0f, -1.0f), strength}, s, eye);
        QCOMPARE(v.size(), std::size_t(3 * 2 * ui::kVertexFloats));
        // the shaft: from the centre, r (1 + 4 strength) towards -z
        QCOMPARE(vertex(v, 0), QVector3D(1.0f, 0.5f, 0.0f));
        const QVector3D tip = vertex(v, 1);
        QVERIFY(qFuzzyCompare(tip.z(), -0.5f * (1.0f + ui::SteeringArrow::kArrowRadii * strength)));
        QCOMPARE(tip.x(), 1.0f);
        // every vertex in the steering colour, opaque
        for (int i = 0; i < 6; ++i)
            for (int c = 0; c < 3; ++c)
                QCOMPARE(v[std::size_t(i) * ui::kVertexFloats + 3 + std::size_t(c)],
                         ui::kSteeringColour[std::size_t(c)]);
    }
}

void TestSteeringArrow::barbsFaceTheEye()
{
    // seen from above, the barbs spread sideways (x) and point back from the tip (+z), level
    const core::Snapshot s = twoBalls();
    const std::vector<float> v = ui::packSteeringArrow({0, QVector3D(0.0f, 0.0f, -1.0f), 1.0f}, s,
                                                       QVector3D(1.0f, 10.0f, 0.0f));
    const QVector3D tip = vertex(v, 1);
    const QVector3D left = vertex(v, 3) - tip;
    const QVector3D right = vertex(v, 5) - tip;
    QCOMPARE(vertex(v, 2), tip);
    QCOMPARE(vertex(v, 4), tip);
    QVERIFY(left.z() > 0.0f && right.z() > 0.0f);
    QVERIFY(left.x() * right.x() < 0.0f);
    QVERIFY(std::abs(left.y()) < 1e-5f && std::abs(right.y()) < 1e-5f);

    // looking straight along the shaft: still two barbs, apart
    const std::vector<float> along = ui::packSteeringArrow({0, QVector3D(0.0f, 0.0f, -1.0f), 1.0f}, s,
                                                           QVector3D(1.0f, 0.5f, -20.0f));
    QVERIFY((vertex(along, 3) - vertex(along, 5)).length() > 0.1f);
}

void TestSteeringArrow::nothingWithoutAPush()
{
    const core::Snapshot s = twoBalls();
    const QVector3D eye(0.0f, 5.0f, 5.0f);
    QVERIFY(ui::packSteeringArrow({0, QVector3D(1.0f, 0.0f, 0.0f), 0.0f}, s, eye).empty());   // no push
    QVERIFY(ui::packSteeringArrow({-1, QVector3D(1.0f, 0.0f, 0.0f), 1.0f}, s, eye).empty());  // nothing steered
    QVERIFY(ui::packSteeringArrow({2, QVector3D(1.0f, 0.0f, 0.0f), 1.0f}, s, eye).empty());   // no such particle
    QVERIFY(ui::packSteeringArrow({1, QVector3D(), 1.0f}, s, eye).empty());                   // no direction
    const ui::SteeringArrow still{0, QVector3D(1.0f, 0.0f, 0.0f), 0.0f};
    const ui::SteeringArrow pushed{1, QVector3D(1.0f, 0.0f, 0.0f), 0.05f};
    QVERIFY(!still.visible());
    QVERIFY(pushed.visible());
}

QTEST_APPLESS_MAIN(TestSteeringArrow)
#include "test_steering_arrow.moc"
