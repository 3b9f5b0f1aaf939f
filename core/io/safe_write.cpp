#include "safe_write.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <cerrno>
#include <system_error>

#ifdef Q_OS_UNIX
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>
#endif

namespace io {

using namespace Qt::Literals::StringLiterals;

namespace {

// the folder a file is in, as the user would write it
QString shownFolder(const QString &path)
{
    return QDir::toNativeSeparators(QFileInfo(path).absolutePath());
}

// the file system holding folder is mounted read-only: no permission bit would let a write through
bool onReadOnlyFileSystem(const QString &folder)
{
#ifdef Q_OS_UNIX
    struct statvfs status {};
    return ::statvfs(QFile::encodeName(folder).constData(), &status) == 0 && (status.f_flag & ST_RDONLY) != 0;
#else
    Q_UNUSED(folder);
    return false;
#endif
}

// why a file could not be read or written, when the file itself, its folder or their file system
// says so; empty when none does (then the failing step, or the system, must say why)
QString causeAtTarget(const QString &path, bool writing, int savedErrno)
{
    const QFileInfo info(path);
    const QFileInfo folder(info.absolutePath());
    if (path.isEmpty())
        return QStringLiteral("no file name given");
    if (info.isDir())
        return QStringLiteral("it is a folder, not a file");
    // (a link that leads in a circle does not exist either, but is not missing)
    if (!writing && !info.exists())
        return savedErrno != 0 && savedErrno != ENOENT ? systemReason(savedErrno, QString())
                                                       : QStringLiteral("no such file");
    if (writing && !folder.exists())
        return u"the folder "_s + QDir::toNativeSeparators(folder.filePath()) + u" does not exist"_s;
    if (writing && !folder.isDir())
        return QDir::toNativeSeparators(folder.filePath()) + u" is not a folder"_s;
    // a read-only mount before the permission bits, which it makes look closed
    if (writing && (savedErrno == EROFS || onReadOnlyFileSystem(folder.filePath())))
        return u"read-only file system: "_s + QDir::toNativeSeparators(folder.filePath()) +
               u" is on a file system mounted read-only"_s;
    if (!writing && !info.isReadable())
        return QStringLiteral("permission denied: the file is not readable");
    if (writing && info.exists() && !info.isWritable())
        return QStringLiteral("permission denied: the file is read-only");
    if (writing && !folder.isWritable())
        return u"permission denied: cannot create files in "_s + QDir::toNativeSeparators(folder.filePath());
    return {};
}

}  // namespace

QString refuseToReplace(const QString &path)
{
#ifdef Q_OS_UNIX
    // stat, not lstat: a symbolic link is judged by what it points to (a dangling one is nothing yet)
    struct stat status {};
    if (::stat(QFile::encodeName(path).constData(), &status) != 0)
        return {};
    const auto kind = [](mode_t mode) -> const char * {
        if (S_ISREG(mode))
            return nullptr;
        if (S_ISFIFO(mode))
            return "a named pipe (FIFO)";
        if (S_ISCHR(mode))
            return "a character device";
        if (S_ISBLK(mode))
            return "a block device";
        if (S_ISSOCK(mode))
            return "a socket";
        return "something other than a file";
    };
    // a folder in the words the loader uses for one
    if (S_ISDIR(status.st_mode))
        return QStringLiteral("it is a folder, not a file");
    if (const char *what = kind(status.st_mode))
        return QStringLiteral("it is %1, not a regular file").arg(QString::fromLatin1(what));
    return {};
#else
    // elsewhere Qt can only tell a file from a folder from anything else
    const QFileInfo info(path);
    if (!info.exists() || info.isFile())
        return {};
    return info.isDir() ? QStringLiteral("it is a folder, not a file")
                        : QStringLiteral("it is not a regular file");
#endif
}

QString writeFileAtomically(const QString &path, const QByteArray &bytes)
{
    // a device node or a FIFO is refused before anything is written: the rename would replace it
    if (const QString refused = refuseToReplace(path); !refused.isEmpty())
        return refused;

    // QSaveFile writes a temporary file and renames it over the old one only at commit(); when
    // neither the target nor its folder explains a failure to open, making that file beside it
    // failed (in /proc, say), and the message names that step rather than leave the system's
    // reason to seem the target's own
    QSaveFile file(path);
    errno = 0;
    if (!file.open(QIODevice::WriteOnly)) {
        const int savedErrno = errno;
        if (QString cause = causeAtTarget(path, true, savedErrno); !cause.isEmpty())
            return cause;
        return u"cannot create the temporary file beside it in "_s + shownFolder(path) +
               u" (a save writes one there, then renames it over the file): "_s +
               systemReason(savedErrno, file.errorString());
    }
    // errno and Qt's reason are taken before cancelWriting(), which may change both
    const auto fail = [&](int savedErrno) {
        const QString reason = explainFailure(path, true, savedErrno, file.errorString());
        file.cancelWriting();
        return reason;
    };

    // the bytes, then everything Qt still buffers: a full disk shows here, not at commit()
    errno = 0;
    if (file.write(bytes) != bytes.size())
        return fail(errno);
    while (file.bytesToWrite() > 0) {
        errno = 0;
        if (!file.flush())
            return fail(errno);
    }

    // on the disk before the rename, so that a crash cannot leave the new name on unwritten data
#ifdef Q_OS_UNIX
    errno = 0;
    if (::fsync(file.handle()) != 0)
        return fail(errno);
#endif

    // the rename; commit() can still fail (the folder's permissions, a rename across devices)
    errno = 0;
    if (!file.commit()) {
        const int savedErrno = errno;
        if (QString cause = causeAtTarget(path, true, savedErrno); !cause.isEmpty())
            return cause;
        return u"cannot rename the temporary file over it: "_s + systemReason(savedErrno, file.errorString());
    }
    return {};
}

QString systemReason(int savedErrno, const QString &qtReason)
{
    // no permission bit is to blame, and none would help
    if (savedErrno == EROFS)
        return QStringLiteral("read-only file system: nothing on it can be written");
    if (savedErrno != 0)
        return QString::fromStdString(std::generic_category().message(savedErrno));
    return qtReason;
}

QString explainFailure(const QString &path, bool writing, int savedErrno, const QString &qtReason)
{
    if (QString cause = causeAtTarget(path, writing, savedErrno); !cause.isEmpty())
        return cause;
    return systemReason(savedErrno, qtReason);
}

}  // namespace io
