#pragma once
// Autosave: every few seconds (60 by default), a document with changes not yet autosaved is
// written to a recovery file of this session's own in the recovery folder, never over the user's
// file. A clean document (saved, reverted, another one opened) has no recovery file, and a clean
// end of the session removes it. A QLockFile beside it marks the session as alive, so a start
// that finds a recovery file whose lock no running process holds knows that session crashed, and
// a second window or process never takes another's live file for a crashed one.
//
// Files, per session: <id>.recovery.json (the scene), <id>.recovery.source (the path of the
// user's file it was edited from; empty for an untitled scene) and <id>.recovery.lock.

#include <QDateTime>
#include <QList>
#include <QObject>
#include <QString>
#include <memory>

class QLockFile;
class QTimer;

namespace ui {

class SceneDocument;

class Autosave : public QObject {
    Q_OBJECT

public:
    static constexpr int kDefaultIntervalSeconds = 60;

    // a recovery file left by a session that did not end cleanly
    struct Recovery {
        QString scenePath;   // the autosaved scene
        QString sourcePath;  // the user's file it came from; empty for an untitled scene
        QDateTime saved;     // when it was last written
    };

    // the interval and the folder come from the settings (configuredIntervalSeconds(),
    // configuredDirectory())
    explicit Autosave(const SceneDocument &document, QObject *parent = nullptr);
    // a clean end: this session's recovery file goes
    ~Autosave() override;

    // QSettings "autosave/intervalSeconds" (s, 0: off), else kDefaultIntervalSeconds
    static int configuredIntervalSeconds();
    // QSettings "autosave/directory", else "recovery" in the application's data folder
    static QString configuredDirectory();

    // s between autosaves; 0 switches autosave off (and removes this session's file)
    int intervalSeconds() const { return m_intervalSeconds; }
    void setIntervalSeconds(int seconds);

    QString directory() const { return m_directory; }
    void setDirectory(const QString &directory);

    // this session's recovery file; it exists only while the document has autosaved changes
    QString recoveryPath() const;
    // whether path is one of the recovery folder's files (this session's or another's), which
    // autosave writes over and removes: nothing else may be saved there. Compared as files
    // (io::sameFile), so a link to one or another spelling of the folder counts too
    bool isRecoveryFile(const QString &path) const;

    // writes the document now if it has changes not yet autosaved; false and why on failure
    bool saveNow(QString *error = nullptr);
    // removes this session's recovery file
    void discard();

    // recovery files of sessions that ended without removing theirs, newest first
    static QList<Recovery> findRecoveries(const QString &directory);
    // removes a recovery file and its companion
    static void removeRecovery(const Recovery &recovery);

signals:
    void saved(const QString &path);
    void failed(const QString &message);

private:
    void tick();
    void removeFiles();
    QString filePath(const char *suffix) const;

    const SceneDocument &m_document;
    QTimer *m_timer = nullptr;
    QString m_directory;
    QString m_id;                        // this session's name for its files
    std::unique_ptr<QLockFile> m_lock;   // held from the first write until discarded
    int m_intervalSeconds = 0;
    bool m_pending = false;              // changed since the last autosave
};

}  // namespace ui
