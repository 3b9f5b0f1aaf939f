// The parameters panel with real widgets: its rows come from the parameter table, a slider move or
// a typed value edits the document (one undo step per drag), and a value out of range is refused
// with a message and never reaches the document. The integrator combo box lists every integrator;
// each choice is one undo step, the tolerance row is enabled for adaptive-rk45 only and the
// iterations row for xpbd only. In the contacts group, a friction drag is one undo step, the static
// friction row follows it until it is set (and can be made to follow again), and the contact solver
// is a choice like the integrator.

#include "ui/panels/parameter_row.h"
#include "ui/panels/parameters_panel.h"
#include "ui/document/scene_document.h"
#include "ui/panels/value_spin_box.h"

#include "core/model/generators.h"
#include "core/contacts/solver_names.h"

#include <QAbstractItemView>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QWheelEvent>
#include <QSignalSpy>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QUndoStack>
#include <QtTest>

namespace {

core::SceneDesc netScene()
{
    core::NetOptions options;
    options.rows = 3;
    options.cols = 3;
    options.stiffness = 4000.0;
    options.damping = 2.0;
    return core::makeNet(options);
}

// types text into a spin box as a user would, then presses Enter
void type(QAbstractSpinBox *spinBox, const QString &text)
{
    spinBox->setFocus();
    spinBox->selectAll();
    QTest::keyClicks(spinBox, text);
    QTest::keyClick(spinBox, Qt::Key_Return);
}

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

QString fromView(std::string_view text)
{
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

}  // namespace

class TestParametersPanel : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void rowsComeFromTheParameterTable();
    void showsTheDocumentsValues();
    void sliderMoveSetsEverySpring();
    void aDragIsOneUndoStep();
    void typedValueIsApplied();
    void outOfRangeValueIsRefused_data();
    void outOfRangeValueIsRefused();
    void collisionSwitchesEditTheSettings();
    void springsGroupSaysWhatItAppliesTo();
    void integratorBoxListsEveryIntegrator();
    void choosingAnIntegratorIsOneUndoStep();
    void toleranceRowIsForTheAdaptiveIntegratorOnly();
    void iterationsRowIsForXpbdOnly();
    void frictionRowsSayWhichCoefficient();
    void frictionDragIsOneUndoStep();
    void staticFrictionFollowsUntilSet();
    void contactSolverIsOneUndoStepPerChoice();
    void wheelChangesOnlyAFocusedControl();

private:
    ui::SceneDocument *m_document = nullptr;
    ui::ParametersPanel *m_panel = nullptr;
};

void TestParametersPanel::init()
{
    m_document = new ui::SceneDocument;
    m_document->replace(netScene(), QString());
    m_panel = new ui::ParametersPanel(*m_document);
    m_panel->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_panel));
}

void TestParametersPanel::cleanup()
{
    delete m_panel;
    delete m_document;
}

void TestParametersPanel::rowsComeFromTheParameterTable()
{
    // label, unit, tooltip and default all from the table
    const struct {
        const char *key;
        core::Parameter parameter;
        const char *suffix;
    } expected[] = {
        {"timeStep", core::Parameter::TimeStep, ""},   {"substeps", core::Parameter::Substeps, ""},
        {"gravity.x", core::Parameter::Gravity, " x"}, {"gravity.y", core::Parameter::Gravity, " y"},
        {"gravity.z", core::Parameter::Gravity, " z"}, {"viscosity", core::Parameter::Viscosity, ""},
        {"restitution", core::Parameter::Restitution, ""}, {"stiffness", core::Parameter::Stiffness, ""},
        {"damping", core::Parameter::Damping, ""},     {"tolerance", core::Parameter::Tolerance, ""},
        {"xpbdIterations", core::Parameter::XpbdIterations, ""},
        {"solverIterations", core::Parameter::SolverIterations, ""},
    };
    for (const auto &e : expected) {
        ui::ParameterRow *row = m_panel->row(QString::fromLatin1(e.key));
        QVERIFY2(row, e.key);
        const core::ParameterInfo &info = core::parameterInfo(e.parameter);
        QCOMPARE(row->label()->text(), fromView(info.label) + QString::fromLatin1(e.suffix));
        QCOMPARE(row->toolTip(), fromView(info.tooltip));
        QVERIFY(row->findChildren<QLabel *>().size() >= 1);
        bool unitShown = info.unit.empty();
        for (const QLabel *label : row->findChildren<QLabel *>())
            unitShown = unitShown || label->text() == fromView(info.unit);
        QVERIFY2(unitShown, e.key);
    }
    QVERIFY(m_panel->row(QStringLiteral("mass")) == nullptr);
}

void TestParametersPanel::showsTheDocumentsValues()
{
    QCOMPARE(m_panel->row("stiffness")->value(), 4000.0);
    QCOMPARE(m_panel->row("damping")->value(), 2.0);
    QCOMPARE(m_panel->row("gravity.y")->value(), -9.81);
    QCOMPARE(m_panel->row("gravity.y")->spinBox()->text(), QStringLiteral("-9.81"));
    QCOMPARE(m_panel->row("timeStep")->value(), m_document->scene().settings.timeStep);
    QVERIFY(m_panel->planeCollisionsBox()->isChecked() == m_document->scene().settings.planeCollisions);
}

void TestParametersPanel::sliderMoveSetsEverySpring()
{
    QSlider *slider = m_panel->row("stiffness")->slider();
    const ui::SliderScale scale = ui::sliderScale(core::parameterInfo(core::Parameter::Stiffness));
    slider->setValue(scale.positionOf(250.0));
    const double expected = scale.valueAt(slider->value());
    QVERIFY(std::abs(expected - 250.0) < 10.0);
    for (const core::SpringDesc &spring : m_document->scene().springs)
        QCOMPARE(spring.stiffness, expected);
    QCOMPARE(m_panel->row("stiffness")->spinBox()->value(), expected);
    QVERIFY(m_document->isModified());
}

void TestParametersPanel::aDragIsOneUndoStep()
{
    // the slider dragged with the mouse from its handle to the left end
    QSlider *slider = m_panel->row("gravity.y")->slider();
    const QPoint handle = handleCentre(slider);
    QTest::mousePress(slider, Qt::LeftButton, {}, handle);
    for (int x = handle.x(); x > 0; x -= 10)
        QTest::mouseMove(slider, QPoint(x, handle.y()));
    QTest::mouseRelease(slider, Qt::LeftButton, {}, QPoint(0, handle.y()));
    QCOMPARE(m_document->scene().settings.gravity.y(), -20.0);
    QCOMPARE(m_document->undoStack()->count(), 1);

    // undo gives the old value back everywhere
    m_document->undoStack()->undo();
    QCOMPARE(m_document->scene().settings.gravity.y(), -9.81);
    QCOMPARE(m_panel->row("gravity.y")->value(), -9.81);
    QVERIFY(!m_document->isModified());
}

void TestParametersPanel::typedValueIsApplied()
{
    type(m_panel->row("viscosity")->spinBox(), QStringLiteral("0.75"));
    QCOMPARE(m_document->scene().settings.viscosity, 0.75);
    type(m_panel->row("damping")->spinBox(), QStringLiteral("1e-3"));
    for (const core::SpringDesc &spring : m_document->scene().springs)
        QCOMPARE(spring.damping, 1e-3);
    QVERIFY(m_panel->message().isEmpty());
}

void TestParametersPanel::outOfRangeValueIsRefused_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("reason");
    QTest::newRow("stiffness too high") << "stiffness" << "5e9" << "must be at most";
    QTest::newRow("negative damping") << "damping" << "-1" << "must be at least";
    QTest::newRow("negative stiffness") << "stiffness" << "-5" << "must be at least";
    QTest::newRow("zero time step") << "timeStep" << "0" << "must be greater than";
    QTest::newRow("restitution above 1") << "restitution" << "1.5" << "must be at most";
    QTest::newRow("half a substep") << "substeps" << "2.5" << "whole number";
    QTest::newRow("friction above 10") << "friction" << "11" << "must be at most 10 (got 11)";
    QTest::newRow("negative static friction") << "staticFriction" << "-0.5" << "must be at least 0 (got -0.5)";
}

void TestParametersPanel::outOfRangeValueIsRefused()
{
    QFETCH(QString, key);
    QFETCH(QString, typed);
    QFETCH(QString, reason);
    const core::SceneDesc before = m_document->scene();
    ui::ParameterRow *row = m_panel->row(key);
    const double shown = row->value();
    QSignalSpy refused(m_panel, &ui::ParametersPanel::valueRefused);

    type(row->spinBox(), typed);

    // a message naming the parameter and the reason; nothing changed, nothing to undo
    QCOMPARE(refused.count(), 1);
    QVERIFY2(m_panel->message().contains(reason), qPrintable(m_panel->message()));
    QVERIFY2(m_panel->message().startsWith(row->label()->text()), qPrintable(m_panel->message()));
    QVERIFY(m_document->scene() == before);
    QCOMPARE(m_document->undoStack()->count(), 0);
    QCOMPARE(row->value(), shown);
    QCOMPARE(row->spinBox()->value(), shown);

    // the next accepted change clears the message
    row->slider()->setValue(row->slider()->value() < 500 ? 800 : 100);
    QVERIFY(m_panel->message().isEmpty());
}

void TestParametersPanel::collisionSwitchesEditTheSettings()
{
    const bool planes = m_document->scene().settings.planeCollisions;
    QTest::mouseClick(m_panel->planeCollisionsBox(), Qt::LeftButton, {},
                      QPoint(4, m_panel->planeCollisionsBox()->height() / 2));
    QCOMPARE(m_document->scene().settings.planeCollisions, !planes);
    m_panel->particleCollisionsBox()->click();
    QCOMPARE(m_document->scene().settings.particleCollisions, !netScene().settings.particleCollisions);

    // and they follow the document
    m_document->undoStack()->undo();
    QCOMPARE(m_panel->particleCollisionsBox()->isChecked(), m_document->scene().settings.particleCollisions);

    // spin: on by default, off and back by its box, one undo step each
    auto *spin = m_panel->findChild<QCheckBox *>(QStringLiteral("parameter-spin"));
    QVERIFY(spin);
    QVERIFY(spin->isChecked() && m_document->scene().settings.spin);
    spin->click();
    QVERIFY(!m_document->scene().settings.spin);
    m_document->undoStack()->undo();
    QVERIFY(m_document->scene().settings.spin && spin->isChecked());
    // rolling resistance and spinning friction are rows of the contacts group
    QVERIFY(m_panel->row(QStringLiteral("rollingFriction")));
    QVERIFY(m_panel->row(QStringLiteral("spinningFriction")));
}

void TestParametersPanel::springsGroupSaysWhatItAppliesTo()
{
    QVERIFY(m_panel->row("stiffness")->isEnabled());
    bool saysAll = false;
    for (const QLabel *label : m_panel->findChildren<QLabel *>())
        saysAll = saysAll || label->text().contains(QStringLiteral("all springs"));
    QVERIFY(saysAll);

    // no springs: nothing to tune
    core::SceneDesc lonely = netScene();
    lonely.springs.clear();
    m_document->replace(lonely, QString());
    QVERIFY(!m_panel->row("stiffness")->isEnabled());
}

void TestParametersPanel::integratorBoxListsEveryIntegrator()
{
    QComboBox *box = m_panel->integratorBox();
    QCOMPARE(box->count(), int(std::size(core::kIntegrators)));
    for (int i = 0; i < box->count(); ++i)
        QCOMPARE(box->itemText(i), fromView(core::integratorName(core::kIntegrators[i])));
    QCOMPARE(box->currentText(), fromView(core::integratorName(m_document->scene().settings.integrator)));
}

void TestParametersPanel::choosingAnIntegratorIsOneUndoStep()
{
    // the popup opened with a click, rk4 picked in it with the mouse
    QComboBox *box = m_panel->integratorBox();
    QTest::mouseClick(box, Qt::LeftButton);
    QAbstractItemView *list = box->view();
    QTRY_VERIFY(list->isVisible());
    // The item is hovered, then clicked once the hover has made it the current one: a move that
    // far from the click that opened the popup also ends the popup's guard against taking that
    // click's release for a choice. On a loaded machine the popup can still drop a click, so it
    // is repeated until the popup closes.
    const QModelIndex rk4 = list->model()->index(3, 0);
    const QPoint item = list->visualRect(rk4).center();
    for (int attempt = 0; attempt < 10; ++attempt) {
        QTest::mouseMove(list->viewport(), item);
        if (!QTest::qWaitFor([list, rk4] { return list->currentIndex() == rk4; }, 1000))
            continue;
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, item);
        if (QTest::qWaitFor([list] { return !list->isVisible(); }, 1000))
            break;
    }
    QTRY_VERIFY(!list->isVisible());
    QCOMPARE(m_document->scene().settings.integrator, core::Integrator::Rk4);
    QCOMPARE(m_document->undoStack()->count(), 1);

    // then the next one down from the keyboard: a second step of undo, not merged with the first
    box->setFocus();
    QTest::keyClick(box, Qt::Key_Down);
    QCOMPARE(m_document->scene().settings.integrator, core::Integrator::ImplicitEuler);
    QCOMPARE(m_document->undoStack()->count(), 2);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->scene().settings.integrator, core::Integrator::Rk4);
    QCOMPARE(box->currentText(), QStringLiteral("rk4"));
    m_document->undoStack()->undo();
    QCOMPARE(m_document->scene().settings.integrator, netScene().settings.integrator);
}

void TestParametersPanel::toleranceRowIsForTheAdaptiveIntegratorOnly()
{
    ui::ParameterRow *row = m_panel->row(QStringLiteral("tolerance"));
    QVERIFY(!row->isEnabled());
    QComboBox *box = m_panel->integratorBox();
    box->setFocus();
    // the last entries are xpbd, projective and vbd, which have no tolerance; before them the
    // adaptive one
    QTest::keyClick(box, Qt::Key_End);
    QCOMPARE(m_document->scene().settings.integrator, core::Integrator::Vbd);
    QCOMPARE(box->currentText(), QStringLiteral("vbd"));
    QVERIFY(!row->isEnabled());
    QTest::keyClick(box, Qt::Key_Up);
    QTest::keyClick(box, Qt::Key_Up);
    QCOMPARE(m_document->scene().settings.integrator, core::Integrator::Xpbd);
    QVERIFY(!row->isEnabled());
    QTest::keyClick(box, Qt::Key_Up);
    QCOMPARE(m_document->scene().settings.integrator, core::Integrator::AdaptiveRk45);
    QVERIFY(row->isEnabled());

    // typed in, and refused out of the table's range
    type(row->spinBox(), QStringLiteral("1e-8"));
    QCOMPARE(m_document->scene().settings.tolerance, 1e-8);
    type(row->spinBox(), QStringLiteral("5"));
    QVERIFY2(m_panel->message().contains(QStringLiteral("must be at most")), qPrintable(m_panel->message()));
    QCOMPARE(m_document->scene().settings.tolerance, 1e-8);

    QTest::keyClick(box, Qt::Key_Home);
    QVERIFY(!row->isEnabled());
}

void TestParametersPanel::iterationsRowIsForXpbdOnly()
{
    ui::ParameterRow *row = m_panel->row(QStringLiteral("xpbdIterations"));
    ui::ParameterRow *solver = m_panel->row(QStringLiteral("solverIterations"));
    QVERIFY(!row->isEnabled());
    QVERIFY(!solver->isEnabled());
    QComboBox *box = m_panel->integratorBox();
    box->setFocus();
    // vbd and projective (the last two) take the solver's iterations, xpbd its own
    QTest::keyClick(box, Qt::Key_End);
    QCOMPARE(m_document->scene().settings.integrator, core::Integrator::Vbd);
    QVERIFY(solver->isEnabled());
    QVERIFY(!row->isEnabled());
    type(solver->spinBox(), QStringLiteral("25"));
    QCOMPARE(m_document->scene().settings.solverIterations, 25);
    QTest::keyClick(box, Qt::Key_Up);
    QCOMPARE(m_document->scene().settings.integrator, core::Integrator::Projective);
    QVERIFY(solver->isEnabled());
    QTest::keyClick(box, Qt::Key_Up);
    QCOMPARE(m_document->scene().settings.integrator, core::Integrator::Xpbd);
    QVERIFY(row->isEnabled());
    QVERIFY(!solver->isEnabled());

    // a whole number, typed in, and refused out of the table's range
    type(row->spinBox(), QStringLiteral("4"));
    QCOMPARE(m_document->scene().settings.xpbdIterations, 4);
    type(row->spinBox(), QStringLiteral("500"));
    QVERIFY2(m_panel->message().contains(QStringLiteral("must be at most")), qPrintable(m_panel->message()));
    QCOMPARE(m_document->scene().settings.xpbdIterations, 4);

    QTest::keyClick(box, Qt::Key_Home);
    QVERIFY(!row->isEnabled());
}

void TestParametersPanel::frictionRowsSayWhichCoefficient()
{
    // both from the table's friction entry, each named and explained for its coefficient
    ui::ParameterRow *friction = m_panel->row(QStringLiteral("friction"));
    ui::ParameterRow *staticFriction = m_panel->row(QStringLiteral("staticFriction"));
    QVERIFY(friction && staticFriction);
    QVERIFY(friction->info().parameter == core::Parameter::Friction);
    QVERIFY(staticFriction->info().parameter == core::Parameter::Friction);
    QCOMPARE(friction->label()->text(), QStringLiteral("Friction"));
    QCOMPARE(staticFriction->label()->text(), QStringLiteral("Static friction"));
    QVERIFY2(friction->toolTip().contains(QStringLiteral("Kinetic")), qPrintable(friction->toolTip()));
    QVERIFY2(staticFriction->toolTip().contains(QStringLiteral("Static")), qPrintable(staticFriction->toolTip()));
    QVERIFY(!m_panel->staticFollowsBox()->toolTip().isEmpty());
    QVERIFY(!m_panel->contactSolverBox()->toolTip().isEmpty());

    // the scene's values: no friction, the static one following it
    QCOMPARE(friction->value(), 0.0);
    QCOMPARE(staticFriction->value(), 0.0);
    QVERIFY(m_panel->staticFollowsBox()->isChecked());
}

void TestParametersPanel::frictionDragIsOneUndoStep()
{
    // the friction slider dragged with the mouse from its handle to the right end: the slider's
    // end of the table's range
    ui::ParameterRow *friction = m_panel->row(QStringLiteral("friction"));
    QSlider *slider = friction->slider();
    const QPoint handle = handleCentre(slider);
    QTest::mousePress(slider, Qt::LeftButton, {}, handle);
    for (int x = handle.x(); x < slider->width(); x += 10)
        QTest::mouseMove(slider, QPoint(x, handle.y()));
    QTest::mouseRelease(slider, Qt::LeftButton, {}, QPoint(slider->width() - 1, handle.y()));
    const double top = core::parameterInfo(core::Parameter::Friction).sliderMaximum;
    QCOMPARE(m_document->scene().settings.friction, top);
    QCOMPARE(friction->spinBox()->value(), top);
    QCOMPARE(m_document->undoStack()->count(), 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Set Friction to %1").arg(top));

    // the static coefficient still follows: unset in the scene, friction's value in its row
    QVERIFY(!m_document->scene().settings.staticFriction);
    QCOMPARE(m_panel->row(QStringLiteral("staticFriction"))->value(), top);

    // undo gives the old value back everywhere
    m_document->undoStack()->undo();
    QCOMPARE(m_document->scene().settings.friction, 0.0);
    QCOMPARE(friction->value(), 0.0);
    QCOMPARE(slider->value(), 0);
    QCOMPARE(m_panel->row(QStringLiteral("staticFriction"))->value(), 0.0);
    QVERIFY(!m_document->isModified());
}

void TestParametersPanel::staticFrictionFollowsUntilSet()
{
    ui::ParameterRow *friction = m_panel->row(QStringLiteral("friction"));
    ui::ParameterRow *staticFriction = m_panel->row(QStringLiteral("staticFriction"));
    QCheckBox *follows = m_panel->staticFollowsBox();
    type(friction->spinBox(), QStringLiteral("0.4"));
    QCOMPARE(staticFriction->value(), 0.4);

    // typed: set apart, and no longer following friction
    type(staticFriction->spinBox(), QStringLiteral("0.7"));
    QCOMPARE(m_document->scene().settings.staticFriction, std::optional<double>(0.7));
    QCOMPARE(m_document->scene().settings.friction, 0.4);
    QVERIFY(!follows->isChecked());
    type(friction->spinBox(), QStringLiteral("0.3"));
    QCOMPARE(staticFriction->value(), 0.7);
    QCOMPARE(m_document->undoStack()->count(), 3);

    // checked again with a click: unset, showing friction's value; one undo step sets it back
    QTest::mouseClick(follows, Qt::LeftButton, {}, QPoint(4, follows->height() / 2));
    QVERIFY(!m_document->scene().settings.staticFriction);
    QCOMPARE(staticFriction->value(), 0.3);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Let static friction follow friction"));
    m_document->undoStack()->undo();
    QCOMPARE(m_document->scene().settings.staticFriction, std::optional<double>(0.7));
    QVERIFY(!follows->isChecked());
    QCOMPARE(staticFriction->value(), 0.7);

    // unchecked by hand: set to the value it showed, friction's
    m_document->undoStack()->undo();  // friction 0.3
    m_document->undoStack()->undo();  // static 0.7
    QVERIFY(follows->isChecked());
    QTest::mouseClick(follows, Qt::LeftButton, {}, QPoint(4, follows->height() / 2));
    QCOMPARE(m_document->scene().settings.staticFriction, std::optional<double>(0.4));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Set static friction apart"));
}

void TestParametersPanel::contactSolverIsOneUndoStepPerChoice()
{
    // the solvers in the core's order, by their names in the panel
    QComboBox *box = m_panel->contactSolverBox();
    QCOMPARE(box->count(), int(std::size(core::kContactSolvers)));
    QCOMPARE(box->itemText(0), QStringLiteral("Iterative"));
    QCOMPARE(box->itemText(1), QStringLiteral("Handout"));
    QCOMPARE(box->currentIndex(), 0);
    for (int i = 0; i < box->count(); ++i)
        QVERIFY(!box->itemData(i, Qt::ToolTipRole).toString().isEmpty());

    // chosen from the keyboard: one undo step each
    box->setFocus();
    QTest::keyClick(box, Qt::Key_Down);
    QVERIFY(m_document->scene().settings.contactSolver == core::ContactSolver::Handout);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Set contact solver to handout"));
    QTest::keyClick(box, Qt::Key_Up);
    QVERIFY(m_document->scene().settings.contactSolver == core::ContactSolver::Iterative);
    QCOMPARE(m_document->undoStack()->count(), 2);
    m_document->undoStack()->undo();
    QCOMPARE(box->currentText(), QStringLiteral("Handout"));
    m_document->undoStack()->undo();
    QCOMPARE(box->currentText(), QStringLiteral("Iterative"));
    QVERIFY(!m_document->isModified());
}

void TestParametersPanel::wheelChangesOnlyAFocusedControl()
{
    // two notches of the wheel over the slider and the box of gravity x: nothing changes while they
    // are not focused (the wheel is the dock's, to scroll); once focused, they take it
    ui::ParameterRow *row = m_panel->row("gravity.x");
    const double before = m_document->scene().settings.gravity.x();
    const int undoSteps = m_document->undoStack()->count();
    const auto wheel = [](QWidget *target) {
        const QPoint at = target->rect().center();
        for (int notch = 0; notch < 2; ++notch) {
            QWheelEvent event(at, target->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                              Qt::NoScrollPhase, false);
            QCoreApplication::sendEvent(target, &event);
        }
    };
    wheel(row->slider());
    wheel(row->spinBox());
    QCOMPARE(m_document->scene().settings.gravity.x(), before);
    QCOMPARE(m_document->undoStack()->count(), undoSteps);
    QVERIFY(!row->slider()->hasFocus() && !row->spinBox()->hasFocus());

    m_panel->activateWindow();  // focus needs an active window (with no window manager, asked for)
    QVERIFY(QTest::qWaitForWindowActive(m_panel));
    row->slider()->setFocus();
    QTRY_VERIFY(row->slider()->hasFocus());
    wheel(row->slider());
    QVERIFY(m_document->scene().settings.gravity.x() != before);
}

QTEST_MAIN(TestParametersPanel)
#include "test_parameters_panel.moc"

