#pragma once
// What every load of a Springlab file (a scene, a recording) checks around its parsing, so that
// both kinds of file are refused in the same words: bytes that are not UTF-8 text, and a load that
// runs out of memory.

#include <QByteArrayView>
#include <QString>

namespace io {

// why bytes cannot be a Springlab file's JSON text, which is UTF-8, in words; empty when they may
// be. "the file is UTF-16 text (it starts with the byte order mark FF FE): save it as UTF-8",
// "not a text file (byte 0 is a zero byte): ...". A UTF-8 byte order mark is accepted.
QString encodingProblem(QByteArrayView bytes);

// the memory a load could not have: "more memory than this process may use (its address space
// is limited to 2.9 GiB: see ulimit -v)" when the process has such a limit, which binds however
// much the machine has free, else "more memory than is free"
QString memoryShortfall();

// "FILE: cannot load: out of memory: reading it needs " + memoryShortfall(), the message of a load
// that ran out of memory, whichever kind of file it read
QString cannotLoadForMemory(const QString &sourceName);

}  // namespace io
