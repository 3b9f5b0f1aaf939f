// Editing by mouse in the real main window, under a virtual X server: real mouse events on the
// viewport and real key presses pick the tools and act on the scene. Each test checks the
// document afterwards, and that undo gives back exactly the scene before and redo exactly the one
// after. Waits are on the worker's frames, never fixed sleeps.

#include "ui/viewport/edit_tools.h"
#include "core/model/generators.h"
#include "ui/panels/inspector_panel.h"
#include "ui/panels/status_text.h"
#include "ui/viewport/guide_line.h"
#include "ui/window/main_window.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include <QLabel>
#include <QStatusBar>
#include <QUndoStack>
#include <QWheelEvent>
#include <numbers>
#include <QtTest>

#include "editor_fixture.h"

namespace {

// a particle of radius r at p
core::ParticleDesc particle(const Eigen::Vector3d &p, double r = 0.1, bool pinned = false)
{
    core::ParticleDesc d;
    d.position = p;
    d.radius = r;
    d.pinned = pinned;
    return d;
}

// nothing moves unless the test moves it: no gravity, no planes, no contacts
core::SceneDesc stillScene()
{
    core::SceneDesc scene;
    scene.name = "still";
    scene.settings.gravity.setZero();
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    return scene;
}

QVector3D toQt(const Eigen::Vector3d &v)
{
    return {float(v.x()), float(v.y()), float(v.z())};
}

}  // namespace

class TestEditing : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void addToolPlacesAParticleUnderTheCursor();
    void addToolRestsOnTheSurfaceUnderTheCursor();
    void addToolSnapsToTheGrid();
    void pinToolPinsAndFrees();
    void springToolJoinsTwoParticlesAtTheirDistance();
    void springToolDragsARubberBandToTheNextParticle();
    void boxSelectSelectsExactlyTheParticlesInside();
    void clickAndShiftClickSelect();
    void hoverShowsWhatAClickWouldPick();
    void deleteRemovesParticlesAndTheirSprings();
    void clickBeforeThePictureCatchesUpPicksNothingGone();
    void copyPasteAndDuplicate();
    void nothingGrowsPastTheParticleLimit();
    void dragWhilePausedMovesTheSelectionAsOneStep();
    void selectingKeepsTheViewItsSize();
    void dragWhileRunningPullsTheParticleAndLetsGo();
    void wheelWhileDraggingSpinsTheParticle();
    void buildTheHandoutNetByMouse();
    void measureToolShowsTheDistanceAndFollowsTheRun();
    void measureToolDragsABandWithTheDistance();

private:
    ui::Viewport *viewport() { return m_window->viewport(); }
    ui::EditTools *tools() { return m_window->editTools(); }
    const core::SceneDesc &scene() { return m_window->document()->scene(); }
    QUndoStack *undo() { return m_window->document()->undoStack(); }

    // the viewport shows the document's scene as the worker has it now
    void settle()
    {
        const std::uint64_t sequence = controller().sync();
        QTRY_VERIFY(controller().frame() && controller().frame()->appliedMessage >= sequence);
        QTRY_VERIFY(viewport()->snapshot() == controller().frame()->snapshot);
    }
    // opens a scene and looks at it from a fixed camera: down on the origin from 6 m
    void open(const core::SceneDesc &s)
    {
        m_window->document()->replace(s, QString());
        settle();
        ui::Camera &camera = viewport()->camera();
        camera.setTarget(QVector3D(0.0f, 0.0f, 0.0f));
        camera.setDistance(6.0f);
        camera.setAngles(20.0f, 45.0f);
        viewport()->update();
    }
    QPoint pixelOf(const Eigen::Vector3d &p)
    {
        const auto pixel = viewport()->camera().project(toQt(p));
        return pixel ? pixel->toPoint() : QPoint(-1, -1);
    }
    void key(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QTest::keyClick(m_window, key, modifiers);
    }
    void click(const QPoint &pixel, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QTest::mouseClick(viewport(), Qt::LeftButton, modifiers, pixel);
    }
    // undo gives back `before`, redo `after`
    void checkUndoRedo(const core::SceneDesc &before, const core::SceneDesc &after)
    {
        undo()->undo();
        QVERIFY(scene() == before);
        undo()->redo();
        QVERIFY(scene() == after);
    }

};

void TestEditing::init()
{
    QVERIFY2(openEditor({.size = QSize(900, 700)}), qPrintable(editorFailure()));
    settle();
}

void TestEditing::cleanup()
{
    closeEditor();
}

void TestEditing::addToolPlacesAParticleUnderTheCursor()
{
    open(stillScene());
    const core::SceneDesc before = scene();
    key(Qt::Key_2);
    QCOMPARE(tools()->tool(), ui::Tool::AddParticle);

    // resting on the ground where the ray through the pixel meets it: the centre one radius up
    const QPoint pixel = viewport()->rect().center() + QPoint(60, 40);
    const ui::Ray ray = viewport()->camera().unproject(pixel);
    const float t = -ray.origin.y() / ray.direction.y();
    const QVector3D expected = ray.at(t) + QVector3D(0.0f, float(tools()->defaults().radius), 0.0f);
    click(pixel);
    QCOMPARE(scene().particles.size(), std::size_t(1));
    const Eigen::Vector3d placed = scene().particles[0].position;
    QVERIFY2((toQt(placed) - expected).length() < 1e-4f, qPrintable(QStringLiteral("%1 %2 %3").arg(placed.x()).arg(placed.y()).arg(placed.z())));
    QCOMPARE(placed.y(), tools()->defaults().radius);
    QCOMPARE(scene().particles[0].mass, tools()->defaults().mass);
    QCOMPARE(scene().particles[0].radius, tools()->defaults().radius);
    QCOMPARE(undo()->count(), 1);
    checkUndoRedo(before, core::SceneDesc(scene()));

    // it reaches the worker, which draws it where it was placed
    settle();
    QCOMPARE(viewport()->snapshot()->particleCount(), 1);
    const auto centre = viewport()->camera().project(toQt(placed));
    QVERIFY(centre);
    QCOMPARE(viewport()->particleAt(centre->toPoint()), 0);

    // a second click, with the first particle still selected, rests on the ground too (it used to
    // land on a plane through the selected particle facing the camera, under the floor)
    tools()->setSelection(ui::Selection{{0}, {}});
    click(viewport()->rect().center() + QPoint(-80, 60));
    QCOMPARE(scene().particles.size(), std::size_t(2));
    QCOMPARE(scene().particles[1].position.y(), tools()->defaults().radius);
}

void TestEditing::addToolRestsOnTheSurfaceUnderTheCursor()
{
    // a table (a rectangle 0.5 m up) over the floor: a click on the table rests the particle on
    // it, a click beside it on the floor
    core::SceneDesc s = stillScene();
    core::PlaneDesc floor;
    core::PlaneDesc table;
    table.offset = 0.5;
    table.size = {1.0, 1.0};
    s.planes = {floor, table};
    open(s);
    key(Qt::Key_2);
    const double r = tools()->defaults().radius;
    const auto pixelOf = [&](const Eigen::Vector3d &p) { return viewport()->camera().project(toQt(p))->toPoint(); };
    click(pixelOf({0.0, 0.5, 0.0}));
    QCOMPARE(scene().particles.size(), std::size_t(1));
    QVERIFY2(std::abs(scene().particles[0].position.y() - (0.5 + r)) < 1e-9,
             qPrintable(QString::number(scene().particles[0].position.y())));
    click(pixelOf({2.0, 0.0, 0.0}));
    QCOMPARE(scene().particles.size(), std::size_t(2));
    QVERIFY2(std::abs(scene().particles[1].position.y() - r) < 1e-9,
             qPrintable(QString::number(scene().particles[1].position.y())));
}

void TestEditing::addToolSnapsToTheGrid()
{
    open(stillScene());
    tools()->defaults().snap = true;
    tools()->defaults().gridStep = 0.5;
    key(Qt::Key_2);
    click(viewport()->rect().center() + QPoint(37, 23));
    QCOMPARE(scene().particles.size(), std::size_t(1));
    // on the grid along the ground, resting on it
    const Eigen::Vector3d p = scene().particles[0].position;
    for (int axis : {0, 2}) {
        const double steps = p[axis] / 0.5;
        QVERIFY2(std::abs(steps - std::round(steps)) < 1e-9, qPrintable(QString::number(p[axis])));
    }
    QCOMPARE(p.y(), tools()->defaults().radius);
}

void TestEditing::pinToolPinsAndFrees()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({0.0, 0.0, 0.0}), particle({1.0, 0.0, 0.0})};
    open(s);
    key(Qt::Key_3);
    click(pixelOf(s.particles[1].position));
    QVERIFY(scene().particles[1].pinned);
    QVERIFY(!scene().particles[0].pinned);
    const core::SceneDesc pinned = scene();
    checkUndoRedo(s, pinned);
    settle();
    QCOMPARE(viewport()->snapshot()->pinned[1], std::uint8_t(1));
    // again: freed
    click(pixelOf(s.particles[1].position));
    QVERIFY(!scene().particles[1].pinned);
    // P pins the selection
    tools()->setSelection(ui::Selection{{0, 1}, {}});
    key(Qt::Key_P);
    QVERIFY(scene().particles[0].pinned && scene().particles[1].pinned);
}

void TestEditing::springToolJoinsTwoParticlesAtTheirDistance()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({-1.0, 0.0, 0.0}), particle({1.0, 0.5, 0.3})};
    open(s);
    tools()->defaults().stiffness = 250.0;
    key(Qt::Key_4);
    click(pixelOf(s.particles[0].position));
    QCOMPARE(tools()->springStart(), 0);
    QVERIFY(scene().springs.empty());
    click(pixelOf(s.particles[1].position));
    QCOMPARE(scene().springs.size(), std::size_t(1));
    const core::SpringDesc spring = scene().springs[0];
    QCOMPARE(spring.a, 0);
    QCOMPARE(spring.b, 1);
    QCOMPARE(spring.restLength, (s.particles[0].position - s.particles[1].position).norm());
    QCOMPARE(spring.stiffness, 250.0);
    QCOMPARE(undo()->count(), 1);
    checkUndoRedo(s, core::SceneDesc(scene()));

    // the same pair again is refused, the scene unchanged
    click(pixelOf(s.particles[1].position));
    click(pixelOf(s.particles[0].position));
    QCOMPARE(scene().springs.size(), std::size_t(1));
}

void TestEditing::springToolDragsARubberBandToTheNextParticle()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({-1.0, 0.0, 0.0}), particle({1.0, 0.5, 0.3}), particle({0.0, 0.0, 1.0})};
    open(s);
    key(Qt::Key_4);
    const ui::GuideLine *band = tools()->springBand();
    QVERIFY(band && !band->isVisible());

    // pressed on particle 0 and dragged: a line from it to the cursor, ending on the centre of a
    // particle under the cursor
    const QPoint from = pixelOf(s.particles[0].position);
    const QPoint to = pixelOf(s.particles[1].position);
    const QPoint between = (from + to) / 2 + QPoint(0, 30);
    QTest::mousePress(viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(viewport(), between);
    QVERIFY(band->isVisible());
    QVERIFY((band->line().p1() - QPointF(from)).manhattanLength() < 2.0);
    QCOMPARE(band->line().p2(), QPointF(between));
    QTest::mouseMove(viewport(), to + QPoint(2, 1));
    QVERIFY((band->line().p2() - viewport()->camera().project(toQt(s.particles[1].position)).value()).manhattanLength() < 0.01);

    // released on particle 1: joined, and the band gone
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, to);
    QCOMPARE(scene().springs.size(), std::size_t(1));
    QCOMPARE(std::pair(scene().springs[0].a, scene().springs[0].b), std::pair(0, 1));
    QVERIFY(!band->isVisible());

    // a click on particle 2 shows the band while the mouse moves with no button held; a click on
    // empty space lets it go
    click(pixelOf(s.particles[2].position));
    QTest::mouseMove(viewport(), between);
    QVERIFY(band->isVisible());
    QCOMPARE(band->line().p2(), QPointF(between));
    click(pixelOf({0.0, 0.0, -2.5}));
    QCOMPARE(tools()->springStart(), -1);
    QVERIFY(!band->isVisible());
    QCOMPARE(scene().springs.size(), std::size_t(1));
}

void TestEditing::boxSelectSelectsExactlyTheParticlesInside()
{
    // a 4 × 4 grid on the ground, 0.5 m apart
    core::SceneDesc s = stillScene();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            s.particles.push_back(particle({-0.75 + 0.5 * i, 0.0, -0.75 + 0.5 * j}, 0.05));
    open(s);
    key(Qt::Key_1);

    // a box from the empty space left of particle 0 to between particles 5 and 10
    const QPoint from = pixelOf({-1.2, 0.0, -1.2});
    const QPoint to = pixelOf({0.0, 0.0, 0.0});
    const QRect box = QRect(from, to).normalized();
    std::vector<int> expected;
    for (int i = 0; i < int(s.particles.size()); ++i)
        if (box.contains(pixelOf(s.particles[std::size_t(i)].position)))
            expected.push_back(i);
    QVERIFY(!expected.empty() && expected.size() < s.particles.size());

    QTest::mousePress(viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(viewport(), (from + to) / 2);
    QTest::mouseMove(viewport(), to);
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, to);
    QCOMPARE(tools()->selection().particles, expected);
    QCOMPARE(viewport()->selection(), expected);
    QCOMPARE(undo()->count(), 0);  // selecting is not an edit

    // Esc clears it
    key(Qt::Key_Escape);
    QVERIFY(tools()->selection().empty());
}

void TestEditing::clickAndShiftClickSelect()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({-1.0, 0.0, 0.0}), particle({0.0, 0.0, 0.0}), particle({1.0, 0.0, 0.0})};
    s.springs = {{0, 1, 10.0, 0.0, 1.0}};
    open(s);
    key(Qt::Key_1);
    click(pixelOf(s.particles[0].position));
    QCOMPARE(tools()->selection().particles, std::vector<int>{0});
    click(pixelOf(s.particles[2].position), Qt::ControlModifier);
    QCOMPARE(tools()->selection().particles, (std::vector<int>{0, 2}));
    // a click on the spring's middle selects the spring alone
    click(pixelOf({-0.5, 0.0, 0.0}));
    QVERIFY(tools()->selection().particles.empty());
    QCOMPARE(tools()->selection().springs, std::vector<int>{0});
    // Ctrl+A: everything
    key(Qt::Key_A, Qt::ControlModifier);
    QCOMPARE(tools()->selection().particles, (std::vector<int>{0, 1, 2}));
    QCOMPARE(tools()->selection().springs, std::vector<int>{0});
    QVERIFY(scene() == s);
}

void TestEditing::hoverShowsWhatAClickWouldPick()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({0.0, 0.0, 0.0}), particle({1.0, 0.0, 0.0})};
    open(s);
    key(Qt::Key_1);
    QTest::mouseMove(viewport(), pixelOf(s.particles[1].position));
    QTRY_COMPARE(viewport()->hoveredParticle(), 1);
    QTest::mouseMove(viewport(), pixelOf({-2.0, 0.0, 2.0}));
    QTRY_COMPARE(viewport()->hoveredParticle(), -1);

    // a far, tiny particle can still be picked: within a few pixels of its centre
    core::SceneDesc tiny = stillScene();
    tiny.particles = {particle({0.0, 0.0, 0.0}, 1e-4)};
    open(tiny);
    QCOMPARE(viewport()->particleAt(pixelOf({0.0, 0.0, 0.0}) + QPoint(3, 2)), 0);
}

void TestEditing::deleteRemovesParticlesAndTheirSprings()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({-1.0, 0.0, 0.0}), particle({0.0, 0.0, 0.0}), particle({1.0, 0.0, 0.0})};
    s.springs = {{0, 1, 10.0, 0.0, 1.0}, {1, 2, 20.0, 0.0, 1.0}, {0, 2, 30.0, 0.0, 2.0}};
    open(s);
    key(Qt::Key_1);
    click(pixelOf(s.particles[1].position));
    key(Qt::Key_Delete);
    QCOMPARE(scene().particles.size(), std::size_t(2));
    QCOMPARE(scene().springs.size(), std::size_t(1));
    QCOMPARE(scene().springs[0].stiffness, 30.0);
    QCOMPARE(scene().springs[0].a, 0);
    QCOMPARE(scene().springs[0].b, 1);
    QVERIFY(tools()->selection().empty());
    checkUndoRedo(s, core::SceneDesc(scene()));
    settle();
    QCOMPARE(viewport()->snapshot()->particleCount(), 2);
    QCOMPARE(viewport()->snapshot()->springCount(), 1);
}

void TestEditing::clickBeforeThePictureCatchesUpPicksNothingGone()
{
    // found by the monkey: a click right after a delete, before the worker's next frame, picked
    // from the old picture an index past the end of the scene, and the Pin tool read past it
    core::SceneDesc s = stillScene();
    s.particles = {particle({-1.0, 0.0, 0.0}), particle({0.0, 0.0, 0.0}), particle({1.0, 0.0, 0.0})};
    s.springs = {{0, 1, 10.0, 0.0, 1.0}, {1, 2, 20.0, 0.0, 1.0}};
    open(s);
    key(Qt::Key_1);
    click(pixelOf(s.particles[2].position));
    key(Qt::Key_Delete);
    QCOMPARE(scene().particles.size(), std::size_t(2));
    // no events processed since: the picture still shows three particles and two springs
    QCOMPARE(viewport()->snapshot()->particleCount(), 3);
    QCOMPARE(viewport()->particleAt(pixelOf(s.particles[2].position)), 2);
    const int steps = undo()->count();
    key(Qt::Key_3);  // Pin
    click(pixelOf(s.particles[2].position));
    QCOMPARE(undo()->count(), steps);  // no edit made
    QCOMPARE(scene().particles.size(), std::size_t(2));
    QVERIFY(!scene().particles[0].pinned && !scene().particles[1].pinned);
    // Select, on the deleted particle's spring: nothing selected either
    key(Qt::Key_1);
    click(pixelOf(0.5 * (s.particles[1].position + s.particles[2].position)));
    QVERIFY(tools()->selection().empty());
    // once it has caught up, a click picks again
    settle();
    key(Qt::Key_3);
    click(pixelOf(s.particles[1].position));
    QVERIFY(scene().particles[1].pinned);
}

void TestEditing::copyPasteAndDuplicate()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({-0.5, 0.0, 0.0}), particle({0.5, 0.0, 0.0})};
    s.springs = {{0, 1, 10.0, 0.0, 1.0}};
    open(s);
    key(Qt::Key_A, Qt::ControlModifier);
    key(Qt::Key_C, Qt::ControlModifier);
    key(Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(scene().particles.size(), std::size_t(4));
    QCOMPARE(scene().springs.size(), std::size_t(2));
    QCOMPARE(scene().springs[1].a, 2);
    QCOMPARE(scene().springs[1].b, 3);
    // beside the original, not on it
    QVERIFY((scene().particles[2].position - scene().particles[0].position).norm() > 0.2);
    QCOMPARE(tools()->selection().particles, (std::vector<int>{2, 3}));
    const core::SceneDesc pasted = scene();

    // Ctrl+D duplicates the new selection, beside it
    key(Qt::Key_D, Qt::ControlModifier);
    QCOMPARE(scene().particles.size(), std::size_t(6));
    QCOMPARE(scene().springs.size(), std::size_t(3));
    QCOMPARE(tools()->selection().particles, (std::vector<int>{4, 5}));
    QVERIFY((scene().particles[4].position - scene().particles[2].position).norm() > 0.2);
    const core::SceneDesc duplicated = scene();
    undo()->undo();
    QVERIFY(scene() == pasted);
    checkUndoRedo(s, pasted);
    undo()->redo();
    QVERIFY(scene() == duplicated);

    // into another scene, a paste lands where it was copied
    open(stillScene());
    key(Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(scene().particles.size(), std::size_t(2));
    QCOMPARE(scene().springs.size(), std::size_t(1));
}

void TestEditing::nothingGrowsPastTheParticleLimit()
{
    // a scene at the editor's limit, in a plane below the view: duplicate, paste and add particle
    // are each refused with a message naming the limit, and leave the scene, the undo history, the
    // selection and the clipboard as they were
    core::SceneDesc s = stillScene();
    const int side = 500;
    for (int i = 0; i < int(ui::kMaxSceneParticles); ++i)
        s.particles.push_back(particle({0.01 * (i % side) - 2.5, -1.0, 0.01 * (i / side) - 2.5}, 0.004));
    open(s);
    const int commands = undo()->count();
    key(Qt::Key_A, Qt::ControlModifier);
    key(Qt::Key_C, Qt::ControlModifier);
    const ui::Selection all = tools()->selection();
    QCOMPARE(all.particles.size(), ui::kMaxSceneParticles);

    const QString limit = QString::number(ui::kMaxSceneParticles);
    key(Qt::Key_D, Qt::ControlModifier);
    QVERIFY2(m_window->statusWarning().startsWith(QStringLiteral("Not duplicated")), qPrintable(m_window->statusWarning()));
    QVERIFY2(m_window->statusWarning().contains(limit), qPrintable(m_window->statusWarning()));
    QVERIFY(scene() == s);
    QCOMPARE(undo()->count(), commands);
    QVERIFY(tools()->selection() == all);

    key(Qt::Key_V, Qt::ControlModifier);
    QVERIFY2(m_window->statusWarning().startsWith(QStringLiteral("Not pasted")), qPrintable(m_window->statusWarning()));
    QVERIFY(m_window->statusWarning().contains(limit));
    QVERIFY(scene() == s);
    QCOMPARE(undo()->count(), commands);

    key(Qt::Key_Escape);
    key(Qt::Key_2);
    QCOMPARE(tools()->tool(), ui::Tool::AddParticle);
    click(pixelOf({0.0, 0.0, 0.0}));
    QVERIFY2(m_window->statusWarning().startsWith(QStringLiteral("Not added")), qPrintable(m_window->statusWarning()));
    QVERIFY(m_window->statusWarning().contains(limit));
    QVERIFY(scene() == s);
    QCOMPARE(undo()->count(), commands);

    // one fewer, and the particle is added
    s.particles.pop_back();
    open(s);
    key(Qt::Key_2);
    click(pixelOf({0.0, 0.0, 0.0}));
    QCOMPARE(scene().particles.size(), ui::kMaxSceneParticles);
}

void TestEditing::dragWhilePausedMovesTheSelectionAsOneStep()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({0.0, 0.0, 0.0}), particle({0.5, 0.0, 0.0}), particle({-1.0, 0.0, 0.0})};
    open(s);
    tools()->setSelection(ui::Selection{{0, 1}, {}});
    key(Qt::Key_5);
    const QPoint start = pixelOf(s.particles[0].position);
    const QPoint end = start + QPoint(50, -30);
    QTest::mousePress(viewport(), Qt::LeftButton, {}, start);
    QTest::mouseMove(viewport(), start + QPoint(20, -10));
    QTest::mouseMove(viewport(), end);
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, end);

    // both moved by the same amount, in the plane facing the view; the third stayed
    const Eigen::Vector3d d0 = scene().particles[0].position - s.particles[0].position;
    const Eigen::Vector3d d1 = scene().particles[1].position - s.particles[1].position;
    QVERIFY(d0.norm() > 0.1);
    QVERIFY((d0 - d1).norm() < 1e-6);
    QVERIFY(scene().particles[2] == s.particles[2]);
    QVERIFY(std::abs(d0.dot(Eigen::Vector3d(double(viewport()->camera().forward().x()),
                                             double(viewport()->camera().forward().y()),
                                             double(viewport()->camera().forward().z())))) < 1e-4);
    // the particle is under the cursor where the drag ended
    settle();
    QCOMPARE(viewport()->particleAt(end), 0);
    QCOMPARE(undo()->count(), 1);
    checkUndoRedo(s, core::SceneDesc(scene()));
}

void TestEditing::selectingKeepsTheViewItsSize()
{
    // the inspector shows its particle, spring and distance groups as a selection calls for them;
    // the dock beside the view must not widen as they come (it narrowed the view by 27 pixels at the
    // first particle selected, mid-drag, and a drag's end no longer lay over the particle dragged)
    core::SceneDesc s = stillScene();
    s.particles = {particle({0.0, 0.0, 0.0}), particle({0.5, 0.0, 0.0})};
    s.springs = {core::SpringDesc{0, 1, 100.0, 0.0, 0.5}};
    open(s);
    const auto laidOut = [] {
        for (int round = 0; round < 8; ++round) {
            QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
            QCoreApplication::processEvents();
        }
    };
    laidOut();
    const QSize before = viewport()->size();
    for (const ui::Selection &selection : {ui::Selection{{0}, {}}, ui::Selection{{0, 1}, {}}, ui::Selection{{}, {0}},
                                           ui::Selection{{0, 1}, {0}}, ui::Selection{}}) {
        tools()->setSelection(selection);
        settle();
        laidOut();
        QCOMPARE(viewport()->size(), before);
    }
}

void TestEditing::dragWhileRunningPullsTheParticleAndLetsGo()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({0.0, 0.0, 0.0})};
    open(s);
    key(Qt::Key_5);
    key(Qt::Key_F4);
    QTRY_VERIFY(controller().isRunning());

    // hold the particle and move the cursor: the worker pulls it there
    const QPoint start = pixelOf(s.particles[0].position);
    const QPoint end = start + QPoint(80, 0);
    QTest::mousePress(viewport(), Qt::LeftButton, {}, start);
    QCOMPARE(tools()->grabbed(), 0);
    QTest::mouseMove(viewport(), start + QPoint(40, 0));
    QTest::mouseMove(viewport(), end);
    QTRY_COMPARE_WITH_TIMEOUT(viewport()->particleAt(end), 0, 10000);
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, end);
    QCOMPARE(tools()->grabbed(), -1);

    // the run moved it, not the scene: nothing to undo, the initial position unchanged
    QCOMPARE(undo()->count(), 0);
    QVERIFY(scene() == s);
    // let go, it coasts: nothing holds it at the cursor any more
    settle();
    const auto frame = controller().frame();
    QVERIFY(frame->snapshot->positions[0] > 0.1f);
}

void TestEditing::wheelWhileDraggingSpinsTheParticle()
{
    // a floor far below with friction: the scene can turn, so a spin given is kept
    core::SceneDesc s = stillScene();
    s.settings.planeCollisions = true;
    s.settings.friction = 0.5;
    s.planes = {core::floorPlane(-10.0)};
    s.particles = {particle({0.0, 0.0, 0.0})};
    open(s);
    key(Qt::Key_5);
    key(Qt::Key_F4);
    QTRY_VERIFY(controller().isRunning());
    const float scale = viewport()->camera().worldPerPixel();

    // hold it and turn the wheel two notches away: two turns a second about the line of sight,
    // counter-clockwise as the view shows it; one notch back leaves one
    const QPoint at = pixelOf(s.particles[0].position);
    QTest::mousePress(viewport(), Qt::LeftButton, {}, at);
    QCOMPARE(tools()->grabbed(), 0);
    const auto turnWheel = [&](int eighths) {
        QWheelEvent wheel(at, viewport()->mapToGlobal(at), QPoint(), QPoint(0, eighths), Qt::LeftButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(viewport(), &wheel);
    };
    turnWheel(2 * 120);
    QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("spun 2 turns/s counter-clockwise")),
             qPrintable(m_window->statusBar()->currentMessage()));
    turnWheel(-120);
    turnWheel(2 * 120);
    QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("spun 3 turns/s counter-clockwise")),
             qPrintable(m_window->statusBar()->currentMessage()));
    QCOMPARE(viewport()->camera().worldPerPixel(), scale);  // the wheel spun, it did not zoom
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, at);
    QCOMPARE(tools()->grabbed(), -1);
    settle();

    const auto frame = controller().frame();
    QCOMPARE(frame->snapshot->angularVelocities.size(), std::size_t(3));
    const Eigen::Vector3d spin(frame->snapshot->angularVelocities[0], frame->snapshot->angularVelocities[1],
                               frame->snapshot->angularVelocities[2]);
    const QVector3D back = -viewport()->camera().forward();
    const Eigen::Vector3d expected = 3.0 * 2.0 * std::numbers::pi * Eigen::Vector3d(back.x(), back.y(), back.z()).normalized();
    QVERIFY2((spin - expected).norm() < 1e-4 * expected.norm(),
             qPrintable(QStringLiteral("%1 %2 %3").arg(spin.x()).arg(spin.y()).arg(spin.z())));
    // the spin is the run's, not the scene's: nothing to undo
    QCOMPARE(undo()->count(), 0);

    // let go, the wheel zooms again
    QWheelEvent wheel(at, viewport()->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);
    QCOMPARE_LT(viewport()->camera().worldPerPixel(), scale);
}

void TestEditing::buildTheHandoutNetByMouse()
{
    // a 3 × 3 net from an empty scene: place, join, pin the top row, run, undo it all
    open(stillScene());
    const core::SceneDesc empty = scene();
    key(Qt::Key_2);
    std::vector<QPoint> pixels;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const QPoint pixel = pixelOf({-0.6 + 0.6 * j, 0.0, -0.6 + 0.6 * i});
            pixels.push_back(pixel);
            key(Qt::Key_Escape);  // nothing selected: each lands on the ground
                    click(pixel);
        }
    QCOMPARE(scene().particles.size(), std::size_t(9));
    settle();

    key(Qt::Key_4);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int n = 3 * i + j;
            if (j < 2) {
                click(pixels[std::size_t(n)]);
                click(pixels[std::size_t(n + 1)]);
            }
            if (i < 2) {
                click(pixels[std::size_t(n)]);
                click(pixels[std::size_t(n + 3)]);
            }
        }
    QCOMPARE(scene().springs.size(), std::size_t(12));
    // each at rest at the distance between its particles, which a click places to within a pixel
    for (const core::SpringDesc &spring : scene().springs) {
        const double distance =
            (scene().particles[std::size_t(spring.a)].position - scene().particles[std::size_t(spring.b)].position).norm();
        QVERIFY(std::abs(spring.restLength - distance) < 1e-9);
        QVERIFY(std::abs(spring.restLength - 0.6) < 0.03);
    }

    key(Qt::Key_3);
    for (int j = 0; j < 3; ++j)
        click(pixels[std::size_t(j)]);
    for (int j = 0; j < 3; ++j)
        QVERIFY(scene().particles[std::size_t(j)].pinned);

    // every step undoes, back to the empty scene
    QCOMPARE(undo()->count(), 9 + 12 + 3);
    while (undo()->canUndo())
        undo()->undo();
    QVERIFY(scene() == empty);
}

// the number a length label starts with: 2.5 of "2.5 m"
double labelled(const QString &label)
{
    return label.section(QLatin1Char(' '), 0, 0).toDouble();
}

// particle i's position in a snapshot
Eigen::Vector3d positionIn(const core::Snapshot &snapshot, int i)
{
    const float *p = snapshot.positions.data() + 3 * std::size_t(i);
    return {double(p[0]), double(p[1]), double(p[2])};
}

void TestEditing::measureToolShowsTheDistanceAndFollowsTheRun()
{
    // two particles still, a third drifting away from particle 0 along x at 0.5 m/s
    core::SceneDesc s = stillScene();
    s.particles = {particle({-1.0, 0.0, 0.0}), particle({1.0, 0.5, 0.3}), particle({0.5, 0.0, -1.0})};
    s.particles[2].velocity = {0.5, 0.0, 0.0};
    open(s);
    key(Qt::Key_6);
    QCOMPARE(tools()->tool(), ui::Tool::Measure);
    const ui::GuideLine *line = tools()->measureLine();
    QVERIFY(line && !line->isVisible());

    // a click on one particle, then on another
    click(pixelOf(s.particles[0].position));
    QCOMPARE(tools()->measureStart(), 0);
    QVERIFY(!tools()->measurement());
    click(pixelOf(s.particles[1].position));
    const auto measured = tools()->measurement();
    QVERIFY(measured);
    QCOMPARE(std::pair(measured->from, measured->to), std::pair(0, 1));
    const Eigen::Vector3d truth = s.particles[1].position - s.particles[0].position;
    QVERIFY2((measured->delta - truth).norm() < 1e-6, qPrintable(ui::distanceText(measured->delta)));

    // the view shows a line from one to the other labelled with the distance (to its 4 digits),
    // drawn
    QVERIFY(line->isVisible());
    QVERIFY((line->line().p1() - QPointF(pixelOf(s.particles[0].position))).manhattanLength() < 2.0);
    QVERIFY((line->line().p2() - QPointF(pixelOf(s.particles[1].position))).manhattanLength() < 2.0);
    QVERIFY2(std::abs(labelled(line->label()) - truth.norm()) < 5e-4 * truth.norm(), qPrintable(line->label()));
    QTRY_VERIFY(line->painted() && line->painted()->label == line->label());
    // the status bar says it with its parts; the pair is the selection, for the inspector
    const QString status = m_window->statusBar()->currentMessage();
    QVERIFY2(status.startsWith(QStringLiteral("Particles 0 → 1: %1 m (Δx 2, Δy 0.5, Δz 0.3)")
                                   .arg(QString::number(truth.norm(), 'g', 6))),
             qPrintable(status));
    QCOMPARE(tools()->selection().particles, (std::vector<int>{0, 1}));
    QCOMPARE(m_window->inspector()->distanceField(QStringLiteral("current"))->text(), ui::distanceLines(measured->delta));
    // measuring changes nothing in the scene
    QCOMPARE(undo()->count(), 0);

    // measure 0 to the drifting particle, then play: the label follows the run's positions
    click(pixelOf(s.particles[0].position));
    click(pixelOf(s.particles[2].position));
    const double start = tools()->measurement()->delta.norm();
    const int paints = line->paintCount();
    key(Qt::Key_F4);
    QTRY_VERIFY_WITH_TIMEOUT(viewport()->snapshot() && viewport()->snapshot()->time > 0.5, 20000);
    key(Qt::Key_F4);
    QTRY_VERIFY(!controller().isRunning());
    settle();
    const core::Snapshot &now = *viewport()->snapshot();
    const double distance = (positionIn(now, 2) - positionIn(now, 0)).norm();
    QVERIFY2(distance > start + 0.2, qPrintable(QStringLiteral("%1 %2").arg(distance).arg(start)));
    QVERIFY(std::abs(tools()->measurement()->delta.norm() - distance) < 1e-9);
    // drawn again with the run, at the distance of the frame shown
    QTRY_VERIFY2(line->paintCount() > paints && line->painted() &&
                     std::abs(labelled(line->painted()->label) - distance) < 5e-4 * distance,
                 qPrintable(line->painted() ? line->painted()->label : QStringLiteral("nothing painted")));
    QVERIFY((line->line().p2() - QPointF(pixelOf(positionIn(now, 2)))).manhattanLength() < 2.0);
    QCOMPARE(m_window->inspector()->distanceField(QStringLiteral("current"))->text(),
             ui::distanceLines(positionIn(now, 2) - positionIn(now, 0)));
    // the scene's initial positions are untouched
    QVERIFY(scene() == s);

    // another tool, or Escape, puts the measure away
    key(Qt::Key_1);
    QVERIFY(!line->isVisible());
    QVERIFY(!tools()->measurement());
    key(Qt::Key_6);
    click(pixelOf(s.particles[0].position));
    click(pixelOf(s.particles[1].position));
    QVERIFY(line->isVisible());
    key(Qt::Key_Escape);
    QVERIFY(!line->isVisible());
}

void TestEditing::measureToolDragsABandWithTheDistance()
{
    core::SceneDesc s = stillScene();
    s.particles = {particle({-1.0, 0.0, 0.0}), particle({1.0, 0.5, 0.3})};
    open(s);
    key(Qt::Key_6);
    const ui::GuideLine *band = tools()->springBand();

    // pressed on particle 0 and dragged: a band to the cursor without a label, then over particle
    // 1 a label with the distance to it
    const QPoint from = pixelOf(s.particles[0].position);
    const QPoint to = pixelOf(s.particles[1].position);
    QTest::mousePress(viewport(), Qt::LeftButton, {}, from);
    QTest::mouseMove(viewport(), (from + to) / 2 + QPoint(0, 30));
    QVERIFY(band->isVisible());
    QVERIFY(band->label().isEmpty());
    QTest::mouseMove(viewport(), to + QPoint(1, 1));
    const double truth = (s.particles[1].position - s.particles[0].position).norm();
    QVERIFY2(std::abs(labelled(band->label()) - truth) < 5e-4 * truth, qPrintable(band->label()));

    // released there: measured, the band gone, the line shown
    QTest::mouseRelease(viewport(), Qt::LeftButton, {}, to);
    QVERIFY(!band->isVisible());
    QVERIFY(tools()->measurement());
    QCOMPARE(tools()->measurement()->to, 1);
    QVERIFY(tools()->measureLine()->isVisible());

    // a particle removed by undoing its addition can no longer be measured: the line goes
    key(Qt::Key_2);
    key(Qt::Key_Escape);
    click(viewport()->rect().center() + QPoint(-150, 100));
    QCOMPARE(scene().particles.size(), std::size_t(3));
    settle();
    key(Qt::Key_6);
    click(pixelOf(s.particles[0].position));
    click(pixelOf(scene().particles[2].position));
    QVERIFY(tools()->measurement());
    QCOMPARE(tools()->measurement()->to, 2);
    undo()->undo();
    QVERIFY(!tools()->measurement());
    QVERIFY(!tools()->measureLine()->isVisible());

    // deleting a particle renumbers those after it: the measure of 0 to 1 goes with particle 0
    click(pixelOf(s.particles[0].position));
    click(pixelOf(s.particles[1].position));
    QVERIFY(tools()->measurement());
    tools()->setSelection(ui::Selection{{0}, {}});
    key(Qt::Key_Delete);
    QCOMPARE(scene().particles.size(), std::size_t(1));
    QVERIFY(!tools()->measurement());
    QVERIFY(!tools()->measureLine()->isVisible());
}

QTEST_MAIN(TestEditing)
#include "test_editing.moc"
