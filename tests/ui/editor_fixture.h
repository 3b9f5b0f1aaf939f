#pragma once
// The one fixture of the editor's UI tests. A test class that drives the main window derives from
// EditorTest instead of QObject: OpenGL is set up before the application exists, the settings
// (autosave, recent files, docks) live in a throwaway folder for the whole run, beside another for
// the files a test writes (m_files), and openEditor() gives a test a new main window, shown, made the
// active window and settled on the worker's frame; closeEditor(), the next openEditor() or the end
// of the run deletes it. What a test needs beyond that (its own answers to questions, a size, a
// window that is made but not shown) it says in EditorOptions, rather than writing the steps again.

#include "ui/window/main_window.h"
#include "ui/simulation/simulation_controller.h"

#include <QElapsedTimer>
#include <QObject>
#include <QSettings>
#include <QSize>
#include <QTemporaryDir>
#include <QtTest>
#include <functional>

#include "editor_test_setup.h"
#include "frame_wait.h"

namespace test {

// how a test wants its new window
struct EditorOptions {
    // given the window before it is shown: the answers to its questions and file dialogs
    std::function<void(ui::MainWindow &)> setup = {};
    QSize size = {};       // the window's size; empty: its own (or the one the settings remember)
    bool show = true;      // false: made and left hidden, as a start that only reads the settings
    bool activate = true;  // the active window, which shortcuts need; false: shown and exposed only
    bool settle = true;    // waits for the worker's frame of the scene the window opened on
};

// waits (running the event loop) until widget's size has held for holdMs, as docks settle their
// widths through the X server after a window is shown; false if it still changes after 10 s
inline bool sizeHeld(const QWidget &widget, int holdMs = 200)
{
    QElapsedTimer held;
    held.start();
    QSize size = widget.size();
    return QTest::qWaitFor(
        [&] {
            if (widget.size() != size) {
                size = widget.size();
                held.restart();
            }
            return held.elapsed() >= holdMs;
        },
        10000);
}

class EditorTest : public QObject {
public:
    // QTEST_MAIN calls it before the application exists
    static void initMain() { prepareOpenGL(); }
    ~EditorTest() override { closeEditor(); }

protected:
    // the settings under the test's name (its executable's), in a folder of this run's own;
    // QTEST_MAIN makes the test object once the application exists
    EditorTest()
    {
        if (m_settings.isValid())
            useSettingsIn(m_settings.path(), QCoreApplication::applicationName());
    }

    // both throwaway folders were made
    bool foldersReady() const { return m_settings.isValid() && m_files.isValid(); }
    QString settingsPath() const { return m_settings.path(); }
    ui::SimulationController &controller() const { return *m_window->controller(); }

    // autosave into directory every intervalSeconds (0: off), as File › Autosave stores it
    static void setAutosave(const QString &directory, int intervalSeconds)
    {
        QSettings settings;
        settings.setValue(QStringLiteral("autosave/directory"), directory);
        settings.setValue(QStringLiteral("autosave/intervalSeconds"), intervalSeconds);
    }

    // a new window, as options say, in m_window (the one before is deleted first); false if a
    // step did not happen, which editorFailure() names
    bool openEditor(const EditorOptions &options = {})
    {
        closeEditor();
        m_failure.clear();
        if (!foldersReady())
            return fail(QStringLiteral("no throwaway folders: ") + m_settings.errorString() + m_files.errorString());
        m_window = new ui::MainWindow;
        if (options.setup)
            options.setup(*m_window);
        if (options.size.isValid())
            m_window->resize(options.size);
        if (!options.show)
            return true;
        if (options.activate) {
            if (!showActive(*m_window))
                return fail(QStringLiteral("the window never became active"));
        } else {
            m_window->show();
            if (!QTest::qWaitForWindowExposed(m_window))
                return fail(QStringLiteral("the window was never exposed"));
        }
        if (options.settle && !settledFrame(*m_window->controller()))
            return fail(QStringLiteral("no frame of the opened scene from the worker"));
        return true;
    }
    void closeEditor()
    {
        delete m_window;
        m_window = nullptr;
    }
    const QString &editorFailure() const { return m_failure; }

    ui::MainWindow *m_window = nullptr;
    QTemporaryDir m_files;  // the test's own files: scenes, exports, recovery folders

private:
    bool fail(const QString &why)
    {
        m_failure = why;
        qWarning("openEditor: %s", qPrintable(why));
        return false;
    }

    QTemporaryDir m_settings;
    QString m_failure;
};

}  // namespace test
