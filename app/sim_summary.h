#pragma once
// The summary of one springlab-sim run as data, written with --summary-json (one JSON object) or
// --summary-csv (one row under the header --summary-csv-header prints), so that a sweep's runs join
// into one table (docs/batch.md). One list of fields makes both, so the JSON keys and the CSV
// columns are the same names in the same order.

#include "core/model/diagnostics.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <cstddef>
#include <cstdint>

namespace app {

struct RunSummary {
    QString scene;           // the path as given
    QJsonObject overrides;   // "settings.restitution": 0.5, from --set and the settings' options
    int exitCode = 0;        // as springlab-sim exits: 0, 2, 3
    QString error;           // why it failed (a blow-up explained); empty when it did not
    QStringList warnings;    // the file's and the run's

    // what the run did; null in the summary while ran is false (a bad file or --set)
    bool ran = false;
    QString integrator;
    QString contactSolver;
    double timeStep = 0.0;  // s
    int substeps = 0;       // per step, as run (auto substeps may raise the file's)
    std::uint64_t stepsRequested = 0;
    std::uint64_t steps = 0;  // run: fewer than requested when it blew up
    double simulatedTime = 0.0;  // s
    double wallTime = 0.0;       // s, stepping alone
    core::Energies start;        // J
    core::Energies end;          // J
    std::size_t springBreaks = 0;
};

// the exit code in a word: "ok", "bad-input", "blew-up", "replay-differs"
QString statusWord(int exitCode);

// the overrides as --set spells them, one after another: "settings.restitution=0.5 springs.damping=2"
QString overridesText(const QJsonObject &overrides);

// the summary as one JSON object, indented, ending in a newline
QByteArray summaryJson(const RunSummary &summary);

// the CSV header, and the summary as one row under it; each ends in a newline
QByteArray summaryCsvHeader();
QByteArray summaryCsvRow(const RunSummary &summary);

// writes the summary to each path that is not empty, atomically (core/io/safe_write.h); empty on
// success, else "FILE: cannot save: why"
QString saveSummary(const RunSummary &summary, const QString &jsonPath, const QString &csvPath);

}  // namespace app
