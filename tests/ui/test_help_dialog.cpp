// F1's help at its default size, opened by the key in the real main window: every key cell shows
// the whole of its text on one line (its width with the cell's font and margins within the keys
// column), and the descriptions still have room beside them; so too once the font grows after the
// dialog was built, as a desktop's font or scale setting does.

#include "ui/dialogs/help_dialog.h"
#include "ui/window/main_window.h"

#include <QApplication>
#include <QHeaderView>
#include <QStyle>
#include <QTableWidget>
#include <QTimer>
#include <QtTest>

#include "editor_fixture.h"

namespace {

// what the open help dialog shows: one line per key cell that does not fit, and the widths
struct HelpLayout {
    bool opened = false;
    QStringList cut;      // "keys: needs N px, has M px"
    int keysWidth = 0;    // px
    int viewWidth = 0;    // px, the table's viewport
    int descriptionWidth = 0;
};

HelpLayout measure(const ui::HelpDialog &help)
{
    HelpLayout layout;
    layout.opened = true;
    const auto *table = help.findChild<QTableWidget *>();
    const int margin = table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table) + 1;
    layout.keysWidth = table->columnWidth(0);
    layout.descriptionWidth = table->columnWidth(1);
    layout.viewWidth = table->viewport()->width();
    for (int row = 0; row < table->rowCount(); ++row) {
        const QTableWidgetItem *keys = table->item(row, 0);
        if (!keys || table->columnSpan(row, 0) > 1)
            continue;  // a section's title, across both columns
        // the cell's own font where it has one, else the table's
        const QFont font = keys->data(Qt::FontRole).isValid() ? keys->font() : table->font();
        const int needed = QFontMetrics(font).horizontalAdvance(keys->text()) + 2 * margin;
        if (needed > layout.keysWidth)
            layout.cut << QStringLiteral("%1: needs %2 px, has %3 px").arg(keys->text()).arg(needed).arg(layout.keysWidth);
    }
    return layout;
}

}  // namespace

class TestHelpDialog : public test::EditorTest {
    Q_OBJECT

private slots:
    void init() { QVERIFY2(openEditor(), qPrintable(editorFailure())); }
    void cleanup() { closeEditor(); }

    void everyKeyShowsWhole_data();
    void everyKeyShowsWhole();
};

void TestHelpDialog::everyKeyShowsWhole_data()
{
    QTest::addColumn<double>("fontScale");
    QTest::newRow("its own font") << 1.0;
    QTest::newRow("a font 1.3 times larger, set once shown") << 1.3;
}

void TestHelpDialog::everyKeyShowsWhole()
{
    // F1, then measured once the dialog is shown at its own size
    QFETCH(double, fontScale);
    HelpLayout layout;
    QTimer::singleShot(0, m_window, [&layout, fontScale] {
        auto *help = qobject_cast<ui::HelpDialog *>(QApplication::activeModalWidget());
        if (!help)
            return;
        if (QTest::qWaitForWindowExposed(help)) {
            if (fontScale != 1.0) {
                QFont font = help->font();
                font.setPointSizeF(font.pointSizeF() * fontScale);
                help->setFont(font);
                // the relayout after the font change is posted: wait until the keys fit, or 2 s
                // (then the measure below reports what is cut)
                (void)QTest::qWaitFor([help] { return measure(*help).cut.isEmpty(); }, 2000);
            }
            layout = measure(*help);
        }
        help->reject();
    });
    QTest::keyClick(m_window, Qt::Key_F1);
    QVERIFY(layout.opened);
    QVERIFY2(layout.cut.isEmpty(), qPrintable(layout.cut.join(QLatin1Char('\n'))));
    // both columns within the table, the descriptions with room for a few words a line
    QVERIFY2(layout.keysWidth + layout.descriptionWidth <= layout.viewWidth,
             qPrintable(QStringLiteral("%1 + %2 > %3").arg(layout.keysWidth).arg(layout.descriptionWidth).arg(layout.viewWidth)));
    QVERIFY2(layout.descriptionWidth >= 200, qPrintable(QString::number(layout.descriptionWidth)));
}

QTEST_MAIN(TestHelpDialog)
#include "test_help_dialog.moc"
