#include "autosave.h"

#include "scene_document.h"

#include "core/io/file_identity.h"
#include "core/io/safe_write.h"
#include "core/io/scene_file.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>
#include <QUuid>
#include <algorithm>

namespace ui {

namespace {

const QString kIntervalKey = QStringLiteral("autosave/intervalSeconds");
const QString kDirectoryKey = QStringLiteral("autosave/directory");
constexpr const char *kSceneSuffix = ".recovery.json";
constexpr const char *kSourceSuffix = ".recovery.source";
constexpr const char *kLockSuffix = ".recovery.lock";

// the companion file of a recovery scene: same stem, another suffix
QString companion(const QString &scenePath, const char *suffix)
{
    QString path = scenePath;
    path.chop(qsizetype(qstrlen(kSceneSuffix)));
    return path + QLatin1String(suffix);
}

}  // namespace

Autosave::Autosave(const SceneDocument &document, QObject *parent)
    : QObject(parent), m_document(document), m_timer(new QTimer(this)), m_directory(configuredDirectory()),
      m_id(QUuid::createUuid().toString(QUuid::WithoutBraces))
{
    connect(m_timer, &QTimer::timeout, this, &Autosave::tick);
    // an edit is owed to the recovery file; a clean document needs none
    connect(&m_document, &SceneDocument::sceneChanged, this, [this] { m_pending = true; });
    connect(&m_document, &SceneDocument::modifiedChanged, this, [this](bool modified) {
        if (!modified)
            discard();
    });
    setIntervalSeconds(configuredIntervalSeconds());
}

Autosave::~Autosave()
{
    // the document may be gone already: only the files
    removeFiles();
}

int Autosave::configuredIntervalSeconds()
{
    bool ok = false;
    const int seconds = QSettings().value(kIntervalKey, kDefaultIntervalSeconds).toInt(&ok);
    return ok && seconds >= 0 ? seconds : kDefaultIntervalSeconds;
}

QString Autosave::configuredDirectory()
{
    const QString configured = QSettings().value(kDirectoryKey).toString();
    if (!configured.isEmpty())
        return configured;
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(QStringLiteral("recovery"));
}

void Autosave::setIntervalSeconds(int seconds)
{
    m_intervalSeconds = std::max(0, seconds);
    if (m_intervalSeconds == 0) {
        m_timer->stop();
        discard();
        return;
    }
    m_timer->start(m_intervalSeconds * 1000);
}

void Autosave::setDirectory(const QString &directory)
{
    if (directory == m_directory)
        return;
    discard();
    m_directory = directory;
    m_pending = true;
}

QString Autosave::filePath(const char *suffix) const
{
    return QDir(m_directory).filePath(m_id + QLatin1String(suffix));
}

QString Autosave::recoveryPath() const
{
    return filePath(kSceneSuffix);
}

bool Autosave::isRecoveryFile(const QString &path) const
{
    // this session's files, also through a link to one
    for (const char *suffix : {kSceneSuffix, kSourceSuffix, kLockSuffix})
        if (io::sameFile(path, filePath(suffix)))
            return true;
    // any session's, by its name in the folder: where the path is, and where a link there leads
    const auto named = [this](const QFileInfo &file) {
        for (const char *suffix : {kSceneSuffix, kSourceSuffix, kLockSuffix})
            if (file.fileName().endsWith(QLatin1String(suffix)) && io::sameFile(file.path(), m_directory))
                return true;
        return false;
    };
    const QFileInfo given(path);
    return named(given) || (given.exists() && named(QFileInfo(given.canonicalFilePath())));
}

bool Autosave::saveNow(QString *error)
{
    auto fail = [error](const QString &reason) {
        if (error)
            *error = reason;
        return false;
    };
    if (!m_document.isModified())
        return true;
    // the user's file is written by Save alone, even when it is reached as the recovery file
    if (io::sameFile(recoveryPath(), m_document.filePath()))
        return fail(tr("Autosave: %1 is the scene's own file, %2; autosave never writes over it")
                        .arg(QDir::toNativeSeparators(recoveryPath()), QDir::toNativeSeparators(m_document.filePath())));
    if (!QDir().mkpath(m_directory))
        return fail(tr("Autosave: cannot create the folder %1").arg(QDir::toNativeSeparators(m_directory)));

    // the lock first: it tells a later start that this session is alive
    if (!m_lock) {
        m_lock = std::make_unique<QLockFile>(filePath(kLockSuffix));
        m_lock->setStaleLockTime(0);
        if (!m_lock->tryLock(0))
            return fail(tr("Autosave: cannot lock %1").arg(QDir::toNativeSeparators(filePath(kLockSuffix))));
    }
    const io::SaveResult written = io::saveScene(recoveryPath(), m_document.scene());
    if (!written.ok())
        return fail(tr("Autosave: %1").arg(written.error));
    if (const QString failure = io::writeFileAtomically(filePath(kSourceSuffix), m_document.filePath().toUtf8());
        !failure.isEmpty())
        return fail(tr("Autosave: cannot write %1: %2").arg(QDir::toNativeSeparators(filePath(kSourceSuffix)), failure));
    m_pending = false;
    emit saved(recoveryPath());
    return true;
}

void Autosave::discard()
{
    removeFiles();
    m_pending = m_document.isModified();
}

void Autosave::removeFiles()
{
    QFile::remove(recoveryPath());
    QFile::remove(filePath(kSourceSuffix));
    m_lock.reset();  // unlocks, which removes the lock file
}

void Autosave::tick()
{
    if (!m_pending || !m_document.isModified())
        return;
    QString error;
    if (!saveNow(&error))
        emit failed(error);
}

QList<Autosave::Recovery> Autosave::findRecoveries(const QString &directory)
{
    QList<Recovery> found;
    const QDir folder(directory);
    const QStringList names =
        folder.entryList({QStringLiteral("*") + QLatin1String(kSceneSuffix)}, QDir::Files, QDir::Time);
    for (const QString &name : names) {
        const QString scenePath = folder.filePath(name);
        // a lock that a live process holds: its session is running, the file is not abandoned
        QLockFile lock(companion(scenePath, kLockSuffix));
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0))
            continue;
        lock.unlock();

        Recovery recovery;
        recovery.scenePath = scenePath;
        QFile source(companion(scenePath, kSourceSuffix));
        if (source.open(QIODevice::ReadOnly))
            recovery.sourcePath = QString::fromUtf8(source.readAll());
        recovery.saved = QFileInfo(scenePath).lastModified();
        found << recovery;
    }
    return found;
}

void Autosave::removeRecovery(const Recovery &recovery)
{
    QFile::remove(recovery.scenePath);
    QFile::remove(companion(recovery.scenePath, kSourceSuffix));
}

}  // namespace ui
