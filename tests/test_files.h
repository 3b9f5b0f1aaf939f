#pragma once
// What many tests do with files: read one whole, write one whole, and write text in another
// encoding. Header-only, for tests in any folder.

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QStringEncoder>

namespace test {

// a file's bytes, or none when it cannot be read
inline QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// true when every byte was written and flushed
inline bool writeAll(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size() && file.flush();
}

// UTF-8 text in another encoding, with its byte order mark or without
inline QByteArray encoded(const QByteArray &utf8, QStringConverter::Encoding encoding, bool mark)
{
    QStringEncoder encoder(encoding, mark ? QStringConverter::Flag::WriteBom : QStringConverter::Flag::Default);
    return encoder.encode(QString::fromUtf8(utf8));
}

}  // namespace test
