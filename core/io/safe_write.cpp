#include "safe_write.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <cerrno>
#include <system_error>

#ifdef Q_OS_UNIX
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace io {

using namespace Qt::Literals::StringLiterals;

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

    // QSaveFile writes a temporary file and renames it over the old one only at commit()
    QSaveFile file(path);
    errno = 0;
    if (!file.open(QIODevice::WriteOnly))
        return explainFailure(path, true, errno, file.errorString());
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
    if (!file.commit())
        return explainFailure(path, true, errno, file.errorString());
    return {};
}

QString explainFailure(const QString &path, bool writing, int savedErrno, const QString &qtReason)
{
    const QFileInfo info(path);
    const QFileInfo folder(info.absolutePath());
    if (path.isEmpty())
        return QStringLiteral("no file name given");
    if (info.isDir())
        return QStringLiteral("it is a folder, not a file");
    // (a link that leads in a circle does not exist either, but is not missing)
    if (!writing && !info.exists())
        return savedErrno != 0 && savedErrno != ENOENT ? QString::fromStdString(std::generic_category().message(savedErrno))
                                                       : QStringLiteral("no such file");
    if (writing && !folder.exists())
        return u"the folder "_s + QDir::toNativeSeparators(folder.filePath()) + u" does not exist"_s;
    if (writing && !folder.isDir())
        return QDir::toNativeSeparators(folder.filePath()) + u" is not a folder"_s;
    if (!writing && !info.isReadable())
        return QStringLiteral("permission denied: the file is not readable");
    if (writing && info.exists() && !info.isWritable())
        return QStringLiteral("permission denied: the file is read-only");
    if (writing && !folder.isWritable())
        return u"permission denied: cannot create files in "_s + QDir::toNativeSeparators(folder.filePath());
    if (savedErrno != 0)
        return QString::fromStdString(std::generic_category().message(savedErrno));
    return qtReason;
}

}  // namespace io
