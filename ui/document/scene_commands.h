#pragma once
// Undo commands for the scene's parameters. Consecutive changes of the same parameter merge into
// one command, named after the last, so a slider drag is one step of undo that says where it ended.

#include "core/model/scene.h"

#include <QUndoCommand>
#include <memory>
#include <vector>

namespace ui {

class SceneDocument;

// replaces the scene's settings; mergeKey names the parameter that changed (e.g. "gravity.y"); an
// empty key never merges (a choice, such as the integrator, is one undo step each time)
class SettingsCommand : public QUndoCommand {
public:
    SettingsCommand(SceneDocument &document, const QString &text, const QString &mergeKey, const core::Settings &after);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    SceneDocument &m_document;
    QString m_mergeKey;
    core::Settings m_before;
    core::Settings m_after;
};

// sets one value (stiffness or damping) of every spring; undo gives each spring its own value back
class SpringValueCommand : public QUndoCommand {
public:
    SpringValueCommand(SceneDocument &document, const QString &text, double core::SpringDesc::*field, double value);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    SceneDocument &m_document;
    double core::SpringDesc::*m_field;
    std::vector<double> m_before;  // per spring
    double m_after;
};

// any edit of the scene's content (particles, springs, planes, initial conditions): keeps the whole
// scene before and after, so undo returns exactly the previous scene whatever the edit did. Scenes
// are shared immutable values, so each side costs a pointer, not a copy. Commands with the same
// non-empty mergeKey merge (one drag, one typed value), as the settings do.
class SceneCommand : public QUndoCommand {
public:
    SceneCommand(SceneDocument &document, const QString &text, std::shared_ptr<const core::SceneDesc> after,
                 const QString &mergeKey = {});

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    SceneDocument &m_document;
    QString m_mergeKey;
    std::shared_ptr<const core::SceneDesc> m_before;
    std::shared_ptr<const core::SceneDesc> m_after;
};

}  // namespace ui
