#pragma once
// Writing a file so that a failure never costs the old one. Every save of the program (scenes,
// autosave, recordings, exports) comes through here, so a fix to how files are written is made once.

#include <QString>

namespace io {

// why a save must not replace what is at path, in words ("it is a named pipe (FIFO), not a regular
// file"); empty when a save may go ahead: nothing is there, or a regular file, or a symbolic link to
// one. A save writes a temporary file and renames it over the target, which would turn a device
// node or a FIFO into a plain file, so anything else is refused before any file is touched.
QString refuseToReplace(const QString &path);

}  // namespace io
