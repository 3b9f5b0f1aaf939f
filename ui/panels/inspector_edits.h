#pragma once
// InspectorEdits: how the inspector's sections change the scene. An edit makes a changed copy of
// the scene, checks it with the same validation as the file loader (core::findProblem), and pushes
// it as one SceneCommand; a refused edit leaves the scene and the undo stack alone and says why.
// Arrow and wheel steps on one field merge into one undo step, until the session ends: the user
// leaves the field or types a value, the selection changes, or the scene changes from elsewhere
// (undo, redo, another tool), so an earlier sequence is never extended by a later one.

#include "core/model/parameters.h"
#include "core/model/scene.h"

#include <QObject>
#include <QString>
#include <functional>
#include <memory>
#include <optional>

namespace ui {

class SceneDocument;

class InspectorEdits : public QObject {
    Q_OBJECT

public:
    explicit InspectorEdits(SceneDocument *document, QObject *parent = nullptr);

    SceneDocument *document() const { return m_document; }

    // the reason `label` may not take this value ("Mass must be greater than 0 kg (got 0 kg);
    // not applied"), or nullopt when the parameter table allows it
    static std::optional<QString> refusal(core::Parameter parameter, const QString &label, double value);
    // the first problem of an edited scene, named after `label`; nullopt when it can be simulated
    // or when the scene already had a problem before the edit (the edit is not to blame)
    std::optional<QString> problemIn(const core::SceneDesc &edited, const QString &label) const;

    // checks one value, edits a copy of the scene with it and pushes the result; stepField names
    // the field for a step that merges with the previous steps of that field, empty for a typed
    // value (its own undo step). Returns false when refused (valueRefused says why).
    bool apply(const QString &text, core::Parameter parameter, const QString &label, double value,
               const std::function<void(core::SceneDesc &)> &edit, const QString &stepField = {});
    // pushes an edited scene after checking it as a whole; nothing when it equals the scene
    bool push(const QString &text, const QString &label, std::shared_ptr<core::SceneDesc> edited,
              const QString &stepField = {});

    // the next step starts an undo command of its own
    void endSession() { ++m_session; }

    // emits valueRefused; for checks the sections make themselves
    void refuse(const QString &message);

signals:
    void valueRefused(const QString &message);
    // an edit was pushed (so an earlier refusal no longer stands)
    void applied();

private:
    SceneDocument *m_document;
    int m_session = 0;
    bool m_pushing = false;
};

}  // namespace ui
