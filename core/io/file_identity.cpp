#include "file_identity.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#ifdef Q_OS_UNIX
#include <QByteArrayList>

#include <cerrno>
#include <optional>

#include <sys/stat.h>
#include <unistd.h>
#endif

namespace io {

namespace {

// the old comparison, for where the file system cannot be asked: the paths, links resolved where
// the file is there, else as written
bool sameSpelling(const QString &a, const QString &b)
{
    const QFileInfo first(a), second(b);
    if (first.exists() && second.exists())
        return first.canonicalFilePath() == second.canonicalFilePath();
    return QDir::cleanPath(first.absoluteFilePath()) == QDir::cleanPath(second.absoluteFilePath());
}

#ifdef Q_OS_UNIX

// symbolic links followed before giving up: the kernel's own limit (MAXSYMLINKS)
constexpr int kMaxLinks = 40;

// where a path leads: the deepest file or folder on it that is there, by device and inode, and
// the names below that are not there yet
struct Location {
    dev_t device = 0;
    ino_t inode = 0;
    QByteArrayList missing;

    bool operator==(const Location &) const = default;
};

// "." dropped and ".." taken back among the names that are not there: the kernel would refuse
// such a path anyway, and it is "the same" as its plain spelling for a check that errs on refusing
QByteArrayList plainNames(const QByteArrayList &names)
{
    QByteArrayList plain;
    for (const QByteArray &name : names) {
        if (name == ".")
            continue;
        if (name == ".." && !plain.isEmpty() && plain.back() != "..")
            plain.pop_back();
        else
            plain << name;
    }
    return plain;
}

// nullopt when the path cannot be looked at (no permission, a loop of links, too long)
std::optional<Location> locate(const QString &given)
{
    QByteArray path = QFile::encodeName(given);
    if (!path.startsWith('/'))
        path = QFile::encodeName(QDir::currentPath()) + '/' + path;
    QByteArrayList missing;  // in order, below the path looked at
    int links = 0;
    while (true) {
        while (path.size() > 1 && path.endsWith('/'))
            path.chop(1);
        struct stat status {};
        if (::stat(path.constData(), &status) == 0)
            return Location{status.st_dev, status.st_ino, plainNames(missing)};
        // a name that is not there (or a file where a folder should be) is looked past; any other
        // failure leaves the question open
        if (errno != ENOENT && errno != ENOTDIR)
            return std::nullopt;
        if (path == "/")
            return std::nullopt;

        // a dangling symbolic link: a write through it makes the file it points to
        struct stat link {};
        if (::lstat(path.constData(), &link) == 0 && S_ISLNK(link.st_mode)) {
            if (++links > kMaxLinks)
                return std::nullopt;
            QByteArray target(link.st_size > 0 ? qsizetype(link.st_size) + 1 : 4096, '\0');
            const ssize_t length = ::readlink(path.constData(), target.data(), std::size_t(target.size()));
            if (length <= 0 || length >= target.size())
                return std::nullopt;
            target.truncate(length);
            if (!target.startsWith('/'))
                target = path.left(path.lastIndexOf('/') + 1) + target;
            path = target;
            continue;
        }

        // else its folder is looked at next, and the name joins the ones not there
        const qsizetype slash = path.lastIndexOf('/');
        missing.prepend(path.mid(slash + 1));
        path = slash == 0 ? QByteArray("/") : path.left(slash);
    }
}

#endif

}  // namespace

bool sameFile(const QString &a, const QString &b)
{
    if (a.isEmpty() || b.isEmpty())
        return false;
#ifdef Q_OS_UNIX
    const std::optional<Location> first = locate(a);
    const std::optional<Location> second = locate(b);
    if (first && second)
        return *first == *second;
#endif
    return sameSpelling(a, b);
}

}  // namespace io
