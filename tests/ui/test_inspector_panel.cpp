// The inspector with real widgets and real key presses: it shows the selection's values (mixed
// where they differ), a typed value edits every selected item as one undo step, arrow steps on one
// field merge into one step, a bad value is refused with a message and leaves the scene and the
// undo stack alone, planes are added, edited and removed (two-sided, with friction of their own or
// the scene's, as rectangles with a centre and an axis, each change one named undo step), and undo
// shows in the fields at once.

#include "ui/viewport/edit_tools.h"
#include "ui/panels/inspector_field.h"
#include "ui/panels/inspector_panel.h"
#include "ui/panels/inspector_planes.h"
#include "ui/panels/status_text.h"
#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include <QCheckBox>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QUndoStack>
#include <QFormLayout>
#include <QtTest>

#include "editor_test_setup.h"

#include <cmath>
#include <limits>

namespace {

// three particles (the last one pinned), two springs, the ground
core::SceneDesc smallScene()
{
    core::SceneDesc scene;
    scene.name = "inspector";
    core::ParticleDesc p;
    p.position = {0.0, 1.0, 0.0};
    p.mass = 1.0;
    scene.particles.push_back(p);
    p.position = {1.0, 1.0, 0.0};
    p.velocity = {0.5, 0.0, 0.0};
    p.mass = 2.0;
    scene.particles.push_back(p);
    p.position = {0.0, 2.0, 0.0};
    p.velocity = {0.0, 0.0, 0.0};
    p.pinned = true;
    scene.particles.push_back(p);
    scene.springs.push_back({0, 1, 100.0, 0.5, 1.0});
    scene.springs.push_back({0, 2, 200.0, 0.5, 1.0});
    scene.planes.push_back(core::PlaneDesc{});
    return scene;
}

// types text into a spin box as a user would, then presses Enter
void type(QAbstractSpinBox *spinBox, const QString &text)
{
    spinBox->setFocus();
    spinBox->selectAll();
    QTest::keyClicks(spinBox, text);
    QTest::keyClick(spinBox, Qt::Key_Return);
}

// what the user sees in a field
QString shown(QAbstractSpinBox *spinBox)
{
    return spinBox->findChild<QLineEdit *>()->text();
}

}  // namespace

class TestInspectorPanel : public QObject {
    Q_OBJECT

public:
    // the viewport the tools need is a QOpenGLWidget: OpenGL settings before the QApplication exists
    static void initMain() { test::prepareOpenGL(); }

private slots:
    void init();
    void cleanup();

    void nothingSelectedShowsThePlanesOnly();
    void titleSaysWhatIsSelected();
    void showsOneParticlesValues();
    void typedMassIsOneUndoStep();
    void severalParticlesShowMixedAndEditTogether();
    void enterOnAMixedFieldChangesNothing();
    void pinnedIsTriState();
    void pinnedParticlesStayAtRest();
    void spinIsEditedPinnedOrFree();
    void springFieldsEditTheSelectedSpringsOnly();
    void labelsGiveUnitsOnlyWhereThereAreSome();
    void badValueIsRefused_data();
    void badValueIsRefused();
    void arrowStepsMergeIntoOneUndoStep();
    void positionTooltipSaysInitialConditions();
    void planesAreAddedEditedAndRemoved();
    void zeroNormalIsRefused();
    void normalIsMadeUnitLength();
    void planeIsMadeTwoSided();
    void planeFrictionIsItsOwnOrTheScenes();
    void sizeMakesARectangleWithCentreAndAxis();
    void badPlaneValueIsRefused_data();
    void badPlaneValueIsRefused();
    void fieldsFollowUndoAndOtherEdits();
    void twoParticlesShowTheirDistance();

private:
    ui::InspectorSpinBox *field(const char *key) const { return m_panel->particleField(QLatin1String(key)); }
    int commands() const { return m_document->undoStack()->count(); }
    void select(std::vector<int> particles, std::vector<int> springs = {})
    {
        m_tools->setSelection({std::move(particles), std::move(springs)});
    }

    ui::SceneDocument *m_document = nullptr;
    ui::Viewport *m_viewport = nullptr;
    ui::SimulationController *m_controller = nullptr;
    ui::EditTools *m_tools = nullptr;
    ui::InspectorPanel *m_panel = nullptr;
};

void TestInspectorPanel::init()
{
    // the tools work on a viewport that is never shown: the inspector needs no OpenGL
    m_document = new ui::SceneDocument;
    m_document->replace(smallScene(), QString());
    m_viewport = new ui::Viewport;
    m_controller = new ui::SimulationController;
    m_tools = new ui::EditTools(m_viewport, m_document, m_controller);
    m_panel = new ui::InspectorPanel(m_document, m_tools);
    m_panel->show();
    m_panel->activateWindow();
    QVERIFY(QTest::qWaitForWindowExposed(m_panel));
}

void TestInspectorPanel::cleanup()
{
    delete m_panel;
    delete m_tools;
    delete m_controller;
    delete m_viewport;
    delete m_document;
}

void TestInspectorPanel::nothingSelectedShowsThePlanesOnly()
{
    QCOMPARE(m_panel->titleLabel()->text(), QStringLiteral("Nothing selected"));
    QVERIFY(m_panel->particlesGroup()->isHidden());
    QVERIFY(m_panel->springsGroup()->isHidden());
    QVERIFY(m_panel->planes()->isVisible());
    QCOMPARE(m_panel->planes()->list()->count(), 1);
    QCOMPARE(m_panel->planes()->currentPlane(), 0);
}

void TestInspectorPanel::titleSaysWhatIsSelected()
{
    select({0, 2}, {1});
    QCOMPARE(m_panel->titleLabel()->text(), QStringLiteral("2 particles, 1 spring"));
    QVERIFY(m_panel->particlesGroup()->isVisible());
    QVERIFY(m_panel->springsGroup()->isVisible());
    select({}, {0, 1});
    QCOMPARE(m_panel->titleLabel()->text(), QStringLiteral("2 springs"));
    QVERIFY(m_panel->particlesGroup()->isHidden());
    select({1});
    QCOMPARE(m_panel->titleLabel()->text(), QStringLiteral("1 particle"));
}

void TestInspectorPanel::showsOneParticlesValues()
{
    select({1});
    QCOMPARE(field("mass")->value(), 2.0);
    QCOMPARE(shown(field("mass")), QStringLiteral("2"));
    QVERIFY(!field("mass")->isMixed());
    QCOMPARE(field("radius")->value(), 0.1);
    QCOMPARE(field("position.x")->value(), 1.0);
    QCOMPARE(field("position.y")->value(), 1.0);
    QCOMPARE(field("velocity.x")->value(), 0.5);
    QCOMPARE(m_panel->pinnedBox()->checkState(), Qt::Unchecked);
    select({2});
    QCOMPARE(field("position.y")->value(), 2.0);
    QCOMPARE(m_panel->pinnedBox()->checkState(), Qt::Checked);
}

void TestInspectorPanel::typedMassIsOneUndoStep()
{
    select({0});
    const core::SceneDesc before = m_document->scene();
    const int count = commands();
    type(field("mass"), QStringLiteral("3.5"));
    QCOMPARE(m_document->scene().particles[0].mass, 3.5);
    QCOMPARE(commands(), count + 1);
    // nothing else changed
    core::SceneDesc expected = before;
    expected.particles[0].mass = 3.5;
    QVERIFY(m_document->scene() == expected);

    m_document->undoStack()->undo();
    QVERIFY(m_document->scene() == before);
    QCOMPARE(shown(field("mass")), QStringLiteral("1"));
}

void TestInspectorPanel::severalParticlesShowMixedAndEditTogether()
{
    select({0, 1});
    QVERIFY(field("mass")->isMixed());
    QCOMPARE(shown(field("mass")), QString());
    QCOMPARE(field("mass")->findChild<QLineEdit *>()->placeholderText(), QStringLiteral("mixed"));
    QVERIFY(!field("radius")->isMixed());  // both 0.1
    QCOMPARE(shown(field("radius")), QStringLiteral("0.1"));
    QVERIFY(field("position.x")->isMixed());
    QVERIFY(!field("position.y")->isMixed());

    const core::SceneDesc before = m_document->scene();
    const int count = commands();
    type(field("mass"), QStringLiteral("4"));
    QCOMPARE(m_document->scene().particles[0].mass, 4.0);
    QCOMPARE(m_document->scene().particles[1].mass, 4.0);
    QCOMPARE(m_document->scene().particles[2].mass, 2.0);  // not selected
    QCOMPARE(commands(), count + 1);
    QVERIFY(!field("mass")->isMixed());
    QCOMPARE(shown(field("mass")), QStringLiteral("4"));

    m_document->undoStack()->undo();
    QVERIFY(m_document->scene() == before);
    QVERIFY(field("mass")->isMixed());
}

void TestInspectorPanel::enterOnAMixedFieldChangesNothing()
{
    select({0, 1});
    const core::SceneDesc before = m_document->scene();
    const int count = commands();
    QTest::keyClick(field("mass"), Qt::Key_Return);
    // an emptied field is no value either
    type(field("position.x"), QString());
    QVERIFY(m_document->scene() == before);
    QCOMPARE(commands(), count);
    QVERIFY(field("mass")->isMixed());
    QVERIFY(field("position.x")->isMixed());
    QCOMPARE(shown(field("mass")), QString());
}

void TestInspectorPanel::pinnedIsTriState()
{
    // particle 1 is free, particle 2 pinned
    select({1, 2});
    QCheckBox *pinned = m_panel->pinnedBox();
    QCOMPARE(pinned->checkState(), Qt::PartiallyChecked);

    const core::SceneDesc before = m_document->scene();
    const int count = commands();
    QTest::mouseClick(pinned, Qt::LeftButton, {}, QPoint(5, pinned->height() / 2));
    QVERIFY(m_document->scene().particles[1].pinned);
    QVERIFY(m_document->scene().particles[2].pinned);
    QCOMPARE(m_document->scene().particles[1].velocity, Eigen::Vector3d::Zero().eval());  // pinned: at rest
    QVERIFY(!m_document->scene().particles[0].pinned);
    QCOMPARE(commands(), count + 1);
    QCOMPARE(pinned->checkState(), Qt::Checked);

    // a second click frees both
    QTest::mouseClick(pinned, Qt::LeftButton, {}, QPoint(5, pinned->height() / 2));
    QVERIFY(!m_document->scene().particles[1].pinned);
    QVERIFY(!m_document->scene().particles[2].pinned);
    QCOMPARE(pinned->checkState(), Qt::Unchecked);
    QCOMPARE(commands(), count + 2);

    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QVERIFY(m_document->scene() == before);
    QCOMPARE(pinned->checkState(), Qt::PartiallyChecked);
}

void TestInspectorPanel::pinnedParticlesStayAtRest()
{
    // only pinned particles: their velocity is not for editing
    select({2});
    QVERIFY(!field("velocity.x")->isEnabled());
    QVERIFY(field("position.x")->isEnabled());

    // with a free one too, a velocity reaches the free one only
    select({1, 2});
    QVERIFY(field("velocity.x")->isEnabled());
    const int count = commands();
    type(field("velocity.x"), QStringLiteral("3"));
    QCOMPARE(m_document->scene().particles[1].velocity.x(), 3.0);
    QCOMPARE(m_document->scene().particles[2].velocity.x(), 0.0);
    QCOMPARE(commands(), count + 1);
}

void TestInspectorPanel::spinIsEditedPinnedOrFree()
{
    // ω: a free particle's and a pinned one's alike (a pinned ball turns in place, a wheel), one undo
    // step, and the file's value afterwards
    select({1, 2});
    QVERIFY(field("spin.z")->isEnabled());
    const int count = commands();
    type(field("spin.z"), QStringLiteral("-40"));
    QCOMPARE(m_document->scene().particles[1].angularVelocity, Eigen::Vector3d(0.0, 0.0, -40.0));
    QCOMPARE(m_document->scene().particles[2].angularVelocity, Eigen::Vector3d(0.0, 0.0, -40.0));
    QCOMPARE(commands(), count + 1);
    QCOMPARE(field("spin.z")->value(), -40.0);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->scene().particles[1].angularVelocity, Eigen::Vector3d::Zero().eval());
    // a spin beyond the state's bound is refused, as a speed is
    type(field("spin.x"), QStringLiteral("2e9"));
    QCOMPARE(m_document->scene().particles[1].angularVelocity, Eigen::Vector3d::Zero().eval());
}

void TestInspectorPanel::labelsGiveUnitsOnlyWhereThereAreSome()
{
    // "Stiffness (N/m)", but "Breaking strain", not "Breaking strain ()"
    select({}, {1});
    const auto labelOf = [&](const QString &key) {
        QWidget *field = m_panel->springField(key);
        auto *form = qobject_cast<QFormLayout *>(field->parentWidget()->layout());
        return qobject_cast<QLabel *>(form->labelForField(field))->text();
    };
    QCOMPARE(labelOf(QStringLiteral("stiffness")), QStringLiteral("Stiffness (N/m)"));
    QCOMPARE(labelOf(QStringLiteral("breakStrain")), QStringLiteral("Breaking strain"));
    QVERIFY(!m_panel->springField(QStringLiteral("breakStrain"))->toolTip().contains(QStringLiteral("()")));
}

void TestInspectorPanel::springFieldsEditTheSelectedSpringsOnly()
{
    select({}, {1});
    ui::InspectorSpinBox *stiffness = m_panel->springField(QStringLiteral("stiffness"));
    QCOMPARE(stiffness->value(), 200.0);
    QCOMPARE(m_panel->springField(QStringLiteral("restLength"))->value(), 1.0);
    QCOMPARE(m_panel->springEndsLabel()->text(), QStringLiteral("particles 0 and 2"));

    const core::SceneDesc before = m_document->scene();
    const int count = commands();
    type(stiffness, QStringLiteral("250"));
    QCOMPARE(m_document->scene().springs[1].stiffness, 250.0);
    QCOMPARE(m_document->scene().springs[0].stiffness, 100.0);
    QCOMPARE(commands(), count + 1);

    // both springs: stiffness differs (mixed), damping is shared
    select({}, {0, 1});
    QVERIFY(stiffness->isMixed());
    QVERIFY(!m_panel->springField(QStringLiteral("damping"))->isMixed());
    type(m_panel->springField(QStringLiteral("restLength")), QStringLiteral("1.5"));
    QCOMPARE(m_document->scene().springs[0].restLength, 1.5);
    QCOMPARE(m_document->scene().springs[1].restLength, 1.5);
    QCOMPARE(commands(), count + 2);

    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QVERIFY(m_document->scene() == before);
}

void TestInspectorPanel::badValueIsRefused_data()
{
    QTest::addColumn<bool>("spring");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("named");   // how the message starts
    QTest::addColumn<QString>("reason");  // what it says is wrong

    QTest::newRow("mass 0") << false << "mass" << "0" << "Mass" << "greater than 0";
    QTest::newRow("mass -2") << false << "mass" << "-2" << "Mass" << "greater than 0";
    QTest::newRow("radius -1") << false << "radius" << "-1" << "Radius" << "greater than 0";
    QTest::newRow("mass NaN") << false << "mass" << "nan" << "Mass" << "NaN";
    QTest::newRow("radius inf") << false << "radius" << "inf" << "Radius" << "finite";
    QTest::newRow("velocity NaN") << false << "velocity.y" << "NaN" << "Velocity y" << "NaN";
    QTest::newRow("position huge") << false << "position.z" << "1e12" << "Position z" << "at most";
    QTest::newRow("stiffness -5") << true << "stiffness" << "-5" << "Stiffness" << "at least 0";
    QTest::newRow("damping -1") << true << "damping" << "-1" << "Damping" << "at least 0";
    QTest::newRow("rest length -1") << true << "restLength" << "-1" << "Rest length" << "at least 0";
}

void TestInspectorPanel::badValueIsRefused()
{
    QFETCH(bool, spring);
    QFETCH(QString, key);
    QFETCH(QString, text);
    QFETCH(QString, named);
    QFETCH(QString, reason);

    select({0, 1}, {0});
    ui::InspectorSpinBox *box = spring ? m_panel->springField(key) : m_panel->particleField(key);
    QVERIFY(box);
    const QString before = shown(box);
    const core::SceneDesc scene = m_document->scene();
    const int count = commands();
    QSignalSpy refused(m_panel, &ui::InspectorPanel::valueRefused);

    type(box, text);
    QVERIFY(m_document->scene() == scene);
    QCOMPARE(commands(), count);
    QCOMPARE(refused.count(), 1);
    const QString message = refused.first().first().toString();
    QVERIFY2(message.startsWith(named + QLatin1Char(' ')), qPrintable(message));
    QVERIFY2(message.contains(reason), qPrintable(message));
    QCOMPARE(m_panel->message(), message);
    // the field shows the scene's value again
    QCOMPARE(shown(box), before);

    // the next accepted edit clears the message
    type(field("radius"), QStringLiteral("0.2"));
    QCOMPARE(m_panel->message(), QString());
    QCOMPARE(commands(), count + 1);
}

void TestInspectorPanel::arrowStepsMergeIntoOneUndoStep()
{
    select({0});
    const core::SceneDesc before = m_document->scene();
    const int count = commands();
    ui::InspectorSpinBox *radius = field("radius");
    radius->setFocus();
    QTest::keyClick(radius, Qt::Key_Up);
    const double once = m_document->scene().particles[0].radius;
    QVERIFY(once > 0.1);
    QTest::keyClick(radius, Qt::Key_Up);
    QTest::keyClick(radius, Qt::Key_Up);
    QVERIFY(m_document->scene().particles[0].radius > once);
    QCOMPARE(commands(), count + 1);
    QCOMPARE(radius->value(), m_document->scene().particles[0].radius);

    // leaving the field ends the sequence: the next step is an undo step of its own
    QFocusEvent out(QEvent::FocusOut, Qt::TabFocusReason);
    QCoreApplication::sendEvent(radius, &out);
    QTest::keyClick(radius, Qt::Key_Down);
    QCOMPARE(commands(), count + 2);

    // steps on another field are another undo step
    QTest::keyClick(field("position.x"), Qt::Key_Up);
    QCOMPARE(commands(), count + 3);
    QVERIFY(m_document->scene().particles[0].position.x() > 0.0);

    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QVERIFY(m_document->scene() == before);
}

void TestInspectorPanel::positionTooltipSaysInitialConditions()
{
    QVERIFY(field("position.x")->toolTip().contains(QStringLiteral("initial conditions")));
    QVERIFY(field("velocity.z")->toolTip().contains(QStringLiteral("initial conditions")));
}

void TestInspectorPanel::planesAreAddedEditedAndRemoved()
{
    ui::InspectorPlanes *planes = m_panel->planes();
    const core::SceneDesc before = m_document->scene();
    const int count = commands();

    // add: a ground plane, chosen at once
    QTest::mouseClick(planes->addButton(), Qt::LeftButton);
    QCOMPARE(m_document->scene().planes.size(), std::size_t(2));
    QVERIFY(m_document->scene().planes[1] == core::PlaneDesc{});
    QCOMPARE(m_document->scene().planes[1].normal, Eigen::Vector3d(0.0, 1.0, 0.0));
    QCOMPARE(m_document->scene().planes[1].offset, 0.0);
    QCOMPARE(commands(), count + 1);
    QCOMPARE(planes->list()->count(), 2);
    QCOMPARE(planes->currentPlane(), 1);

    // edit its offset
    type(planes->offsetField(), QStringLiteral("-2"));
    QCOMPARE(m_document->scene().planes[1].offset, -2.0);
    QCOMPARE(m_document->scene().planes[0].offset, 0.0);
    QCOMPARE(commands(), count + 2);
    QVERIFY(planes->list()->item(1)->text().contains(QStringLiteral("-2")));

    // remove the first one: the edited one is left
    planes->setCurrentPlane(0);
    QTest::mouseClick(planes->removeButton(), Qt::LeftButton);
    QCOMPARE(m_document->scene().planes.size(), std::size_t(1));
    QCOMPARE(m_document->scene().planes[0].offset, -2.0);
    QCOMPARE(commands(), count + 3);
    QCOMPARE(planes->list()->count(), 1);
    QCOMPARE(planes->offsetField()->value(), -2.0);

    // each undo steps back exactly
    m_document->undoStack()->undo();
    QCOMPARE(m_document->scene().planes.size(), std::size_t(2));
    QCOMPARE(planes->list()->count(), 2);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->scene().planes[1].offset, 0.0);
    m_document->undoStack()->undo();
    QVERIFY(m_document->scene() == before);
    QCOMPARE(planes->list()->count(), 1);

    // removing the last plane leaves nothing to edit
    planes->setCurrentPlane(0);
    QTest::mouseClick(planes->removeButton(), Qt::LeftButton);
    QVERIFY(m_document->scene().planes.empty());
    QCOMPARE(planes->currentPlane(), -1);
    QVERIFY(!planes->removeButton()->isEnabled());
    QVERIFY(!planes->offsetField()->isEnabled());
}

void TestInspectorPanel::zeroNormalIsRefused()
{
    ui::InspectorPlanes *planes = m_panel->planes();
    QCOMPARE(planes->currentPlane(), 0);
    const core::SceneDesc before = m_document->scene();
    const int count = commands();
    QSignalSpy refused(m_panel, &ui::InspectorPanel::valueRefused);

    // (0, 1, 0) with y = 0 has no direction
    type(planes->normalField(1), QStringLiteral("0"));
    QVERIFY(m_document->scene() == before);
    QCOMPARE(commands(), count);
    QCOMPARE(refused.count(), 1);
    const QString message = refused.first().first().toString();
    QVERIFY2(message.startsWith(QStringLiteral("Plane normal")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("zero")), qPrintable(message));
    QCOMPARE(planes->normalField(1)->value(), 1.0);
}

void TestInspectorPanel::normalIsMadeUnitLength()
{
    ui::InspectorPlanes *planes = m_panel->planes();
    const int count = commands();
    type(planes->normalField(0), QStringLiteral("1"));
    const Eigen::Vector3d normal = m_document->scene().planes[0].normal;
    QCOMPARE(normal.norm(), 1.0);
    QVERIFY(std::abs(normal.x() - std::sqrt(0.5)) < 1e-15);
    QVERIFY(std::abs(normal.y() - std::sqrt(0.5)) < 1e-15);
    QCOMPARE(normal.z(), 0.0);
    QCOMPARE(commands(), count + 1);
    QCOMPARE(planes->normalField(0)->value(), normal.x());
}

void TestInspectorPanel::planeIsMadeTwoSided()
{
    ui::InspectorPlanes *planes = m_panel->planes();
    QCheckBox *box = planes->twoSidedBox();
    QVERIFY(box->isEnabled());
    QVERIFY(!box->isChecked());
    const int count = commands();

    // a click: two-sided, one named undo step, said in the list too
    QTest::mouseClick(box, Qt::LeftButton, {}, QPoint(4, box->height() / 2));
    QVERIFY(m_document->scene().planes[0].twoSided);
    QCOMPARE(commands(), count + 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Make plane 0 two-sided"));
    QVERIFY(planes->list()->item(0)->text().contains(QStringLiteral("two-sided")));
    QTest::mouseClick(box, Qt::LeftButton, {}, QPoint(4, box->height() / 2));
    QVERIFY(!m_document->scene().planes[0].twoSided);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Make plane 0 one-sided"));

    // undo shows in the box
    m_document->undoStack()->undo();
    QVERIFY(box->isChecked());
    m_document->undoStack()->undo();
    QVERIFY(!box->isChecked());
    QCOMPARE(commands(), count + 2);
}

void TestInspectorPanel::planeFrictionIsItsOwnOrTheScenes()
{
    ui::InspectorPlanes *planes = m_panel->planes();
    QCheckBox *own = planes->ownFrictionBox();
    ui::InspectorSpinBox *friction = planes->frictionField();

    // the scene's friction, shown greyed; it follows the settings
    auto scene = std::make_shared<core::SceneDesc>(m_document->scene());
    scene->settings.friction = 0.25;
    m_document->undoStack()->push(new ui::SceneCommand(*m_document, QStringLiteral("settings"), scene));
    QVERIFY(!own->isChecked());
    QVERIFY(!friction->isEnabled());
    QCOMPARE(friction->value(), 0.25);
    const int count = commands();

    // its own: starts from the scene's, then typed
    QTest::mouseClick(own, Qt::LeftButton, {}, QPoint(4, own->height() / 2));
    QCOMPARE(m_document->scene().planes[0].friction, std::optional<double>(0.25));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Give plane 0 its own friction"));
    QVERIFY(friction->isEnabled());
    type(friction, QStringLiteral("0.6"));
    QCOMPARE(m_document->scene().planes[0].friction, std::optional<double>(0.6));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Set plane 0 friction to 0.6"));
    QVERIFY(planes->list()->item(0)->text().contains(QStringLiteral("μ 0.6")));
    QCOMPARE(m_document->scene().settings.friction, 0.25);

    // arrow steps merge into one undo step
    friction->setFocus();
    QTest::keyClick(friction, Qt::Key_Up);
    QTest::keyClick(friction, Qt::Key_Up);
    const double stepped = *m_document->scene().planes[0].friction;
    QVERIFY(stepped > 0.6);
    QCOMPARE(commands(), count + 3);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Set plane 0 friction to %1").arg(stepped, 0, 'g', 6));

    // back to the scene's: unset, and the field shows the scene's again
    QTest::mouseClick(own, Qt::LeftButton, {}, QPoint(4, own->height() / 2));
    QVERIFY(!m_document->scene().planes[0].friction);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Let plane 0 take the scene's friction"));
    QVERIFY(!friction->isEnabled());
    QCOMPARE(friction->value(), 0.25);
    QCOMPARE(commands(), count + 4);

    // each undo steps back
    m_document->undoStack()->undo();
    QVERIFY(own->isChecked());
    m_document->undoStack()->undo();
    QCOMPARE(friction->value(), 0.6);
    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QVERIFY(!own->isChecked());
    QVERIFY(!m_document->scene().planes[0].friction);
}

void TestInspectorPanel::sizeMakesARectangleWithCentreAndAxis()
{
    ui::InspectorPlanes *planes = m_panel->planes();
    const core::SceneDesc before = m_document->scene();
    const int count = commands();

    // an unbounded plane: no centre, no axis to edit
    QVERIFY(planes->sizeField(0)->isVisible());
    QVERIFY(!planes->centreField(0)->isVisible());
    QVERIFY(!planes->axisField(2)->isVisible());

    // a width on the whole plane makes a square of it, which shows its centre and axis
    type(planes->sizeField(0), QStringLiteral("2"));
    QCOMPARE(m_document->scene().planes[0].size, Eigen::Vector2d(2.0, 2.0));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Make plane 0 a 2 × 2 m rectangle"));
    QCOMPARE(planes->sizeField(1)->value(), 2.0);
    QVERIFY(planes->centreField(0)->isVisible());
    QVERIFY(planes->axisField(2)->isVisible());
    QVERIFY(planes->list()->item(0)->text().contains(QStringLiteral("2 × 2 m rectangle")));

    // a rectangle is two-sided, whatever its flag says
    QVERIFY(planes->twoSidedBox()->isChecked());
    QVERIFY(!planes->twoSidedBox()->isEnabled());
    QVERIFY(!m_document->scene().planes[0].twoSided);

    // each side, the centre and the axis on their own
    type(planes->sizeField(1), QStringLiteral("0.5"));
    QCOMPARE(m_document->scene().planes[0].size, Eigen::Vector2d(2.0, 0.5));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Set plane 0 height to 0.5 m"));
    type(planes->centreField(0), QStringLiteral("1.5"));
    QCOMPARE(m_document->scene().planes[0].centre, Eigen::Vector3d(1.5, 0.0, 0.0));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Set plane 0 centre x to 1.5"));
    type(planes->axisField(2), QStringLiteral("1"));
    QCOMPARE(m_document->scene().planes[0].axis, Eigen::Vector3d(0.0, 0.0, 1.0));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Set plane 0 axis z to 1"));
    QCOMPARE(commands(), count + 4);

    // a zero side makes the whole plane again; centre and axis stay in the scene, out of sight
    type(planes->sizeField(0), QStringLiteral("0"));
    QCOMPARE(m_document->scene().planes[0].size, Eigen::Vector2d(0.0, 0.0));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Make plane 0 unbounded"));
    QVERIFY(!planes->centreField(0)->isVisible());
    QVERIFY(planes->twoSidedBox()->isEnabled());
    QVERIFY(!planes->twoSidedBox()->isChecked());
    QCOMPARE(m_document->scene().planes[0].centre, Eigen::Vector3d(1.5, 0.0, 0.0));

    // undo all the way: the rectangle comes back, then the plane as it was
    m_document->undoStack()->undo();
    QCOMPARE(planes->sizeField(0)->value(), 2.0);
    QCOMPARE(planes->sizeField(1)->value(), 0.5);
    QCOMPARE(planes->axisField(2)->value(), 1.0);
    QVERIFY(planes->centreField(0)->isVisible());
    while (m_document->undoStack()->index() > count)
        m_document->undoStack()->undo();
    QVERIFY(m_document->scene() == before);
    QVERIFY(!planes->centreField(0)->isVisible());
}

void TestInspectorPanel::badPlaneValueIsRefused_data()
{
    // field: "friction", "width", "height", "centre.y", "axis.x"; each on a rectangle with its own friction
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("message");
    QTest::newRow("friction above 10") << "friction" << "12" << "Plane friction must be at most 10 (got 12)";
    QTest::newRow("negative friction") << "friction" << "-1" << "Plane friction must be at least 0 (got -1)";
    QTest::newRow("friction nan") << "friction" << "nan" << "Plane friction is not a number";
    QTest::newRow("negative width") << "width" << "-1" << "Plane width must be at least 0 m (got -1 m)";
    QTest::newRow("height past 1e6") << "height" << "2e6" << "Plane height must be at most 1e+06 m";
    QTest::newRow("centre far away") << "centre.y" << "2e9" << "Plane centre y must be at most";
    QTest::newRow("axis infinite") << "axis.x" << "inf" << "Plane axis x must be finite";
}

void TestInspectorPanel::badPlaneValueIsRefused()
{
    QFETCH(QString, field);
    QFETCH(QString, typed);
    QFETCH(QString, message);

    // plane 0 a rectangle with friction of its own, so that every field is there to type in
    auto scene = std::make_shared<core::SceneDesc>(m_document->scene());
    scene->planes[0].size = {1.0, 1.0};
    scene->planes[0].friction = 0.5;
    m_document->undoStack()->push(new ui::SceneCommand(*m_document, QStringLiteral("rectangle"), scene));
    ui::InspectorPlanes *planes = m_panel->planes();
    ui::InspectorSpinBox *box = field == u"friction"   ? planes->frictionField()
                                : field == u"width"    ? planes->sizeField(0)
                                : field == u"height"   ? planes->sizeField(1)
                                : field == u"centre.y" ? planes->centreField(1)
                                                       : planes->axisField(0);
    QVERIFY(box->isEnabled() && box->isVisible());
    const core::SceneDesc before = m_document->scene();
    const int count = commands();
    QSignalSpy refused(m_panel, &ui::InspectorPanel::valueRefused);

    // refused with a message naming the field; the scene, the undo stack and the field as they were
    type(box, typed);
    QCOMPARE(refused.count(), 1);
    const QString said = refused.first().first().toString();
    QVERIFY2(said.startsWith(message) && said.endsWith(QStringLiteral("; not applied")), qPrintable(said));
    QVERIFY(m_document->scene() == before);
    QCOMPARE(commands(), count);
}

void TestInspectorPanel::fieldsFollowUndoAndOtherEdits()
{
    select({0});
    type(field("mass"), QStringLiteral("5"));
    QCOMPARE(m_document->scene().particles[0].mass, 5.0);

    // another tool's edit shows without the inspector pushing anything
    auto edited = std::make_shared<core::SceneDesc>(m_document->scene());
    edited->particles[0].mass = 7.0;
    edited->particles[0].position.z() = -3.0;
    m_document->undoStack()->push(new ui::SceneCommand(*m_document, QStringLiteral("other tool"), edited));
    const int count = commands();
    QCOMPARE(field("mass")->value(), 7.0);
    QCOMPARE(shown(field("mass")), QStringLiteral("7"));
    QCOMPARE(field("position.z")->value(), -3.0);

    // undo and redo show at once, and push nothing
    m_document->undoStack()->undo();
    QCOMPARE(shown(field("mass")), QStringLiteral("5"));
    QCOMPARE(field("position.z")->value(), 0.0);
    m_document->undoStack()->undo();
    QCOMPARE(shown(field("mass")), QStringLiteral("1"));
    m_document->undoStack()->redo();
    QCOMPARE(shown(field("mass")), QStringLiteral("5"));
    QCOMPARE(commands(), count);
    QCOMPARE(m_document->undoStack()->index(), count - 1);

    // a new scene: nothing of the old selection is kept (its indices mean nothing there), and the
    // inspector follows
    core::SceneDesc one;
    one.particles.push_back(core::ParticleDesc{});
    m_document->replace(one, QString());
    QCOMPARE(m_panel->titleLabel()->text(), QStringLiteral("Nothing selected"));
    QCOMPARE(m_panel->planes()->list()->count(), 0);
    QCOMPARE(commands(), 0);
    select({0});
    QCOMPARE(m_panel->titleLabel()->text(), QStringLiteral("1 particle"));
    QCOMPARE(field("mass")->value(), 1.0);
}

void TestInspectorPanel::twoParticlesShowTheirDistance()
{
    // one particle, three, or a spring: no distance
    select({0});
    QVERIFY(m_panel->distanceGroup()->isHidden());
    select({0, 1, 2});
    QVERIFY(m_panel->distanceGroup()->isHidden());
    select({}, {0});
    QVERIFY(m_panel->distanceGroup()->isHidden());

    // two: from the lower index to the higher, initially; the run's value once a snapshot has them
    select({2, 0});
    QVERIFY(m_panel->distanceGroup()->isVisible());
    QCOMPARE(m_panel->distanceGroup()->title(), QStringLiteral("Distance from particle 0 to 2"));
    QCOMPARE(m_panel->distanceField(QStringLiteral("initial"))->text(), QStringLiteral("1 m\n(Δx 0, Δy 1, Δz 0)"));
    QCOMPARE(m_panel->distanceField(QStringLiteral("current"))->text(), QStringLiteral("—"));
    auto snapshot = std::make_shared<core::Snapshot>();
    snapshot->positions = {0.0f, 1.0f, 0.0f, 1.0f, 1.0f, 0.0f, 3.0f, 5.0f, 0.0f};
    snapshot->radii = {0.1f, 0.1f, 0.1f};
    snapshot->velocities.assign(9, 0.0f);
    m_panel->showSnapshot(snapshot);
    QCOMPARE(m_panel->distanceField(QStringLiteral("current"))->text(), QStringLiteral("5 m\n(Δx 3, Δy 4, Δz 0)"));
    QCOMPARE(m_panel->distanceField(QStringLiteral("current"))->text(), ui::distanceLines({3.0, 4.0, 0.0}));

    // an edit of an initial position shows at once
    m_document->modify([](core::SceneDesc &scene) { scene.particles[2].position = {0.0, 1.0, -2.0}; },
                       ui::SceneChange::InitialConditions);
    QCOMPARE(m_panel->distanceField(QStringLiteral("initial"))->text(), QStringLiteral("2 m\n(Δx 0, Δy 0, Δz -2)"));
}

QTEST_MAIN(TestInspectorPanel)
#include "test_inspector_panel.moc"
