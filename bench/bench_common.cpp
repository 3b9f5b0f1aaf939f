#include "bench_common.h"

#include <QByteArray>
#include <QFile>
#include <QSaveFile>
#include <QThread>

#include <algorithm>
#include <cstdint>
#include <ctime>

namespace bench {

QString machineDescription()
{
    QString model = QStringLiteral("unknown CPU");
    QFile cpuinfo(QStringLiteral("/proc/cpuinfo"));
    if (cpuinfo.open(QIODevice::ReadOnly | QIODevice::Text))
        for (const QByteArray &line : cpuinfo.readAll().split('\n'))
            if (line.startsWith("model name")) {
                model = QString::fromUtf8(line.mid(line.indexOf(':') + 1).trimmed());
                break;
            }
    return QStringLiteral("%1, %2 logical cores").arg(model).arg(QThread::idealThreadCount());
}

double cpuSeconds()
{
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

RunClock::RunClock() : m_cpuStart(cpuSeconds())
{
    m_wall.start();
}

QString RunClock::text() const
{
    return QStringLiteral("%1 s wall, %2 s CPU")
        .arg(m_wall.elapsed() / 1000.0, 0, 'f', 0)
        .arg(cpuSeconds() - m_cpuStart, 0, 'f', 0);
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

QString nameOf(core::Integrator integrator)
{
    const std::string_view name = core::integratorName(integrator);
    return QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size()));
}

double loadAverage()
{
    QFile file(QStringLiteral("/proc/loadavg"));
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return -1.0;
    bool ok = false;
    const double load = file.readLine().split(' ').value(0).toDouble(&ok);
    return ok ? load : -1.0;
}

QString loadText()
{
    const double load = loadAverage();
    if (load < 0.0)
        return QStringLiteral("unknown");
    QString text = QString::number(load, 'f', 2);
    if (load > 0.5 * QThread::idealThreadCount())
        text += QStringLiteral(" (busy: other work competes for the cores, so the times are pessimistic)");
    return text;
}

std::optional<QDir> outputFolder(const QString &path, QTextStream &out)
{
    const QDir dir(path);
    if (dir.mkpath(QStringLiteral(".")))
        return dir;
    out << "springlab-bench: cannot create the folder " << path << '\n';
    return std::nullopt;
}

bool writeLines(const QDir &dir, const QString &name, const QStringList &lines, QTextStream &out)
{
    QSaveFile file(dir.filePath(name));
    if (!file.open(QIODevice::WriteOnly) || file.write((lines.join('\n') + '\n').toUtf8()) < 0 || !file.commit()) {
        out << "cannot write " << file.fileName() << '\n';
        return false;
    }
    out << "wrote " << file.fileName() << '\n';
    return true;
}

BusyCore::BusyCore()
    : m_thread([this] {
          volatile std::uint64_t spins = 0;
          while (!m_stop.load(std::memory_order_relaxed))
              spins = spins + 1;
      })
{
}

BusyCore::~BusyCore()
{
    m_stop = true;
    m_thread.join();
}

}  // namespace bench
