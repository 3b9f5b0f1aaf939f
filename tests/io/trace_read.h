#pragma once
// What the tests of trace files share: reading one back, header and rows, and its numbers as the
// exact float or double they were written from.

#include <QByteArray>
#include <QFile>
#include <QList>

#include <charconv>

namespace test {

// the rows of a trace file split into fields, and its header; empty when it cannot be read or
// does not end with a newline
inline QList<QList<QByteArray>> readTraceRows(const QString &path, QByteArray *header)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QList<QByteArray> lines = file.readAll().split('\n');
    if (lines.size() < 2 || !lines.last().isEmpty())
        return {};
    lines.removeLast();
    *header = lines.takeFirst();
    QList<QList<QByteArray>> rows;
    for (const QByteArray &line : lines)
        rows << line.split(',');
    return rows;
}

// a field as the number it was written from (a float as a float, a double as a double)
template <typename Number>
Number parseNumber(const QByteArray &text)
{
    Number value{};
    std::from_chars(text.constData(), text.constData() + text.size(), value);
    return value;
}

}  // namespace test
