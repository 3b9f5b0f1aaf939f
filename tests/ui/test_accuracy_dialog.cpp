// Simulation › Accuracy (F7) in the real main window: at its default size every column header
// shows whole (font metrics and the header's margins within its section, the sections within the
// table), before and after a plan; Preview shows the plan the worker made and changes nothing;
// adaptive-rk45, which the planner does not measure, is offered in the table and applied at the
// tolerance typed as one undoable edit.

#include "ui/dialogs/accuracy_dialog.h"
#include "ui/document/scene_document.h"
#include "ui/panels/value_spin_box.h"
#include "ui/window/main_window.h"

#include "core/integrators/accuracy_planner.h"

#include <QHeaderView>
#include <QPushButton>
#include <QStyle>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest>

#include "editor_fixture.h"

namespace {

// "" when every header shows whole and the sections fit the table, else which does not
QString headerProblem(const QTableWidget &table)
{
    const QHeaderView *header = table.horizontalHeader();
    const int margin = header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
    int right = 0;
    for (int c = 0; c < table.columnCount(); ++c) {
        const QString text = table.horizontalHeaderItem(c)->text();
        const int needed = header->fontMetrics().horizontalAdvance(text) + 2 * margin;
        if (needed > header->sectionSize(c))
            return QStringLiteral("\"%1\" needs %2 px, has %3 px").arg(text).arg(needed).arg(header->sectionSize(c));
        right = std::max(right, header->sectionViewportPosition(c) + header->sectionSize(c));
    }
    if (right > header->viewport()->width())
        return QStringLiteral("the sections end at %1 px, the table at %2 px").arg(right).arg(header->viewport()->width());
    return QString();
}

// the table's row for an integrator, or -1
int rowOf(const QTableWidget &table, const QString &integrator)
{
    for (int r = 0; r < table.rowCount(); ++r)
        if (table.item(r, 0) && table.item(r, 0)->text() == integrator)
            return r;
    return -1;
}

}  // namespace

class TestAccuracyDialog : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup() { closeEditor(); }

    void headersShowWholeAtTheDefaultSize();
    void previewShowsThePlanAndChangesNothing();
    void adaptiveRk45IsOfferedAndApplied();

private:
    ui::AccuracyDialog *m_dialog = nullptr;
    QUndoStack *undo() const { return m_window->document()->undoStack(); }
    void typeTolerance(const QString &text)
    {
        m_dialog->toleranceBox()->setFocus();
        m_dialog->toleranceBox()->selectAll();
        QTest::keyClicks(m_dialog->toleranceBox(), text);
    }
};

void TestAccuracyDialog::init()
{
    QVERIFY2(openEditor(), qPrintable(editorFailure()));
    QTest::keyClick(m_window, Qt::Key_F7);
    m_dialog = m_window->accuracyDialog();
    QVERIFY(m_dialog);
    QVERIFY(QTest::qWaitForWindowExposed(m_dialog));
}

void TestAccuracyDialog::headersShowWholeAtTheDefaultSize()
{
    QVERIFY(test::sizeHeld(*m_dialog));
    QVERIFY2(headerProblem(*m_dialog->table()).isEmpty(), qPrintable(headerProblem(*m_dialog->table())));
    // and with a plan's rows in the table
    QTest::mouseClick(m_dialog->previewButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(m_dialog->table()->rowCount() == int(std::size(core::kIntegrators)) &&
                                 m_dialog->previewButton()->isEnabled(),
                             20000);
    QVERIFY2(headerProblem(*m_dialog->table()).isEmpty(), qPrintable(headerProblem(*m_dialog->table())));
}

void TestAccuracyDialog::previewShowsThePlanAndChangesNothing()
{
    const core::SceneDesc before = m_window->document()->scene();
    typeTolerance(QStringLiteral("1e-7"));
    QTest::mouseClick(m_dialog->previewButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(m_dialog->summary().contains(QStringLiteral("preview")), 20000);
    // the plan's pick is named and bold in the table, and nothing was applied
    QVERIFY2(m_dialog->summary().contains(QStringLiteral("meet")), qPrintable(m_dialog->summary()));
    bool bold = false;
    for (int r = 0; r < m_dialog->table()->rowCount(); ++r)
        bold = bold || m_dialog->table()->item(r, 0)->font().bold();
    QVERIFY(bold);
    QCOMPARE(undo()->count(), 0);
    QVERIFY(m_window->document()->scene() == before);
    QVERIFY(!m_window->isWindowModified());
}

void TestAccuracyDialog::adaptiveRk45IsOfferedAndApplied()
{
    // offered before any plan and after one
    const QString adaptive = QStringLiteral("adaptive-rk45");
    QVERIFY(rowOf(*m_dialog->table(), adaptive) >= 0);
    QTest::mouseClick(m_dialog->previewButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(m_dialog->summary().contains(QStringLiteral("preview")), 20000);
    QCOMPARE(rowOf(*m_dialog->table(), adaptive), m_dialog->table()->rowCount() - 1);

    // applied at the tolerance typed, as one undoable edit
    const core::Settings before = m_window->document()->scene().settings;
    QVERIFY(before.integrator != core::Integrator::AdaptiveRk45);
    typeTolerance(QStringLiteral("2e-7"));
    QTest::mouseClick(m_dialog->adaptiveButton(), Qt::LeftButton);
    QCOMPARE(m_window->document()->scene().settings.integrator, core::Integrator::AdaptiveRk45);
    QCOMPARE(m_window->document()->scene().settings.tolerance, 2e-7);
    QCOMPARE(undo()->count(), 1);
    QVERIFY2(m_dialog->summary().startsWith(adaptive), qPrintable(m_dialog->summary()));
    undo()->undo();
    QCOMPARE(m_window->document()->scene().settings.integrator, before.integrator);
    QCOMPARE(m_window->document()->scene().settings.tolerance, before.tolerance);
}

QTEST_MAIN(TestAccuracyDialog)
#include "test_accuracy_dialog.moc"
