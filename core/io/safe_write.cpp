#include "safe_write.h"

#include <QFileInfo>

#ifdef Q_OS_UNIX
#include <sys/stat.h>
#endif

namespace io {

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

}  // namespace io
