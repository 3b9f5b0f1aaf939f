// load_peak FILE: loads a scene file and prints the process's resident memory before loading and
// its peak after, in KiB ("rss BEFORE peak AFTER"), then "ok" or the loader's message.
// test_scene_memory runs it in a process of its own, so that the peak is the load's alone.
#include "core/io/scene_file.h"

#include <QFile>

#include <cstdio>
#include <cstring>

namespace {

// a "Name:   1234 kB" line of /proc/self/status, in KiB; -1 when there is none
long statusKib(const char *name)
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n'))
        if (line.startsWith(name))
            return line.mid(qsizetype(std::strlen(name))).trimmed().split(' ').value(0).toLong();
    return -1;
}

}  // namespace

int main(int argc, char *argv[])
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: load_peak FILE\n");
        return 2;
    }
    const long before = statusKib("VmRSS:");
    const io::LoadResult loaded = io::loadScene(QString::fromLocal8Bit(argv[1]));
    std::printf("rss %ld peak %ld\n%s\n", before, statusKib("VmHWM:"), loaded.ok() ? "ok" : qPrintable(loaded.error));
    return 0;
}
