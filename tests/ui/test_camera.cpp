// Camera maths without GL: projection and unprojection agree, zooming keeps the point under the
// cursor, framing puts a sphere inside the view, and the gestures move the view the right way.

#include "ui/viewport/camera.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using ui::Camera;

namespace {

// a camera looking at an off-centre target from an oblique direction
Camera obliqueCamera(QSize size)
{
    Camera camera;
    camera.setViewportSize(size);
    camera.setFieldOfView(50.0f);
    camera.setTarget(QVector3D(1.0f, -2.0f, 0.5f));
    camera.setDistance(7.0f);
    camera.setAngles(-60.0f, 20.0f);
    camera.setSceneBounds(QVector3D(1.0f, -2.0f, 0.5f), 3.0f);
    return camera;
}

}  // namespace

class TestCamera : public QObject {
    Q_OBJECT

private slots:
    void targetProjectsToTheCentre_data();
    void targetProjectsToTheCentre();
    void projectUnprojectRoundTrip_data();
    void projectUnprojectRoundTrip();
    void pointsBehindTheEyeDoNotProject();
    void zoomKeepsThePointUnderTheCursor_data();
    void zoomKeepsThePointUnderTheCursor();
    void zoomStopsAtTheMinimumDistance();
    void frameSphereFitsItInView_data();
    void frameSphereFitsItInView();
    void orbitTurnsAboutTheTarget();
    void pitchStopsShortOfThePoles();
    void panMovesTheTargetPlaneWithTheMouse();
    void clipPlanesHoldTheScene();
};

void TestCamera::targetProjectsToTheCentre_data()
{
    QTest::addColumn<QSize>("size");
    QTest::newRow("landscape") << QSize(800, 600);
    QTest::newRow("portrait") << QSize(300, 700);
    QTest::newRow("odd") << QSize(641, 479);
}

void TestCamera::targetProjectsToTheCentre()
{
    QFETCH(QSize, size);
    const Camera camera = obliqueCamera(size);
    const auto pixel = camera.project(camera.target());
    QVERIFY(pixel.has_value());
    QCOMPARE_LT(std::abs(pixel->x() - size.width() / 2.0), 1e-3);
    QCOMPARE_LT(std::abs(pixel->y() - size.height() / 2.0), 1e-3);

    // and the ray through the centre is the viewing direction
    const ui::Ray ray = camera.unproject(QPointF(size.width() / 2.0, size.height() / 2.0));
    QCOMPARE_GT(QVector3D::dotProduct(ray.direction, camera.forward()), 0.999999f);
    QCOMPARE_LT((ray.origin - camera.eye()).length(), 1e-5f);
}

void TestCamera::projectUnprojectRoundTrip_data()
{
    QTest::addColumn<QPointF>("pixel");
    QTest::addColumn<float>("depth");
    QTest::newRow("centre near") << QPointF(400, 300) << 0.5f;
    QTest::newRow("top left") << QPointF(0.5, 0.5) << 3.0f;
    QTest::newRow("bottom right far") << QPointF(799.5, 599.5) << 40.0f;
    QTest::newRow("off screen") << QPointF(-200, 900) << 10.0f;
    QTest::newRow("fraction") << QPointF(123.25, 456.75) << 7.0f;
}

void TestCamera::projectUnprojectRoundTrip()
{
    // a point along the ray through a pixel projects back onto that pixel
    QFETCH(QPointF, pixel);
    QFETCH(float, depth);
    const Camera camera = obliqueCamera(QSize(800, 600));
    const ui::Ray ray = camera.unproject(pixel);
    QCOMPARE_LT(std::abs(ray.direction.length() - 1.0f), 1e-5f);
    const auto back = camera.project(ray.at(depth));
    QVERIFY(back.has_value());
    QCOMPARE_LT(std::abs(back->x() - pixel.x()), 2e-3);
    QCOMPARE_LT(std::abs(back->y() - pixel.y()), 2e-3);
}

void TestCamera::pointsBehindTheEyeDoNotProject()
{
    const Camera camera = obliqueCamera(QSize(800, 600));
    QVERIFY(!camera.project(camera.eye() - camera.forward()).has_value());
    QVERIFY(camera.project(camera.eye() + camera.forward()).has_value());
}

void TestCamera::zoomKeepsThePointUnderTheCursor_data()
{
    QTest::addColumn<QPointF>("cursor");
    QTest::addColumn<float>("factor");
    QTest::newRow("in at a corner") << QPointF(60, 50) << 0.5f;
    QTest::newRow("out at a corner") << QPointF(700, 520) << 1.8f;
    QTest::newRow("in at the centre") << QPointF(400, 300) << 0.85f;
    QTest::newRow("far in, off centre") << QPointF(250, 420) << 0.01f;
}

void TestCamera::zoomKeepsThePointUnderTheCursor()
{
    QFETCH(QPointF, cursor);
    QFETCH(float, factor);
    Camera camera = obliqueCamera(QSize(800, 600));

    // the point under the cursor on the plane through the target, facing the eye
    const ui::Ray ray = camera.unproject(cursor);
    const float t = camera.distance() / QVector3D::dotProduct(ray.direction, camera.forward());
    const QVector3D underCursor = ray.at(t);
    const float distanceBefore = camera.distance();
    const QVector3D forwardBefore = camera.forward();

    camera.zoomAt(cursor, factor);

    // it is still under the cursor, the distance changed by the factor and the direction did not
    const auto after = camera.project(underCursor);
    QVERIFY(after.has_value());
    QCOMPARE_LT(std::abs(after->x() - cursor.x()), 1e-2);
    QCOMPARE_LT(std::abs(after->y() - cursor.y()), 1e-2);
    QCOMPARE_LT(std::abs(camera.distance() - distanceBefore * factor), 1e-4f * distanceBefore);
    QCOMPARE_GT(QVector3D::dotProduct(camera.forward(), forwardBefore), 0.999999f);

    // zooming in at the centre keeps the target where it was
    if (cursor == QPointF(400, 300))
        QCOMPARE_LT((camera.target() - QVector3D(1.0f, -2.0f, 0.5f)).length(), 1e-4f);
}

void TestCamera::zoomStopsAtTheMinimumDistance()
{
    Camera camera = obliqueCamera(QSize(800, 600));
    for (int i = 0; i < 200; ++i)
        camera.zoomAt(QPointF(400, 300), 0.5f);
    QCOMPARE(camera.distance(), Camera::kMinDistance);
    QVERIFY(std::isfinite(camera.target().x()));
    QCOMPARE_LT(camera.nearPlane(), camera.farPlane());
}

void TestCamera::frameSphereFitsItInView_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<float>("yaw");
    QTest::addColumn<float>("pitch");
    QTest::newRow("landscape") << QSize(900, 500) << 35.0f << 25.0f;
    QTest::newRow("portrait") << QSize(300, 800) << -120.0f << 60.0f;
    QTest::newRow("from below") << QSize(640, 480) << 10.0f << -80.0f;
}

void TestCamera::frameSphereFitsItInView()
{
    QFETCH(QSize, size);
    QFETCH(float, yaw);
    QFETCH(float, pitch);
    Camera camera;
    camera.setViewportSize(size);
    camera.setAngles(yaw, pitch);
    const QVector3D centre(5.0f, 1.0f, -3.0f);
    const float radius = 2.5f;
    camera.setSceneBounds(centre, radius);
    camera.frameSphere(centre, radius);

    // the six extreme points and the points of its outline seen from the eye are all in view
    QCOMPARE_LT((camera.target() - centre).length(), 1e-5f);
    QCOMPARE_GT((camera.eye() - centre).length(), radius);
    std::vector<QVector3D> points;
    for (const QVector3D &axis : {QVector3D(1, 0, 0), QVector3D(0, 1, 0), QVector3D(0, 0, 1)}) {
        points.push_back(centre + radius * axis);
        points.push_back(centre - radius * axis);
    }
    for (int k = 0; k < 64; ++k) {
        const float angle = float(k) * 2.0f * std::numbers::pi_v<float> / 64.0f;
        const QVector3D towardEye = (camera.eye() - centre).normalized();
        const QVector3D offset = std::cos(angle) * camera.right() + std::sin(angle) * camera.up();
        const float d = (camera.eye() - centre).length();
        // the tangent circle seen from the eye
        const float across = radius * std::sqrt(1.0f - radius * radius / (d * d));
        points.push_back(centre + towardEye * (radius * radius / d) + offset * across);
    }
    float nearestEdge = 1e9f;
    for (const QVector3D &p : points) {
        const auto pixel = camera.project(p);
        QVERIFY(pixel.has_value());
        QVERIFY2(pixel->x() >= 0 && pixel->x() <= size.width() && pixel->y() >= 0 && pixel->y() <= size.height(),
                 qPrintable(QStringLiteral("(%1, %2)").arg(pixel->x()).arg(pixel->y())));
        const double edge = std::min({pixel->x(), size.width() - pixel->x(), pixel->y(), size.height() - pixel->y()});
        nearestEdge = std::min(nearestEdge, float(edge));
    }

    // and it is not lost in the middle: it reaches close to the narrower pair of edges
    QCOMPARE_LT(nearestEdge, 0.15f * std::min(size.width(), size.height()));
}

void TestCamera::orbitTurnsAboutTheTarget()
{
    Camera camera = obliqueCamera(QSize(800, 600));
    const QVector3D target = camera.target();
    const float distance = (camera.eye() - target).length();
    const QVector3D eyeBefore = camera.eye();

    // dragging right turns the scene as if grabbed: its near side moves right, its far side left
    const QVector3D nearSide = target - camera.forward();
    const QVector3D farSide = target + camera.forward();
    const double nearBefore = camera.project(nearSide)->x();
    const double farBefore = camera.project(farSide)->x();
    camera.orbit(50.0f, 0.0f);
    QCOMPARE_GT(camera.project(nearSide)->x(), nearBefore + 10.0);
    QCOMPARE_LT(camera.project(farSide)->x(), farBefore - 10.0);
    QCOMPARE_LT(std::abs(camera.yaw() - (-60.0f - 50.0f * Camera::kOrbitDegreesPerPixel)), 1e-4f);

    // dragging down raises the eye; the target and the distance stay
    camera.orbit(0.0f, 30.0f);
    QCOMPARE_GT(camera.eye().y(), eyeBefore.y());
    QCOMPARE_LT((camera.target() - target).length(), 1e-6f);
    QCOMPARE_LT(std::abs((camera.eye() - target).length() - distance), 1e-4f);
}

void TestCamera::pitchStopsShortOfThePoles()
{
    Camera camera = obliqueCamera(QSize(800, 600));
    camera.orbit(0.0f, 10000.0f);
    QCOMPARE_LT(camera.pitch(), 90.0f);
    QCOMPARE_GT(camera.up().y(), 0.0f);
    QVERIFY(std::isfinite(camera.right().x()));
    camera.orbit(0.0f, -20000.0f);
    QCOMPARE_GT(camera.pitch(), -90.0f);
}

void TestCamera::panMovesTheTargetPlaneWithTheMouse()
{
    // a point on the target's plane follows the mouse pixel for pixel
    Camera camera = obliqueCamera(QSize(800, 600));
    const QPointF start(300, 200);
    const ui::Ray ray = camera.unproject(start);
    const QVector3D grabbed = ray.at(camera.distance() / QVector3D::dotProduct(ray.direction, camera.forward()));
    camera.pan(40.0f, -25.0f);
    const auto after = camera.project(grabbed);
    QVERIFY(after.has_value());
    QCOMPARE_LT(std::abs(after->x() - (start.x() + 40.0)), 0.05);
    QCOMPARE_LT(std::abs(after->y() - (start.y() - 25.0)), 0.05);
}

void TestCamera::clipPlanesHoldTheScene()
{
    // every point of the scene's sphere lies between the clip planes, however the target wandered
    Camera camera = obliqueCamera(QSize(800, 600));
    camera.pan(3000.0f, 0.0f);
    camera.zoomAt(QPointF(10, 10), 0.2f);
    const QVector3D centre(1.0f, -2.0f, 0.5f);
    const float radius = 3.0f;
    const float centreDepth = QVector3D::dotProduct(centre - camera.eye(), camera.forward());
    QCOMPARE_LT(centreDepth + radius, camera.farPlane());
    QCOMPARE_GT(camera.nearPlane(), 0.0f);
}

QTEST_APPLESS_MAIN(TestCamera)
#include "test_camera.moc"
