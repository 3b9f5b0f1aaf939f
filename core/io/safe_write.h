#pragma once
// Writing a file so that a failure never costs the old one. Every save of the program (scenes,
// autosave, recordings, exports) comes through here, so a fix to how files are written is made once.

#include <QByteArray>
#include <QString>

namespace io {

// why a save must not replace what is at path, in words ("it is a named pipe (FIFO), not a regular
// file"); empty when a save may go ahead: nothing is there, or a regular file, or a symbolic link to
// one. A save writes a temporary file and renames it over the target, which would turn a device
// node or a FIFO into a plain file, so anything else is refused before any file is touched.
QString refuseToReplace(const QString &path);

// writes bytes to path atomically: into a temporary file beside it, flushed and synced to the disk,
// then renamed over it. Empty on success; else why not, and the old file is as it was; a failure
// to make the temporary file or to rename it names that step ("cannot create the temporary file
// beside it in /proc (...): No such file or directory"). Every step is checked, because Qt 6.4
// buffers a small write and QSaveFile::commit() does not report the flush that fails on a full
// disk (QTBUG-75077): it renamed a truncated file over the old one.
QString writeFileAtomically(const QString &path, const QByteArray &bytes);

// why a file could not be read or written, in words: what the file, its folder or their file
// system shows ("permission denied: the file is read-only", "read-only file system: FOLDER is on a
// file system mounted read-only"), else systemReason()
QString explainFailure(const QString &path, bool writing, int savedErrno, const QString &qtReason);

// errno (savedErrno) in words, when set, else Qt's reason: the system's words ("No such file or
// directory"), but for EROFS "read-only file system: nothing on it can be written"
QString systemReason(int savedErrno, const QString &qtReason);

}  // namespace io
