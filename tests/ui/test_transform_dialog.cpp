// Edit › Transform Selection… in the real editor: Ctrl+T opens the dialog; values typed into its
// fields move, rotate and scale the selected particles about their centroid as one undo step named
// after what it did, which reaches the worker; undo gives back exactly the scene before, redo
// exactly the one after. A value that cannot be used is named and changes nothing; the dialog
// follows the selection while it is open.

#include "ui/dialogs/transform_dialog.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/edit_tools.h"
#include "ui/window/main_window.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QStatusBar>
#include <QUndoStack>
#include <QtTest>

#include "editor_fixture.h"
#include "help_entries.h"

namespace {

// nothing moves unless the test moves it: an L of four moving particles (particle 2 pinned)
// joined in a chain, and particle 4 apart, joined to particle 3
core::SceneDesc bent()
{
    core::SceneDesc scene;
    scene.name = "bent";
    scene.settings.gravity.setZero();
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    const Eigen::Vector3d at[] = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {2.0, 0.5, 0.0}, {2.0, 1.5, -1.0}, {5.0, 2.0, 1.0}};
    for (int i = 0; i < 5; ++i) {
        core::ParticleDesc p;
        p.position = at[i];
        p.velocity = {0.5, 0.0, 0.0};
        p.radius = 0.05;
        scene.particles.push_back(p);
    }
    scene.particles[2].pinned = true;
    scene.particles[2].velocity.setZero();
    for (int i = 0; i < 4; ++i)
        scene.springs.push_back({i, i + 1, 100.0, 0.5, 0.9 + 0.1 * i});
    return scene;
}

double distance(const core::SceneDesc &scene, int i, int j)
{
    return (scene.particles[std::size_t(i)].position - scene.particles[std::size_t(j)].position).norm();
}

}  // namespace

class TestTransformDialog : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void movesRotatesAndScalesAsOneUndoStep();
    void perAxisScaleAboutATypedAxis();
    void badInputIsNamedAndChangesNothing_data();
    void badInputIsNamedAndChangesNothing();
    void followsTheSelectionWhileOpen();
    void okAppliesAndClosesCloseDoesNot();
    void f1ListsTheDialogAndTheMeasureTool();

private:
    const core::SceneDesc &scene() { return m_window->document()->scene(); }
    QUndoStack *undo() { return m_window->document()->undoStack(); }
    ui::EditTools *tools() { return m_window->editTools(); }

    // Ctrl+T, as a user would press it; the dialog, shown and active
    ui::TransformDialog *open()
    {
        if (!test::showActive(*m_window))
            return nullptr;
        QTest::keyClick(m_window, Qt::Key_T, Qt::ControlModifier);
        ui::TransformDialog *dialog = m_window->transformDialog();
        return dialog && test::showActive(*dialog) ? dialog : nullptr;
    }
    template <class Widget>
    Widget *field(ui::TransformDialog *dialog, const char *name)
    {
        return dialog->findChild<Widget *>(QString::fromLatin1(name));
    }
    // types text into a field and presses Return, as a user would
    void type(ui::TransformDialog *dialog, const char *name, const QString &text)
    {
        auto *box = field<QDoubleSpinBox>(dialog, name);
        QVERIFY2(box != nullptr, name);
        QVERIFY2(box->isEnabled(), name);
        box->setFocus();
        box->selectAll();
        QTest::keyClicks(box, text);
        QTest::keyClick(box, Qt::Key_Return);
    }
    void settle()
    {
        const std::uint64_t sequence = controller().sync();
        QTRY_VERIFY(controller().frame() && controller().frame()->appliedMessage >= sequence);
    }
};

void TestTransformDialog::init()
{
    QVERIFY2(openEditor({.size = QSize(900, 700)}), qPrintable(editorFailure()));
    m_window->document()->replace(bent(), QString());
    settle();
    tools()->setSelection(ui::Selection{{0, 1, 2, 3}, {}});
}

void TestTransformDialog::cleanup()
{
    closeEditor();
}

void TestTransformDialog::movesRotatesAndScalesAsOneUndoStep()
{
    const core::SceneDesc before = scene();
    ui::TransformDialog *dialog = open();
    QVERIFY(dialog != nullptr);
    QCOMPARE(dialog->pivotText(), QStringLiteral("About the centroid of 4 particles: (1.25, 0.5, -0.25) m"));

    // move by (1, 0, 0), a quarter turn about z, twice the size with the rest lengths
    type(dialog, "transform-move-x", QStringLiteral("1"));
    type(dialog, "transform-angle", QStringLiteral("90"));
    dialog->axisBox()->setCurrentIndex(int(ui::TransformDialog::Axis::Z));
    type(dialog, "transform-scale-x", QStringLiteral("2"));
    QTest::mouseClick(dialog->restLengthsBox(), Qt::LeftButton);
    QVERIFY(dialog->restLengthsBox()->isChecked());
    // Return in a field applied nothing
    QCOMPARE(undo()->count(), 0);
    QVERIFY(dialog->problemText().isEmpty());
    QTest::mouseClick(dialog->applyButton(), Qt::LeftButton);

    // one undo step, named after what it did; the dialog stays open for another
    QCOMPARE(undo()->count(), 1);
    const QString text = QStringLiteral("Transform 4 particles: move by (1, 0, 0) m, rotate 90° about z, scale ×2 with "
                                        "rest lengths");
    QCOMPARE(undo()->text(0), text);
    QCOMPARE(m_window->statusBar()->currentMessage(), text);
    QVERIFY(dialog->isVisible());

    // the centroid moved by (1, 0, 0); every distance within doubled; the pinned particle moved too
    const core::SceneDesc after = scene();
    const Eigen::Vector3d centre(1.25, 0.5, -0.25);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i)
        sum += after.particles[std::size_t(i)].position;
    QVERIFY(((sum / 4.0) - (centre + Eigen::Vector3d(1.0, 0.0, 0.0))).norm() < 1e-12);
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            QVERIFY(std::abs(distance(after, i, j) - 2.0 * distance(before, i, j)) < 1e-12);
    QVERIFY(after.particles[2].pinned);
    QVERIFY((after.particles[2].position - before.particles[2].position).norm() > 0.5);
    // the quarter turn about z: particle 0's offset from the centre (-1.25, -0.5, 0.25), doubled
    // and turned, is (1, -2.5, 0.5)
    QVERIFY((after.particles[0].position - (centre + Eigen::Vector3d(1.0, 0.0, 0.0) + Eigen::Vector3d(1.0, -2.5, 0.5)))
                .norm() < 1e-12);
    // velocities turned with them: +x becomes +y
    QVERIFY((after.particles[0].velocity - Eigen::Vector3d(0.0, 0.5, 0.0)).norm() < 1e-15);
    // rest lengths within doubled, the spring to particle 4 and particle 4 itself left alone
    for (int s = 0; s < 3; ++s)
        QVERIFY(std::abs(after.springs[std::size_t(s)].restLength - 2.0 * before.springs[std::size_t(s)].restLength) < 1e-12);
    QCOMPARE(after.springs[3], before.springs[3]);
    QCOMPARE(after.particles[4], before.particles[4]);

    // the worker runs the transformed scene
    settle();
    const core::Snapshot &shown = *controller().frame()->snapshot;
    for (int axis = 0; axis < 3; ++axis)
        QCOMPARE(shown.positions[std::size_t(axis)], float(after.particles[0].position[axis]));

    // undo: exactly the scene before; redo: exactly the one after
    undo()->undo();
    QVERIFY(scene() == before);
    undo()->redo();
    QVERIFY(scene() == after);
}

void TestTransformDialog::perAxisScaleAboutATypedAxis()
{
    // particles 0 and 1 only: centroid (0.5, 0, 0)
    tools()->setSelection(ui::Selection{{0, 1}, {}});
    const core::SceneDesc before = scene();
    ui::TransformDialog *dialog = open();
    QVERIFY(dialog != nullptr);

    // per axis: y and z are free once Uniform is off
    QVERIFY(!field<QDoubleSpinBox>(dialog, "transform-scale-y")->isEnabled());
    QTest::mouseClick(dialog->uniformBox(), Qt::LeftButton);
    QVERIFY(field<QDoubleSpinBox>(dialog, "transform-scale-y")->isEnabled());
    type(dialog, "transform-scale-x", QStringLiteral("3"));
    type(dialog, "transform-scale-y", QStringLiteral("0.5"));
    QCOMPARE(field<QDoubleSpinBox>(dialog, "transform-scale-z")->value(), 1.0);

    // half a turn about the typed axis (1, 1, 0): x goes to y
    QVERIFY(!field<QDoubleSpinBox>(dialog, "transform-axis-x")->isEnabled());
    dialog->axisBox()->setCurrentIndex(int(ui::TransformDialog::Axis::Typed));
    type(dialog, "transform-axis-x", QStringLiteral("1"));
    type(dialog, "transform-axis-y", QStringLiteral("1"));
    type(dialog, "transform-axis-z", QStringLiteral("0"));
    type(dialog, "transform-angle", QStringLiteral("180"));
    QTest::mouseClick(dialog->applyButton(), Qt::LeftButton);
    QCOMPARE(undo()->count(), 1);
    QCOMPARE(undo()->text(0),
             QStringLiteral("Transform 2 particles: rotate 180° about (1, 1, 0), scale ×(3, 0.5, 1)"));

    // particle 1's offset (0.5, 0, 0) scaled to (1.5, 0, 0), turned to (0, 1.5, 0)
    QVERIFY((scene().particles[1].position - Eigen::Vector3d(0.5, 1.5, 0.0)).norm() < 1e-12);
    QVERIFY((scene().particles[0].position - Eigen::Vector3d(0.5, -1.5, 0.0)).norm() < 1e-12);
    // the rest lengths kept, as the box was not checked
    QCOMPARE(scene().springs, before.springs);
}

void TestTransformDialog::badInputIsNamedAndChangesNothing_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("perAxis");
    QTest::addColumn<bool>("typedAxis");
    QTest::addColumn<QString>("problem");
    QTest::addColumn<bool>("applyOn");  // the fields are fine; the result is refused when applied

    QTest::newRow("move not a number") << "transform-move-x" << "nan" << false << false
                                       << "Move x must be a number (got nan)" << false;
    QTest::newRow("move infinite") << "transform-move-z" << "-inf" << false << false
                                   << "Move z must be a number (got -inf)" << false;
    QTest::newRow("angle not a number") << "transform-angle" << "nan" << false << false
                                        << "The angle must be a number (got nan)" << false;
    QTest::newRow("zero scale") << "transform-scale-x" << "0" << false << false
                                << "Scale x must not be 0" << false;
    QTest::newRow("zero scale along one axis") << "transform-scale-z" << "0" << true << false
                                               << "Scale z must not be 0" << false;
    QTest::newRow("empty axis") << "transform-axis-y" << "0" << false << true
                                << "The rotation axis is zero: type a direction, or rotate about x, y or z" << false;
    QTest::newRow("result out of range") << "transform-move-y" << "2e9" << false << false
                                         << "Not transformed: particles[0].position[1] must be" << true;
    QTest::newRow("scaled out of range") << "transform-scale-x" << "1e10" << false << false
                                         << "Not transformed: particles[0].position[0] must be" << true;
}

void TestTransformDialog::badInputIsNamedAndChangesNothing()
{
    QFETCH(QString, name);
    QFETCH(QString, text);
    QFETCH(bool, perAxis);
    QFETCH(bool, typedAxis);
    QFETCH(QString, problem);
    QFETCH(bool, applyOn);
    const core::SceneDesc before = scene();
    ui::TransformDialog *dialog = open();
    QVERIFY(dialog != nullptr);
    if (perAxis)
        QTest::mouseClick(dialog->uniformBox(), Qt::LeftButton);
    if (typedAxis) {
        // a turn about an axis typed as (0, 0, 0)
        type(dialog, "transform-angle", QStringLiteral("30"));
        dialog->axisBox()->setCurrentIndex(int(ui::TransformDialog::Axis::Typed));
        type(dialog, "transform-axis-x", QStringLiteral("0"));
        type(dialog, "transform-axis-z", QStringLiteral("0"));
    }
    type(dialog, name.toLatin1().constData(), text);

    // named under the fields, and Apply and OK off (or refused when pressed)
    if (text == QLatin1String("nan") || text.endsWith(QLatin1String("inf")))
        QCOMPARE(field<QDoubleSpinBox>(dialog, name.toLatin1().constData())->text(), text);
    if (!applyOn) {
        QVERIFY2(dialog->problemText().startsWith(problem), qPrintable(dialog->problemText()));
        QVERIFY(!dialog->applyButton()->isEnabled());
        QVERIFY(!dialog->okButton()->isEnabled());
        QVERIFY(!dialog->transform());
        QVERIFY(!dialog->apply());
    } else {
        QVERIFY2(dialog->problemText().isEmpty(), qPrintable(dialog->problemText()));
        QVERIFY(dialog->applyButton()->isEnabled());
        QTest::mouseClick(dialog->okButton(), Qt::LeftButton);
        QVERIFY2(dialog->problemText().startsWith(problem), qPrintable(dialog->problemText()));
        QVERIFY2(dialog->problemText().endsWith(QStringLiteral("; nothing was changed")), qPrintable(dialog->problemText()));
        // OK did not close it
        QVERIFY(dialog->isVisible());
    }
    QCOMPARE(undo()->count(), 0);
    QVERIFY(scene() == before);
}

void TestTransformDialog::followsTheSelectionWhileOpen()
{
    ui::TransformDialog *dialog = open();
    QVERIFY(dialog != nullptr);
    type(dialog, "transform-move-y", QStringLiteral("1"));

    // nothing selected: said, and nothing to apply
    tools()->setSelection({});
    QCOMPARE(dialog->pivotText(), QStringLiteral("Nothing selected"));
    QVERIFY(dialog->problemText().startsWith(QStringLiteral("Nothing selected")));
    QVERIFY(!dialog->applyButton()->isEnabled());

    // a spring selected: its two ends are transformed
    tools()->setSelection(ui::Selection{{}, {3}});
    QCOMPARE(dialog->pivotText(), QStringLiteral("About the centroid of 2 particles: (3.5, 1.75, 0) m"));
    QVERIFY(dialog->applyButton()->isEnabled());
    const core::SceneDesc before = scene();
    QTest::mouseClick(dialog->applyButton(), Qt::LeftButton);
    QCOMPARE(undo()->text(0), QStringLiteral("Transform 2 particles: move by (0, 1, 0) m"));
    QCOMPARE(scene().particles[3].position, (before.particles[3].position + Eigen::Vector3d(0.0, 1.0, 0.0)).eval());
    QCOMPARE(scene().particles[4].position, (before.particles[4].position + Eigen::Vector3d(0.0, 1.0, 0.0)).eval());
    QCOMPARE(scene().particles[0], before.particles[0]);
    // and the centroid shown follows the edit
    QCOMPARE(dialog->pivotText(), QStringLiteral("About the centroid of 2 particles: (3.5, 2.75, 0) m"));

    // Apply again: another step, from where the first left them
    QTest::mouseClick(dialog->applyButton(), Qt::LeftButton);
    QCOMPARE(undo()->count(), 2);
    QCOMPARE(scene().particles[4].position, (before.particles[4].position + Eigen::Vector3d(0.0, 2.0, 0.0)).eval());
}

void TestTransformDialog::okAppliesAndClosesCloseDoesNot()
{
    ui::TransformDialog *dialog = open();
    QVERIFY(dialog != nullptr);
    const core::SceneDesc before = scene();

    // no change typed: OK closes with no undo step
    QTest::mouseClick(dialog->okButton(), Qt::LeftButton);
    QTRY_VERIFY(!dialog->isVisible());
    QCOMPARE(undo()->count(), 0);

    // a move typed, then Close: nothing applied; opened again it keeps the values
    dialog = open();
    QVERIFY(dialog != nullptr);
    type(dialog, "transform-move-x", QStringLiteral("0.25"));
    QTest::mouseClick(field<QPushButton>(dialog, "transformClose"), Qt::LeftButton);
    QTRY_VERIFY(!dialog->isVisible());
    QVERIFY(scene() == before);
    dialog = open();
    QVERIFY(dialog != nullptr);
    QCOMPARE(field<QDoubleSpinBox>(dialog, "transform-move-x")->value(), 0.25);
    QTest::mouseClick(dialog->okButton(), Qt::LeftButton);
    QTRY_VERIFY(!dialog->isVisible());
    QCOMPARE(undo()->count(), 1);
    QCOMPARE(scene().particles[0].position.x(), 0.25);
}

void TestTransformDialog::f1ListsTheDialogAndTheMeasureTool()
{
    const std::optional<QStringList> entries = test::helpEntries(m_window);
    QVERIFY(entries);
    const QString all = entries->join(QLatin1Char('\n'));
    QVERIFY2(all.contains(QStringLiteral("Ctrl+T\tEdit › Transform Selection")), qPrintable(all));
    QVERIFY(all.contains(QStringLiteral("6\tEdit › Tool › Measure")));
    QVERIFY(all.contains(QStringLiteral("Measure tool (6)")));
    // and no key of the menus does two things
    QStringList keys;
    for (const QString &entry : *entries) {
        const QString key = entry.section(QLatin1Char('\t'), 0, 0);
        const QString description = entry.section(QLatin1Char('\t'), 1);
        const bool menuKey = !key.contains(QStringLiteral("›")) &&
                             QRegularExpression(QStringLiteral("^(File|Edit|Simulation|View|Help) › ")).match(description).hasMatch();
        if (menuKey)
            keys << key.split(QStringLiteral(", "));
    }
    QVERIFY(keys.contains(QStringLiteral("Ctrl+T")));
    for (const QString &key : keys)
        QVERIFY2(keys.count(key) == 1, qPrintable(key + QStringLiteral(" does two things")));
}

QTEST_MAIN(TestTransformDialog)
#include "test_transform_dialog.moc"
