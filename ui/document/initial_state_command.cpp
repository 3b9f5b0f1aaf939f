#include "initial_state_command.h"

#include "scene_document.h"

#include <cassert>

namespace ui {

InitialStateCommand::InitialStateCommand(SceneDocument &document, const QString &text, const core::State &state)
    : QUndoCommand(text), m_document(document), m_before(document.sharedScene())
{
    assert(static_cast<std::size_t>(state.particleCount()) == m_before->particles.size());
    auto after = std::make_shared<core::SceneDesc>(*m_before);
    core::storeState(state, *after);
    m_after = std::move(after);
}

// the worker keeps its running state either way (SceneChange::InitialConditions): only a reset
// reads these conditions
void InitialStateCommand::redo()
{
    m_document.setScene(m_after, SceneChange::InitialConditions);
}

void InitialStateCommand::undo()
{
    m_document.setScene(m_before, SceneChange::InitialConditions);
}

}  // namespace ui
