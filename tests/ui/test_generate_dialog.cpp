// Edit › Generate… in the real editor: Ctrl+G opens the dialog; values typed into its spin boxes
// remake the preview with the counts they say; wrong options are named and cannot be added; Add
// puts exactly the generated particles and springs into the scene, centred where the dialog says,
// as one undo step that reaches the worker, and undo gives back exactly the scene before. Every
// kind's default is the core generator's default; a soft ball of the points typed in is drawn at the
// dialog's size. (The dialog's picture in the docs is taken by tools/editor_screenshot.)

#include "ui/dialogs/generate_dialog.h"
#include "ui/dialogs/generate_preview.h"
#include "ui/dialogs/help_dialog.h"
#include "ui/viewport/edit_tools.h"
#include "ui/window/main_window.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

#include <numeric>

#include "editor_fixture.h"
#include "help_entries.h"

class TestGenerateDialog : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void addsTheClothAsOneUndoStep();
    void wrongOptionsAreNamedAndCannotBeAdded();
    void everyKindIsTheCoreGeneratorsDefault();
    void softBallOptionsReachTheGenerator();
    void cancelAddsNothing();
    void f1ListsTheGenerators();
    void softBallOfTheTypedPointsIsDrawn();

private:
    const core::SceneDesc &scene() { return m_window->document()->scene(); }
    QUndoStack *undo() { return m_window->document()->undoStack(); }

    // Ctrl+G, as a user would press it; the dialog, shown and active
    ui::GenerateDialog *open()
    {
        QTest::keyClick(m_window, Qt::Key_G, Qt::ControlModifier);
        ui::GenerateDialog *dialog = m_window->generateDialog();
        return dialog && test::showActive(*dialog) ? dialog : nullptr;
    }
    template <class Box>
    Box *field(ui::GenerateDialog *dialog, const char *name)
    {
        return dialog->findChild<Box *>(QString::fromLatin1(name));
    }
    // types text into a spin box and presses Return, as a user would
    void type(QAbstractSpinBox *box, const QString &text)
    {
        QVERIFY(box != nullptr);
        box->setFocus();
        box->selectAll();
        QTest::keyClicks(box, text);
        QTest::keyClick(box, Qt::Key_Return);
    }
    // the kind box moved down to index, by the arrow key
    void chooseKind(ui::GenerateDialog *dialog, ui::GenerateDialog::Kind kind)
    {
        QComboBox *box = dialog->kindBox();
        box->setFocus();
        while (box->currentIndex() < int(kind))
            QTest::keyClick(box, Qt::Key_Down);
        while (box->currentIndex() > int(kind))
            QTest::keyClick(box, Qt::Key_Up);
    }
    // the preview paints again, after `paints`, drawing this many particles and springs
    void expectPreview(ui::GenerateDialog *dialog, int paints, int particles, int springs)
    {
        ui::GeneratePreview *preview = dialog->preview();
        QTRY_VERIFY2_WITH_TIMEOUT(preview->paintCount() > paints && preview->drawnParticles() == particles &&
                                      preview->drawnSprings() == springs,
                                  qPrintable(QStringLiteral("drew %1 particles, %2 springs in paint %3 (after %4); %5")
                                                 .arg(preview->drawnParticles())
                                                 .arg(preview->drawnSprings())
                                                 .arg(preview->paintCount())
                                                 .arg(paints)
                                                 .arg(dialog->countText())),
                                  5000);
    }
};

void TestGenerateDialog::init()
{
    QVERIFY2(openEditor(), qPrintable(editorFailure()));
}

void TestGenerateDialog::cleanup()
{
    closeEditor();
}

void TestGenerateDialog::addsTheClothAsOneUndoStep()
{
    const core::SceneDesc before = scene();
    QVERIFY(!before.particles.empty());
    ui::GenerateDialog *dialog = open();
    QVERIFY(dialog != nullptr);
    QCOMPARE(dialog->kind(), ui::GenerateDialog::Kind::Cloth);

    // 3 × 4: 12 particles; structural 3·3 + 2·4, shear 2·2·3, bend 3·2 + 1·4
    int paints = dialog->preview()->paintCount();
    type(field<QSpinBox>(dialog, "generate-cloth-rows"), QStringLiteral("3"));
    type(field<QSpinBox>(dialog, "generate-cloth-cols"), QStringLiteral("4"));
    expectPreview(dialog, paints, 12, 39);
    if (QTest::currentTestFailed())
        return;
    QVERIFY2(dialog->countText().startsWith(QStringLiteral("12 particle(s), 39 spring(s)")),
             qPrintable(dialog->countText()));
    // and what it costs, timed here: a figure in ms and the speed it allows against real time
    static const QRegularExpression cost(
        QStringLiteral("; a step of it alone takes [0-9.e+-]+ ms here, [0-9.e+-]+× (faster|slower) than real time$"));
    QVERIFY2(cost.match(dialog->countText()).hasMatch(), qPrintable(dialog->countText()));
    QVERIFY(dialog->problemText().isEmpty());
    // Return in a field only remade the preview
    QVERIFY(dialog->isVisible());
    QCOMPARE(undo()->count(), 0);

    // its middle at (2, 1.5, -1)
    type(field<QDoubleSpinBox>(dialog, "generate-x"), QStringLiteral("2"));
    type(field<QDoubleSpinBox>(dialog, "generate-y"), QStringLiteral("1.5"));
    type(field<QDoubleSpinBox>(dialog, "generate-z"), QStringLiteral("-1"));
    QCOMPARE(dialog->position(), Eigen::Vector3d(2.0, 1.5, -1.0));

    // Add: one undo step with exactly the cloth's particles and springs after the scene's own
    QVERIFY(dialog->addButton()->isEnabled());
    QTest::mouseClick(dialog->addButton(), Qt::LeftButton);
    QTRY_VERIFY(!dialog->isVisible());
    QCOMPARE(undo()->count(), 1);
    QCOMPARE(undo()->text(0), QStringLiteral("Generate Cloth"));
    const core::SceneDesc &after = scene();
    const std::size_t n = before.particles.size();
    QCOMPARE(after.particles.size(), n + 12);
    QCOMPARE(after.springs.size(), before.springs.size() + 39);
    QVERIFY(std::equal(before.particles.begin(), before.particles.end(), after.particles.begin()));
    QVERIFY(std::equal(before.springs.begin(), before.springs.end(), after.springs.begin()));
    for (std::size_t s = before.springs.size(); s < after.springs.size(); ++s) {
        QVERIFY(after.springs[s].a >= int(n) && after.springs[s].b >= int(n));
        const double distance = (after.particles[std::size_t(after.springs[s].a)].position -
                                 after.particles[std::size_t(after.springs[s].b)].position)
                                    .norm();
        QVERIFY(std::abs(distance - after.springs[s].restLength) < 1e-12);
    }
    const Eigen::Vector3d middle = 0.5 * (after.particles[n].position + after.particles.back().position);
    QVERIFY((middle - Eigen::Vector3d(2.0, 1.5, -1.0)).norm() < 1e-12);
    QCOMPARE(after.settings.substeps, std::max(before.settings.substeps, core::ClothOptions{}.substeps));
    // the cloth collides as a surface: its 12 cells' triangles listed, the scene's collisions on
    QVERIFY(after.settings.triangleCollisions);
    QVERIFY(after.triangles.size() >= 12);

    // the new particles are the selection, and the worker runs the new scene
    std::vector<int> added(12);
    std::iota(added.begin(), added.end(), int(n));
    QCOMPARE(m_window->editTools()->selection().particles, added);
    auto frame = test::settledFrame(controller());
    QVERIFY(frame != nullptr);
    QCOMPARE(frame->snapshot->particleCount(), int(n + 12));

    // Ctrl+Z: exactly the scene before, in the worker too
    QVERIFY(test::showActive(*m_window));
    QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier);
    QTRY_COMPARE(undo()->index(), 0);
    QVERIFY(scene() == before);
    frame = test::settledFrame(controller());
    QVERIFY(frame != nullptr);
    QCOMPARE(frame->snapshot->particleCount(), int(n));
}

void TestGenerateDialog::wrongOptionsAreNamedAndCannotBeAdded()
{
    ui::GenerateDialog *dialog = open();
    QVERIFY(dialog != nullptr);

    // no rows: named, nothing drawn, Add off
    int paints = dialog->preview()->paintCount();
    type(field<QSpinBox>(dialog, "generate-cloth-rows"), QStringLiteral("0"));
    QVERIFY2(dialog->problemText().contains(QStringLiteral("rows must be at least 2 (got 0)")),
             qPrintable(dialog->problemText()));
    QVERIFY(!dialog->addButton()->isEnabled());
    QVERIFY(dialog->countText().isEmpty());
    expectPreview(dialog, paints, 0, 0);
    if (QTest::currentTestFailed())
        return;

    // a negative spacing, with the rows back
    type(field<QSpinBox>(dialog, "generate-cloth-rows"), QStringLiteral("5"));
    type(field<QDoubleSpinBox>(dialog, "generate-cloth-spacing"), QStringLiteral("-0.1"));
    QVERIFY2(dialog->problemText().contains(QStringLiteral("spacing must be greater than 0 m (got -0.1 m)")),
             qPrintable(dialog->problemText()));
    QVERIFY(!dialog->addButton()->isEnabled());

    // too many particles
    type(field<QDoubleSpinBox>(dialog, "generate-cloth-spacing"), QStringLiteral("0.05"));
    type(field<QSpinBox>(dialog, "generate-cloth-rows"), QStringLiteral("1000"));
    type(field<QSpinBox>(dialog, "generate-cloth-cols"), QStringLiteral("1000"));
    QVERIFY2(dialog->problemText().contains(QStringLiteral("more than the 200000 a generator may make")),
             qPrintable(dialog->problemText()));

    // a position out of range
    type(field<QSpinBox>(dialog, "generate-cloth-rows"), QStringLiteral("5"));
    type(field<QSpinBox>(dialog, "generate-cloth-cols"), QStringLiteral("5"));
    type(field<QDoubleSpinBox>(dialog, "generate-y"), QStringLiteral("1e12"));
    QVERIFY2(dialog->problemText().contains(QStringLiteral("position y must be at most")),
             qPrintable(dialog->problemText()));
    QVERIFY(!dialog->addButton()->isEnabled());

    // all well again: 25 particles drawn, Add on
    paints = dialog->preview()->paintCount();
    type(field<QDoubleSpinBox>(dialog, "generate-y"), QStringLiteral("1"));
    QVERIFY(dialog->problemText().isEmpty());
    QVERIFY(dialog->addButton()->isEnabled());
    core::ClothOptions five;
    five.rows = five.cols = 5;
    expectPreview(dialog, paints, 25, int(core::makeCloth(five).springs.size()));
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(undo()->count(), 0);
}

void TestGenerateDialog::everyKindIsTheCoreGeneratorsDefault()
{
    ui::GenerateDialog *dialog = open();
    QVERIFY(dialog != nullptr);
    using Kind = ui::GenerateDialog::Kind;
    // the dialog's cloth collides as a surface (its triangles listed), the generator's by default not
    core::ClothOptions surface;
    surface.sheetCollisions = true;
    const std::pair<Kind, core::SceneDesc> kinds[] = {
        {Kind::Rope, core::makeRope({})},   {Kind::Chain, core::makeChain({})},
        {Kind::Block, core::makeBlock({})}, {Kind::Ball, core::makeBall({})},
        {Kind::SoftBall, core::makeSoftBall({})}, {Kind::Cloth, core::makeCloth(surface)},
    };
    QVERIFY(!core::makeCloth(surface).triangles.empty());
    QVERIFY(core::makeCloth(surface).settings.triangleCollisions);
    for (const auto &[kind, expected] : kinds) {
        const int paints = dialog->preview()->paintCount();
        chooseKind(dialog, kind);
        QCOMPARE(dialog->kind(), kind);
        QVERIFY(dialog->generated() != nullptr);
        QVERIFY(*dialog->generated() == expected);
        expectPreview(dialog, paints, int(expected.particles.size()), int(expected.springs.size()));
        if (QTest::currentTestFailed())
            return;
        QVERIFY2(dialog->countText().startsWith(QStringLiteral("%1 particle(s)").arg(expected.particles.size())),
                 qPrintable(dialog->countText()));
        QVERIFY(dialog->addButton()->isEnabled());
    }
}

void TestGenerateDialog::softBallOptionsReachTheGenerator()
{
    ui::GenerateDialog *dialog = open();
    QVERIFY(dialog != nullptr);
    chooseKind(dialog, ui::GenerateDialog::Kind::SoftBall);

    // 50 points, no centre: the shell alone
    core::SoftBallOptions options;
    options.points = 50;
    options.centre = false;
    const core::SceneDesc expected = core::makeSoftBall(options);
    const int paints = dialog->preview()->paintCount();
    type(field<QSpinBox>(dialog, "generate-softBall-points"), QStringLiteral("50"));
    QCheckBox *centre = field<QCheckBox>(dialog, "generate-softBall-centre");
    QVERIFY(centre != nullptr && centre->isChecked());
    QTest::mouseClick(centre, Qt::LeftButton, {}, QPoint(4, centre->height() / 2));
    QVERIFY(!centre->isChecked());
    expectPreview(dialog, paints, 50, int(expected.springs.size()));
    if (QTest::currentTestFailed())
        return;
    QVERIFY(*dialog->generated() == expected);

    // added at the default place: the middle of its box 1 m up
    const std::size_t n = scene().particles.size();
    QTest::mouseClick(dialog->addButton(), Qt::LeftButton);
    QTRY_VERIFY(!dialog->isVisible());
    QCOMPARE(scene().particles.size(), n + 50);
    QCOMPARE(undo()->text(0), QStringLiteral("Generate Soft ball"));
    Eigen::Vector3d low = scene().particles[n].position, high = low;
    for (std::size_t i = n; i < scene().particles.size(); ++i) {
        low = low.cwiseMin(scene().particles[i].position);
        high = high.cwiseMax(scene().particles[i].position);
    }
    QVERIFY((0.5 * (low + high) - Eigen::Vector3d(0.0, 1.0, 0.0)).norm() < 1e-12);
}

void TestGenerateDialog::cancelAddsNothing()
{
    const core::SceneDesc before = scene();
    ui::GenerateDialog *dialog = open();
    QVERIFY(dialog != nullptr);
    QTest::keyClick(dialog, Qt::Key_Escape);
    QTRY_VERIFY(!dialog->isVisible());
    QCOMPARE(undo()->count(), 0);
    QVERIFY(scene() == before);
}

void TestGenerateDialog::f1ListsTheGenerators()
{
    const std::optional<QStringList> entries = test::helpEntries(m_window);
    QVERIFY(entries);
    const QString all = entries->join(QLatin1Char('\n'));
    QVERIFY(all.contains(QStringLiteral("Ctrl+G\tEdit › Generate")));
    QVERIFY(all.contains(QStringLiteral("soft ball")));
}

void TestGenerateDialog::softBallOfTheTypedPointsIsDrawn()
{
    // 200 points typed in: the preview draws them and the centre, and the dialog grabs at its size
    ui::GenerateDialog *dialog = open();
    QVERIFY(dialog != nullptr);
    chooseKind(dialog, ui::GenerateDialog::Kind::SoftBall);
    const int paints = dialog->preview()->paintCount();
    type(field<QSpinBox>(dialog, "generate-softBall-points"), QStringLiteral("200"));
    type(field<QDoubleSpinBox>(dialog, "generate-softBall-radius"), QStringLiteral("0.015"));
    dialog->kindBox()->setFocus();
    QTRY_VERIFY(dialog->preview()->paintCount() > paints && dialog->preview()->drawnParticles() == 201);
    const QImage picture = dialog->grab().toImage();
    QVERIFY(!picture.isNull());
    QCOMPARE(picture.size(), dialog->size());
}

QTEST_MAIN(TestGenerateDialog)
#include "test_generate_dialog.moc"
