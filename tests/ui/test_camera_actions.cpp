// The View menu's camera in the real editor, driven by its keys: Top, Front and Side look along
// -y, -z and -x with the whole scene in view, and Default goes back; Orthographic changes the
// projection, is remembered by the next window, and a click still picks the particle under the
// cursor; Follow Selection keeps the target on the selected particles' centroid while the run
// plays and leaves the camera be when turned off; a generated cloth out of view is framed, a small
// one in view leaves the camera alone; the ground grid is drawn on floors alone, at their height.
// F1 lists the new keys.

#include "ui/dialogs/generate_dialog.h"
#include "ui/document/scene_document.h"
#include "ui/viewport/edit_tools.h"
#include "ui/viewport/render_data.h"
#include "ui/viewport/viewport.h"
#include "ui/window/main_window.h"

#include <QAction>
#include <QPushButton>
#include <QSpinBox>
#include <QtTest>

#include "editor_fixture.h"
#include "help_entries.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace {

QVector3D toQt(const Eigen::Vector3d &p) { return QVector3D(float(p.x()), float(p.y()), float(p.z())); }

bool near(const QVector3D &a, const QVector3D &b, float tolerance = 1e-4f) { return (a - b).length() < tolerance; }

// pinned particles, so that nothing moves: A at the middle, B to +x, C to -z, D above A
core::SceneDesc markers()
{
    core::SceneDesc scene;
    scene.name = "markers";
    for (const Eigen::Vector3d &p : {Eigen::Vector3d(0.0, 0.5, 0.0), Eigen::Vector3d(1.0, 0.5, 0.0),
                                     Eigen::Vector3d(0.0, 0.5, -1.0), Eigen::Vector3d(0.0, 1.5, 0.0)}) {
        core::ParticleDesc particle;
        particle.position = p;
        particle.radius = 0.1;
        particle.pinned = true;
        scene.particles.push_back(particle);
    }
    return scene;
}

// the grid's grey, or a line of it only partly covering the pixel: grey (the grid's channels are
// within 12 of each other), and brighter than the background in every channel; not the planes'
// blue, nor the particles' or the axes' colours, nor their edges over the background
bool gridGrey(const QColor &seen)
{
    const int low = std::min({seen.red(), seen.green(), seen.blue()});
    const int high = std::max({seen.red(), seen.green(), seen.blue()});
    const QColor background = QColor::fromRgbF(ui::kBackgroundColour[0], ui::kBackgroundColour[1], ui::kBackgroundColour[2]);
    return high - low <= 16 && seen.red() >= background.red() + 6 && seen.green() >= background.green() + 6 &&
           seen.blue() >= background.blue() + 6;
}

}  // namespace

class TestCameraActions : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void presetsLookAlongTheAxes();
    void orthographicStillPicksTheParticleUnderTheCursor();
    void followSelectionMovesTheTargetWithTheParticles();
    void generatedClothOutOfViewIsFramed();
    void smallGeneratedContentInViewKeepsTheCamera();
    void gridOnlyOnFloors();
    void f1ListsTheCameraKeys();

private:
    ui::Viewport &viewport() const { return *m_window->viewport(); }
    const ui::Camera &camera() const { return m_window->viewport()->camera(); }
    void press(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QTest::keyClick(m_window, key, modifiers);
    }
    QAction *action(const char *name) const { return m_window->findChild<QAction *>(QString::fromLatin1(name)); }
    // replaces the scene and waits until the view shows it, framed
    bool show(const core::SceneDesc &scene)
    {
        m_window->document()->replace(scene, QString());
        const auto frame = test::settledFrame(controller());
        return frame && QTest::qWaitFor([&] { return viewport().snapshot() == controller().frame()->snapshot; });
    }
    // waits until the view shows the worker's frame of every edit made so far
    bool settled()
    {
        return test::settledFrame(controller()) &&
               QTest::qWaitFor([&] { return viewport().snapshot() == controller().frame()->snapshot; });
    }
    QPointF pixelOf(const QVector3D &world) const { return camera().project(world).value_or(QPointF(-1e6, -1e6)); }
    QColor seenAt(const QImage &image, const QPointF &pixel) const
    {
        const double scale = double(image.width()) / viewport().width();
        return image.pixelColor(QPoint(int(pixel.x() * scale), int(pixel.y() * scale)));
    }
    // the view's pixels in the grid's colour (gridGrey)
    std::vector<QPoint> gridPixels() const
    {
        const QImage image = viewport().grabFramebuffer();
        std::vector<QPoint> pixels;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                if (gridGrey(image.pixelColor(x, y)))
                    pixels.emplace_back(x, y);
        return pixels;
    }
    // types text into one of the Generate dialog's spin boxes, as a user would
    void type(ui::GenerateDialog *dialog, const char *name, const QString &text)
    {
        auto *box = dialog->findChild<QAbstractSpinBox *>(QString::fromLatin1(name));
        QVERIFY2(box, name);
        box->setFocus();
        box->selectAll();
        QTest::keyClicks(box, text);
        QTest::keyClick(box, Qt::Key_Return);
    }
    // Ctrl+G, a cloth of rows × cols at (x, y, z), Add; the new particles (selected by Add)
    std::vector<int> generateCloth(int rows, int cols, const QVector3D &at);
};

void TestCameraActions::init()
{
    QVERIFY2(openEditor({.size = QSize(1000, 760)}), qPrintable(editorFailure()));
}

void TestCameraActions::cleanup()
{
    closeEditor();
}

void TestCameraActions::presetsLookAlongTheAxes()
{
    QVERIFY(show(markers()));
    const QVector3D a(0.0f, 0.5f, 0.0f), b(1.0f, 0.5f, 0.0f), c(0.0f, 0.5f, -1.0f), d(0.0f, 1.5f, 0.0f);
    auto allInView = [&] { return viewport().particlesInView({0, 1, 2, 3}); };
    // two points on one line along the view land on one line through the middle of the view
    auto alongTheView = [&](const QVector3D &p, const QVector3D &q) {
        const QPointF middle(viewport().width() / 2.0, viewport().height() / 2.0);
        const QPointF u = pixelOf(p) - middle, v = pixelOf(q) - middle;
        const double cross = u.x() * v.y() - u.y() * v.x();
        return std::abs(cross) <= 1e-3 * std::max(1.0, std::hypot(u.x(), u.y()) * std::hypot(v.x(), v.y()));
    };

    // Top: straight down, +x to the right and -z up the screen; D right over A
    viewport().camera().pan(500.0f, 0.0f);  // the scene partly out of view first
    QVERIFY(!allInView());
    press(Qt::Key_7, Qt::ControlModifier);
    QVERIFY(near(camera().forward(), QVector3D(0.0f, -1.0f, 0.0f)));
    QVERIFY(allInView());
    QCOMPARE_GT(pixelOf(b).x(), pixelOf(a).x() + 20.0);
    QCOMPARE_LT(pixelOf(c).y(), pixelOf(a).y() - 20.0);
    QVERIFY(alongTheView(a, d));
    // and drawn there: B's pixel shows a particle, and half way from A to B is background
    const QImage top = viewport().grabFramebuffer();
    const QColor background = QColor::fromRgbF(ui::kBackgroundColour[0], ui::kBackgroundColour[1], ui::kBackgroundColour[2]);
    QVERIFY(seenAt(top, pixelOf(b)).name() != background.name());
    QCOMPARE(seenAt(top, (pixelOf(a) + pixelOf(b)) / 2.0).name(), background.name());

    // Front: along -z, D above A, B to the right
    press(Qt::Key_1, Qt::ControlModifier);
    QVERIFY(near(camera().forward(), QVector3D(0.0f, 0.0f, -1.0f)));
    QVERIFY(allInView());
    QCOMPARE_LT(pixelOf(d).y(), pixelOf(a).y() - 20.0);
    QCOMPARE_GT(pixelOf(b).x(), pixelOf(a).x() + 20.0);

    // Side: along -x, C (at -z) to the right, B right in front of A
    press(Qt::Key_3, Qt::ControlModifier);
    QVERIFY(near(camera().forward(), QVector3D(-1.0f, 0.0f, 0.0f)));
    QVERIFY(allInView());
    QCOMPARE_GT(pixelOf(c).x(), pixelOf(a).x() + 20.0);
    QVERIFY(alongTheView(a, b));

    // Default: the opening direction, framed about the scene's middle
    press(Qt::Key_0, Qt::ControlModifier);
    QCOMPARE(camera().yaw(), ui::Camera::kDefaultYaw);
    QCOMPARE(camera().pitch(), ui::Camera::kDefaultPitch);
    QVERIFY(allInView());
    const ui::Sphere bounds = ui::particleBounds(*viewport().snapshot());
    QVERIFY(near(camera().target(), bounds.centre));
}

void TestCameraActions::orthographicStillPicksTheParticleUnderTheCursor()
{
    // a 3 × 3 square of particles, seen obliquely: the far corner lands elsewhere in each projection
    core::SceneDesc scene = markers();
    scene.particles.clear();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            core::ParticleDesc particle;
            particle.position = {double(i) - 1.0, 0.5, double(j) - 1.0};
            particle.radius = 0.12;
            particle.pinned = true;
            scene.particles.push_back(particle);
        }
    QVERIFY(show(scene));
    const int corner = 8;
    const QVector3D world = toQt(scene.particles[corner].position);
    const QPointF perspective = pixelOf(world);
    QVERIFY(!camera().orthographic());

    // Ctrl+5: orthographic, kept in the settings
    QAction *orthographic = action("actionOrthographic");
    QVERIFY(orthographic);
    press(Qt::Key_5, Qt::ControlModifier);
    QVERIFY(orthographic->isChecked());
    QVERIFY(camera().orthographic());
    QCOMPARE(camera().projectionMatrix()(3, 3), 1.0f);
    QCOMPARE(QSettings().value(QStringLiteral("view/orthographic")).toBool(), true);
    const QPointF parallel = pixelOf(world);
    const double radiusPixels = 0.12 / camera().worldPerPixel();
    QCOMPARE_GT(QLineF(perspective, parallel).length(), 1.5 * radiusPixels);

    // the particle is drawn where the orthographic camera says, and a click there selects it
    const QImage image = viewport().grabFramebuffer();
    const QColor seen = seenAt(image, parallel);
    QVERIFY2(seen.saturationF() > 0.3, qPrintable(seen.name()));
    press(Qt::Key_1);  // the Select tool
    QTest::mouseClick(&viewport(), Qt::LeftButton, {}, parallel.toPoint());
    QCOMPARE(m_window->editTools()->selection().particles, std::vector<int>{corner});

    // the wheel zooms at the cursor: the particle stays under it
    QWheelEvent wheel(parallel, viewport().mapToGlobal(parallel), QPoint(), QPoint(0, 2 * 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    const float before = camera().worldPerPixel();
    QApplication::sendEvent(&viewport(), &wheel);
    QCOMPARE_LT(camera().worldPerPixel(), 0.8f * before);
    QCOMPARE_LT(QLineF(pixelOf(world), parallel).length(), 0.5);

    // a new window opens orthographic, as this one was left
    QVERIFY2(openEditor(), qPrintable(editorFailure()));
    QVERIFY(action("actionOrthographic")->isChecked());
    QVERIFY(camera().orthographic());
    press(Qt::Key_5, Qt::ControlModifier);
    QVERIFY(!camera().orthographic());
    QCOMPARE(QSettings().value(QStringLiteral("view/orthographic")).toBool(), false);
}

void TestCameraActions::followSelectionMovesTheTargetWithTheParticles()
{
    // particle 0 flies off sideways and falls; 1 is pinned; the selection is both
    core::SceneDesc scene = markers();
    scene.particles.resize(2);
    scene.particles[0].pinned = false;
    scene.particles[0].velocity = {2.0, 0.0, 0.0};
    QVERIFY(show(scene));
    m_window->editTools()->setSelection(ui::Selection{{0, 1}, {}});
    auto centroid = [&] {
        const core::Snapshot &s = *viewport().snapshot();
        return 0.5f * (QVector3D(s.positions[0], s.positions[1], s.positions[2]) +
                       QVector3D(s.positions[3], s.positions[4], s.positions[5]));
    };
    const QVector3D start = centroid();

    // Shift+F: the target goes to the centroid at once, and follows it while the run plays
    QAction *follow = action("actionFollowSelection");
    QVERIFY(follow);
    press(Qt::Key_F, Qt::ShiftModifier);
    QVERIFY(follow->isChecked());
    QVERIFY(near(camera().target(), start, 1e-5f));
    press(Qt::Key_F4);
    QVERIFY(QTest::qWaitFor([&] { return (centroid() - start).length() > 0.3f; }, 10000));
    QVERIFY(near(camera().target(), centroid(), 1e-5f));

    // off: the camera stays where it is while the particle goes on
    press(Qt::Key_F, Qt::ShiftModifier);
    QVERIFY(!follow->isChecked());
    const QVector3D left = camera().target();
    const QVector3D at = centroid();
    QVERIFY(QTest::qWaitFor([&] { return (centroid() - at).length() > 0.3f; }, 10000));
    press(Qt::Key_F4);
    QCOMPARE(camera().target(), left);
}

std::vector<int> TestCameraActions::generateCloth(int rows, int cols, const QVector3D &at)
{
    QTest::keyClick(m_window, Qt::Key_G, Qt::ControlModifier);
    ui::GenerateDialog *dialog = m_window->generateDialog();
    if (!dialog || !test::showActive(*dialog))
        return {};
    type(dialog, "generate-cloth-rows", QString::number(rows));
    type(dialog, "generate-cloth-cols", QString::number(cols));
    type(dialog, "generate-x", QString::number(double(at.x())));
    type(dialog, "generate-y", QString::number(double(at.y())));
    type(dialog, "generate-z", QString::number(double(at.z())));
    if (!QTest::qWaitFor([&] { return dialog->generated() && dialog->addButton()->isEnabled(); }))
        return {};
    QTest::mouseClick(dialog->addButton(), Qt::LeftButton);
    if (!settled())
        return {};
    return m_window->editTools()->selection().particles;
}

void TestCameraActions::generatedClothOutOfViewIsFramed()
{
    // the camera close in on the origin; a cloth 9 m off to the side
    ui::Camera &camera = viewport().camera();
    camera.setTarget(QVector3D(0.0f, 0.5f, 0.0f));
    camera.setDistance(2.0f);
    const QVector3D far(9.0f, 1.0f, 0.0f);
    QVERIFY(!camera.sphereInView(far, 0.1f));
    const std::size_t before = m_window->document()->scene().particles.size();

    const std::vector<int> added = generateCloth(8, 8, far);
    QCOMPARE(added.size(), std::size_t(64));
    QCOMPARE(m_window->document()->scene().particles.size(), before + 64);
    QVERIFY(viewport().particlesInView(added));
    // with the rest of the scene
    std::vector<int> all(m_window->document()->scene().particles.size());
    std::iota(all.begin(), all.end(), 0);
    QVERIFY(viewport().particlesInView(all));
}

void TestCameraActions::smallGeneratedContentInViewKeepsTheCamera()
{
    // a 2 × 2 cloth at the camera's target is in view already: the camera does not move
    const ui::Camera &camera = viewport().camera();
    const QVector3D target = camera.target();
    const float distance = camera.distance();
    const std::vector<int> added = generateCloth(2, 2, target);
    QCOMPARE(added.size(), std::size_t(4));
    QVERIFY(viewport().particlesInView(added));
    QCOMPARE(camera.target(), target);
    QCOMPARE(camera.distance(), distance);
}

void TestCameraActions::gridOnlyOnFloors()
{
    // two particles, no planes: no grid at all, from above. A grid is hundreds of grey pixels
    // (over 500 below); a sphere's shaded rim can give one or two of that grey, depending on
    // the view's size, so "none" is under 20
    constexpr std::size_t kNoGrid = 20;
    core::SceneDesc scene = markers();
    scene.particles.resize(2);
    scene.particles[0].position = {-1.0, 0.5, 0.0};
    QVERIFY(show(scene));
    press(Qt::Key_7, Qt::ControlModifier);
    QCOMPARE_LT(gridPixels().size(), kNoGrid);

    // a wall is not a floor
    core::PlaneDesc wall;
    wall.normal = {1.0, 0.0, 0.0};
    wall.offset = -3.0;
    scene.planes.push_back(wall);
    QVERIFY(show(scene));
    press(Qt::Key_7, Qt::ControlModifier);
    QCOMPARE_LT(gridPixels().size(), kNoGrid);

    // a floor at y = -0.4: the grid, and seen edge on from the front, a line at its height
    core::PlaneDesc floor;
    floor.offset = -0.4;
    scene.planes.push_back(floor);
    QVERIFY(show(scene));
    press(Qt::Key_7, Qt::ControlModifier);
    QCOMPARE_GT(gridPixels().size(), std::size_t(500));
    press(Qt::Key_1, Qt::ControlModifier);
    press(Qt::Key_5, Qt::ControlModifier);  // orthographic: the floor edge on is one row
    const std::vector<QPoint> edgeOn = gridPixels();
    QCOMPARE_GT(edgeOn.size(), std::size_t(100));
    const double scale = viewport().grabFramebuffer().width() / double(viewport().width());
    const double row = pixelOf(QVector3D(0.0f, -0.4f, 0.0f)).y() * scale;
    for (const QPoint &p : edgeOn)
        QVERIFY2(std::abs(p.y() - row) < 2.0 * scale + 1.0, qPrintable(QStringLiteral("grid at row %1, floor at %2").arg(p.y()).arg(row)));
    press(Qt::Key_5, Qt::ControlModifier);
}

void TestCameraActions::f1ListsTheCameraKeys()
{
    const std::optional<QStringList> entries = test::helpEntries(m_window);
    QVERIFY(entries);
    for (const char *expected : {"Ctrl+7\tView › Top View", "Ctrl+1\tView › Front View", "Ctrl+3\tView › Side View",
                                 "Ctrl+0\tView › Default View", "Ctrl+5\tView › Orthographic",
                                 "Shift+F\tView › Follow Selection", "Ground grid\tOn the scene's floors"}) {
        const QString prefix = QString::fromUtf8(expected);
        QVERIFY2(std::any_of(entries->begin(), entries->end(), [&](const QString &e) { return e.startsWith(prefix); }),
                 expected);
    }
}

QTEST_MAIN(TestCameraActions)
#include "test_camera_actions.moc"
