#pragma once
// RecentFiles: the scene files opened or saved lately, most recent first, at most kMaximum, kept
// in QSettings so that every window and the next start share them. The list is read from the
// settings each time, so two windows never overwrite each other's entries with a stale copy.

#include <QObject>
#include <QString>
#include <QStringList>

namespace ui {

class RecentFiles : public QObject {
    Q_OBJECT

public:
    static constexpr int kMaximum = 10;

    explicit RecentFiles(QObject *parent = nullptr);

    // absolute paths, most recent first
    QStringList paths() const;

    // puts path first (moving it up if it is listed already) and drops the oldest beyond kMaximum;
    // nothing while not remembering
    void add(const QString &path);
    // off for a run that is not the user's (springlab --exit-after, a benchmark): what it opens
    // and saves stays out of the list
    void setRemembering(bool on) { m_remembering = on; }
    // false if it was not listed
    bool remove(const QString &path);
    void clear();

signals:
    void changed();

private:
    void store(const QStringList &paths);

    bool m_remembering = true;
};

}  // namespace ui
