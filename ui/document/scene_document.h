#pragma once
// SceneDocument: the scene being edited, owned by the UI thread. It holds the SceneDesc as an
// immutable shared value (an edit makes a changed copy), so handing the current scene to the
// worker thread costs a pointer, and the worker can never see a scene half-edited. Changes go
// through the undo stack's commands (scene_commands.h), and the stack's clean state is the
// document's saved state.

#include "session/messages.h"

#include "core/model/scene.h"

#include <QObject>
#include <QString>
#include <functional>
#include <memory>

class QUndoStack;

namespace ui {

class SceneDocument : public QObject {
    Q_OBJECT

public:
    explicit SceneDocument(QObject *parent = nullptr);

    const core::SceneDesc &scene() const { return *m_scene; }
    std::shared_ptr<const core::SceneDesc> sharedScene() const { return m_scene; }

    // the file the scene was loaded from or saved to; empty for an example or a new scene
    const QString &filePath() const { return m_filePath; }
    // the scene's name, else the file's base name, else "untitled"
    QString displayName() const;
    // where file dialogs for this scene start: its file's folder, or the home folder before it has one
    QString folder() const;

    QUndoStack *undoStack() const { return m_undoStack; }
    bool isModified() const;

    // a whole new scene, opened or from the examples: the undo history starts afresh
    void replace(core::SceneDesc scene, const QString &filePath);

    // the scene was written to filePath: that is its saved state now
    void markSaved(const QString &filePath);

    // replaces the scene with an edited copy; for the undo commands
    void modify(const std::function<void(core::SceneDesc &)> &edit, SceneChange change);
    // puts a whole scene in place; for the undo commands
    void setScene(std::shared_ptr<const core::SceneDesc> scene, SceneChange change);

signals:
    void sceneChanged(ui::SceneChange change);
    void filePathChanged(const QString &filePath);
    void modifiedChanged(bool modified);

private:
    std::shared_ptr<const core::SceneDesc> m_scene;
    QString m_filePath;
    QUndoStack *m_undoStack = nullptr;
};

}  // namespace ui
