#include "trace_writer.h"

#include "safe_write.h"

#include <QDir>

#include <cerrno>

#include <array>
#include <charconv>

namespace io {

using namespace Qt::Literals::StringLiterals;

namespace {

// rows are gathered up to this size, then written in one go
constexpr qsizetype kFlushBytes = 1 << 20;

// the shortest text that reads back as the same value (a float as a float, a double as a double)
template <typename Number>
void appendNumber(QByteArray &out, Number value)
{
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    out.append(buffer.data(), result.ptr - buffer.data());
}

}  // namespace

QString TraceWriter::open(const QString &path)
{
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return QDir::toNativeSeparators(path) + u": cannot write the trace: "_s + m_file.errorString();
    m_buffer = kTraceHeader;
    m_buffer += '\n';
    return {};
}

template <typename Value>
void TraceWriter::writeRow(std::uint64_t step, double time, std::uint64_t particle, const Value *position,
                           const Value *velocity)
{
    // columns in the header's order
    appendNumber(m_buffer, step);
    m_buffer += ',';
    appendNumber(m_buffer, time);
    m_buffer += ',';
    appendNumber(m_buffer, particle);
    for (int axis = 0; axis < 3; ++axis) {
        m_buffer += ',';
        appendNumber(m_buffer, position[axis]);
    }
    for (int axis = 0; axis < 3; ++axis) {
        m_buffer += ',';
        appendNumber(m_buffer, velocity ? velocity[axis] : Value(0));
    }
    m_buffer += '\n';
    ++m_rows;
    if (m_buffer.size() >= kFlushBytes)
        flush();
}

void TraceWriter::writeRows(const core::State &state)
{
    // the state's columns are one particle's xyz each
    for (Eigen::Index i = 0; i < state.position.cols(); ++i)
        writeRow(state.step, state.time, static_cast<std::uint64_t>(i), state.position.col(i).data(),
                 state.velocity.col(i).data());
}

void TraceWriter::writeRows(const core::Snapshot &snapshot)
{
    const std::size_t n = snapshot.positions.size() / 3;
    const bool withVelocities = snapshot.velocities.size() >= 3 * n;
    for (std::size_t i = 0; i < n; ++i)
        writeRow(snapshot.step, snapshot.time, i, snapshot.positions.data() + 3 * i,
                 withVelocities ? snapshot.velocities.data() + 3 * i : nullptr);
}

bool TraceWriter::flush()
{
    errno = 0;
    if (!m_failed && m_file.write(m_buffer) != m_buffer.size())
        fail(errno);
    m_buffer.clear();
    return !m_failed;
}

void TraceWriter::fail(int savedErrno)
{
    if (m_failed)
        return;
    m_failed = true;
    m_reason = explainFailure(m_file.fileName(), true, savedErrno, m_file.errorString());
}

QString TraceWriter::close()
{
    // the rows, then whatever Qt still buffers: a full disk may show only here
    flush();
    while (!m_failed && m_file.bytesToWrite() > 0) {
        errno = 0;
        if (!m_file.flush())
            fail(errno);
    }
    m_file.close();
    if (m_failed)
        return QDir::toNativeSeparators(m_file.fileName()) + u": cannot write the trace: "_s + m_reason;
    return {};
}

}  // namespace io
