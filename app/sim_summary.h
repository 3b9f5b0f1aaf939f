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

// how a run ended, each in a word of its own (statusWord), so that a sweep's table tells them
// apart; several share an exit code (docs/batch.md, "What the exit codes say")
enum class RunStatus {
    Ok,             // the run went to its end and wrote all it was asked to
    BadInput,       // the file, an option or a --set was refused before the run: nothing ran
    OutOfMemory,    // loading the scene, or a step, needed more memory than the process may use
    WriteFailed,    // --output, --trace, a --render frame or the printed report could not be
                    // written; the figures say how far the run got (null: not to the first step)
    BlewUp,         // a position or velocity stopped being finite or passed the state limit
    ReplayDiffers,  // a --replay did not end with the recorded state
};

struct RunSummary {
    QString scene;           // the path as given
    QJsonObject overrides;   // "settings.restitution": 0.5, from --set and the settings' options
    RunStatus status = RunStatus::Ok;
    int exitCode = 0;        // as springlab-sim exits: 0, 2, 3
    QString error;           // why it failed (a blow-up explained); empty when it did not
    QStringList warnings;    // the file's and the run's

    // what the run did, as far as it went; null in the summary while ran is false (a bad file or
    // --set, or memory that ran out while loading). An energy that is not known (the end of a step
    // that ran out of memory half-way) is NaN, null in the summary
    bool ran = false;
    QString integrator;
    QString contactSolver;
    double timeStep = 0.0;  // s
    int substeps = 0;       // per step, as run (auto substeps may raise the file's)
    std::uint64_t stepsRequested = 0;
    std::uint64_t steps = 0;  // run: fewer than requested when it blew up
    double simulatedTime = 0.0;  // s
    double wallTime = 0.0;       // s, stepping alone
    int threads = 0;             // the threads the last steps ran on (core::ThreadChooser's choice)
    core::Energies start;        // J
    core::Energies end;          // J
    std::size_t springBreaks = 0;
    // implicit-euler's, projective's and vbd's solves (null in the summary for the others): the
    // mean and most iterations of a sub-step (0 for implicit-euler's direct solve), the largest
    // residual left (relative: ‖r‖/‖b‖, or ‖∇E‖ after the iterations over before), and the
    // sub-steps whose solve stopped at its cap
    bool solved = false;
    double solverIterations = 0.0;
    int solverIterationsMost = 0;
    double solverResidual = 0.0;
    std::uint64_t solverCapHits = 0;
};

// the status in a word: "ok", "bad-input", "out-of-memory", "write-failed", "blew-up",
// "replay-differs"
QString statusWord(RunStatus status);

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
