#include "trace_writer.h"

#include <QDir>

#include <array>
#include <charconv>

namespace app {

using namespace Qt::Literals::StringLiterals;

namespace {

// rows are gathered up to this size, then written in one go
constexpr qsizetype kFlushBytes = 1 << 20;

void appendNumber(QByteArray &out, double value)
{
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    out.append(buffer.data(), result.ptr - buffer.data());
}

void appendInteger(QByteArray &out, std::uint64_t value)
{
    std::array<char, 24> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    out.append(buffer.data(), result.ptr - buffer.data());
}

}  // namespace

QString TraceWriter::open(const QString &path)
{
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return QDir::toNativeSeparators(path) + u": cannot write the trace: "_s + m_file.errorString();
    m_buffer = "step,time,particle,x,y,z,vx,vy,vz\n";
    return {};
}

void TraceWriter::writeRows(const core::State &state)
{
    // one row per particle, columns in the header's order
    for (Eigen::Index i = 0; i < state.position.cols(); ++i) {
        appendInteger(m_buffer, state.step);
        m_buffer += ',';
        appendNumber(m_buffer, state.time);
        m_buffer += ',';
        appendInteger(m_buffer, static_cast<std::uint64_t>(i));
        for (int axis = 0; axis < 3; ++axis) {
            m_buffer += ',';
            appendNumber(m_buffer, state.position(axis, i));
        }
        for (int axis = 0; axis < 3; ++axis) {
            m_buffer += ',';
            appendNumber(m_buffer, state.velocity(axis, i));
        }
        m_buffer += '\n';
        ++m_rows;
    }
    if (m_buffer.size() >= kFlushBytes)
        flush();
}

bool TraceWriter::flush()
{
    if (!m_failed && m_file.write(m_buffer) != m_buffer.size())
        m_failed = true;
    m_buffer.clear();
    return !m_failed;
}

QString TraceWriter::close()
{
    const bool written = flush() && m_file.flush();
    const QString reason = m_file.errorString();
    m_file.close();
    if (!written)
        return QDir::toNativeSeparators(m_file.fileName()) + u": cannot write the trace: "_s + reason;
    return {};
}

}  // namespace app
