#pragma once
// "Use current state as initial": one undo step that makes a captured state of the run the
// scene's initial conditions (every particle's position and velocity). The run itself goes on
// untouched; Reset (F5) is what returns to these conditions.

#include "captured_state.h"

#include <QUndoCommand>
#include <vector>

namespace ui {

class SceneDocument;

class InitialStateCommand : public QUndoCommand {
public:
    // the state must have one column per particle of the document's scene
    InitialStateCommand(SceneDocument &document, const QString &text, const CapturedState &state);

    void redo() override;
    void undo() override;

private:
    SceneDocument &m_document;
    Eigen::Matrix3Xd m_beforePosition;  // m
    Eigen::Matrix3Xd m_beforeVelocity;  // m/s
    Eigen::Matrix3Xd m_afterPosition;
    Eigen::Matrix3Xd m_afterVelocity;
};

}  // namespace ui
