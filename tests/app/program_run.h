#pragma once
// Runs one of Springlab's programs to completion for the end-to-end tests and keeps what it said.

#include <QByteArray>
#include <QProcess>
#include <QStringList>

namespace test {

struct ProgramRun {
    int exitCode = -1;  // -1: it did not finish in time, or crashed
    QByteArray out;
    QByteArray err;
};

// this process's environment with the offscreen platform (the benchmarks draw their plots with
// QPainter and need no display)
inline QProcessEnvironment offscreenEnvironment()
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    return environment;
}

// program with arguments, in that environment unless told otherwise, waiting at most timeoutMs
inline ProgramRun runProgram(const QString &program, const QStringList &arguments, int timeoutMs = 600000,
                             const QProcessEnvironment &environment = offscreenEnvironment())
{
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(program, arguments);
    ProgramRun run;
    if (!process.waitForFinished(timeoutMs) || process.exitStatus() != QProcess::NormalExit)
        return run;
    run.exitCode = process.exitCode();
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

}  // namespace test
