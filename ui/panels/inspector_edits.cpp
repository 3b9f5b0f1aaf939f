#include "inspector_edits.h"

#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"

#include "core/model/validate.h"

#include <QUndoStack>

namespace ui {

InspectorEdits::InspectorEdits(SceneDocument *document, QObject *parent) : QObject(parent), m_document(document)
{
    // a change that is not ours (undo, redo, another tool, a new scene) ends any step sequence
    connect(m_document, &SceneDocument::sceneChanged, this, [this] {
        if (!m_pushing)
            endSession();
    });
}

std::optional<QString> InspectorEdits::refusal(core::Parameter parameter, const QString &label, double value)
{
    if (const std::optional<std::string> reason = core::checkParameter(parameter, value))
        return tr("%1 %2; not applied").arg(label, QString::fromStdString(*reason));
    return std::nullopt;
}

std::optional<QString> InspectorEdits::problemIn(const core::SceneDesc &edited, const QString &label) const
{
    const std::optional<core::SceneProblem> problem = core::findProblem(edited);
    if (!problem || core::findProblem(m_document->scene()))
        return std::nullopt;
    return tr("%1 %2; not applied").arg(label, QString::fromStdString(problem->message));
}

bool InspectorEdits::apply(const QString &text, core::Parameter parameter, const QString &label, double value,
                           const std::function<void(core::SceneDesc &)> &edit, const QString &stepField)
{
    if (const std::optional<QString> refused = refusal(parameter, label, value)) {
        refuse(*refused);
        return false;
    }
    auto edited = std::make_shared<core::SceneDesc>(m_document->scene());
    edit(*edited);
    return push(text, label, std::move(edited), stepField);
}

bool InspectorEdits::push(const QString &text, const QString &label, std::shared_ptr<core::SceneDesc> edited,
                          const QString &stepField)
{
    if (const std::optional<QString> problem = problemIn(*edited, label)) {
        refuse(*problem);
        return false;
    }
    // a value every item already has changes nothing and adds no undo step
    if (*edited == m_document->scene())
        return true;

    // a typed value is its own step; steps of one field in one session merge
    QString mergeKey;
    if (!stepField.isEmpty())
        mergeKey = QStringLiteral("inspector/%1/%2").arg(stepField).arg(m_session);
    else
        endSession();
    m_pushing = true;
    m_document->undoStack()->push(
        new SceneCommand(*m_document, text, std::shared_ptr<const core::SceneDesc>(std::move(edited)), mergeKey));
    m_pushing = false;
    emit applied();
    return true;
}

void InspectorEdits::refuse(const QString &message)
{
    emit valueRefused(message);
}

}  // namespace ui
