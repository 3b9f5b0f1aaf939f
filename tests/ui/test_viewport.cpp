// The viewport on screen, with real events: what grabFramebuffer() shows at the pixels the camera
// says a particle (in either projection), a plane or a spring lands on; orbit, pan and zoom by
// mouse and wheel; frame all by key; the style uploaded only when it changes; drawing again after
// the context is replaced; and
// the same view drawn offscreen at any size, with the camera scaled to it and its lines as much
// wider, and smoothed as the view is; a cloth drawn as a sheet between its beads, holes where its springs tore, and the layers
// that show its spheres and springs too; springs a few pixels wide, wider when selected, with the
// legend to their colours while any is drawn; the steering arrow at the steered particle while
// there is a push, as long as the push is strong, and gone without one.

#include "ui/viewport/strain_legend.h"
#include "ui/viewport/viewport.h"

#include "core/model/generators.h"
#include "core/model/model.h"
#include "core/model/snapshot.h"
#include "core/model/state.h"

#include <QSignalSpy>
#include <QVBoxLayout>
#include <QtTest>

#include "editor_test_setup.h"
#include "line_thickness.h"
#include "pool_planes.h"

#include <cmath>

namespace {

constexpr QSize kViewportSize(480, 360);

// particle 0 free, 1 pinned, 2 free; a stretched spring from 0 to 2
std::shared_ptr<core::Snapshot> tinySnapshot()
{
    auto s = std::make_shared<core::Snapshot>();
    s->positions = {0.0f, 0.5f, 0.0f, 1.2f, 0.5f, 0.0f, -1.0f, 0.9f, 0.6f};
    s->radii = {0.25f, 0.25f, 0.2f};
    s->pinned = {0, 1, 0};
    s->springEnds = {0.0f, 0.5f, 0.0f, -1.0f, 0.9f, 0.6f};
    s->springStrain = {0.5f};
    return s;
}

QVector3D positionOf(const core::Snapshot &s, int i)
{
    return QVector3D(s.positions[3 * i], s.positions[3 * i + 1], s.positions[3 * i + 2]);
}

QColor toColour(const ui::Rgb &c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

// the colour of the grabbed framebuffer at a logical pixel
QColor colourAt(const QImage &image, const QWidget &widget, QPointF pixel)
{
    const double scale = double(image.width()) / widget.width();
    return image.pixelColor(QPoint(int(pixel.x() * scale), int(pixel.y() * scale)));
}

// a lit surface keeps its hue: the hue is close and the colour is clearly not grey
bool sameHue(const QColor &seen, const ui::Rgb &expected, QString *why)
{
    const QColor want = toColour(expected);
    double difference = std::abs(seen.hueF() - want.hueF());
    difference = std::min(difference, 1.0 - difference);
    *why = QStringLiteral("seen %1 (hue %2, saturation %3), expected hue %4")
               .arg(seen.name())
               .arg(seen.hueF() * 360.0)
               .arg(seen.saturationF())
               .arg(want.hueF() * 360.0);
    return seen.saturationF() > 0.3 && difference < 12.0 / 360.0;
}

bool nearColour(const QColor &seen, const QColor &expected, int tolerance, QString *why)
{
    *why = QStringLiteral("seen %1, expected %2").arg(seen.name(), expected.name());
    return std::abs(seen.red() - expected.red()) <= tolerance &&
           std::abs(seen.green() - expected.green()) <= tolerance &&
           std::abs(seen.blue() - expected.blue()) <= tolerance;
}

// the pixels of the image in the steering arrow's colour, in logical pixels of the widget
std::vector<QPointF> steeringPixels(const QImage &image, const QWidget &widget)
{
    const QColor arrow = toColour(ui::kSteeringColour);
    const double scale = double(image.width()) / widget.width();
    std::vector<QPointF> found;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - arrow.red()) <= 8 && std::abs(c.green() - arrow.green()) <= 8 &&
                std::abs(c.blue() - arrow.blue()) <= 8)
                found.emplace_back(x / scale, y / scale);
        }
    return found;
}

bool isBackground(const QColor &seen, QString *why)
{
    return nearColour(seen, toColour(ui::kBackgroundColour), 2, why);
}

// the lit front of the sheet: bright, and warmer than grey but far from the particles' amber
bool isSheet(const QColor &seen)
{
    const int warmth = seen.red() - seen.blue();
    return seen.red() > 110 && warmth > 15 && warmth < 90;
}

// a 4 × 4 cloth of structural, shear and bend springs, level at y = 0, 0.5 m apart
core::SceneDesc smallCloth()
{
    core::ClothOptions options;
    options.rows = 4;
    options.cols = 4;
    options.spacing = 0.5;
    options.height = 0.0;
    options.radius = 0.06;
    return core::makeCloth(options);
}

std::shared_ptr<const core::Snapshot> snapshotOf(const core::SceneDesc &scene)
{
    const auto model = core::compileModel(scene);
    return core::makeSnapshot(*model, core::makeState(*model, scene));
}

int springJoining(const core::SceneDesc &scene, int a, int b)
{
    for (std::size_t k = 0; k < scene.springs.size(); ++k)
        if (std::minmax(scene.springs[k].a, scene.springs[k].b) == std::minmax(a, b))
            return int(k);
    return -1;
}

}  // namespace

class TestViewport : public QObject {
    Q_OBJECT

public:
    // GL has to be set up before the QApplication exists
    static void initMain() { test::prepareOpenGL(); }

private slots:
    void init();
    void cleanup();

    void showsParticlesOverTheBackground_data();
    void showsParticlesOverTheBackground();
    void pinnedParticlesCarryADarkRing();
    void selectionIsHighlighted();
    void styleIsUploadedOnlyWhenItChanges();
    void springsAreColouredByStrain();
    void planesAreTranslucent();
    void drawsASnapshotOfTheCore();
    void turningBallsCarryTheirPattern();
    void leftDragOnEmptySpaceOrbits();
    void leftPressOnAParticleDoesNotOrbit();
    void middleAndShiftDragPan_data();
    void middleAndShiftDragPan();
    void wheelZoomsAtTheCursor();
    void frameAllKeysBringEveryParticleIntoView_data();
    void frameAllKeysBringEveryParticleIntoView();
    void initialViewFramesTheSceneAtItsFinalSize();
    void framesAPoolFromOutsideItsWalls();
    void reportsFrameTimes();
    void drawsAgainInANewContext();
    void rendersOffscreenAtAnySize_data();
    void rendersOffscreenAtAnySize();
    void offscreenImagesAreSmoothedLikeTheView();
    void refusesImagesLargerThanTheDriverDraws();
    void clothIsDrawnAsASheet();
    void tornSpringsOpenHoles();
    void layersShowTheSheetsSpheresAndSprings();
    void springsAreWideAndScaleWithTheImage();
    void steeringArrowShowsThePush();

private:
    QPointF projected(int particle) const;
    QImage grab();

    std::unique_ptr<ui::Viewport> m_viewport;
    std::shared_ptr<core::Snapshot> m_snapshot;
};

void TestViewport::init()
{
    m_viewport = std::make_unique<ui::Viewport>();
    m_viewport->resize(kViewportSize);
    m_viewport->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_viewport.get()));
    m_snapshot = tinySnapshot();
    m_viewport->setSnapshot(m_snapshot);
}

void TestViewport::cleanup()
{
    m_viewport.reset();
    m_snapshot.reset();
}

QPointF TestViewport::projected(int particle) const
{
    const auto pixel = m_viewport->camera().project(positionOf(*m_snapshot, particle));
    return pixel.value_or(QPointF(-1.0, -1.0));
}

QImage TestViewport::grab()
{
    QImage image = m_viewport->grabFramebuffer();
    if (image.isNull())
        qWarning("grabFramebuffer() gave no image");
    return image;
}

void TestViewport::showsParticlesOverTheBackground_data()
{
    QTest::addColumn<ui::ParticleDrawing>("drawing");
    QTest::addColumn<ui::Projection>("projection");
    QTest::newRow("impostor") << ui::ParticleDrawing::Impostor << ui::Projection::Perspective;
    QTest::newRow("mesh") << ui::ParticleDrawing::Mesh << ui::Projection::Perspective;
    QTest::newRow("impostor, orthographic") << ui::ParticleDrawing::Impostor << ui::Projection::Orthographic;
    QTest::newRow("mesh, orthographic") << ui::ParticleDrawing::Mesh << ui::Projection::Orthographic;
}

void TestViewport::showsParticlesOverTheBackground()
{
    QFETCH(ui::ParticleDrawing, drawing);
    QFETCH(ui::Projection, projection);
    m_viewport->setParticleDrawing(drawing);
    m_viewport->setProjection(projection);
    const QImage image = grab();
    QCOMPARE(image.size(), kViewportSize * m_viewport->devicePixelRatio());
    QString why;

    // the free particles in the free colour, the pinned one in the pinned colour
    for (int particle : {0, 2}) {
        const QPointF pixel = projected(particle);
        QVERIFY(QRectF(QPointF(0, 0), QSizeF(kViewportSize)).contains(pixel));
        QVERIFY2(sameHue(colourAt(image, *m_viewport, pixel), ui::kFreeColour, &why), qPrintable(why));
    }
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(1)), ui::kPinnedColour, &why), qPrintable(why));

    // the background far from everything
    QVERIFY2(isBackground(colourAt(image, *m_viewport, QPointF(2, 2)), &why), qPrintable(why));
    QCOMPARE(m_viewport->particleAt(QPointF(2, 2)), -1);
    QCOMPARE(m_viewport->particleAt(projected(2)), 2);
}

void TestViewport::pinnedParticlesCarryADarkRing()
{
    // 61 % of the way to the outline the pinned particle is much darker than at its middle; the
    // free one is not
    const QImage image = grab();
    const ui::Camera &camera = m_viewport->camera();
    auto ringOverMiddle = [&](int particle) {
        const QVector3D centre = positionOf(*m_snapshot, particle);
        const QVector3D towardEye = (camera.eye() - centre).normalized();
        const QVector3D side = QVector3D::crossProduct(towardEye, camera.up()).normalized();
        const QPointF ring = camera.project(centre + side * 0.61f * m_snapshot->radii[particle]).value();
        return colourAt(image, *m_viewport, ring).valueF() / colourAt(image, *m_viewport, projected(particle)).valueF();
    };
    const double pinned = ringOverMiddle(1);
    const double free = ringOverMiddle(0);
    QCOMPARE_LT(pinned, 0.5);
    QCOMPARE_GT(free, 0.7);
}

void TestViewport::selectionIsHighlighted()
{
    QString why;
    m_viewport->setSelection({0});
    QImage image = grab();
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(0)), ui::kSelectedColour, &why), qPrintable(why));
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(2)), ui::kFreeColour, &why), qPrintable(why));

    // and back
    m_viewport->setSelection({});
    image = grab();
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(0)), ui::kFreeColour, &why), qPrintable(why));
}

void TestViewport::styleIsUploadedOnlyWhenItChanges()
{
    grab();
    const int uploads = m_viewport->styleUploads();
    QCOMPARE_GE(uploads, 1);

    // new positions every frame: no new style
    for (int frame = 0; frame < 3; ++frame) {
        auto moved = std::make_shared<core::Snapshot>(*m_snapshot);
        moved->positions[0] += 0.05f * float(frame + 1);
        moved->step = std::uint64_t(frame + 1);
        m_viewport->setSnapshot(moved);
        grab();
    }
    QCOMPARE(m_viewport->styleUploads(), uploads);

    // the moved particle is drawn where it now is
    m_snapshot = std::make_shared<core::Snapshot>(*m_viewport->snapshot());
    QString why;
    QVERIFY2(sameHue(colourAt(grab(), *m_viewport, projected(0)), ui::kFreeColour, &why), qPrintable(why));

    // a pin does need one, and shows
    auto pinned = std::make_shared<core::Snapshot>(*m_snapshot);
    pinned->pinned[2] = 1;
    m_snapshot = pinned;
    m_viewport->setSnapshot(pinned);
    const QImage image = grab();
    QCOMPARE(m_viewport->styleUploads(), uploads + 1);
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(2)), ui::kPinnedColour, &why), qPrintable(why));
}

void TestViewport::springsAreColouredByStrain()
{
    // the middle of the stretched spring, away from both spheres, is red (a 1-pixel line: look at
    // the pixels around it for the reddest)
    const QImage image = grab();
    const QVector3D middle = 0.5f * (positionOf(*m_snapshot, 0) + positionOf(*m_snapshot, 2));
    const QPointF pixel = m_viewport->camera().project(middle).value();
    QCOMPARE(m_viewport->particleAt(pixel), -1);
    int reddest = -255;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const QColor c = colourAt(image, *m_viewport, pixel + QPointF(dx, dy));
            reddest = std::max(reddest, c.red() - c.blue());
        }
    QCOMPARE_GT(reddest, 60);

    // compressed, it turns blue
    auto compressed = std::make_shared<core::Snapshot>(*m_snapshot);
    compressed->springStrain[0] = -0.5f;
    m_viewport->setSnapshot(compressed);
    const QImage blue = grab();
    int bluest = -255;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const QColor c = colourAt(blue, *m_viewport, pixel + QPointF(dx, dy));
            bluest = std::max(bluest, c.blue() - c.red());
        }
    QCOMPARE_GT(bluest, 60);
}

void TestViewport::planesAreTranslucent()
{
    // a wall behind the particles, facing the eye: a point on it, in no particle, shows the
    // background blended with the plane colour
    const ui::Camera &camera = m_viewport->camera();
    core::PlaneDesc wall;
    const QVector3D facing = -camera.forward();
    wall.normal = Eigen::Vector3d(facing.x(), facing.y(), facing.z());
    const QVector3D behind = camera.target() + camera.forward() * 0.8f;
    wall.offset = QVector3D::dotProduct(facing, behind);
    m_viewport->setPlanes({wall});

    const QVector3D onWall = behind + camera.up() * 0.9f + camera.right() * 0.3f;
    const QPointF pixel = camera.project(onWall).value();
    QCOMPARE(m_viewport->particleAt(pixel), -1);
    const QImage image = grab();
    const float a = ui::kPlaneAlpha;
    const QColor expected = QColor::fromRgbF(ui::kBackgroundColour[0] * (1 - a) + ui::kPlaneColour[0] * a,
                                             ui::kBackgroundColour[1] * (1 - a) + ui::kPlaneColour[1] * a,
                                             ui::kBackgroundColour[2] * (1 - a) + ui::kPlaneColour[2] * a);
    QString why;
    QVERIFY2(nearColour(colourAt(image, *m_viewport, pixel), expected, 3, &why), qPrintable(why));

    // the corner is outside the wall's square and stays background
    QVERIFY2(isBackground(colourAt(image, *m_viewport, QPointF(2, 2)), &why), qPrintable(why));
}

void TestViewport::turningBallsCarryTheirPattern()
{
    // a ball of a scene that turns is drawn with white caps about its own y axis and its colour as a
    // band between them: unturned, the top of the ball (in the world) is a cap; turned a quarter
    // about x, the band; in a scene that cannot turn, its plain colour
    core::SceneDesc scene;
    scene.name = "pattern";
    core::ParticleDesc ball;
    ball.position = {0.0, 0.0, 0.0};
    ball.radius = 0.5;
    ball.angularVelocity = {0.0, 0.0, 1.0};  // the scene turns
    scene.particles = {ball};
    const auto model = core::compileModel(scene);
    QVERIFY(model->plan.spin);
    core::State state = core::makeState(*model, scene);
    const auto colourOnTop = [&](const core::State &drawn, const core::Model &of) {
        m_snapshot = std::make_shared<core::Snapshot>(*core::makeSnapshot(of, drawn));
        m_viewport->setSnapshot(m_snapshot);
        m_viewport->frameAll();
        const QImage image = grab();
        const QPointF top = m_viewport->camera().project(QVector3D(0.0f, 0.42f, 0.0f)).value();
        return colourAt(image, *m_viewport, top);
    };
    QString why;
    const QColor cap = colourOnTop(state, *model);
    QCOMPARE_LT(cap.saturationF(), 0.15);  // white, shaded
    state.orientation.col(0) = Eigen::Vector4d(std::sqrt(0.5), std::sqrt(0.5), 0.0, 0.0);  // 90° about x
    const QColor band = colourOnTop(state, *model);
    QVERIFY2(sameHue(band, ui::kFreeColour, &why), qPrintable(why));
    // without spin nothing is patterned
    scene.particles[0].angularVelocity.setZero();
    const auto still = core::compileModel(scene);
    QVERIFY(!still->plan.spin);
    QVERIFY2(sameHue(colourOnTop(core::makeState(*still, scene), *still), ui::kFreeColour, &why), qPrintable(why));
}

void TestViewport::drawsASnapshotOfTheCore()
{
    // the core's own snapshot of a small scene: a pinned particle and a free one on a spring
    core::SceneDesc scene;
    scene.name = "viewport test";
    core::ParticleDesc anchor;
    anchor.position = {0.0, 1.0, 0.0};
    anchor.radius = 0.2;
    anchor.pinned = true;
    core::ParticleDesc bob;
    bob.position = {0.8, 0.4, 0.0};
    bob.radius = 0.3;
    scene.particles = {anchor, bob};
    core::SpringDesc spring;
    spring.a = 0;
    spring.b = 1;
    spring.stiffness = 50.0;
    spring.restLength = 0.5;
    scene.springs = {spring};
    const auto model = core::compileModel(scene);
    const core::State state = core::makeState(*model, scene);
    const auto snapshot = core::makeSnapshot(*model, state);
    QCOMPARE(snapshot->particleCount(), 2);

    m_snapshot = std::make_shared<core::Snapshot>(*snapshot);
    m_viewport->setSnapshot(snapshot);
    m_viewport->frameAll();
    const QImage image = grab();
    QString why;
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(0)), ui::kPinnedColour, &why), qPrintable(why));
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(1)), ui::kFreeColour, &why), qPrintable(why));
    QVERIFY2(isBackground(colourAt(image, *m_viewport, QPointF(2, 2)), &why), qPrintable(why));
}

void TestViewport::leftDragOnEmptySpaceOrbits()
{
    const QPoint start(30, 30);
    QCOMPARE(m_viewport->particleAt(start), -1);
    const QPointF before = projected(2);
    const float yaw = m_viewport->camera().yaw();

    // a real drag: press, a few moves, release
    QTest::mousePress(m_viewport.get(), Qt::LeftButton, Qt::NoModifier, start);
    for (int step = 1; step <= 4; ++step)
        QTest::mouseMove(m_viewport.get(), start + QPoint(20 * step, 5 * step));
    QTest::mouseRelease(m_viewport.get(), Qt::LeftButton, Qt::NoModifier, start + QPoint(80, 20));

    QCOMPARE_LT(std::abs(m_viewport->camera().yaw() - (yaw - 80.0f * ui::Camera::kOrbitDegreesPerPixel)), 1e-3f);
    const QPointF after = projected(2);
    QCOMPARE_GT(QLineF(before, after).length(), 10.0);

    // and the picture agrees with the camera
    QString why;
    QVERIFY2(sameHue(colourAt(grab(), *m_viewport, after), ui::kFreeColour, &why), qPrintable(why));
}

void TestViewport::leftPressOnAParticleDoesNotOrbit()
{
    QSignalSpy pressed(m_viewport.get(), &ui::Viewport::particlePressed);
    const QPoint onParticle = projected(1).toPoint();
    const float yaw = m_viewport->camera().yaw();
    QTest::mousePress(m_viewport.get(), Qt::LeftButton, Qt::ControlModifier, onParticle);
    QTest::mouseMove(m_viewport.get(), onParticle + QPoint(60, 0));
    QTest::mouseRelease(m_viewport.get(), Qt::LeftButton, Qt::NoModifier, onParticle + QPoint(60, 0));

    QCOMPARE(pressed.count(), 1);
    QCOMPARE(pressed.at(0).at(0).toInt(), 1);
    QCOMPARE(pressed.at(0).at(1).value<Qt::KeyboardModifiers>(), Qt::KeyboardModifiers(Qt::ControlModifier));
    QCOMPARE(m_viewport->camera().yaw(), yaw);
}

void TestViewport::middleAndShiftDragPan_data()
{
    QTest::addColumn<Qt::MouseButton>("button");
    QTest::addColumn<Qt::KeyboardModifiers>("modifiers");
    QTest::newRow("middle") << Qt::MiddleButton << Qt::KeyboardModifiers();
    QTest::newRow("shift+left") << Qt::LeftButton << Qt::KeyboardModifiers(Qt::ShiftModifier);
}

void TestViewport::middleAndShiftDragPan()
{
    // the scene follows the mouse; the view direction stays
    QFETCH(Qt::MouseButton, button);
    QFETCH(Qt::KeyboardModifiers, modifiers);
    const QPoint start(40, 300);
    const QVector3D onTargetPlane = m_viewport->camera().target();
    const QPointF before = m_viewport->camera().project(onTargetPlane).value();
    const QPointF particleBefore = projected(0);
    const QVector3D forward = m_viewport->camera().forward();
    QTest::mousePress(m_viewport.get(), button, modifiers, start);
    QTest::mouseMove(m_viewport.get(), start + QPoint(30, -10));
    QTest::mouseMove(m_viewport.get(), start + QPoint(60, -20));
    QTest::mouseRelease(m_viewport.get(), button, modifiers, start + QPoint(60, -20));

    // the target's plane moves pixel for pixel, a particle in front of it a little more or less
    const QPointF after = m_viewport->camera().project(onTargetPlane).value();
    QCOMPARE_LT(std::abs(after.x() - before.x() - 60.0), 0.5);
    QCOMPARE_LT(std::abs(after.y() - before.y() + 20.0), 0.5);
    const QPointF particleAfter = projected(0);
    QCOMPARE_GT(particleAfter.x() - particleBefore.x(), 40.0);
    QCOMPARE_LT(particleAfter.y() - particleBefore.y(), -10.0);
    QCOMPARE_GT(QVector3D::dotProduct(m_viewport->camera().forward(), forward), 0.99999f);
}

void TestViewport::wheelZoomsAtTheCursor()
{
    // the wheel over particle 2: it stays under the cursor and grows on screen
    const QPointF cursor = projected(2);
    const float distance = m_viewport->camera().distance();
    auto screenRadius = [&] {
        const ui::Camera &camera = m_viewport->camera();
        return QLineF(projected(2), camera.project(positionOf(*m_snapshot, 2) + camera.up() * 0.2f).value()).length();
    };
    const double radiusBefore = screenRadius();

    QWheelEvent wheel(cursor, m_viewport->mapToGlobal(cursor), QPoint(), QPoint(0, 2 * 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(m_viewport.get(), &wheel);

    QCOMPARE_LT(m_viewport->camera().distance(), 0.8f * distance);
    QCOMPARE_GT(screenRadius(), 1.2 * radiusBefore);
    QCOMPARE_LT(QLineF(projected(2), cursor).length(), 0.5 * screenRadius());
    QString why;
    QVERIFY2(sameHue(colourAt(grab(), *m_viewport, cursor), ui::kFreeColour, &why), qPrintable(why));

    // and back out
    QWheelEvent back(cursor, m_viewport->mapToGlobal(cursor), QPoint(), QPoint(0, -2 * 120), Qt::NoButton,
                     Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(m_viewport.get(), &back);
    QCOMPARE_LT(std::abs(m_viewport->camera().distance() - distance), 1e-3f * distance);
}

void TestViewport::frameAllKeysBringEveryParticleIntoView_data()
{
    QTest::addColumn<int>("key");
    QTest::newRow("F") << int(Qt::Key_F);
    QTest::newRow("Home") << int(Qt::Key_Home);
}

void TestViewport::frameAllKeysBringEveryParticleIntoView()
{
    QFETCH(int, key);

    // lose the scene: look at a point far away, from close by, from another side
    ui::Camera &camera = m_viewport->camera();
    camera.setTarget(QVector3D(40.0f, 30.0f, -20.0f));
    camera.setDistance(0.5f);
    camera.orbit(300.0f, 50.0f);
    auto inView = [&](int particle) {
        const auto pixel = camera.project(positionOf(*m_snapshot, particle));
        return pixel && QRectF(QPointF(0, 0), QSizeF(kViewportSize)).contains(*pixel);
    };
    QVERIFY(!inView(0) && !inView(1) && !inView(2));

    QTest::keyClick(m_viewport.get(), Qt::Key(key));
    for (int particle = 0; particle < 3; ++particle) {
        QVERIFY2(inView(particle), qPrintable(QString::number(particle)));
        // the whole sphere, not only its centre
        const QVector3D centre = positionOf(*m_snapshot, particle);
        const float r = m_snapshot->radii[particle];
        for (const QVector3D &edge : {camera.right(), -camera.right(), camera.up(), -camera.up()}) {
            const QPointF pixel = camera.project(centre + edge * r).value();
            QVERIFY(QRectF(QPointF(0, 0), QSizeF(kViewportSize)).contains(pixel));
        }
    }
    QString why;
    QVERIFY2(sameHue(colourAt(grab(), *m_viewport, projected(1)), ui::kPinnedColour, &why), qPrintable(why));
}

void TestViewport::initialViewFramesTheSceneAtItsFinalSize()
{
    // a snapshot given before the widget is shown, wide, then shown tall: every particle in view
    ui::Viewport viewport;
    viewport.resize(600, 200);
    viewport.setSnapshot(m_snapshot);
    const QSize tall(200, 600);
    viewport.resize(tall);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    const QImage image = viewport.grabFramebuffer();
    QCOMPARE(viewport.camera().viewportSize(), tall);
    QString why;
    for (int particle = 0; particle < 3; ++particle) {
        const QVector3D centre = positionOf(*m_snapshot, particle);
        for (const QVector3D &edge : {viewport.camera().right(), -viewport.camera().right()}) {
            const QPointF pixel = viewport.camera().project(centre + edge * m_snapshot->radii[particle]).value();
            QVERIFY(QRectF(QPointF(0, 0), QSizeF(tall)).contains(pixel));
        }
        const ui::Rgb &colour = particle == 1 ? ui::kPinnedColour : ui::kFreeColour;
        const QPointF pixel = viewport.camera().project(centre).value();
        QVERIFY2(sameHue(colourAt(image, viewport, pixel), colour, &why), qPrintable(why));
    }
}

void TestViewport::framesAPoolFromOutsideItsWalls()
{
    // a floor and four walls 5 m out around the small scene: framed from inside, the near wall
    // would cover the whole view; framed whole, the eye is beyond a wall and the floor in view
    const std::vector<core::PlaneDesc> planes = test::poolPlanes();
    m_viewport->setPlanes(planes);
    m_viewport->frameAll();
    const QVector3D eye = m_viewport->camera().eye();
    QCOMPARE_GT(std::max(std::abs(eye.x()), std::abs(eye.z())), 5.0f);
    for (const QVector3D corner : {QVector3D(5, 0, 5), QVector3D(-5, 0, 5), QVector3D(5, 0, -5), QVector3D(-5, 0, -5)}) {
        const auto pixel = m_viewport->camera().project(corner);
        QVERIFY(pixel.has_value());
        QVERIFY(QRectF(QPointF(0, 0), QSizeF(kViewportSize)).contains(*pixel));
    }

    // and without the walls, the particles fill the view as before
    m_viewport->setPlanes({planes[0]});
    m_viewport->frameAll();
    QCOMPARE_LT(m_viewport->camera().eye().length(), 5.0f);
}

void TestViewport::reportsFrameTimes()
{
    QSignalSpy frames(m_viewport.get(), &ui::Viewport::frameTimeMeasured);
    m_viewport->update();
    QVERIFY(frames.wait(10000));
    const double seconds = frames.last().at(0).toDouble();
    QCOMPARE_GT(seconds, 0.0);
    QCOMPARE_LT(seconds, 10.0);
}

void TestViewport::drawsAgainInANewContext()
{
    // moving the viewport into another window replaces its context: it frees and rebuilds
    QWidget window;
    auto *layout = new QVBoxLayout(&window);
    layout->setContentsMargins(0, 0, 0, 0);
    ui::Viewport *viewport = m_viewport.get();
    layout->addWidget(viewport);
    window.resize(kViewportSize);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_COMPARE(viewport->size(), kViewportSize);

    QString why;
    QVERIFY2(sameHue(colourAt(grab(), *viewport, projected(1)), ui::kPinnedColour, &why), qPrintable(why));
    QVERIFY2(sameHue(colourAt(grab(), *viewport, projected(0)), ui::kFreeColour, &why), qPrintable(why));

    // hand it back before the window goes
    viewport->setParent(nullptr);
}

void TestViewport::rendersOffscreenAtAnySize_data()
{
    // twice the widget (480 × 360), a wide size of another aspect ratio, and odd sides
    QTest::addColumn<QSize>("size");
    QTest::newRow("2x") << kViewportSize * 2;
    QTest::newRow("1000x300") << QSize(1000, 300);
    QTest::newRow("odd 749x563") << QSize(749, 563);
}

void TestViewport::rendersOffscreenAtAnySize()
{
    QFETCH(QSize, size);
    const QImage onScreen = grab();
    QString error;
    const QImage image = m_viewport->renderImage(size, &error);
    QVERIFY2(!image.isNull(), qPrintable(error));
    QCOMPARE(image.size(), size);

    // the same camera with the image's aspect ratio: the vertical field of view is kept, so a
    // pixel of the widget lands at its offset from the centre scaled by the heights' ratio
    const QSizeF widget(m_viewport->size());
    const double scale = size.height() / widget.height();
    auto scaled = [&](QPointF pixel) {
        return QPointF(size.width() / 2.0 + (pixel.x() - widget.width() / 2.0) * scale,
                       size.height() / 2.0 + (pixel.y() - widget.height() / 2.0) * scale);
    };
    auto colourAtScaled = [&](QPointF pixel) {
        const QPointF at = scaled(pixel);
        return image.pixelColor(QPoint(int(at.x()), int(at.y())));
    };
    QString why;
    for (int particle : {0, 2}) {
        QVERIFY(QRectF(QPointF(0, 0), QSizeF(size)).contains(scaled(projected(particle))));
        QVERIFY2(sameHue(colourAtScaled(projected(particle)), ui::kFreeColour, &why), qPrintable(why));
    }
    QVERIFY2(sameHue(colourAtScaled(projected(1)), ui::kPinnedColour, &why), qPrintable(why));
    QVERIFY2(isBackground(image.pixelColor(2, 2), &why), qPrintable(why));

    // the view on screen is as it was
    QCOMPARE(m_viewport->camera().viewportSize(), kViewportSize);
    QCOMPARE(grab(), onScreen);
}

void TestViewport::offscreenImagesAreSmoothedLikeTheView()
{
    // OpenGL is drawn on the CPU here (Mesa's llvmpipe), so the view is not multisampled: a
    // frame costs half as much. An exported image still is: where it differs from the view, the
    // view has an outline within two pixels (a sphere or a line beside what is behind it), and
    // nowhere else by more than a faint line's few levels
    QVERIFY(ui::Viewport::drawnOnTheCpu());
    const QImage onScreen = grab().convertToFormat(QImage::Format_RGB32);
    QCOMPARE(m_viewport->samples(), 0);

    QString error;
    const QImage image = m_viewport->renderImage(onScreen.size(), &error);
    QVERIFY2(!image.isNull(), qPrintable(error));
    // an outline: within two pixels of (x, y) the view has a colour far from the one at (x, y)
    const auto nearOutline = [&](int x, int y) {
        const QColor centre = onScreen.pixelColor(x, y);
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                const QColor c = onScreen.pixelColor(std::clamp(x + dx, 0, onScreen.width() - 1),
                                                     std::clamp(y + dy, 0, onScreen.height() - 1));
                if (std::max({std::abs(c.red() - centre.red()), std::abs(c.green() - centre.green()),
                              std::abs(c.blue() - centre.blue())}) > 32)
                    return true;
            }
        return false;
    };
    int differing = 0, awayFromOutlines = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (image.pixel(x, y) == onScreen.pixel(x, y))
                continue;
            ++differing;
            // (faint lines, a few levels from the background, are drawn a little differently)
            const QColor a = image.pixelColor(x, y), b = onScreen.pixelColor(x, y);
            const int by = std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()),
                                     std::abs(a.blue() - b.blue())});
            awayFromOutlines += by > 16 && !nearOutline(x, y);
        }
    QCOMPARE_GT(differing, 0);
    QCOMPARE(awayFromOutlines, 0);
}

void TestViewport::refusesImagesLargerThanTheDriverDraws()
{
    const int most = m_viewport->maxImageSide();
    QCOMPARE_GE(most, 1024);  // OpenGL 3.3 promises 1024 a side at least (Mesa gives 16384)
    QString error;
    QVERIFY(m_viewport->renderImage(QSize(most + 1, 10), &error).isNull());
    QVERIFY2(error.contains(QStringLiteral("at most %1 px").arg(most)), qPrintable(error));
    QVERIFY(m_viewport->renderImage(QSize(0, 10), &error).isNull());
    QVERIFY2(error.contains(QStringLiteral("at least 1")), qPrintable(error));
}

void TestViewport::clothIsDrawnAsASheet()
{
    // seen from above at an angle: the middle of a cell, between four beads, is the sheet; the
    // beads and springs it joins are not drawn over it, nor is the legend to springs not drawn
    const core::SceneDesc scene = smallCloth();
    const auto snapshot = snapshotOf(scene);
    QVERIFY(snapshot->triangles && snapshot->triangles->count() == 18);
    m_snapshot = std::make_shared<core::Snapshot>(*snapshot);
    m_viewport->setSnapshot(snapshot);
    m_viewport->frameAll();
    m_viewport->camera().setAngles(30.0f, 55.0f);
    QCOMPARE(m_viewport->surfaceTriangles(), 18);

    // (a corner cell: the middle one has the axes' origin at its centre, drawn over the sheet)
    const QPointF middle = m_viewport->camera().project(0.25f * (positionOf(*snapshot, 0) + positionOf(*snapshot, 1) +
                                                                 positionOf(*snapshot, 4) + positionOf(*snapshot, 5))).value();
    QImage image = grab();
    QVERIFY2(isSheet(colourAt(image, *m_viewport, middle)), qPrintable(colourAt(image, *m_viewport, middle).name()));
    QVERIFY2(isSheet(colourAt(image, *m_viewport, projected(5))), qPrintable(colourAt(image, *m_viewport, projected(5)).name()));
    QVERIFY(!m_viewport->strainLegend()->isVisible());

    // without the sheet: the beads, and between them the background (or the grid under it)
    m_viewport->setLayers({false, false, false});
    QCOMPARE(m_viewport->surfaceTriangles(), 0);
    image = grab();
    QVERIFY(!isSheet(colourAt(image, *m_viewport, middle)));
    QString why;
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(5)), ui::kFreeColour, &why), qPrintable(why));
    QVERIFY(m_viewport->strainLegend()->isVisible());
}

void TestViewport::tornSpringsOpenHoles()
{
    // both diagonals of the cell of particles 5, 6, 9 and 10 torn: its two triangles are gone,
    // the cell beside it stays
    const core::SceneDesc scene = smallCloth();
    auto torn = std::make_shared<core::Snapshot>(*snapshotOf(scene));
    torn->springBroken.assign(scene.springs.size(), 0);
    for (const auto &[a, b] : {std::pair{5, 10}, std::pair{6, 9}}) {
        const int k = springJoining(scene, a, b);
        QVERIFY(k >= 0);
        torn->springBroken[std::size_t(k)] = 1;
    }
    m_snapshot = torn;
    m_viewport->setSnapshot(torn);
    m_viewport->frameAll();
    m_viewport->camera().setAngles(30.0f, 55.0f);
    QCOMPARE(m_viewport->surfaceTriangles(), 16);

    auto cellMiddle = [&](int corner) {
        const int cols = 4;
        return m_viewport->camera()
            .project(0.25f * (positionOf(*torn, corner) + positionOf(*torn, corner + 1) + positionOf(*torn, corner + cols) +
                              positionOf(*torn, corner + cols + 1)))
            .value();
    };
    // the hole seen a third of the way from its middle to a corner: the cloth is centred on the
    // origin, where the axes start, and which pixel their ends cover there is a matter of rounding
    const QImage image = grab();
    const QPointF inHole = cellMiddle(5) + (m_viewport->camera().project(positionOf(*torn, 6)).value() - cellMiddle(5)) / 3.0;
    const QColor hole = colourAt(image, *m_viewport, inHole);
    QVERIFY2(!isSheet(hole) && hole.red() < 110, qPrintable(hole.name()));
    QVERIFY(isSheet(colourAt(image, *m_viewport, cellMiddle(4))));
    QVERIFY(isSheet(colourAt(image, *m_viewport, cellMiddle(6))));
}

void TestViewport::layersShowTheSheetsSpheresAndSprings()
{
    // every spring stretched, so that a spring drawn over the sheet is red
    const core::SceneDesc scene = smallCloth();
    auto stretched = std::make_shared<core::Snapshot>(*snapshotOf(scene));
    std::fill(stretched->springStrain.begin(), stretched->springStrain.end(), 0.5f);
    m_snapshot = stretched;
    m_viewport->setSnapshot(stretched);
    m_viewport->frameAll();
    m_viewport->camera().setAngles(30.0f, 55.0f);
    const QPointF onSpring = m_viewport->camera().project(0.5f * (positionOf(*stretched, 5) + positionOf(*stretched, 6))).value();
    auto reddest = [&](const QImage &image) {
        int most = -255;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const QColor c = colourAt(image, *m_viewport, onSpring + QPointF(dx, dy));
                most = std::max(most, c.red() - c.blue());
            }
        return most;
    };

    // the sheet alone: no spring there, and none to pick
    QImage image = grab();
    QCOMPARE_LT(reddest(image), 100);
    QCOMPARE(m_viewport->springAt(onSpring), -1);

    // with its springs: drawn, picked, and the legend shown
    m_viewport->setLayers({true, false, true});
    image = grab();
    QCOMPARE_GT(reddest(image), 150);
    QVERIFY(m_viewport->springAt(onSpring) >= 0);
    QVERIFY(m_viewport->strainLegend()->isVisible());

    // with its spheres: a bead where the sheet was
    m_viewport->setLayers({true, true, false});
    image = grab();
    QString why;
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(5)), ui::kFreeColour, &why), qPrintable(why));
    QVERIFY(!m_viewport->strainLegend()->isVisible());

    // a selected particle of the sheet is drawn even when its spheres are not
    m_viewport->setLayers({true, false, false});
    m_viewport->setSelection({5});
    image = grab();
    QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(5)), ui::kSelectedColour, &why), qPrintable(why));

    // the hidden spheres are left out of the draw, not drawn at radius 0: the two drawn are each
    // at their own place, and once nothing is selected none is drawn
    m_viewport->setSelection({10, 5});
    image = grab();
    for (int particle : {5, 10})
        QVERIFY2(sameHue(colourAt(image, *m_viewport, projected(particle)), ui::kSelectedColour, &why), qPrintable(why));
    QVERIFY(isSheet(colourAt(image, *m_viewport, projected(6))));
    m_viewport->setSelection({});
    image = grab();
    for (int particle : {5, 10})
        QVERIFY(isSheet(colourAt(image, *m_viewport, projected(particle))));
}

void TestViewport::springsAreWideAndScaleWithTheImage()
{
    // one spring across the view, seen from the front; measured a quarter of the way along it
    auto s = std::make_shared<core::Snapshot>();
    s->positions = {-1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f};
    s->radii = {0.02f, 0.02f};
    s->pinned = {1, 1};
    s->springEnds = {-1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f};
    s->springStrain = {0.0f};
    m_snapshot = s;
    m_viewport->setSnapshot(s);
    ui::Camera &camera = m_viewport->camera();
    camera.setTarget(QVector3D(0.0f, 0.0f, 0.0f));
    camera.setDistance(4.0f);
    camera.setAngles(0.0f, 0.0f);
    QVERIFY(m_viewport->strainLegend()->isVisible());
    const QPoint at = camera.project(QVector3D(-0.5f, 0.0f, 0.0f)).value().toPoint();

    // 2 pixels in the view, 8 in an image 4 times its size
    const double inView = test::lineThickness(grab(), at.x(), at.y(), 4);
    QVERIFY2(inView >= 1.5 && inView <= 3.0, qPrintable(QString::number(inView)));
    QString error;
    const QImage large = m_viewport->renderImage(kViewportSize * 4, &error);
    QVERIFY2(!large.isNull(), qPrintable(error));
    QCOMPARE(m_viewport->lineScale(large.height()), 4.0);
    const double inImage = test::lineThickness(large, 4 * at.x() + 1, 4 * at.y() + 1, 16);
    QVERIFY2(inImage >= 3.0 * inView && inImage <= 5.0 * inView,
             qPrintable(QStringLiteral("%1 px in the view, %2 px in the image").arg(inView).arg(inImage)));

    // selected: wider, in the selection's colour
    m_viewport->setSpringSelection({0});
    const QImage selected = grab();
    QCOMPARE_GE(test::lineThickness(selected, at.x(), at.y(), 4), 1.5 * inView);
    QString why;
    QVERIFY2(sameHue(colourAt(selected, *m_viewport, at), ui::kSelectedColour, &why), qPrintable(why));
}

void TestViewport::steeringArrowShowsThePush()
{
    // no push: not a pixel of the arrow's colour
    QVERIFY(steeringPixels(grab(), *m_viewport).empty());

    // a push on particle 0 along +x: the arrow's pixels, from the particle's centre out along it
    const QPointF centre = projected(0);
    const auto along = m_viewport->camera().project(positionOf(*m_snapshot, 0) + QVector3D(1.0f, 0.0f, 0.0f));
    QVERIFY(along);
    const QPointF onScreen = (*along - centre) / QLineF(centre, *along).length();
    auto reach = [&](const std::vector<QPointF> &pixels) {
        double furthest = 0.0;
        for (const QPointF &p : pixels)
            furthest = std::max(furthest, QPointF::dotProduct(p - centre, onScreen));
        return furthest;
    };
    m_viewport->setSteeringArrow({0, QVector3D(1.0f, 0.0f, 0.0f), 0.25f});
    const std::vector<QPointF> weak = steeringPixels(grab(), *m_viewport);
    QCOMPARE_GT(weak.size(), std::size_t(20));
    // drawn over the ball it starts in too
    QVERIFY(std::any_of(weak.begin(), weak.end(), [&](const QPointF &p) { return QLineF(p, centre).length() < 3.0; }));

    // the strongest push: a longer arrow, as far past the ball as four radii
    m_viewport->setSteeringArrow({0, QVector3D(1.0f, 0.0f, 0.0f), 1.0f});
    const std::vector<QPointF> strong = steeringPixels(grab(), *m_viewport);
    const auto tip = m_viewport->camera().project(positionOf(*m_snapshot, 0) +
                                                  QVector3D(m_snapshot->radii[0] * 5.0f, 0.0f, 0.0f));
    QVERIFY(tip);
    const double tipReach = QPointF::dotProduct(*tip - centre, onScreen);
    QCOMPARE_GT(reach(strong), reach(weak) + 10.0);
    QVERIFY2(std::abs(reach(strong) - tipReach) < 4.0,
             qPrintable(QStringLiteral("%1 px against %2").arg(reach(strong)).arg(tipReach)));

    // the push let go of: gone
    m_viewport->setSteeringArrow({0, QVector3D(1.0f, 0.0f, 0.0f), 0.0f});
    QVERIFY(steeringPixels(grab(), *m_viewport).empty());
}

QTEST_MAIN(TestViewport)
#include "test_viewport.moc"
