#include "scene_document.h"

#include <QDir>
#include <QFileInfo>
#include <QUndoStack>

namespace ui {

SceneDocument::SceneDocument(QObject *parent)
    : QObject(parent), m_scene(std::make_shared<const core::SceneDesc>()), m_undoStack(new QUndoStack(this))
{
    connect(m_undoStack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

QString SceneDocument::folder() const
{
    return m_filePath.isEmpty() ? QDir::homePath() : QFileInfo(m_filePath).absolutePath();
}

QString SceneDocument::displayName() const
{
    if (!m_scene->name.empty())
        return QString::fromStdString(m_scene->name);
    if (!m_filePath.isEmpty())
        return QFileInfo(m_filePath).completeBaseName();
    return tr("untitled");
}

bool SceneDocument::isModified() const
{
    return !m_undoStack->isClean();
}

void SceneDocument::replace(core::SceneDesc scene, const QString &filePath)
{
    m_scene = std::make_shared<const core::SceneDesc>(std::move(scene));
    m_undoStack->clear();
    // a new scene is as its file has it, even after a recovered one was marked unclean for good
    // (resetClean), which clear() leaves as it was
    m_undoStack->setClean();
    if (m_filePath != filePath) {
        m_filePath = filePath;
        emit filePathChanged(m_filePath);
    }
    emit sceneChanged(SceneChange::Replace);
}

void SceneDocument::markSaved(const QString &filePath)
{
    if (m_filePath != filePath) {
        m_filePath = filePath;
        emit filePathChanged(m_filePath);
    }
    m_undoStack->setClean();
}

void SceneDocument::modify(const std::function<void(core::SceneDesc &)> &edit, SceneChange change)
{
    auto edited = std::make_shared<core::SceneDesc>(*m_scene);
    edit(*edited);
    m_scene = std::move(edited);
    emit sceneChanged(change);
}

void SceneDocument::setScene(std::shared_ptr<const core::SceneDesc> scene, SceneChange change)
{
    m_scene = std::move(scene);
    emit sceneChanged(change);
}

}  // namespace ui
