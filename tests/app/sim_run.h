#pragma once
// What the end-to-end tests of springlab-sim share: a run of the program (SPRINGLAB_SIM, defined by
// the test's CMake target) and reading back the files it wrote.

#include "program_run.h"
#include "../test_files.h"

#include <QByteArray>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace test {

// springlab-sim with these arguments, in the offscreen environment, waiting up to two minutes
inline ProgramRun sim(const QStringList &arguments)
{
    return runProgram(QStringLiteral(SPRINGLAB_SIM), arguments, 120000);
}

// a JSON file's top-level object (empty when it is not one)
inline QJsonObject readJson(const QString &path)
{
    return QJsonDocument::fromJson(readAll(path)).object();
}

}  // namespace test
