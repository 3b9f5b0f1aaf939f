#pragma once
// The --trace file: CSV with a header, then one row per particle for each traced step, every
// double written as the shortest text that reads back as the same bits.

#include "core/state.h"

#include <QByteArray>
#include <QFile>
#include <QString>

namespace app {

class TraceWriter {
public:
    // opens (truncates) the file and writes the header; empty on success, else the message
    QString open(const QString &path);

    // one row per particle: step,time,particle,x,y,z,vx,vy,vz
    void writeRows(const core::State &state);

    // writes what is buffered and closes the file; empty on success, else the message
    QString close();

    std::uint64_t rowCount() const { return m_rows; }

private:
    bool flush();

    QFile m_file;
    QByteArray m_buffer;
    std::uint64_t m_rows = 0;
    bool m_failed = false;
};

}  // namespace app
