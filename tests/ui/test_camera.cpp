// Camera maths without GL: projection and unprojection agree, zooming keeps the point under the
// cursor, framing puts a sphere inside the view, and the gestures move the view the right way, in
// perspective and in orthographic projection; the presets look along the axes, straight down too.

#include "ui/viewport/camera.h"

#include <QtTest>

#include <cmath>
#include <functional>
#include <numbers>

using ui::Camera;
using ui::Projection;
using ui::ViewPreset;

namespace {

// a camera looking at an off-centre target from an oblique direction
Camera obliqueCamera(QSize size, Projection projection = Projection::Perspective)
{
    Camera camera;
    camera.setProjection(projection);
    camera.setViewportSize(size);
    camera.setFieldOfView(50.0f);
    camera.setTarget(QVector3D(1.0f, -2.0f, 0.5f));
    camera.setDistance(7.0f);
    camera.setAngles(-60.0f, 20.0f);
    camera.setSceneBounds(QVector3D(1.0f, -2.0f, 0.5f), 3.0f);
    return camera;
}

bool near(const QVector3D &a, const QVector3D &b, float tolerance = 1e-5f) { return (a - b).length() < tolerance; }

// a test's only column: the projection, one row each
void projectionRows()
{
    QTest::addColumn<Projection>("projection");
    QTest::newRow("perspective") << Projection::Perspective;
    QTest::newRow("orthographic") << Projection::Orthographic;
}

// the projection column of the tests that run in both, after their own
void addProjectionRows(const char *name, const std::function<void(QTestData &)> &values)
{
    for (const auto &[label, projection] : {std::pair{"perspective", Projection::Perspective},
                                            std::pair{"orthographic", Projection::Orthographic}}) {
        QTestData &row = QTest::newRow(qPrintable(QStringLiteral("%1, %2").arg(QLatin1String(name), QLatin1String(label))));
        values(row);
        row << projection;
    }
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
    void pitchStopsAtThePoles();
    void panMovesTheTargetPlaneWithTheMouse_data();
    void panMovesTheTargetPlaneWithTheMouse();
    void clipPlanesHoldTheScene_data();
    void clipPlanesHoldTheScene();
    void presetsLookAlongTheAxes_data();
    void presetsLookAlongTheAxes();
    void topViewShowsTheSceneFromAbove();
    void orthographicRaysAreParallel();
    void orthographicKeepsTheTargetPlaneAsItWas();
    void orthographicSizeDoesNotShrinkWithDepth();
    void sphereInView_data();
    void sphereInView();
    void frameFromTargetKeepsTheTarget_data();
    void frameFromTargetKeepsTheTarget();
};

void TestCamera::targetProjectsToTheCentre_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<Projection>("projection");
    addProjectionRows("landscape", [](QTestData &row) { row << QSize(800, 600); });
    addProjectionRows("portrait", [](QTestData &row) { row << QSize(300, 700); });
    addProjectionRows("odd", [](QTestData &row) { row << QSize(641, 479); });
}

void TestCamera::targetProjectsToTheCentre()
{
    QFETCH(QSize, size);
    QFETCH(Projection, projection);
    const Camera camera = obliqueCamera(size, projection);
    const auto pixel = camera.project(camera.target());
    QVERIFY(pixel.has_value());
    QCOMPARE_LT(std::abs(pixel->x() - size.width() / 2.0), 1e-3);
    QCOMPARE_LT(std::abs(pixel->y() - size.height() / 2.0), 1e-3);

    // and the ray through the centre is the viewing direction, through the eye
    const ui::Ray ray = camera.unproject(QPointF(size.width() / 2.0, size.height() / 2.0));
    QCOMPARE_GT(QVector3D::dotProduct(ray.direction, camera.forward()), 0.999999f);
    const QVector3D off = ray.origin - camera.eye();
    QCOMPARE_LT((off - QVector3D::dotProduct(off, camera.forward()) * camera.forward()).length(), 1e-5f);
    if (projection == Projection::Perspective)
        QCOMPARE_LT(off.length(), 1e-5f);
}

void TestCamera::projectUnprojectRoundTrip_data()
{
    QTest::addColumn<QPointF>("pixel");
    QTest::addColumn<float>("depth");
    QTest::addColumn<Projection>("projection");
    addProjectionRows("centre near", [](QTestData &row) { row << QPointF(400, 300) << 0.5f; });
    addProjectionRows("top left", [](QTestData &row) { row << QPointF(0.5, 0.5) << 3.0f; });
    addProjectionRows("bottom right far", [](QTestData &row) { row << QPointF(799.5, 599.5) << 40.0f; });
    addProjectionRows("off screen", [](QTestData &row) { row << QPointF(-200, 900) << 10.0f; });
    addProjectionRows("fraction", [](QTestData &row) { row << QPointF(123.25, 456.75) << 7.0f; });
}

void TestCamera::projectUnprojectRoundTrip()
{
    // a point along the ray through a pixel projects back onto that pixel
    QFETCH(QPointF, pixel);
    QFETCH(float, depth);
    QFETCH(Projection, projection);
    const Camera camera = obliqueCamera(QSize(800, 600), projection);
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

    // orthographic: behind the near plane, however far behind the eye that is
    const Camera orthographic = obliqueCamera(QSize(800, 600), Projection::Orthographic);
    const QVector3D onNearPlane = orthographic.eye() + orthographic.nearPlane() * orthographic.forward();
    QVERIFY(!orthographic.project(onNearPlane - 0.01f * orthographic.forward()).has_value());
    QVERIFY(orthographic.project(onNearPlane + 0.01f * orthographic.forward()).has_value());
}

void TestCamera::zoomKeepsThePointUnderTheCursor_data()
{
    QTest::addColumn<QPointF>("cursor");
    QTest::addColumn<float>("factor");
    QTest::addColumn<Projection>("projection");
    addProjectionRows("in at a corner", [](QTestData &row) { row << QPointF(60, 50) << 0.5f; });
    addProjectionRows("out at a corner", [](QTestData &row) { row << QPointF(700, 520) << 1.8f; });
    addProjectionRows("in at the centre", [](QTestData &row) { row << QPointF(400, 300) << 0.85f; });
    addProjectionRows("far in, off centre", [](QTestData &row) { row << QPointF(250, 420) << 0.01f; });
}

void TestCamera::zoomKeepsThePointUnderTheCursor()
{
    QFETCH(QPointF, cursor);
    QFETCH(float, factor);
    QFETCH(Projection, projection);
    Camera camera = obliqueCamera(QSize(800, 600), projection);

    // the point under the cursor on the plane through the target, facing the eye
    const ui::Ray ray = camera.unproject(cursor);
    const float t = QVector3D::dotProduct(camera.target() - ray.origin, camera.forward()) /
                    QVector3D::dotProduct(ray.direction, camera.forward());
    const QVector3D underCursor = ray.at(t);
    const float sizeBefore = camera.worldPerPixel();
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
    // and the view's scale at the target with it: orthographic zoom is a zoom too
    QCOMPARE_LT(std::abs(camera.worldPerPixel() - sizeBefore * factor), 1e-4f * sizeBefore);

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
    QTest::addColumn<Projection>("projection");
    addProjectionRows("landscape", [](QTestData &row) { row << QSize(900, 500) << 35.0f << 25.0f; });
    addProjectionRows("portrait", [](QTestData &row) { row << QSize(300, 800) << -120.0f << 60.0f; });
    addProjectionRows("from below", [](QTestData &row) { row << QSize(640, 480) << 10.0f << -80.0f; });
    addProjectionRows("from above", [](QTestData &row) { row << QSize(640, 480) << 0.0f << 90.0f; });
}

void TestCamera::frameSphereFitsItInView()
{
    QFETCH(QSize, size);
    QFETCH(float, yaw);
    QFETCH(float, pitch);
    QFETCH(Projection, projection);
    Camera camera;
    camera.setProjection(projection);
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
        // the outline seen from the eye: a tangent circle, or a great circle with parallel rays
        if (projection == Projection::Orthographic) {
            points.push_back(centre + offset * radius);
            continue;
        }
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
    QVERIFY(camera.sphereInView(centre, radius));
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

void TestCamera::pitchStopsAtThePoles()
{
    // orbiting past the pole stops at it, looking straight down (or up) with the bearings kept:
    // the basis stays orthonormal and right() is still the yaw's
    Camera camera = obliqueCamera(QSize(800, 600));
    const QVector3D right = camera.right();
    for (const float drag : {10000.0f, -20000.0f}) {
        camera.orbit(0.0f, drag);
        QCOMPARE(camera.pitch(), drag > 0.0f ? 90.0f : -90.0f);
        QVERIFY(near(camera.forward(), QVector3D(0.0f, drag > 0.0f ? -1.0f : 1.0f, 0.0f)));
        QVERIFY(near(camera.right(), right));
        QCOMPARE_LT(std::abs(camera.up().length() - 1.0f), 1e-5f);
        QCOMPARE_LT(std::abs(QVector3D::dotProduct(camera.up(), camera.forward())), 1e-5f);
        QCOMPARE_LT(std::abs(QVector3D::dotProduct(camera.up(), camera.right())), 1e-5f);
        // and the view still projects the target to the middle
        QCOMPARE_LT(std::abs(camera.project(camera.target())->x() - 400.0), 1e-3);
    }
}

void TestCamera::panMovesTheTargetPlaneWithTheMouse_data()
{
    projectionRows();
}

void TestCamera::panMovesTheTargetPlaneWithTheMouse()
{
    // a point on the target's plane follows the mouse pixel for pixel
    QFETCH(Projection, projection);
    Camera camera = obliqueCamera(QSize(800, 600), projection);
    const QPointF start(300, 200);
    const ui::Ray ray = camera.unproject(start);
    const QVector3D grabbed = ray.at(QVector3D::dotProduct(camera.target() - ray.origin, camera.forward()) /
                                     QVector3D::dotProduct(ray.direction, camera.forward()));
    camera.pan(40.0f, -25.0f);
    const auto after = camera.project(grabbed);
    QVERIFY(after.has_value());
    QCOMPARE_LT(std::abs(after->x() - (start.x() + 40.0)), 0.05);
    QCOMPARE_LT(std::abs(after->y() - (start.y() - 25.0)), 0.05);
}

void TestCamera::clipPlanesHoldTheScene_data()
{
    projectionRows();
}

void TestCamera::clipPlanesHoldTheScene()
{
    // every point of the scene's sphere lies between the clip planes, however the target wandered
    QFETCH(Projection, projection);
    Camera camera = obliqueCamera(QSize(800, 600), projection);
    camera.pan(3000.0f, 0.0f);
    camera.zoomAt(QPointF(10, 10), 0.2f);
    const QVector3D centre(1.0f, -2.0f, 0.5f);
    const float radius = 3.0f;
    const float centreDepth = QVector3D::dotProduct(centre - camera.eye(), camera.forward());
    QCOMPARE_LT(centreDepth + radius, camera.farPlane());
    QCOMPARE_LT(camera.nearPlane(), camera.farPlane());
    if (projection == Projection::Perspective) {
        QCOMPARE_GT(camera.nearPlane(), 0.0f);
        return;
    }

    // orthographic: zoomed in until the eye is inside the scene, none of it is cut off in front
    for (int i = 0; i < 30; ++i)
        camera.zoomAt(QPointF(400, 300), 0.5f);
    const float depthNow = QVector3D::dotProduct(centre - camera.eye(), camera.forward());
    QCOMPARE_LT(camera.nearPlane(), depthNow - radius);
    QCOMPARE_GT(camera.farPlane(), depthNow + radius);
}

void TestCamera::presetsLookAlongTheAxes_data()
{
    QTest::addColumn<ViewPreset>("preset");
    QTest::addColumn<QVector3D>("forward");
    QTest::addColumn<QVector3D>("right");
    QTest::addColumn<QVector3D>("up");
    QTest::newRow("top") << ViewPreset::Top << QVector3D(0, -1, 0) << QVector3D(1, 0, 0) << QVector3D(0, 0, -1);
    QTest::newRow("front") << ViewPreset::Front << QVector3D(0, 0, -1) << QVector3D(1, 0, 0) << QVector3D(0, 1, 0);
    QTest::newRow("side") << ViewPreset::Side << QVector3D(-1, 0, 0) << QVector3D(0, 0, -1) << QVector3D(0, 1, 0);
}

void TestCamera::presetsLookAlongTheAxes()
{
    QFETCH(ViewPreset, preset);
    QFETCH(QVector3D, forward);
    QFETCH(QVector3D, right);
    QFETCH(QVector3D, up);
    Camera camera = obliqueCamera(QSize(800, 600));
    const QVector3D target = camera.target();
    const float distance = camera.distance();
    camera.lookAlong(preset);
    QVERIFY2(near(camera.forward(), forward), qPrintable(QStringLiteral("forward (%1, %2, %3)")
                                                             .arg(camera.forward().x())
                                                             .arg(camera.forward().y())
                                                             .arg(camera.forward().z())));
    QVERIFY(near(camera.right(), right));
    QVERIFY(near(camera.up(), up));
    // at the same target and distance
    QCOMPARE(camera.target(), target);
    QCOMPARE(camera.distance(), distance);

    // and back to the view a scene opens with
    camera.lookAlong(ViewPreset::Default);
    QCOMPARE(camera.yaw(), Camera::kDefaultYaw);
    QCOMPARE(camera.pitch(), Camera::kDefaultPitch);
}

void TestCamera::topViewShowsTheSceneFromAbove()
{
    // from above, +x is to the right of the target on screen and -z above it, and a point straight
    // above or below the target lands on it
    Camera camera = obliqueCamera(QSize(800, 600));
    camera.lookAlong(ViewPreset::Top);
    const QVector3D target = camera.target();
    const QPointF middle = camera.project(target).value();
    const QPointF east = camera.project(target + QVector3D(1, 0, 0)).value();
    const QPointF north = camera.project(target + QVector3D(0, 0, -1)).value();
    const QPointF below = camera.project(target + QVector3D(0, -2, 0)).value();
    QCOMPARE_GT(east.x(), middle.x() + 10.0);
    QCOMPARE_LT(std::abs(east.y() - middle.y()), 1e-2);
    QCOMPARE_LT(north.y(), middle.y() - 10.0);
    QCOMPARE_LT(std::abs(north.x() - middle.x()), 1e-2);
    QCOMPARE_LT(QLineF(below, middle).length(), 1e-2);
}

void TestCamera::orthographicRaysAreParallel()
{
    // every pixel's ray runs along the view, from the near plane, each from its own point
    const Camera camera = obliqueCamera(QSize(800, 600), Projection::Orthographic);
    const ui::Ray a = camera.unproject(QPointF(10, 20));
    const ui::Ray b = camera.unproject(QPointF(700, 580));
    QVERIFY(near(a.direction, camera.forward()));
    QVERIFY(near(b.direction, camera.forward()));
    QCOMPARE_GT((a.origin - b.origin).length(), 1.0f);
    for (const ui::Ray &ray : {a, b}) {
        const float depth = QVector3D::dotProduct(ray.origin - camera.eye(), camera.forward());
        QCOMPARE_LT(std::abs(depth - camera.nearPlane()), 1e-4f);
    }
    // the origins lie as far apart on screen as the pixels, at the target's scale
    const QVector3D apart = a.origin - b.origin;
    QCOMPARE_LT(std::abs(QVector3D::dotProduct(apart, camera.right()) - (10.0f - 700.0f) * camera.worldPerPixel()),
                1e-4f);
}

void TestCamera::orthographicKeepsTheTargetPlaneAsItWas()
{
    // switching projection keeps every point of the target's plane on its pixel
    Camera camera = obliqueCamera(QSize(800, 600));
    const QVector3D onPlane = camera.target() + 1.3f * camera.right() - 0.7f * camera.up();
    const QPointF perspective = camera.project(onPlane).value();
    camera.setProjection(Projection::Orthographic);
    QVERIFY(camera.orthographic());
    const QPointF orthographic = camera.project(onPlane).value();
    QCOMPARE_LT(QLineF(perspective, orthographic).length(), 1e-2);
    // and the matrix is another
    QCOMPARE(camera.projectionMatrix()(3, 3), 1.0f);
    camera.setProjection(Projection::Perspective);
    QCOMPARE(camera.projectionMatrix()(3, 3), 0.0f);
}

void TestCamera::orthographicSizeDoesNotShrinkWithDepth()
{
    // a point and the same point moved along the view land on the same pixel; in perspective they
    // do not
    for (const Projection projection : {Projection::Perspective, Projection::Orthographic}) {
        const Camera camera = obliqueCamera(QSize(800, 600), projection);
        const QVector3D p = camera.target() + 2.0f * camera.right() + camera.up();
        const QPointF nearer = camera.project(p - 2.0f * camera.forward()).value();
        const QPointF farther = camera.project(p + 2.0f * camera.forward()).value();
        const double apart = QLineF(nearer, farther).length();
        if (projection == Projection::Orthographic)
            QCOMPARE_LT(apart, 1e-2);
        else
            QCOMPARE_GT(apart, 10.0);
    }
}

void TestCamera::sphereInView_data()
{
    projectionRows();
}

void TestCamera::sphereInView()
{
    QFETCH(Projection, projection);
    Camera camera = obliqueCamera(QSize(800, 600), projection);
    const QVector3D target = camera.target();
    // at the target, small: in view; as big as the view: not all of it
    QVERIFY(camera.sphereInView(target, 0.1f));
    QVERIFY(!camera.sphereInView(target, 3.0f * camera.halfHeightAtTarget()));
    // just inside the right-hand edge, and just across it
    const float halfWidth = camera.halfHeightAtTarget() * camera.aspect();
    QVERIFY(camera.sphereInView(target + (halfWidth - 0.3f) * camera.right(), 0.2f));
    QVERIFY(!camera.sphereInView(target + (halfWidth - 0.1f) * camera.right(), 0.2f));
    // far off to a side, and behind the eye (past the near plane)
    QVERIFY(!camera.sphereInView(target + 100.0f * camera.up(), 0.1f));
    QVERIFY(!camera.sphereInView(camera.eye() + (camera.nearPlane() - 1.0f) * camera.forward(), 0.1f));
}

void TestCamera::frameFromTargetKeepsTheTarget_data()
{
    projectionRows();
}

void TestCamera::frameFromTargetKeepsTheTarget()
{
    // a sphere off to one side of the target: the target stays and the eye backs off until the
    // sphere is in view
    QFETCH(Projection, projection);
    Camera camera = obliqueCamera(QSize(800, 600), projection);
    camera.setDistance(0.5f);
    const QVector3D target = camera.target();
    const QVector3D centre = target + QVector3D(4.0f, 1.0f, -2.0f);
    camera.setSceneBounds(centre, 1.5f);
    QVERIFY(!camera.sphereInView(centre, 1.5f));
    camera.frameSphereFromTarget(centre, 1.5f);
    QCOMPARE(camera.target(), target);
    QVERIFY(camera.sphereInView(centre, 1.5f));
}

QTEST_APPLESS_MAIN(TestCamera)
#include "test_camera.moc"
