// io::sameFile: two paths name one file when they reach the same inode, however they are spelt
// (the path itself, "./x" beside "x", a symbolic link, a hard link, a bind mount of the folder),
// and two files are two even with the same bytes. A file not there yet is the same as another
// when writing either would make one file: the same folder, by identity, and the same name.

#include "core/io/file_identity.h"

#include <QDir>
#include <QFile>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <cstring>
#include <memory>

#include <sched.h>
#include <sys/mount.h>
#include <unistd.h>

using namespace Qt::Literals::StringLiterals;

namespace {

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

}  // namespace

class TestFileIdentity : public QObject {
    Q_OBJECT

private slots:
    void init();

    void aPathIsItsOwnFile();
    void dotSlashIsTheSameFile();
    void symbolicLinkIsTheSameFile();
    void hardLinkIsTheSameFile();
    void twoFilesAreTwoEvenWithTheSameBytes();
    void aNewFileBySpellingsOfOneFolderIsOne();
    void newFilesOfDistinctNamesAreTwo();
    void aDanglingLinkIsTheFileItWouldMake();
    void bindMountIsTheSameFile();

private:
    QString path(const QString &name) const { return m_dir->filePath(name); }

    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestFileIdentity::init()
{
    // a folder with one file and one subfolder, fresh for each test
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    QVERIFY(writeFile(path(u"scene.json"_s), "{}"));
    QVERIFY(QDir(m_dir->path()).mkdir(u"sub"_s));
}

void TestFileIdentity::aPathIsItsOwnFile()
{
    QVERIFY(io::sameFile(path(u"scene.json"_s), path(u"scene.json"_s)));
    QVERIFY(io::sameFile(path(u"new.csv"_s), path(u"new.csv"_s)));
    // an empty path names no file
    QVERIFY(!io::sameFile(QString(), QString()));
    QVERIFY(!io::sameFile(path(u"scene.json"_s), QString()));
}

void TestFileIdentity::dotSlashIsTheSameFile()
{
    // relative to the working folder, and absolute
    const QString before = QDir::currentPath();
    QVERIFY(QDir::setCurrent(m_dir->path()));
    const auto back = qScopeGuard([&] { QDir::setCurrent(before); });
    QVERIFY(io::sameFile(u"./scene.json"_s, u"scene.json"_s));
    QVERIFY(io::sameFile(u"scene.json"_s, path(u"scene.json"_s)));
    QVERIFY(io::sameFile(u"sub/../scene.json"_s, u"scene.json"_s));
    QVERIFY(io::sameFile(u".//scene.json"_s, m_dir->path() + u"/./scene.json"_s));
    // and for a file not there yet
    QVERIFY(io::sameFile(u"./new.csv"_s, u"new.csv"_s));
    QVERIFY(io::sameFile(u"new.csv"_s, path(u"new.csv"_s)));
}

void TestFileIdentity::symbolicLinkIsTheSameFile()
{
    // a link to the file, and a file through a link to its folder
    QVERIFY(QFile::link(path(u"scene.json"_s), path(u"link.csv"_s)));
    QVERIFY(io::sameFile(path(u"link.csv"_s), path(u"scene.json"_s)));
    QVERIFY(io::sameFile(path(u"scene.json"_s), path(u"link.csv"_s)));
    QVERIFY(QFile::link(m_dir->path(), path(u"sub/up"_s)));
    QVERIFY(io::sameFile(path(u"sub/up/scene.json"_s), path(u"scene.json"_s)));
    QVERIFY(io::sameFile(path(u"sub/up/new.csv"_s), path(u"new.csv"_s)));
    // ".." after a link to a folder goes up from where the link leads, not lexically
    QVERIFY(writeFile(path(u"sub/inner.json"_s), "{}"));
    QVERIFY(QDir(m_dir->path()).mkpath(u"sub/deeper"_s));
    QVERIFY(QFile::link(path(u"sub/deeper"_s), path(u"jump"_s)));
    QVERIFY(io::sameFile(path(u"jump/../inner.json"_s), path(u"sub/inner.json"_s)));
    QVERIFY(!io::sameFile(path(u"jump/../inner.json"_s), path(u"inner.json"_s)));
    // a relative link, resolved from its own folder
    QVERIFY(QFile::link(u"../scene.json"_s, path(u"sub/relative"_s)));
    QVERIFY(io::sameFile(path(u"sub/relative"_s), path(u"scene.json"_s)));
}

void TestFileIdentity::hardLinkIsTheSameFile()
{
    QVERIFY2(::link(QFile::encodeName(path(u"scene.json"_s)).constData(),
                    QFile::encodeName(path(u"sub/alias.csv"_s)).constData()) == 0,
             std::strerror(errno));
    QVERIFY(io::sameFile(path(u"sub/alias.csv"_s), path(u"scene.json"_s)));
    // two links of one file, neither of them the scene
    QVERIFY(::link(QFile::encodeName(path(u"sub/alias.csv"_s)).constData(),
                   QFile::encodeName(path(u"other.txt"_s)).constData()) == 0);
    QVERIFY(io::sameFile(path(u"other.txt"_s), path(u"sub/alias.csv"_s)));
}

void TestFileIdentity::twoFilesAreTwoEvenWithTheSameBytes()
{
    QVERIFY(QFile::copy(path(u"scene.json"_s), path(u"copy.json"_s)));
    QVERIFY(!io::sameFile(path(u"copy.json"_s), path(u"scene.json"_s)));
    QVERIFY(!io::sameFile(path(u"sub"_s), path(u"scene.json"_s)));
    // a file there and one not there yet
    QVERIFY(!io::sameFile(path(u"scene.json"_s), path(u"sub/scene.json"_s)));
    // a name below a file is not that file (nothing can be written there)
    QVERIFY(!io::sameFile(path(u"scene.json/x"_s), path(u"scene.json"_s)));
}

void TestFileIdentity::aNewFileBySpellingsOfOneFolderIsOne()
{
    const QString plain = path(u"sub/out.csv"_s);
    QVERIFY(io::sameFile(m_dir->path() + u"/sub/../sub/out.csv"_s, plain));
    QVERIFY(io::sameFile(m_dir->path() + u"/sub/./out.csv"_s, plain));
    QVERIFY(io::sameFile(m_dir->path() + u"//sub//out.csv"_s, plain));
    // in a folder not there yet either
    QVERIFY(io::sameFile(path(u"new/deeper/out.csv"_s), path(u"new/./deeper/out.csv"_s)));
    QVERIFY(io::sameFile(path(u"new/x/../out.csv"_s), path(u"new/out.csv"_s)));
}

void TestFileIdentity::newFilesOfDistinctNamesAreTwo()
{
    QVERIFY(!io::sameFile(path(u"sub/a.csv"_s), path(u"sub/b.csv"_s)));
    QVERIFY(!io::sameFile(path(u"sub/a.csv"_s), path(u"a.csv"_s)));
    QVERIFY(!io::sameFile(path(u"new/a.csv"_s), path(u"other/a.csv"_s)));
    // names not there yet are compared as written, case included
    QVERIFY(!io::sameFile(path(u"Out.csv"_s), path(u"out.csv"_s)));
}

void TestFileIdentity::aDanglingLinkIsTheFileItWouldMake()
{
    // writing through the link makes sub/later.json: the same file as that path
    QVERIFY(QFile::link(path(u"sub/later.json"_s), path(u"dangling"_s)));
    QVERIFY(io::sameFile(path(u"dangling"_s), path(u"sub/later.json"_s)));
    QVERIFY(!io::sameFile(path(u"dangling"_s), path(u"sub/sooner.json"_s)));
    // a loop of links is no file, and is not the same as a file
    QVERIFY(QFile::link(path(u"loop-b"_s), path(u"loop-a"_s)));
    QVERIFY(QFile::link(path(u"loop-a"_s), path(u"loop-b"_s)));
    QVERIFY(!io::sameFile(path(u"loop-a"_s), path(u"scene.json"_s)));
}

void TestFileIdentity::bindMountIsTheSameFile()
{
    // the folder mounted again at sub/mounted: one inode under two paths that no link explains.
    // That takes a mount namespace of this test's own (root, or CAP_SYS_ADMIN), made private so
    // that nothing mounted here is seen outside
    if (::unshare(CLONE_NEWNS) != 0)
        QSKIP(qPrintable(u"no mount namespace here (%1): bind mounts are not tested"_s
                             .arg(QString::fromLocal8Bit(std::strerror(errno)))));
    if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0)
        QSKIP("the mount namespace cannot be made private: bind mounts are not tested");
    const QByteArray source = QFile::encodeName(path(u"sub"_s));
    const QByteArray target = QFile::encodeName(path(u"mounted"_s));
    QVERIFY(QDir(m_dir->path()).mkdir(u"mounted"_s));
    if (::mount(source.constData(), target.constData(), nullptr, MS_BIND, nullptr) != 0)
        QSKIP(qPrintable(u"bind mounts are not permitted here (%1)"_s.arg(QString::fromLocal8Bit(std::strerror(errno)))));
    const auto unmount = qScopeGuard([&] { ::umount2(target.constData(), MNT_DETACH); });

    QVERIFY(writeFile(path(u"sub/inside.json"_s), "{}"));
    QVERIFY(QFile::exists(path(u"mounted/inside.json"_s)));
    QVERIFY(io::sameFile(path(u"mounted/inside.json"_s), path(u"sub/inside.json"_s)));
    QVERIFY(io::sameFile(path(u"mounted/new.csv"_s), path(u"sub/new.csv"_s)));
    QVERIFY(!io::sameFile(path(u"mounted/inside.json"_s), path(u"scene.json"_s)));
}

QTEST_GUILESS_MAIN(TestFileIdentity)
#include "test_file_identity.moc"
