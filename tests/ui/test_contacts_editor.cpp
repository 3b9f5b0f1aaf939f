// The contact settings in the whole editor, with real events: a friction drag in the parameters
// dock reaches the worker's model (particle pairs and planes) and Ctrl+Z takes it back; the contact
// solver chosen in the dock is the one the worker steps with; a rectangle plane is drawn where it
// is, exactly its size, and the same plane made unbounded is drawn past those edges again.

#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "ui/panels/parameter_row.h"
#include "ui/panels/parameters_panel.h"
#include "ui/viewport/render_data.h"
#include "ui/viewport/viewport.h"

#include "core/model/parameters.h"

#include <QComboBox>
#include <QScrollArea>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QUndoStack>

#include "editor_fixture.h"

using test::settledFrame;

namespace {

// the centre of a slider's handle, where a user grabs it
QPoint handleCentre(const QSlider *slider)
{
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = slider->orientation();
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = slider->sliderPosition();
    option.sliderValue = slider->value();
    option.subControls = QStyle::SC_SliderHandle;
    return slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider).center();
}

// scrolls the dock's scroll area, if any, so that the widget is in view
void bringIntoView(QWidget *widget)
{
    for (QWidget *w = widget->parentWidget(); w; w = w->parentWidget())
        if (auto *area = qobject_cast<QScrollArea *>(w)) {
            area->ensureWidgetVisible(widget);
            return;
        }
}

// a wall z = 0 with a 2 m × 1 m rectangle of it centred on (0, 2, 0), its width along x, between two
// small pinned particles that make the scene wide enough to hold it, high above the grid and axes
core::SceneDesc rectangleScene()
{
    core::SceneDesc scene;
    scene.name = "rectangle";
    for (double x : {-1.5, 1.5}) {
        core::ParticleDesc p;
        p.position = {x, 2.0, 0.0};
        p.radius = 0.05;
        p.pinned = true;
        scene.particles.push_back(p);
    }
    core::PlaneDesc wall;
    wall.normal = {0.0, 0.0, 1.0};
    wall.offset = 0.0;
    wall.size = {2.0, 1.0};
    wall.centre = {0.0, 2.0, 0.0};
    wall.axis = {1.0, 0.0, 0.0};
    scene.planes.push_back(wall);
    return scene;
}

bool nearColour(const QColor &seen, const QColor &expected, int tolerance)
{
    return std::abs(seen.red() - expected.red()) <= tolerance &&
           std::abs(seen.green() - expected.green()) <= tolerance &&
           std::abs(seen.blue() - expected.blue()) <= tolerance;
}

}  // namespace

class TestContactsEditor : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void frictionDragReachesTheWorker();
    void contactSolverReachesTheWorker();
    void rectangleIsDrawnWhereItIs();

private:
    void press(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier) { QTest::keyClick(m_window, key, modifiers); }
    // what the view shows at a world point: "plane", "background" or the colour seen
    QString seenAt(const QImage &image, const QVector3D &world) const;
};

void TestContactsEditor::init()
{
    QVERIFY2(openEditor({.size = QSize(1100, 800)}), qPrintable(editorFailure()));
}

void TestContactsEditor::cleanup()
{
    closeEditor();
}

void TestContactsEditor::frictionDragReachesTheWorker()
{
    // a ball over a floor and a wall; their friction is the scene's, 0
    core::SceneDesc scene;
    scene.name = "floor";
    scene.particles.push_back(core::ParticleDesc{});
    scene.particles.back().position = {0.0, 0.5, 0.0};
    scene.planes.push_back(core::PlaneDesc{});
    scene.planes.push_back(core::PlaneDesc{});
    scene.planes.back().normal = {1.0, 0.0, 0.0};
    scene.planes.back().offset = -2.0;
    m_window->document()->replace(scene, QString());
    const auto start = settledFrame(controller());
    QVERIFY(start);
    QCOMPARE(start->model->friction, 0.0);
    QCOMPARE(start->model->colliders.size(), std::size_t(2));

    // the dock's friction slider dragged with the mouse to its right end
    ui::ParameterRow *row = m_window->parametersPanel()->row(QStringLiteral("friction"));
    QSlider *slider = row->slider();
    bringIntoView(slider);
    QTRY_VERIFY(slider->isVisible());
    const QPoint handle = handleCentre(slider);
    QTest::mousePress(slider, Qt::LeftButton, {}, handle);
    for (int x = handle.x(); x < slider->width(); x += 10)
        QTest::mouseMove(slider, QPoint(x, handle.y()));
    QTest::mouseRelease(slider, Qt::LeftButton, {}, QPoint(slider->width() - 1, handle.y()));
    const double top = core::parameterInfo(core::Parameter::Friction).sliderMaximum;
    QCOMPARE(m_window->document()->scene().settings.friction, top);
    QCOMPARE(m_window->document()->undoStack()->count(), 1);
    QCOMPARE(m_window->document()->undoStack()->undoText(), QStringLiteral("Set Friction to %1").arg(top));

    // the worker steps with it: particle pairs, the static coefficient following, and the floor
    const auto after = settledFrame(controller());
    QVERIFY(after);
    QCOMPARE(after->model->friction, top);
    QCOMPARE(after->model->staticFriction, top);
    for (const core::Collider &collider : after->model->colliders) {
        QCOMPARE(collider.friction, top);
        QCOMPARE(collider.staticFriction, top);
    }
    QVERIFY(m_window->isWindowModified());

    // Ctrl+Z takes it back there too
    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_window->document()->scene().settings.friction, 0.0);
    QCOMPARE(settledFrame(controller())->model->friction, 0.0);
    QCOMPARE(row->value(), 0.0);
}

void TestContactsEditor::contactSolverReachesTheWorker()
{
    QComboBox *box = m_window->parametersPanel()->contactSolverBox();
    bringIntoView(box);
    box->setFocus();
    QTest::keyClick(box, Qt::Key_Down);
    QVERIFY(m_window->document()->scene().settings.contactSolver == core::ContactSolver::Handout);
    QVERIFY(settledFrame(controller())->model->contactSolver == core::ContactSolver::Handout);
    press(Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(settledFrame(controller())->model->contactSolver == core::ContactSolver::Iterative);
    QCOMPARE(box->currentIndex(), 0);
}

QString TestContactsEditor::seenAt(const QImage &image, const QVector3D &world) const
{
    const ui::Viewport &viewport = *m_window->viewport();
    const std::optional<QPointF> pixel = viewport.camera().project(world);
    if (!pixel)
        return QStringLiteral("behind the eye");
    const double scale = double(image.width()) / viewport.width();
    const QColor seen = image.pixelColor(QPoint(int(pixel->x() * scale), int(pixel->y() * scale)));

    // the plane is translucent over the background
    const float a = ui::kPlaneAlpha;
    const QColor plane = QColor::fromRgbF(ui::kBackgroundColour[0] * (1 - a) + ui::kPlaneColour[0] * a,
                                          ui::kBackgroundColour[1] * (1 - a) + ui::kPlaneColour[1] * a,
                                          ui::kBackgroundColour[2] * (1 - a) + ui::kPlaneColour[2] * a);
    const QColor background = QColor::fromRgbF(ui::kBackgroundColour[0], ui::kBackgroundColour[1],
                                               ui::kBackgroundColour[2]);
    if (nearColour(seen, plane, 3))
        return QStringLiteral("plane");
    if (nearColour(seen, background, 2))
        return QStringLiteral("background");
    return seen.name();
}

void TestContactsEditor::rectangleIsDrawnWhereItIs()
{
    // the wall seen head on from 4 m, the grid and the axes well below the points looked at (no
    // line of sight through them meets either)
    m_window->document()->replace(rectangleScene(), QString());
    QVERIFY(settledFrame(controller()));
    ui::Viewport *viewport = m_window->viewport();
    QTRY_VERIFY(viewport->snapshot() == controller().frame()->snapshot);
    ui::Camera &camera = viewport->camera();
    camera.setTarget(QVector3D(0.0f, 2.0f, 0.0f));
    camera.setDistance(4.0f);
    camera.setAngles(0.0f, 0.0f);
    viewport->update();

    // 0.15 m inside each edge it is drawn, 0.15 m outside it is not
    const QVector3D inside[] = {{-0.85f, 2.0f, 0.0f}, {0.85f, 2.0f, 0.0f}, {0.0f, 1.65f, 0.0f},
                                {0.0f, 2.35f, 0.0f}, {0.4f, 2.2f, 0.0f}};
    const QVector3D outside[] = {{-1.15f, 2.0f, 0.0f}, {1.15f, 2.0f, 0.0f}, {0.0f, 1.35f, 0.0f},
                                 {0.0f, 2.65f, 0.0f}, {1.15f, 2.65f, 0.0f}};
    QImage image = viewport->grabFramebuffer();
    QVERIFY(!image.isNull());
    for (const QVector3D &p : inside)
        QVERIFY2(seenAt(image, p) == u"plane",
                 qPrintable(QStringLiteral("(%1, %2): %3").arg(p.x()).arg(p.y()).arg(seenAt(image, p))));
    for (const QVector3D &p : outside)
        QVERIFY2(seenAt(image, p) == u"background",
                 qPrintable(QStringLiteral("(%1, %2): %3").arg(p.x()).arg(p.y()).arg(seenAt(image, p))));

    // the same plane made whole again is drawn past those edges, as a square around the scene
    auto whole = std::make_shared<core::SceneDesc>(m_window->document()->scene());
    whole->planes[0].size = Eigen::Vector2d::Zero();
    m_window->document()->undoStack()->push(
        new ui::SceneCommand(*m_window->document(), QStringLiteral("Make plane 0 unbounded"), whole));
    QVERIFY(settledFrame(controller()));
    QTRY_VERIFY(viewport->snapshot() == controller().frame()->snapshot);
    image = viewport->grabFramebuffer();
    for (const QVector3D &p : outside)
        QVERIFY2(seenAt(image, p) == u"plane",
                 qPrintable(QStringLiteral("(%1, %2): %3").arg(p.x()).arg(p.y()).arg(seenAt(image, p))));
}

QTEST_MAIN(TestContactsEditor)
#include "test_contacts_editor.moc"
