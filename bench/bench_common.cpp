#include "bench_common.h"

#include <QByteArray>
#include <QFile>
#include <QThread>
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

}  // namespace bench
