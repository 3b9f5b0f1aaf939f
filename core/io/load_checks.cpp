#include "load_checks.h"

#include <QLocale>

#include <cstring>

#ifdef Q_OS_UNIX
#include <sys/resource.h>
#endif

namespace io {

namespace {

using namespace Qt::Literals::StringLiterals;

// "UTF-16 text (it starts with the byte order mark FF FE)"
QString markedAs(const char *encoding, QByteArrayView mark)
{
    return QString::fromLatin1(encoding) + u" text (it starts with the byte order mark "_s +
           QString::fromLatin1(mark.toByteArray().toHex(' ').toUpper()) + u")"_s;
}

}  // namespace

QString encodingProblem(QByteArrayView bytes)
{
    const QString saveAsUtf8 = u": save it as UTF-8"_s;

    // a byte order mark of another encoding; UTF-32's little-endian mark begins with UTF-16's
    if (bytes.startsWith(QByteArrayView("\xFF\xFE\x00\x00", 4)))
        return u"the file is "_s + markedAs("UTF-32", bytes.first(4)) + saveAsUtf8;
    if (bytes.startsWith(QByteArrayView("\x00\x00\xFE\xFF", 4)))
        return u"the file is "_s + markedAs("UTF-32", bytes.first(4)) + saveAsUtf8;
    if (bytes.startsWith("\xFF\xFE") || bytes.startsWith("\xFE\xFF"))
        return u"the file is "_s + markedAs("UTF-16", bytes.first(2)) + saveAsUtf8;

    // no mark, but text in ASCII's range with zero bytes between its characters
    const auto at = [&](qsizetype i) { return i < bytes.size() ? bytes[i] : char(1); };
    if (bytes.size() >= 4 && at(0) != 0 && at(1) == 0 && at(2) == 0 && at(3) == 0)
        return u"the file looks like UTF-32 text (little-endian, with no byte order mark)"_s + saveAsUtf8;
    if (bytes.size() >= 4 && at(0) == 0 && at(1) == 0 && at(2) == 0 && at(3) != 0)
        return u"the file looks like UTF-32 text (big-endian, with no byte order mark)"_s + saveAsUtf8;
    if (bytes.size() >= 4 && at(0) != 0 && at(1) == 0 && at(2) != 0 && at(3) == 0)
        return u"the file looks like UTF-16 text (little-endian, with no byte order mark)"_s + saveAsUtf8;
    if (bytes.size() >= 4 && at(0) == 0 && at(1) != 0 && at(2) == 0 && at(3) != 0)
        return u"the file looks like UTF-16 text (big-endian, with no byte order mark)"_s + saveAsUtf8;

    // JSON text never holds a zero byte (one in a string is written \u0000): a binary file, or a
    // device such as /dev/zero
    if (const void *zero = bytes.isEmpty() ? nullptr : std::memchr(bytes.data(), 0, std::size_t(bytes.size())))
        return u"not a text file (byte %1 is a zero byte): a Springlab file is JSON text in UTF-8"_s.arg(
            static_cast<const char *>(zero) - bytes.data());
    return {};
}

QString memoryShortfall()
{
#ifdef Q_OS_UNIX
    // the limit a shell's ulimit sets, which a machine with memory to spare still enforces
    const auto limited = [](int resource, rlim_t &bytes) {
        rlimit limit{};
        if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
            return false;
        bytes = limit.rlim_cur;
        return true;
    };
    const auto size = [](rlim_t bytes) { return QLocale::c().formattedDataSize(qint64(bytes), 1); };
    rlim_t bytes = 0;
    if (limited(RLIMIT_AS, bytes))
        return u"more memory than this process may use (its address space is limited to "_s + size(bytes) +
               u": see ulimit -v)"_s;
    if (limited(RLIMIT_DATA, bytes))
        return u"more memory than this process may use (its data is limited to "_s + size(bytes) + u": see ulimit -d)"_s;
#endif
    return u"more memory than is free"_s;
}

QString cannotLoadForMemory(const QString &sourceName)
{
    return sourceName + u": cannot load: out of memory: reading it needs "_s + memoryShortfall();
}

}  // namespace io
