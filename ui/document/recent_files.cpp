#include "recent_files.h"

#include <QFileInfo>
#include <QSettings>

namespace ui {

namespace {

const QString kKey = QStringLiteral("files/recent");

// one spelling per file, so that a file opened twice by different paths is listed once
QString canonical(const QString &path)
{
    const QFileInfo info(path);
    const QString resolved = info.canonicalFilePath();
    return resolved.isEmpty() ? info.absoluteFilePath() : resolved;
}

}  // namespace

RecentFiles::RecentFiles(QObject *parent) : QObject(parent) {}

QStringList RecentFiles::paths() const
{
    QStringList paths = QSettings().value(kKey).toStringList();
    paths.removeAll(QString());
    return paths.mid(0, kMaximum);
}

void RecentFiles::add(const QString &path)
{
    if (!m_remembering)
        return;
    const QString entry = canonical(path);
    QStringList paths = this->paths();
    paths.removeAll(entry);
    paths.prepend(entry);
    store(paths.mid(0, kMaximum));
}

bool RecentFiles::remove(const QString &path)
{
    QStringList paths = this->paths();
    // a missing file has no canonical path: match it as it was stored, too
    const bool removed = paths.removeAll(path) + paths.removeAll(canonical(path)) > 0;
    if (removed)
        store(paths);
    return removed;
}

void RecentFiles::clear()
{
    store({});
}

void RecentFiles::store(const QStringList &paths)
{
    QSettings().setValue(kKey, paths);
    emit changed();
}

}  // namespace ui
