// The status bar at the window's default size, 1200 × 800, with the longest texts the editor puts
// in it: no two fields overlap, every field lies within the bar, and no field shows a text wider
// than itself (measured with its font), so nothing is cut or drawn over another. A message too
// long for the room left shows elided, with the whole of it in the tooltip, and the warning comes
// back once the message goes.

#include "ui/panels/status_text.h"
#include "ui/window/main_window.h"
#include "ui/window/status_bar.h"

#include "core/integrators/accuracy_planner.h"

#include <QAction>
#include <QLabel>
#include <QStatusBar>
#include <QtTest>

#include "editor_fixture.h"

namespace {

// the fields that show: the labels and the size grip
QList<QWidget *> shownFields(QStatusBar &bar)
{
    QList<QWidget *> fields;
    for (QWidget *field : bar.findChildren<QWidget *>(Qt::FindDirectChildrenOnly))
        if (field->isVisible())
            fields << field;
    return fields;
}

// "" when every field fits and none overlaps another, else what does not
QString layoutProblem(QStatusBar &bar)
{
    const QList<QWidget *> fields = shownFields(bar);
    for (qsizetype i = 0; i < fields.size(); ++i) {
        const QWidget *field = fields[i];
        if (!bar.rect().contains(field->geometry()))
            return QStringLiteral("%1 lies outside the bar").arg(field->objectName());
        for (qsizetype j = i + 1; j < fields.size(); ++j)
            if (field->geometry().intersects(fields[j]->geometry()))
                return QStringLiteral("%1 overlaps %2").arg(field->objectName(), fields[j]->objectName());
        if (const auto *label = qobject_cast<const QLabel *>(field)) {
            const int needed = label->fontMetrics().horizontalAdvance(label->text());
            const int room = label->contentsRect().width() - 2 * label->margin();
            if (needed > room)
                return QStringLiteral("%1 shows \"%2\", %3 px, in %4 px")
                    .arg(label->objectName(), label->text())
                    .arg(needed)
                    .arg(room);
        }
    }
    return QString();
}

}  // namespace

class TestStatusBar : public test::EditorTest {
    Q_OBJECT

private slots:
    void init() { QVERIFY2(openEditor({.size = QSize(1200, 800)}), qPrintable(editorFailure())); }
    void cleanup() { closeEditor(); }

    void longestTextsFitAtTheDefaultSize();
    void aMessageGoesBackToTheWarning();

private:
    ui::StatusBar &bar() const { return *qobject_cast<ui::StatusBar *>(m_window->statusBar()); }
    void setFigure(const char *name, const QString &text) const
    {
        auto *figure = m_window->statusBar()->findChild<QLabel *>(QString::fromLatin1(name));
        QVERIFY2(figure, name);
        figure->setText(text);
        figure->show();
    }
};

void TestStatusBar::longestTextsFitAtTheDefaultSize()
{
    QVERIFY(qobject_cast<ui::StatusBar *>(m_window->statusBar()));
    QCOMPARE(m_window->size(), QSize(1200, 800));

    // the widest figures: a long run, slower than real time, a big scene's energy, the drift in
    // joules, a tiny local error, and the pool's steering
    setFigure("statusSteer", ui::steerText(12345.67, 345.0, 10.0, -5));
    setFigure("statusTime", ui::timeText(99999.999));
    setFigure("statusRate", ui::rateText(true, 0.0123));
    setFigure("statusSteps", ui::stepsText(true, 1234567.0));
    setFigure("statusEnergy", ui::energyText(-1.23456789e7));
    core::Energies initial;
    initial.kinetic = 1e-31;
    setFigure("statusDrift", ui::driftText(initial, -1234.5));
    setFigure("statusError", ui::localErrorText(1.23e-12));

    // the longest passing message: a menu's status tip, or the planner finding nothing
    QString longest = ui::planText(core::AccuracyPlan{1e-12, 0.001, 1e-6, {core::PlanCandidate{}}, -1});
    for (const QAction *action : m_window->findChildren<QAction *>())
        if (action->statusTip().size() > longest.size())
            longest = action->statusTip();
    bar().setWarning(QStringLiteral("Particle 40199's velocity y is not finite at step 1234 (-inf m/s): the springs "
                                    "are too stiff for the time step; use more substeps or implicit-euler. Paused at "
                                    "the last good state."));
    QVERIFY(test::sizeHeld(*m_window->statusBar()));
    QVERIFY2(layoutProblem(bar()).isEmpty(), qPrintable(layoutProblem(bar())));

    m_window->statusBar()->showMessage(longest);
    QVERIFY(test::sizeHeld(*m_window->statusBar()));
    QCOMPARE(m_window->size(), QSize(1200, 800));
    QVERIFY2(layoutProblem(bar()).isEmpty(), qPrintable(layoutProblem(bar())));

    // the message shows, elided, and whole in the tooltip
    ui::ElidedLabel *message = bar().messageLabel();
    QVERIFY(message->isVisible());
    QCOMPARE(message->fullText(), longest);
    QVERIFY2(message->text().endsWith(QChar(0x2026)), qPrintable(message->text()));
    QVERIFY(longest.startsWith(message->text().chopped(1)));
    QCOMPARE(message->toolTip(), longest);
}

void TestStatusBar::aMessageGoesBackToTheWarning()
{
    bar().setWarning(QStringLiteral("Substeps must be at least 1 (got 0.5)"));
    QCOMPARE(bar().messageLabel()->text(), QStringLiteral("Substeps must be at least 1 (got 0.5)"));
    QCOMPARE(bar().messageLabel()->toolTip(), QString());
    m_window->statusBar()->showMessage(QStringLiteral("Collisions on"));
    QCOMPARE(bar().messageLabel()->text(), QStringLiteral("Collisions on"));
    m_window->statusBar()->clearMessage();
    QCOMPARE(bar().messageLabel()->text(), QStringLiteral("Substeps must be at least 1 (got 0.5)"));
    QCOMPARE(m_window->statusWarning(), QStringLiteral("Substeps must be at least 1 (got 0.5)"));
}

QTEST_MAIN(TestStatusBar)
#include "test_status_bar.moc"
