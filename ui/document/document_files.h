#pragma once
// DocumentFiles: what File does with the document's files. New, Open (from the dialog, a recent
// file, a drop or the command line), the built-in examples, Save, Save As and Revert; the recent
// files and autosave with recovery after a crash; and the unsaved-changes question in front of
// anything that would lose work. Every question and file dialog goes through the window's Prompts
// (ui/dialogs/prompts.h), which the tests answer. The window builds the File menu around it and
// shows what it reports: statusMessage() in the status bar, warning() in the warning field.

#include "core/model/scene.h"

#include <QObject>
#include <QString>
#include <QStringList>

class QActionGroup;
class QAction;
class QMenu;
class QMimeData;

namespace ui {

class Autosave;
class Prompts;
class RecentFiles;
class SceneDocument;

class DocumentFiles : public QObject {
    Q_OBJECT

public:
    // the example opened when no scene is given
    static constexpr const char *kDefaultExample = "springs";

    DocumentFiles(SceneDocument &document, const Prompts &prompts, QObject *parent = nullptr);

    // File's submenus, each added at the end of file: Open Recent, Examples, Autosave
    void addRecentMenu(QMenu *file);
    void addExamplesMenu(QMenu *file);
    void addAutosaveMenu(QMenu *file);

    // File › New: an empty scene (newScene()) once unsaved changes are dealt with; false if cancelled
    bool newDocument();
    // what File › New opens: no particles, the default settings, a ground plane y = 0
    static core::SceneDesc newScene();

    // opens a scene file; on failure the current scene stays and error says why
    bool openScene(const QString &path, QString *error = nullptr);
    // opens a scene file as File › Open, a recent file or a drop does: asks about unsaved changes
    // first and shows a failure in a message; false if cancelled or failed
    bool openFile(const QString &path);
    // File › Open: asks about unsaved changes, then for a file
    void openFromDialog();
    // File › Revert: reloads the document's file, after a confirmation if there are changes
    bool revert();
    // the start of the editor: offers to recover a crashed session's work, then opens path (the
    // command line's scene) unless work was recovered; a file that fails is reported in a message
    // (and error), and the default example stays open
    bool start(const QString &path = QString(), QString *error = nullptr);
    // offers the newest recovery file of a crashed session; true if one was recovered
    bool offerRecovery();
    // opens a built-in example by name ("springs"), read from ":/scenes/<name>.json"
    bool openExample(const QString &name, QString *error = nullptr);
    // the examples built in, in the handout's order
    static QStringList exampleNames();

    // saves to the document's file, or asks for one; false if not saved
    bool save();
    bool saveAs();
    bool saveTo(const QString &path, QString *error = nullptr);
    // asks what to do with unsaved changes (save, discard or cancel); true unless cancelled or
    // the save failed
    bool maybeSave();

    // why nothing but a save of the scene may write path: it is the open scene's file, or one of
    // autosave's recovery files (compared as files, io::sameFile, so a link or another spelling
    // counts too); empty when it may be written. Recordings and plots ask before they save.
    QString protectedFileAt(const QString &path) const;

    // the scene file a drop carries: exactly one local .json file, else an empty string
    static QString droppedScenePath(const QMimeData *mime);

    RecentFiles *recentFiles() const { return m_recentFiles; }
    // where Open and Save As start: the scene's folder, or for a scene without a file (an example,
    // a new one) the folder last used (the most recent file's), else the home folder
    QString dialogFolder() const;
    Autosave *autosave() const { return m_autosave; }

signals:
    // what the status bar should say for ms milliseconds
    void statusMessage(const QString &message, int ms);
    // a problem worth the warning field, that needs no answer
    void warning(const QString &message);

private:
    void openRecent(const QString &path);
    void updateRecentMenu();
    void setAutosaveInterval(int seconds);

    SceneDocument &m_document;
    const Prompts &m_prompts;
    RecentFiles *m_recentFiles = nullptr;
    Autosave *m_autosave = nullptr;

    // File › Open Recent: its entries, most recent first, reused as the list changes
    QMenu *m_recentMenu = nullptr;
    QList<QAction *> m_recentActions;
    QAction *m_clearRecentAction = nullptr;
    // File › Autosave: its choices, one checked
    QMenu *m_autosaveMenu = nullptr;
    QActionGroup *m_autosaveGroup = nullptr;
};

}  // namespace ui
