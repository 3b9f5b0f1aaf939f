// springlab-sim: runs a scene with no window (issue 2, docs/scene-format.md).
//   springlab-sim SCENE.json [--duration SECONDS | --steps N] [--time-step H] [--substeps S]
//                 [--integrator NAME] [--tolerance TOL] [--contact-solver NAME] [--friction MU]
//                 [--static-friction MU] [--set KEY=VALUE]... [--output FINAL.json]
//                 [--trace TRACE.csv [--every K]] [--render DIR [--fps F] [--size WxH]]
//                 [--summary-json SUMMARY.json] [--summary-csv ROW.csv] [--quiet]
//        springlab-sim --summary-csv-header
//        springlab-sim --replay SESSION.json [--output FINAL.json] [--quiet]
// Exit code 0 done, 2 bad file or argument (or --render with no display, or an --output that is not
// a regular file), memory that ran out, or an output that could not be written, 3 the simulation
// blew up, 4 a replay did not end with the recorded state. The summary's status tells the
// failures that share exit code 2 apart (app::RunStatus).

#include "sim_import.h"
#include "sim_options.h"
#include "sim_render.h"
#include "sim_summary.h"

#include "core/integrators/solver_report.h"

#include "core/model/diagnostics.h"
#include "core/io/animation_export.h"
#include "core/io/safe_write.h"
#include "core/io/scene_file.h"
#include "core/io/trace_writer.h"
#include "core/model/model.h"
#include "core/contacts/solver_names.h"
#include "core/model/state.h"
#include "core/integrators/stability.h"
#include "core/step.h"
#include "core/thread_chooser.h"
#include "core/threads.h"

#include "session/run_diagnostics.h"
#include "session/session_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>

#include <QTextStream>

#include <cerrno>
#include <cstdio>
#include <system_error>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <new>

using namespace Qt::Literals::StringLiterals;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;
constexpr int kExitBlewUp = 3;
constexpr int kExitReplayDiffers = 4;

// text that came from a file, made safe for a terminal: a control character (an escape sequence
// in a name could recolour or rewrite the screen) is shown as \u001b; line breaks and tabs stay
QString printable(const QString &text)
{
    QString out;
    out.reserve(text.size());
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if ((u < 0x20 && u != u'\n' && u != u'\t') || (u >= 0x7f && u <= 0x9f))
            out += u"\\u%1"_s.arg(int(u), 4, 16, QLatin1Char('0'));
        else
            out += c;
    }
    return out;
}

int failWith(const QString &message)
{
    QTextStream(stderr) << "springlab-sim: " << printable(message) << '\n';
    return kExitBadInput;
}

int exitCodeOf(app::RunStatus status)
{
    switch (status) {
    case app::RunStatus::Ok: return kExitOk;
    case app::RunStatus::BadInput:
    case app::RunStatus::OutOfMemory:
    case app::RunStatus::WriteFailed: return kExitBadInput;
    case app::RunStatus::BlewUp: return kExitBlewUp;
    case app::RunStatus::ReplayDiffers: return kExitReplayDiffers;
    }
    return kExitBadInput;
}

// why what was printed did not reach stdout (a full disk, a closed pipe); empty when it did
QString stdoutFailure()
{
    if (std::fflush(stdout) == 0 && !std::ferror(stdout))
        return {};
    const int savedErrno = errno;
    return u"cannot write to the standard output: "_s + QString::fromStdString(std::generic_category().message(savedErrno));
}

// the exit code, once what was printed has reached stdout: a summary that could not be written
// (a full disk, a closed pipe) is a failure, not a success
int finish(int code)
{
    if (const QString failure = stdoutFailure(); !failure.isEmpty()) {
        failWith(failure);
        return code == kExitOk ? kExitBadInput : code;
    }
    return code;
}

// "1 spring", "2 springs"
QString counted(std::size_t count, const char *noun)
{
    return QString::number(count) + u' ' + QString::fromLatin1(noun) + (count == 1 ? u""_s : u"s"_s);
}

QString energyRow(const char *label, const core::Energies &e)
{
    return QString::asprintf("    %-9s %-14.6g %-14.6g %-14.6g %.6g\n", label, e.kinetic, e.gravitational, e.spring,
                             e.total());
}

// the run's summary written where --summary-json and --summary-csv say, whatever its status; the
// exit code is the status's, and a summary that cannot be written turns success into failure
int reportSummary(app::RunSummary &summary, const QString &jsonPath, const QString &csvPath)
{
    const int code = exitCodeOf(summary.status);
    summary.exitCode = code;
    if (const QString failure = app::saveSummary(summary, jsonPath, csvPath); !failure.isEmpty()) {
        failWith(failure);
        return code == kExitOk ? kExitBadInput : code;
    }
    return code;
}

// an --output that is a device or a FIFO is refused before the run, not after it
QString refusedOutput(const app::SimOptions &options)
{
    if (options.outputPath.isEmpty())
        return {};
    const QString refused = io::refuseToReplace(options.outputPath);
    return refused.isEmpty() ? refused : QDir::toNativeSeparators(options.outputPath) + u": cannot save: "_s + refused;
}

void runScene(const app::SimOptions &options, app::RunSummary &summary);

// a scene that needs more memory than the process may have (a file of millions of particles, a
// crowd of overlapping ones, a cap set with ulimit -v) is a message, exit 2 and the status
// out-of-memory, never an abort. What the run held is freed by the time the exception gets here,
// so the message can be made; the steps catch their own, to say which step.
void runSceneWithinMemory(const app::SimOptions &options, app::RunSummary &summary)
{
    try {
        runScene(options, summary);
    } catch (const std::bad_alloc &) {
        summary.status = app::RunStatus::OutOfMemory;
        summary.error = options.scenePath + u": out of memory while loading and preparing the scene: it needs "
                                            "more memory than this process may use (see ulimit -v)"_s;
        failWith(summary.error);
    }
}

// --replay: the recording run again from its start; its final state must hash as recorded
int replaySession(const app::SimOptions &options)
{
    const ui::RecordingLoad loaded = ui::loadRecording(options.scenePath);
    if (!loaded.recording)
        return failWith(loaded.error);
    const ui::SessionRecording &recording = *loaded.recording;
    QElapsedTimer clock;
    clock.start();
    ui::ReplayResult replayed;
    try {
        replayed = ui::replay(recording);
    } catch (const std::bad_alloc &) {
        return failWith(options.scenePath + u": out of memory: the replay needs more memory than this process may "
                                            "use (see ulimit -v)"_s);
    }
    if (!replayed.error.empty()) {
        failWith(options.scenePath + u": "_s + QString::fromStdString(replayed.error));
        return kExitReplayDiffers;
    }
    if (!options.outputPath.isEmpty()) {
        core::SceneDesc final = *recording.scene;
        core::storeState(replayed.state, final);
        if (const io::SaveResult saved = io::saveScene(options.outputPath, final); !saved.ok())
            return failWith(saved.error);
    }
    const auto hex = [](std::uint64_t hash) { return QString::number(hash, 16).rightJustified(16, u'0'); };
    const bool same = replayed.hash == recording.finalHash;
    QTextStream out(same ? stdout : stderr);
    if (!options.quiet || !same)
        out << (same ? u""_s : u"springlab-sim: "_s) << options.scenePath << u": "_s << recording.entries.size()
            << u" edits over "_s << recording.steps << u" steps replayed in "_s << clock.elapsed() << u" ms; final state "_s
            << hex(replayed.hash) << (same ? u", as recorded\n"_s : u", but the recording ended with "_s + hex(recording.finalHash) + u'\n');
    return finish(same ? kExitOk : kExitReplayDiffers);
}

}  // namespace

int main(int argc, char *argv[])
{
    // only --render draws, and so needs a QApplication and a display (app/sim_render.h)
    QString noDisplay;
    const std::unique_ptr<QCoreApplication> application =
        app::makeApplication(argc, argv, app::asksToRender(argc, argv), &noDisplay);
    if (!application)
        return failWith(noDisplay);
    QCoreApplication::setApplicationName(u"springlab-sim"_s);
    QCoreApplication::setApplicationVersion(QStringLiteral(SPRINGLAB_VERSION));

    // the command line
    const app::ParsedOptions parsed = app::parseSimOptions(QCoreApplication::arguments());
    if (!parsed.text.isEmpty()) {
        QTextStream(stdout) << parsed.text;
        return kExitOk;
    }
    if (!parsed.options) {
        app::RunSummary refused = parsed.refused;
        refused.status = app::RunStatus::BadInput;
        failWith(parsed.error + u"\n  (springlab-sim --help lists the options)"_s);
        return finish(reportSummary(refused, parsed.summaryJsonPath, parsed.summaryCsvPath));
    }
    const app::SimOptions &options = *parsed.options;
    if (options.import)
        return finish(app::runImport(options));
    if (options.replay) {
        if (const QString refused = refusedOutput(options); !refused.isEmpty())
            return failWith(refused);
        return replaySession(options);
    }

    // a summary file that is a device or a FIFO is refused before the run, with no summary
    for (const QString &path : {options.summaryJsonPath, options.summaryCsvPath})
        if (const QString refused = path.isEmpty() ? QString() : io::refuseToReplace(path); !refused.isEmpty())
            return failWith(QDir::toNativeSeparators(path) + u": cannot save: "_s + refused);

    // the run; its summary is written whatever its end
    app::RunSummary summary;
    summary.scene = options.scenePath;
    summary.overrides = app::overridesApplied(options);
    runSceneWithinMemory(options, summary);

    // what it printed reaches stdout before the summary is written, so that a run whose report
    // was lost (a full disk, a closed pipe) is not filed as ok
    if (const QString failure = stdoutFailure(); !failure.isEmpty()) {
        failWith(failure);
        if (summary.status == app::RunStatus::Ok) {
            summary.status = app::RunStatus::WriteFailed;
            summary.error = failure;
        }
    }
    return reportSummary(summary, options.summaryJsonPath, options.summaryCsvPath);
}

namespace {

void runScene(const app::SimOptions &options, app::RunSummary &summary)
{
    // a failure before the end: said on stderr and kept for the summary, with what kind it was
    const auto failRun = [&summary](app::RunStatus status, const QString &message) {
        summary.status = status;
        summary.error = message;
        failWith(message);
    };
    if (const QString refused = refusedOutput(options); !refused.isEmpty())
        return failRun(app::RunStatus::BadInput, refused);

    // the scene, with the command line's settings over the file's
    const io::LoadResult loaded = io::loadScene(options.scenePath);
    if (!loaded.ok())
        return failRun(loaded.outOfMemory ? app::RunStatus::OutOfMemory : app::RunStatus::BadInput, loaded.error);
    if (!options.quiet)
        for (const QString &warning : loaded.warnings)
            QTextStream(stderr) << "springlab-sim: warning: " << printable(warning) << '\n';
    core::SceneDesc scene = *loaded.scene;
    if (const QString problem = app::applyOverrides(options, scene); !problem.isEmpty())
        return failRun(app::RunStatus::BadInput, problem);
    QString error;
    const std::optional<std::uint64_t> steps = app::stepsToRun(options, scene.settings, error);
    if (!steps)
        return failRun(app::RunStatus::BadInput, error);

    // model and initial state
    const auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    const core::Energies start = core::energies(*model, state);
    core::Workspace work;

    // what the run did, as far as it went, for --summary-json and --summary-csv
    qint64 nanoseconds = 0;
    const auto record = [&](const core::Energies &end) {
        const auto name = [](std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); };
        summary.ran = true;
        summary.integrator = name(core::integratorName(scene.settings.integrator));
        summary.contactSolver = name(core::contactSolverName(scene.settings.contactSolver));
        summary.timeStep = scene.settings.timeStep;
        summary.substeps = model->substeps;
        summary.stepsRequested = *steps;
        summary.steps = state.step;
        summary.simulatedTime = state.time;
        summary.wallTime = static_cast<double>(nanoseconds) * 1e-9;
        summary.threads = core::threadCount();
        summary.start = start;
        summary.end = end;
        summary.springBreaks = state.breaks.size();
        const core::Profile &profile = work.profile;
        summary.solved = profile.solves > 0;
        summary.solverIterations = summary.solved ? double(profile.solverIterationsTotal) / double(profile.solves) : 0.0;
        summary.solverIterationsMost = profile.mostSolverIterations;
        summary.solverResidual = profile.worstSolverResidual;
        summary.solverCapHits = profile.solverCapHits;
        summary.warnings = loaded.warnings;
    };

    // the trace starts with step 0; a trace or a frame that cannot be written before the first
    // step is a write that failed all the same (the figures stay null: nothing ran)
    io::TraceWriter trace;
    const bool tracing = !options.tracePath.isEmpty();
    if (tracing) {
        if (const QString failure = trace.open(options.tracePath); !failure.isEmpty())
            return failRun(app::RunStatus::WriteFailed, failure);
        trace.writeRows(state);
    }

    // the frames start with step 0 too; a render that cannot start (no OpenGL, a size past the
    // driver's, a folder that cannot be made) is refused before the run
    app::FrameRenderer frames;
    const bool rendering = !options.renderDirectory.isEmpty();
    if (rendering) {
        if (const QString failure = frames.open(options.renderDirectory, options.frameSize, options.fps, scene, *steps);
            !failure.isEmpty())
            return failRun(app::RunStatus::BadInput, failure);
        if (const QString failure = frames.renderDue(*model, state); !failure.isEmpty())
            return failRun(app::RunStatus::WriteFailed, failure);
    }

    // the animation export starts with step 0 too, and is refused before the run when it cannot
    io::AnimationExport exported;
    const bool exporting = app::exportsAnimation(options);
    if (exporting) {
        io::ExportOptions wanted;
        wanted.pc2Path = options.pc2Path;
        wanted.objFolder = options.objFolder;
        wanted.meshPath = options.meshPath;
        wanted.fps = options.fps;
        wanted.from = options.exportFrom;
        wanted.to = options.exportTo;
        wanted.space = options.exportSpace;
        if (const QString failure = exported.open(wanted, scene, scene.settings.timeStep, *steps); !failure.isEmpty()) {
            exported.cancel();
            return failRun(app::RunStatus::BadInput, u"export: "_s + failure);
        }
        if (const QString failure = exported.writeDue(state.step, state.position); !failure.isEmpty()) {
            exported.cancel();
            return failRun(app::RunStatus::WriteFailed, failure);
        }
    }

    // the run, in chunks between trace rows (every K steps, not the last step unless K divides it)
    // and frames; only stepping is timed
    const core::State initial = state;  // to explain a blow-up, should one happen
    // the threads each step runs on, chosen from the steps' times: on a machine whose other cores
    // are busy, threads that wait for a core made a run several times slower than one thread
    core::ThreadChooser threads;
    // the editor's rule as well: a total energy grown a thousandfold its scale with no work done
    // on the scene is a blow-up, even while every value is finite and inside the world (checked
    // every few steps: the sum costs a fraction of a step)
    constexpr std::uint64_t kEnergyCheckSteps = 8;
    ui::RunDiagnostics energyWatch;
    energyWatch.restarted(*model, state);
    QElapsedTimer timer;
    bool blewUp = false;
    while (state.step < *steps && !blewUp) {
        std::uint64_t until = *steps;
        if (tracing)
            until = std::min(until, (state.step / options.every + 1) * options.every);
        if (rendering)
            until = std::min(until, frames.nextStep(*steps));
        if (exporting)
            until = std::min(until, std::max(state.step + 1, exported.nextStep(*steps)));
        timer.start();
        try {
            while (state.step < until) {
                core::setThreadCount(threads.threads());
                const auto began = std::chrono::steady_clock::now();
                if (!core::step(*model, state, work)) {
                    blewUp = true;
                    break;
                }
                threads.stepped(std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count());
                if (state.step % kEnergyCheckSteps == 0)
                    if (std::optional<core::Blowup> runaway = energyWatch.watchEnergy(*model, state, false)) {
                        work.blowup = std::move(runaway);
                        blewUp = true;
                        break;
                    }
            }
        } catch (const std::bad_alloc &) {
            work = core::Workspace{};  // the step's scratch let go before anything else is made
            // the steps before it stand; the state is half-way through a step, so its energies
            // are not known
            nanoseconds += timer.nsecsElapsed();
            const double unknown = std::numeric_limits<double>::quiet_NaN();
            record(core::Energies{unknown, unknown, unknown});
            return failRun(app::RunStatus::OutOfMemory,
                           options.scenePath + u": out of memory in step %1: the step needs more memory than this "
                                               "process may use (see ulimit -v)"_s.arg(state.step + 1));
        }
        nanoseconds += timer.nsecsElapsed();
        if (tracing && !blewUp && state.step % options.every == 0)
            trace.writeRows(state);
        if (rendering && !blewUp)
            if (const QString failure = frames.renderDue(*model, state); !failure.isEmpty()) {
                record(core::energies(*model, state));
                return failRun(app::RunStatus::WriteFailed, failure);
            }
        if (exporting && !blewUp)
            if (const QString failure = exported.writeDue(state.step, state.position); !failure.isEmpty()) {
                exported.cancel();
                record(core::energies(*model, state));
                return failRun(app::RunStatus::WriteFailed, failure);
            }
    }
    // the export ends with the frames written (all, or those before a blow-up)
    if (exporting)
        if (const QString failure = exported.finish(); !failure.isEmpty()) {
            exported.cancel();
            record(core::energies(*model, state));
            return failRun(app::RunStatus::WriteFailed, failure);
        }
    const core::Energies end = core::energies(*model, state);
    if (tracing)
        if (const QString failure = trace.close(); !failure.isEmpty()) {
            record(end);
            return failRun(app::RunStatus::WriteFailed, failure);
        }

    // without contacts nothing in a file adds energy (drag takes it): a total that rose by more
    // than half of all the energy in play (each kind's size, at the start or the end, whichever is
    // larger) is the integrator's instability, even when nothing blew up. A scene that starts at
    // rest at the height of zero has a total near 0 J and trades thousands of joules between its
    // kinds, so the size of the kinds is the scale, not the total. (Contacts are left out:
    // pushing overlaps apart can add energy of its own.)
    QStringList runWarnings;
    const auto inPlay = [](const core::Energies &e) {
        return std::abs(e.kinetic) + std::abs(e.spring) + std::abs(e.gravitational);
    };
    const double scale = 0.5 * std::max(inPlay(start), inPlay(end)) + 1e-9;
    const bool contacts = model->plan.planeCollisions || model->plan.particleCollisions;
    if (!blewUp && !contacts && end.total() - start.total() > scale)
        runWarnings << u"the total energy rose from %1 J to %2 J, and nothing in the scene adds energy: %3 is "
                       "unstable at this step; use more substeps, or symplectic-euler or projective"_s
                           .arg(start.total(), 0, 'g', 4)
                           .arg(end.total(), 0, 'g', 4)
                           .arg(QString::fromUtf8(core::integratorName(scene.settings.integrator).data(),
                                                  qsizetype(core::integratorName(scene.settings.integrator).size())));
    if (const std::string unsolved = core::solverWarning(model->integrator, work.profile); !unsolved.empty())
        runWarnings << QString::fromStdString(unsolved);
    if (!options.quiet)
        for (const QString &warning : runWarnings)
            QTextStream(stderr) << "springlab-sim: warning: " << warning << '\n';

    // what the run did, for --summary-json and --summary-csv
    record(end);
    summary.warnings += runWarnings;
    const QString blowup = blewUp ? QString::fromStdString(core::explainBlowup(
                                        *model, *work.blowup, core::stabilityLimit(*model, initial)))
                                  : QString();
    summary.status = blewUp ? app::RunStatus::BlewUp : app::RunStatus::Ok;
    summary.error = blowup;

    // the final state as a scene to run on from; a blown-up state is not worth saving. A run that
    // went to its end but could not save it is filed as such, its figures kept
    if (!options.outputPath.isEmpty() && !blewUp) {
        core::SceneDesc final = scene;
        core::storeState(state, final);
        // auto substeps chose its count at the start: the run resumed from here keeps at least
        // that many, so that it goes on as this one would have
        if (scene.settings.autoSubsteps)
            final.settings.substeps = model->substeps;
        if (const io::SaveResult saved = io::saveScene(options.outputPath, final); !saved.ok())
            return failRun(app::RunStatus::WriteFailed, saved.error);
    }

    // the summary
    if (!options.quiet) {
        const double seconds = static_cast<double>(nanoseconds) * 1e-9;
        QTextStream out(stdout);
        out << "springlab-sim: " << options.scenePath << " (\"" << printable(QString::fromStdString(scene.name))
            << "\"): " << counted(scene.particles.size(), "particle") << ", " << counted(scene.springs.size(), "spring")
            << ", " << counted(scene.planes.size(), "plane") << '\n';
        out << QString::asprintf("  settings   time step %.9g s, ", scene.settings.timeStep)
            << counted(static_cast<std::size_t>(model->substeps), "substep")
            << (scene.settings.autoSubsteps ? u" (auto: for the stability limit, at least %1)"_s.arg(scene.settings.substeps)
                                            : QString())
            << ", "
            << QString::fromStdString(std::string(core::integratorName(scene.settings.integrator))) << ", "
            << QString::fromStdString(std::string(core::contactSolverName(scene.settings.contactSolver)))
            << " contacts\n";
        if (!summary.overrides.isEmpty())
            out << "  overrides  " << printable(app::overridesText(summary.overrides)) << '\n';
        out << QString::asprintf("  ran        %llu of %llu steps%s, %.9g s simulated, in %.3g s wall time",
                                 static_cast<unsigned long long>(state.step), static_cast<unsigned long long>(*steps),
                                 blewUp ? " (stopped: blew up)" : "", state.time, seconds);
        if (seconds > 0.0)
            out << QString::asprintf(" (%.4g steps/s, %s)", static_cast<double>(state.step) / seconds,
                                     core::threadCount() == 1 ? "one thread" : qPrintable(u"%1 threads"_s.arg(core::threadCount())));
        out << "\n  energy (J) kinetic        gravitational  spring         total\n"
            << energyRow("start", start) << energyRow("end", end);
        if (!state.breaks.empty()) {
            const core::SpringBreak &first = state.breaks.front();
            out << QString::asprintf("  breaks     %zu of %zu springs broke, the first in step %llu (t = %.6g s)\n",
                                     state.breaks.size(), state.springBroken.size(),
                                     static_cast<unsigned long long>(first.step), first.time);
        }
        const qsizetype warnings = loaded.warnings.size() + runWarnings.size();
        out << "  warnings   " << (warnings == 0 ? u"none"_s : QString::number(warnings) + u" (above)"_s) << '\n';
        if (tracing)
            out << "  trace      " << options.tracePath << ", " << trace.rowCount() << " rows\n";
        if (rendering)
            out << "  frames     " << options.renderDirectory << ", " << frames.framesWritten() << " of "
                << frames.frameCount() << QString::asprintf(" at %.6g frames/s, %dx%d px", options.fps,
                                                            options.frameSize.width(), options.frameSize.height())
                << (frames.framesRemoved() > 0 ? u", replacing %1 of an earlier render"_s.arg(frames.framesRemoved())
                                               : QString())
                << '\n';
        if (exporting)
            out << "  export     " << exported.framesWritten() << " of " << exported.frameCount()
                << QString::asprintf(" frames at %.6g frames/s: ", options.fps) << exported.files().size() << " files ("
                << (options.pc2Path.isEmpty() ? QString() : options.pc2Path + u' ')
                << (options.objFolder.isEmpty() ? QString() : options.objFolder + u"/ "_s)
                << (options.meshPath.isEmpty() ? QString() : options.meshPath + u' ') << ")\n";
        if (!options.outputPath.isEmpty() && !blewUp)
            out << "  output     " << options.outputPath << '\n';
    }

    // what went wrong, if it did
    if (blewUp)
        QTextStream(stderr) << "springlab-sim: " << blowup
                            << (options.outputPath.isEmpty() ? "" : "\n  (no --output written)") << '\n';
}

}  // namespace
