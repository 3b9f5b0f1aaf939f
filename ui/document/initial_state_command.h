#pragma once
// "Use current state as initial": one undo step that makes a captured state of the run the
// scene's initial conditions through core::storeState, the path `springlab-sim --output` takes:
// every particle's position and velocity, and the springs the run broke left out, so that Reset
// (F5) starts from the state as it was, not with torn springs whole again. The run itself goes on
// untouched.

#include "core/model/scene.h"
#include "core/model/state.h"

#include <QUndoCommand>
#include <memory>

namespace ui {

class SceneDocument;

class InitialStateCommand : public QUndoCommand {
public:
    // the state must have one column per particle of the document's scene, and broken flags (if
    // any) one per spring
    InitialStateCommand(SceneDocument &document, const QString &text, const core::State &state);

    void redo() override;
    void undo() override;

private:
    SceneDocument &m_document;
    std::shared_ptr<const core::SceneDesc> m_before;
    std::shared_ptr<const core::SceneDesc> m_after;
};

}  // namespace ui
