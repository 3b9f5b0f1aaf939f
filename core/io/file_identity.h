#pragma once
// Whether two paths name one file, judged by the file and not by how its path is spelt. A check
// that compares paths misses a hard link, a bind mount of the folder, or another case of the name
// on a file system that ignores case, and a write meant for a new file then truncates the one
// being read. So, as coreutils does for "are the same file", two files that exist are one
// when they have the same device and inode; that covers hard links, symbolic links, bind mounts,
// "./x" beside "x" and another case of an existing name alike. Every program that writes a file
// it was given checks it with this against the files it reads and the others it writes.

#include <QString>

namespace io {

// whether a and b name one file. Both there: the same device and inode, links followed. One or
// both not there yet: whether writing them would make one file, that is, the nearest folders that
// are there are one folder (by device and inode) and the names below it are the same (a dangling
// symbolic link counts as the path it points to). Names that are not there yet are compared as
// written, case included: on a file system that ignores case, "Out.csv" and "out.csv", neither
// there yet, count as two (an existing file is found by either name, so it is never missed). A
// path that cannot be looked at (a folder without search permission) falls back to its cleaned
// absolute spelling.
bool sameFile(const QString &a, const QString &b);

}  // namespace io
