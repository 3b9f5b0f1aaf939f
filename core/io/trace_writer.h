#pragma once
// Trace files: CSV with a header, then one row per particle for each traced step. springlab-sim
// --trace writes them from the core's State (every double as the shortest text that reads back as
// the same bits); the editor's File › Export › Trace CSV writes them from Snapshots, whose floats
// are written the same way as floats. Both have the same header.

#include "core/model/snapshot.h"
#include "core/model/state.h"

#include <QByteArray>
#include <QFile>
#include <QString>

namespace io {

// the header, and what each row holds
inline constexpr const char *kTraceHeader = "step,time,particle,x,y,z,vx,vy,vz";

class TraceWriter {
public:
    // opens (truncates) the file and writes the header; empty on success, else the message
    QString open(const QString &path);

    // one row per particle: step,time,particle,x,y,z,vx,vy,vz
    void writeRows(const core::State &state);
    // the same from a snapshot; a snapshot without velocities writes them as 0
    void writeRows(const core::Snapshot &snapshot);

    // writes what is buffered and closes the file; empty on success, else the message
    QString close();

    std::uint64_t rowCount() const { return m_rows; }

private:
    template <typename Value>
    void writeRow(std::uint64_t step, double time, std::uint64_t particle, const Value *position,
                  const Value *velocity);
    bool flush();
    // the first failure, with the system's reason taken where it happened ("No space left on
    // device"), since Qt's own string has lost it by the time the trace is closed
    void fail(int savedErrno);

    QFile m_file;
    QByteArray m_buffer;
    std::uint64_t m_rows = 0;
    bool m_failed = false;
    QString m_reason;  // why, once m_failed
};

}  // namespace io
