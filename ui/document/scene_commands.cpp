#include "scene_commands.h"

#include "scene_document.h"

namespace ui {

namespace {

// ids that let QUndoStack merge commands of one kind
constexpr int kSettingsCommandId = 1001;
constexpr int kSpringValueCommandId = 1002;
constexpr int kSceneCommandId = 1003;

}  // namespace

SettingsCommand::SettingsCommand(SceneDocument &document, const QString &text, const QString &mergeKey,
                                 const core::Settings &after)
    : QUndoCommand(text), m_document(document), m_mergeKey(mergeKey), m_before(document.scene().settings),
      m_after(after)
{
}

void SettingsCommand::redo()
{
    m_document.modify([this](core::SceneDesc &scene) { scene.settings = m_after; }, SceneChange::Parameters);
}

void SettingsCommand::undo()
{
    m_document.modify([this](core::SceneDesc &scene) { scene.settings = m_before; }, SceneChange::Parameters);
}

int SettingsCommand::id() const
{
    return kSettingsCommandId;
}

bool SettingsCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const SettingsCommand *>(other);
    if (m_mergeKey.isEmpty() || next->m_mergeKey != m_mergeKey)
        return false;
    // the merged step says where it ended: "Set Friction to 2", not the drag's first value
    m_after = next->m_after;
    setText(next->text());
    setObsolete(m_after == m_before);
    return true;
}

SpringValueCommand::SpringValueCommand(SceneDocument &document, const QString &text, double core::SpringDesc::*field,
                                       double value)
    : QUndoCommand(text), m_document(document), m_field(field), m_after(value)
{
    m_before.reserve(document.scene().springs.size());
    for (const core::SpringDesc &spring : document.scene().springs)
        m_before.push_back(spring.*field);
}

void SpringValueCommand::redo()
{
    m_document.modify(
        [this](core::SceneDesc &scene) {
            for (core::SpringDesc &spring : scene.springs)
                spring.*m_field = m_after;
        },
        SceneChange::Parameters);
}

void SpringValueCommand::undo()
{
    m_document.modify(
        [this](core::SceneDesc &scene) {
            for (std::size_t k = 0; k < scene.springs.size() && k < m_before.size(); ++k)
                scene.springs[k].*m_field = m_before[k];
        },
        SceneChange::Parameters);
}

int SpringValueCommand::id() const
{
    return kSpringValueCommandId;
}

bool SpringValueCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const SpringValueCommand *>(other);
    if (next->m_field != m_field)
        return false;
    m_after = next->m_after;
    setText(next->text());
    return true;
}

SceneCommand::SceneCommand(SceneDocument &document, const QString &text, std::shared_ptr<const core::SceneDesc> after,
                           const QString &mergeKey)
    : QUndoCommand(text), m_document(document), m_mergeKey(mergeKey), m_before(document.sharedScene()),
      m_after(std::move(after))
{
}

void SceneCommand::redo()
{
    m_document.setScene(m_after, SceneChange::Structure);
}

void SceneCommand::undo()
{
    m_document.setScene(m_before, SceneChange::Structure);
}

int SceneCommand::id() const
{
    return kSceneCommandId;
}

bool SceneCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const SceneCommand *>(other);
    if (m_mergeKey.isEmpty() || next->m_mergeKey != m_mergeKey)
        return false;
    m_after = next->m_after;
    setText(next->text());
    setObsolete(*m_after == *m_before);
    return true;
}

}  // namespace ui
