#include "initial_state_command.h"

#include "scene_document.h"

#include <cassert>

namespace ui {

namespace {

void setInitialConditions(SceneDocument &document, const Eigen::Matrix3Xd &position, const Eigen::Matrix3Xd &velocity)
{
    // a parameters-kind change: the worker keeps its running state, only a reset reads these
    document.modify(
        [&](core::SceneDesc &scene) {
            for (std::size_t i = 0; i < scene.particles.size(); ++i) {
                scene.particles[i].position = position.col(static_cast<Eigen::Index>(i));
                scene.particles[i].velocity = velocity.col(static_cast<Eigen::Index>(i));
            }
        },
        SceneChange::Parameters);
}

}  // namespace

InitialStateCommand::InitialStateCommand(SceneDocument &document, const QString &text, const CapturedState &state)
    : QUndoCommand(text), m_document(document), m_afterPosition(state.position), m_afterVelocity(state.velocity)
{
    const auto &particles = document.scene().particles;
    assert(static_cast<Eigen::Index>(particles.size()) == state.position.cols());
    m_beforePosition.resize(3, static_cast<Eigen::Index>(particles.size()));
    m_beforeVelocity.resize(3, static_cast<Eigen::Index>(particles.size()));
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const auto column = static_cast<Eigen::Index>(i);
        m_beforePosition.col(column) = particles[i].position;
        m_beforeVelocity.col(column) = particles[i].velocity;
        // a pinned particle starts at rest, whatever the run says
        if (particles[i].pinned)
            m_afterVelocity.col(column).setZero();
    }
}

void InitialStateCommand::redo()
{
    setInitialConditions(m_document, m_afterPosition, m_afterVelocity);
}

void InitialStateCommand::undo()
{
    setInitialConditions(m_document, m_beforePosition, m_beforeVelocity);
}

}  // namespace ui
