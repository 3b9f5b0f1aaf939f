#pragma once
// The process's address space capped at what it has mapped now plus some room, for as long as the
// cap lives (RLIMIT_AS, as `ulimit -v` sets it): an allocation past it throws std::bad_alloc. For
// the tests of what running out of memory does; not under the sanitizers, which reserve terabytes.

#include <QFile>
#include <QRegularExpression>

#include <cstddef>

#include <sys/resource.h>

namespace test {

class AddressSpaceCap {
public:
    explicit AddressSpaceCap(std::size_t room)
    {
        getrlimit(RLIMIT_AS, &m_before);
        QFile status(QStringLiteral("/proc/self/status"));
        if (!status.open(QIODevice::ReadOnly))
            return;
        const QRegularExpressionMatch size =
            QRegularExpression(QStringLiteral("VmSize:\\s*(\\d+) kB")).match(QString::fromLatin1(status.readAll()));
        if (!size.hasMatch())
            return;
        rlimit capped = m_before;
        capped.rlim_cur = static_cast<rlim_t>(size.captured(1).toULongLong() * 1024 + room);
        m_capped = setrlimit(RLIMIT_AS, &capped) == 0;
    }
    ~AddressSpaceCap() { setrlimit(RLIMIT_AS, &m_before); }
    AddressSpaceCap(const AddressSpaceCap &) = delete;
    AddressSpaceCap &operator=(const AddressSpaceCap &) = delete;
    bool capped() const { return m_capped; }

private:
    rlimit m_before{};
    bool m_capped = false;
};

}  // namespace test
