#include "sim_options.h"

#include "ui/export/image_sequence.h"

#include "core/io/animation_export.h"
#include "core/io/file_identity.h"
#include "core/io/scene_words.h"
#include "core/model/parameters.h"
#include "core/contacts/solver_names.h"
#include "core/model/validate.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <cmath>
#include <tuple>

namespace app {

using namespace Qt::Literals::StringLiterals;

namespace {

// more steps than this cannot be counted exactly in a double, nor run in a lifetime
constexpr double kMaxSteps = 9007199254740992.0;  // 2^53
// --render's limits: frames per simulated second, and pixels a side (a driver may allow fewer)
constexpr double kMaxFps = 1000.0;
constexpr int kMaxFrameSide = 16384;

// the settings that options of their own set, and the keys --set names them with
constexpr std::pair<const char *, const char *> kSettingOptions[] = {
    {"time-step", "settings.timeStep"},           {"substeps", "settings.substeps"},
    {"integrator", "settings.integrator"},        {"tolerance", "settings.tolerance"},
    {"contact-solver", "settings.contactSolver"}, {"friction", "settings.friction"},
    {"static-friction", "settings.staticFriction"},
};

// "--name: reason"
QString optionError(const QString &name, const QString &reason)
{
    return u"--"_s + name + u": "_s + reason;
}

std::optional<std::uint64_t> readCount(const QString &name, const QString &text, std::uint64_t minimum, QString &error)
{
    bool ok = false;
    const qulonglong value = text.trimmed().toULongLong(&ok);
    if (!ok || text.trimmed().startsWith(u'+') || value < minimum) {
        error = optionError(name, u"expected a whole number of at least %1, got \""_s.arg(minimum) + text + u'"');
        return std::nullopt;
    }
    if (static_cast<double>(value) > kMaxSteps) {
        error = optionError(name, u"%1 is too large"_s.arg(value));
        return std::nullopt;
    }
    return value;
}

std::optional<double> readNumber(const QString &name, const QString &text, const QString &what, QString &error)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok) {
        error = optionError(name, u"expected "_s + what + u", got \""_s + text + u'"');
        return std::nullopt;
    }
    return value;
}

// a value checked against the scene files' parameter table
bool checkAgainstTable(const QString &name, core::Parameter parameter, double value, QString &error)
{
    if (const auto reason = core::checkParameter(parameter, value)) {
        error = optionError(name, QString::fromStdString(*reason));
        return false;
    }
    return true;
}

// --render DIR with its --fps and --size; false with error set at the first bad one
bool readRenderOptions(const QCommandLineParser &parser, SimOptions &options, QString &error)
{
    options.renderDirectory = parser.value(u"render"_s);
    if (parser.isSet(u"render"_s) && options.renderDirectory.isEmpty()) {
        error = optionError(u"render"_s, u"needs a folder for the frames"_s);
        return false;
    }
    const bool exporting = parser.isSet(u"export-pc2"_s) || parser.isSet(u"export-obj"_s) || parser.isSet(u"export-mesh"_s);
    if (parser.isSet(u"size"_s) && !parser.isSet(u"render"_s)) {
        error = u"--size only makes sense with --render"_s;
        return false;
    }
    if (parser.isSet(u"fps"_s) && !parser.isSet(u"render"_s) && !exporting) {
        error = u"--fps only makes sense with --render or an export (--export-pc2, --export-obj, --export-mesh)"_s;
        return false;
    }
    if (parser.isSet(u"fps"_s)) {
        const auto fps = readNumber(u"fps"_s, parser.value(u"fps"_s), u"a number of frames per second"_s, error);
        if (!fps)
            return false;
        if (!(*fps > 0.0 && *fps <= kMaxFps)) {
            error = optionError(u"fps"_s, u"must be above 0 and at most %1 frames per second (got %2)"_s.arg(kMaxFps)
                                              .arg(parser.value(u"fps"_s)));
            return false;
        }
        options.fps = *fps;
    }
    if (parser.isSet(u"size"_s)) {
        static const QRegularExpression pattern(u"^\\s*(\\d{1,9})\\s*[xX×]\\s*(\\d{1,9})\\s*$"_s);
        const QRegularExpressionMatch match = pattern.match(parser.value(u"size"_s));
        const int width = match.hasMatch() ? match.captured(1).toInt() : 0;
        const int height = match.hasMatch() ? match.captured(2).toInt() : 0;
        if (width < 1 || height < 1 || width > kMaxFrameSide || height > kMaxFrameSide) {
            error = optionError(u"size"_s, u"expected WIDTHxHEIGHT in pixels, each from 1 to %1, got \""_s
                                               .arg(kMaxFrameSide) + parser.value(u"size"_s) + u'"');
            return false;
        }
        options.frameSize = QSize(width, height);
    }
    return true;
}

// --export-pc2, --export-obj, --export-mesh with --export-from, --export-to and --export-space
bool readExportOptions(const QCommandLineParser &parser, SimOptions &options, QString &error)
{
    for (const auto &[name, value] : {std::pair{u"export-pc2"_s, &options.pc2Path}, std::pair{u"export-obj"_s, &options.objFolder},
                                      std::pair{u"export-mesh"_s, &options.meshPath}}) {
        *value = parser.value(name);
        if (parser.isSet(name) && value->isEmpty()) {
            error = optionError(name, u"needs a file or folder name"_s);
            return false;
        }
    }
    const bool exporting = exportsAnimation(options);
    for (const QString &name : {u"export-from"_s, u"export-to"_s, u"export-space"_s})
        if (parser.isSet(name) && !exporting) {
            error = u"--%1 only makes sense with --export-pc2, --export-obj or --export-mesh"_s.arg(name);
            return false;
        }
    if (parser.isSet(u"export-from"_s)) {
        const auto from = readNumber(u"export-from"_s, parser.value(u"export-from"_s), u"a time in seconds"_s, error);
        if (!from)
            return false;
        if (!(*from >= 0.0) || !std::isfinite(*from)) {
            error = optionError(u"export-from"_s, u"must be a time of 0 s or later (got "_s + parser.value(u"export-from"_s) + u')');
            return false;
        }
        options.exportFrom = *from;
    }
    if (parser.isSet(u"export-to"_s)) {
        options.exportTo = readNumber(u"export-to"_s, parser.value(u"export-to"_s), u"a time in seconds"_s, error);
        if (!options.exportTo)
            return false;
        if (!(*options.exportTo >= options.exportFrom) || !std::isfinite(*options.exportTo)) {
            error = optionError(u"export-to"_s, u"must be a time no earlier than --export-from (got "_s + parser.value(u"export-to"_s) + u')');
            return false;
        }
    }
    if (parser.isSet(u"export-space"_s)) {
        const QString space = parser.value(u"export-space"_s);
        if (space != u"file"_s && space != u"scene"_s) {
            error = optionError(u"export-space"_s, u"expected file or scene, got \""_s + space + u'"');
            return false;
        }
        options.exportSpace = space == u"file"_s ? core::MeshSpace::File : core::MeshSpace::Scene;
    }
    if (!options.meshPath.isEmpty() && io::meshExportFormat(QFileInfo(options.meshPath).suffix()).isEmpty()) {
        error = optionError(u"export-mesh"_s, u"no mesh format has the extension \"."_s + QFileInfo(options.meshPath).suffix() +
                                                  u"\" (known: "_s + io::meshExportExtensions().join(u", "_s) + u')');
        return false;
    }
    return true;
}

// every option's value, one after the other; false with error set at the first bad one
bool readOptions(const QCommandLineParser &parser, SimOptions &options, QString &error)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty()) {
        error = u"missing the scene file (SCENE.json)"_s;
        return false;
    }
    if (positional.size() > 1) {
        error = u"one scene file only, got also: "_s + positional.mid(1).join(u' ');
        return false;
    }
    options.scenePath = positional.first();

    // a replay runs the recording as it was: nothing may change it
    options.replay = parser.isSet(u"replay"_s);
    if (options.replay) {
        for (const QString &name : {u"duration"_s, u"steps"_s, u"time-step"_s, u"substeps"_s, u"integrator"_s,
                                   u"tolerance"_s, u"contact-solver"_s, u"friction"_s, u"static-friction"_s,
                                   u"set"_s, u"trace"_s, u"every"_s, u"render"_s})
            if (parser.isSet(name)) {
                error = u"--replay runs the recording as it was recorded: --%1 cannot change it"_s.arg(name);
                return false;
            }
        for (const QString &name : {u"summary-json"_s, u"summary-csv"_s})
            if (parser.isSet(name)) {
                error = u"--%1 summarises a run of a scene, not a --replay"_s.arg(name);
                return false;
            }
    }

    // how long
    if (parser.isSet(u"steps"_s) && parser.isSet(u"duration"_s)) {
        error = u"--steps and --duration cannot be used together"_s;
        return false;
    }
    if (parser.isSet(u"steps"_s) && !(options.steps = readCount(u"steps"_s, parser.value(u"steps"_s), 0, error)))
        return false;
    if (parser.isSet(u"duration"_s)) {
        options.duration = readNumber(u"duration"_s, parser.value(u"duration"_s), u"a number of seconds"_s, error);
        if (!options.duration)
            return false;
        if (!std::isfinite(*options.duration) || *options.duration < 0.0) {
            error = optionError(u"duration"_s, u"must be a finite number of seconds, at least 0 (got "_s +
                                                   parser.value(u"duration"_s) + u")"_s);
            return false;
        }
    }

    // settings that override the file's
    if (parser.isSet(u"time-step"_s)) {
        options.timeStep = readNumber(u"time-step"_s, parser.value(u"time-step"_s), u"a number of seconds"_s, error);
        if (!options.timeStep ||
            !checkAgainstTable(u"time-step"_s, core::Parameter::TimeStep, *options.timeStep, error))
            return false;
    }
    if (parser.isSet(u"substeps"_s)) {
        bool ok = false;
        const int substeps = parser.value(u"substeps"_s).trimmed().toInt(&ok);
        if (!ok) {
            error =
                optionError(u"substeps"_s, u"expected a whole number, got \""_s + parser.value(u"substeps"_s) + u'"');
            return false;
        }
        if (!checkAgainstTable(u"substeps"_s, core::Parameter::Substeps, substeps, error))
            return false;
        options.substeps = substeps;
    }
    // Coulomb friction: kinetic, and static (which otherwise follows the kinetic one)
    for (const auto &[name, value] : {std::pair{u"friction"_s, &options.friction},
                                      std::pair{u"static-friction"_s, &options.staticFriction}})
        if (parser.isSet(name)) {
            *value = readNumber(name, parser.value(name), u"a coefficient"_s, error);
            if (!*value || !checkAgainstTable(name, core::Parameter::Friction, **value, error))
                return false;
        }
    if (parser.isSet(u"tolerance"_s)) {
        options.tolerance = readNumber(u"tolerance"_s, parser.value(u"tolerance"_s), u"a number"_s, error);
        if (!options.tolerance ||
            !checkAgainstTable(u"tolerance"_s, core::Parameter::Tolerance, *options.tolerance, error))
            return false;
    }
    if (parser.isSet(u"integrator"_s)) {
        QString unknown;
        options.integrator = io::integratorNamed(parser.value(u"integrator"_s), unknown);
        if (!options.integrator) {
            error = optionError(u"integrator"_s, unknown);
            return false;
        }
    }
    if (parser.isSet(u"contact-solver"_s)) {
        QString unknown;
        options.contactSolver = io::contactSolverNamed(parser.value(u"contact-solver"_s), unknown);
        if (!options.contactSolver) {
            error = optionError(u"contact-solver"_s, unknown);
            return false;
        }
    }

    // --set KEY=VALUE, in order; a setting is changed by its option or by --set, never both
    for (const QString &argument : parser.values(u"set"_s)) {
        std::optional<SceneOverride> set = parseOverride(argument, error);
        if (!set)
            return false;
        for (const auto &[option, key] : kSettingOptions)
            if (set->key == QLatin1StringView(key) && parser.isSet(QString::fromLatin1(option))) {
                error = u"--%1 and --set %2 both set %2: give one of them"_s.arg(QString::fromLatin1(option), set->key);
                return false;
            }
        options.sets.push_back(std::move(*set));
    }

    // what to write
    options.outputPath = parser.value(u"output"_s);
    options.tracePath = parser.value(u"trace"_s);
    if (parser.isSet(u"output"_s) && options.outputPath.isEmpty()) {
        error = optionError(u"output"_s, u"needs a file name"_s);
        return false;
    }
    if (parser.isSet(u"trace"_s) && options.tracePath.isEmpty()) {
        error = optionError(u"trace"_s, u"needs a file name"_s);
        return false;
    }
    options.summaryJsonPath = parser.value(u"summary-json"_s);
    options.summaryCsvPath = parser.value(u"summary-csv"_s);
    for (const QString &name : {u"summary-json"_s, u"summary-csv"_s})
        if (parser.isSet(name) && parser.value(name).isEmpty()) {
            error = optionError(name, u"needs a file name"_s);
            return false;
        }
    if (parser.isSet(u"every"_s)) {
        if (!parser.isSet(u"trace"_s)) {
            error = u"--every only makes sense with --trace"_s;
            return false;
        }
        const auto every = readCount(u"every"_s, parser.value(u"every"_s), 1, error);
        if (!every)
            return false;
        options.every = *every;
    }
    options.quiet = parser.isSet(u"quiet"_s);
    return readRenderOptions(parser, options, error) && readExportOptions(parser, options, error);
}

}  // namespace

QString clashingPaths(const SimOptions &options)
{
    // what the run reads, then what it writes, each named by its option. Files are compared as
    // files (io::sameFile), not as paths: a hard link to the scene passed as --trace, or the
    // scene's folder reached through a bind mount, would otherwise be truncated and written over
    const std::pair<const char *, QString> inputs[] = {{options.replay ? "the recording's" : "the scene's", options.scenePath}};
    const std::pair<const char *, QString> outputs[] = {{"--output", options.outputPath},
                                                        {"--trace", options.tracePath},
                                                        {"--summary-json", options.summaryJsonPath},
                                                        {"--summary-csv", options.summaryCsvPath},
                                                        {"--render", options.renderDirectory},
                                                        {"--export-pc2", options.pc2Path},
                                                        {"--export-obj", options.objFolder},
                                                        {"--export-mesh", options.meshPath}};
    for (const auto &[name, written] : outputs) {
        if (written.isEmpty())
            continue;
        for (const auto &[inputName, read] : inputs)
            if (io::sameFile(written, read))
                return u"%1 %2 names %3 file: the run would overwrite what it reads"_s
                    .arg(QString::fromLatin1(name), QDir::toNativeSeparators(written), QString::fromLatin1(inputName));
    }
    for (std::size_t i = 0; i < std::size(outputs); ++i)
        for (std::size_t j = i + 1; j < std::size(outputs); ++j)
            if (io::sameFile(outputs[i].second, outputs[j].second))
                return u"%1 and %2 name one file, %3: one would overwrite the other"_s.arg(
                    QString::fromLatin1(outputs[i].first), QString::fromLatin1(outputs[j].first),
                    QDir::toNativeSeparators(outputs[i].second));

    // --render removes the frame-NNNNN.png files in its folder, then writes its own there
    const QString &frames = options.renderDirectory;
    if (frames.isEmpty())
        return QString();
    for (const auto &[inputName, read] : inputs)
        if (ui::isSequenceFrame(read, frames))
            return u"--render %1 would replace %2 file, %3, with a frame: the run would overwrite what it reads"_s.arg(
                QDir::toNativeSeparators(frames), QString::fromLatin1(inputName), QDir::toNativeSeparators(read));
    for (const auto &[name, written] : outputs)
        if (!written.isEmpty() && written != frames && ui::isSequenceFrame(written, frames))
            return u"%1 %2 is one of the frames of --render %3: one would overwrite the other"_s.arg(
                QString::fromLatin1(name), QDir::toNativeSeparators(written), QDir::toNativeSeparators(frames));
    return QString();
}

namespace {

// where and what a refused command line still reports: the summary files it names, unless they
// name a file the run reads or another output, with the scene and the --set values read so far
void reportRefusal(const QCommandLineParser &parser, ParsedOptions &parsed)
{
    SimOptions named;
    named.scenePath = parser.positionalArguments().value(0);
    named.outputPath = parser.value(u"output"_s);
    named.tracePath = parser.value(u"trace"_s);
    named.summaryJsonPath = parser.value(u"summary-json"_s);
    named.summaryCsvPath = parser.value(u"summary-csv"_s);
    named.renderDirectory = parser.value(u"render"_s);
    if (parser.isSet(u"replay"_s) || !clashingPaths(named).isEmpty())
        return;
    parsed.summaryJsonPath = named.summaryJsonPath;
    parsed.summaryCsvPath = named.summaryCsvPath;
    parsed.refused.scene = named.scenePath;
    for (const QString &argument : parser.values(u"set"_s)) {
        QString ignored;
        if (const auto set = parseOverride(argument, ignored))
            parsed.refused.overrides[set->key] = set->value;
        else if (const qsizetype equals = argument.indexOf(u'='); equals > 0)
            parsed.refused.overrides[argument.left(equals).trimmed()] = argument.mid(equals + 1);
    }
    parsed.refused.exitCode = 2;
    parsed.refused.error = parsed.error;
}

// the options of --import alone
const QStringList kImportOnly{u"as"_s,       u"into"_s,     u"scale"_s,   u"up"_s,  u"at"_s,  u"material"_s,
                              u"density"_s,  u"stiffness"_s, u"damping"_s, u"spacing"_s, u"pin"_s, u"name"_s};

// springlab-sim --import MESH --as KIND --output SCENE.json and its options
bool readImportOptions(const QCommandLineParser &parser, SimOptions &options, QString &error)
{
    ImportRequest request;
    request.meshPath = parser.value(u"import"_s);
    if (request.meshPath.isEmpty()) {
        error = optionError(u"import"_s, u"needs a mesh file"_s);
        return false;
    }
    if (!parser.positionalArguments().isEmpty()) {
        error = u"--import makes a scene of a mesh and runs none: it takes no scene file (got "_s +
                parser.positionalArguments().join(u' ') + u"); use --into to add the mesh to a scene"_s;
        return false;
    }
    for (const QString &name : {u"duration"_s, u"steps"_s, u"time-step"_s, u"substeps"_s, u"integrator"_s, u"tolerance"_s,
                                u"contact-solver"_s, u"friction"_s, u"static-friction"_s, u"set"_s, u"trace"_s, u"every"_s,
                                u"render"_s, u"fps"_s, u"size"_s, u"summary-json"_s, u"summary-csv"_s, u"replay"_s,
                                u"export-pc2"_s, u"export-obj"_s, u"export-mesh"_s, u"export-from"_s, u"export-to"_s,
                                u"export-space"_s})
        if (parser.isSet(name)) {
            error = u"--import makes a scene and runs none: --%1 cannot go with it (run the scene it writes)"_s.arg(name);
            return false;
        }
    if (!parser.isSet(u"as"_s)) {
        error = u"--import needs --as cloth, soft or collider"_s;
        return false;
    }
    const auto kind = core::meshKindNamed(parser.value(u"as"_s).toStdString());
    if (!kind) {
        error = optionError(u"as"_s, u"expected cloth, soft or collider, got \""_s + parser.value(u"as"_s) + u'"');
        return false;
    }
    request.kind = *kind;
    options.outputPath = parser.value(u"output"_s);
    if (options.outputPath.isEmpty()) {
        error = u"--import needs --output SCENE.json: the file the scene is written to"_s;
        return false;
    }
    request.intoPath = parser.value(u"into"_s);
    if (parser.isSet(u"into"_s) && request.intoPath.isEmpty()) {
        error = optionError(u"into"_s, u"needs a scene file"_s);
        return false;
    }
    const auto positive = [&](const QString &name, double &out, const QString &what) {
        const auto value = readNumber(name, parser.value(name), what, error);
        if (!value)
            return false;
        if (!(*value > 0.0) || !std::isfinite(*value)) {
            error = optionError(name, u"must be greater than 0 (got "_s + parser.value(name) + u')');
            return false;
        }
        out = *value;
        return true;
    };
    if (parser.isSet(u"scale"_s) && !positive(u"scale"_s, request.scale, u"a number of metres per unit"_s))
        return false;
    if (parser.isSet(u"spacing"_s) && !positive(u"spacing"_s, request.spacing, u"a number of metres"_s))
        return false;
    for (const auto &[name, value, what] : {std::tuple{u"density"_s, &request.density, u"a density"_s},
                                            std::tuple{u"stiffness"_s, &request.stiffness, u"a number of N/m"_s}})
        if (parser.isSet(name)) {
            double v = 0.0;
            if (!positive(name, v, what))
                return false;
            *value = v;
        }
    if (parser.isSet(u"damping"_s)) {
        request.damping = readNumber(u"damping"_s, parser.value(u"damping"_s), u"a number of N·s/m"_s, error);
        if (!request.damping || !checkAgainstTable(u"damping"_s, core::Parameter::Damping, *request.damping, error))
            return false;
    }
    if (parser.isSet(u"up"_s)) {
        const QString up = parser.value(u"up"_s).trimmed().toLower();
        if (up != u"y"_s && up != u"z"_s) {
            error = optionError(u"up"_s, u"expected y or z, got \""_s + parser.value(u"up"_s) + u'"');
            return false;
        }
        request.zUp = up == u"z"_s;
    }
    if (parser.isSet(u"at"_s)) {
        const QStringList parts = parser.value(u"at"_s).split(u',');
        Eigen::Vector3d at;
        bool ok = parts.size() == 3;
        for (int a = 0; a < 3 && ok; ++a) {
            at[a] = parts[a].trimmed().toDouble(&ok);
            ok = ok && std::isfinite(at[a]);
        }
        if (!ok) {
            error = optionError(u"at"_s, u"expected three numbers X,Y,Z in metres, got \""_s + parser.value(u"at"_s) + u'"');
            return false;
        }
        request.at = at;
    }
    if (parser.isSet(u"material"_s)) {
        const auto material = core::clothMaterialNamed(parser.value(u"material"_s).toStdString());
        if (!material) {
            error = optionError(u"material"_s, u"expected one of "_s + QString::fromLatin1(core::knownClothMaterials().data(), qsizetype(core::knownClothMaterials().size())) +
                                                   u", got \""_s + parser.value(u"material"_s) + u'"');
            return false;
        }
        request.material = *material;
    }
    if (parser.isSet(u"pin"_s)) {
        const auto side = core::pinSideNamed(parser.value(u"pin"_s).toStdString());
        if (!side) {
            error = optionError(u"pin"_s, u"expected one of "_s + QString::fromLatin1(core::knownPinSides().data(), qsizetype(core::knownPinSides().size())) +
                                              u", got \""_s + parser.value(u"pin"_s) + u'"');
            return false;
        }
        request.pin = *side;
    }
    request.name = parser.isSet(u"name"_s) ? parser.value(u"name"_s) : QFileInfo(request.meshPath).completeBaseName();
    // the scene written must not be the mesh or the scene read
    for (const QString &read : {request.meshPath, request.intoPath})
        if (!read.isEmpty() && io::sameFile(options.outputPath, read)) {
            error = u"--output %1 names a file the import reads: it would overwrite it"_s.arg(QDir::toNativeSeparators(options.outputPath));
            return false;
        }
    options.quiet = parser.isSet(u"quiet"_s);
    options.import = request;
    return true;
}

}  // namespace

ParsedOptions parseSimOptions(const QStringList &arguments)
{
    // the options, as --help lists them
    QCommandLineParser parser;
    parser.setApplicationDescription(
        u"Runs a Springlab scene with no window and prints a summary.\n"
        "Without --steps or --duration it runs %1 steps. Command-line settings override the file's.\n"
        "Exit code: 0 done, 2 bad file or argument (or --render with no display), 3 the simulation blew up, "
        "4 a replay did not end as recorded."_s
            .arg(kDefaultSteps));
    parser.addPositionalArgument(u"SCENE.json"_s, u"The scene file to run."_s);
    const QCommandLineOption help(QStringList{u"h"_s, u"help"_s}, u"Show this help."_s);
    const QCommandLineOption version(u"version"_s, u"Show the version."_s);
    parser.addOptions({
        help,
        version,
        {u"duration"_s, u"Simulated time to run: round(SECONDS / time step) steps."_s, u"SECONDS"_s},
        {u"steps"_s, u"Run exactly N steps."_s, u"N"_s},
        {u"time-step"_s, u"Time step in seconds, instead of the file's."_s, u"H"_s},
        {u"substeps"_s, u"Sub-steps per step, instead of the file's."_s, u"S"_s},
        {u"integrator"_s, u"Integrator, instead of the file's: "_s + io::knownIntegrators() + u'.', u"NAME"_s},
        {u"tolerance"_s, u"Local error per step (m, m/s) for adaptive-rk45, instead of the file's."_s, u"TOL"_s},
        {u"contact-solver"_s, u"Contact solver, instead of the file's: "_s + io::knownContactSolvers() + u'.', u"NAME"_s},
        {u"friction"_s, u"Kinetic Coulomb friction coefficient of every contact (0 to 10), instead of the file's; "
                        "a plane with its own keeps it."_s, u"MU"_s},
        {u"static-friction"_s, u"Static friction coefficient (0 to 10), instead of the file's (which, when the "
                               "file has none, is the kinetic one)."_s, u"MU"_s},
        {u"set"_s, u"Change one value of the scene before the run, checked as the file's own: settings.NAME, "
                   "or particles.NAME, springs.NAME, planes.NAME for every element, particles[I].NAME for one "
                   "(mass, radius, stiffness, damping, restLength, ...). Repeatable; a later one wins."_s,
         u"KEY=VALUE"_s},
        {u"output"_s, u"Write the final state as a scene file, to run on from."_s, u"FINAL.json"_s},
        {u"trace"_s, u"Write positions and velocities as CSV: step,time,particle,x,y,z,vx,vy,vz."_s, u"TRACE.csv"_s},
        {u"every"_s, u"With --trace: one set of rows every K steps (default 1), step 0 included."_s, u"K"_s},
        {u"render"_s, u"Draw the run as PNG frames, DIR/frame-00000.png on, with the editor's 3D view framed on "
                      "the scene (frame k shows the first step at or after k / F s). Needs an X display: run it "
                      "under xvfb-run -a where there is none."_s, u"DIR"_s},
        {u"fps"_s, u"With --render or an export: frames per simulated second (default 30)."_s, u"F"_s},
        {u"export-pc2"_s, u"Write the deforming surfaces (imported meshes, or a cloth's sheet) as a PC2 point cache, "
                          "for Blender's Mesh Cache modifier, with the OBJ of its first frame beside it "
                          "(FILE.obj). Several meshes: FILE-NAME.pc2 each. Streamed: one frame in memory."_s,
         u"FILE.pc2"_s},
        {u"export-obj"_s, u"Write the surfaces as an OBJ a frame, FOLDER/NAME_00000.obj on, vertices in the same "
                          "order."_s, u"FOLDER"_s},
        {u"export-mesh"_s, u"Write the surfaces' last exported frame in the format the extension names (glb, gltf, "
                           "ply, stl, obj, ...)."_s, u"FILE"_s},
        {u"export-from"_s, u"With an export: the first frame's time (default 0)."_s, u"SECONDS"_s},
        {u"export-to"_s, u"With an export: the last frame's time at most (default: the run's end)."_s, u"SECONDS"_s},
        {u"export-space"_s, u"With an export: file (an imported mesh where its file has it, placement undone; the "
                            "default) or scene (where the scene has it)."_s, u"file|scene"_s},
        {u"import"_s, u"Make a scene of a mesh file (OBJ, PLY, STL, glTF 2, FBX, Collada, ...) with --as and write it "
                      "to --output, instead of running a scene."_s, u"MESH"_s},
        {u"as"_s, u"With --import: cloth, soft (a closed mesh filled with a lattice) or collider."_s, u"KIND"_s},
        {u"into"_s, u"With --import: add the mesh to this scene rather than to a new one."_s, u"SCENE.json"_s},
        {u"scale"_s, u"With --import: metres per unit of the file (default 1)."_s, u"S"_s},
        {u"up"_s, u"With --import: the file's up axis, y (default) or z."_s, u"AXIS"_s},
        {u"at"_s, u"With --import: where the bottom centre of the mesh's box goes (default: where the file has it)."_s,
         u"X,Y,Z"_s},
        {u"material"_s, u"With --import --as cloth: cotton (default), silk, denim or rubber-sheet."_s, u"NAME"_s},
        {u"density"_s, u"With --import: kg/m² of a cloth (default: the material's), kg/m³ of a soft body (default 200)."_s,
         u"D"_s},
        {u"stiffness"_s, u"With --import: N/m of a cloth's edge springs (shear and bend in the material's proportion) "
                         "or of a soft body's springs."_s, u"K"_s},
        {u"damping"_s, u"With --import: N·s/m of every spring."_s, u"C"_s},
        {u"spacing"_s, u"With --import --as soft: the lattice's spacing in metres (default: a tenth of the mesh's "
                       "longest side)."_s, u"H"_s},
        {u"pin"_s, u"With --import: pin the vertices on one side of the mesh's box: none (default), top, bottom, left, "
                   "right, front, back."_s, u"SIDE"_s},
        {u"name"_s, u"With --import: the mesh's name in the scene (default: the file's)."_s, u"NAME"_s},
        {u"size"_s, u"With --render: the frames' size in pixels (default 1280x720)."_s, u"WxH"_s},
        {u"summary-json"_s, u"Write the summary as one JSON object, also when the run blows up or its file or "
                            "arguments are refused."_s, u"SUMMARY.json"_s},
        {u"summary-csv"_s, u"Write the summary as one CSV row, under the header --summary-csv-header prints."_s,
         u"ROW.csv"_s},
        {u"summary-csv-header"_s, u"Print the CSV header of --summary-csv's rows and exit."_s},
        {u"quiet"_s, u"Print nothing but errors."_s},
        {u"replay"_s, u"The file is a session recorded in the editor (Simulation > Record Session): replay it "
                      "and check that it ends with the recorded state, bit for bit (exit 4 if not)."_s},
    });

    ParsedOptions parsed;
    if (!parser.parse(arguments)) {
        parsed.error = parser.errorText();
        reportRefusal(parser, parsed);
        return parsed;
    }
    if (parser.isSet(help)) {
        parsed.text = parser.helpText();
        return parsed;
    }
    if (parser.isSet(version)) {
        parsed.text = QCoreApplication::applicationName() + u' ' + QCoreApplication::applicationVersion() + u'\n';
        return parsed;
    }
    if (parser.isSet(u"summary-csv-header"_s)) {
        parsed.text = QString::fromUtf8(summaryCsvHeader());
        return parsed;
    }
    SimOptions options;
    if (parser.isSet(u"import"_s)) {
        if (readImportOptions(parser, options, parsed.error))
            parsed.options = options;
        return parsed;
    }
    for (const QString &name : kImportOnly)
        if (parser.isSet(name)) {
            parsed.error = u"--%1 only makes sense with --import"_s.arg(name);
            reportRefusal(parser, parsed);
            return parsed;
        }
    if (readOptions(parser, options, parsed.error)) {
        parsed.error = clashingPaths(options);
        if (parsed.error.isEmpty())
            parsed.options = options;
    }
    if (!parsed.options)
        reportRefusal(parser, parsed);
    return parsed;
}

QJsonObject overridesApplied(const SimOptions &options)
{
    QJsonObject applied;
    const auto name = [](std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); };
    if (options.timeStep)
        applied[u"settings.timeStep"_s] = *options.timeStep;
    if (options.substeps)
        applied[u"settings.substeps"_s] = *options.substeps;
    if (options.integrator)
        applied[u"settings.integrator"_s] = name(core::integratorName(*options.integrator));
    if (options.tolerance)
        applied[u"settings.tolerance"_s] = *options.tolerance;
    if (options.contactSolver)
        applied[u"settings.contactSolver"_s] = name(core::contactSolverName(*options.contactSolver));
    if (options.friction)
        applied[u"settings.friction"_s] = *options.friction;
    if (options.staticFriction)
        applied[u"settings.staticFriction"_s] = *options.staticFriction;
    for (const SceneOverride &set : options.sets)
        applied[set.key] = set.value;
    return applied;
}

QString applyOverrides(const SimOptions &options, core::SceneDesc &scene)
{
    core::Settings &settings = scene.settings;
    if (options.timeStep)
        settings.timeStep = *options.timeStep;
    if (options.substeps)
        settings.substeps = *options.substeps;
    if (options.integrator)
        settings.integrator = *options.integrator;
    if (options.tolerance)
        settings.tolerance = *options.tolerance;
    if (options.contactSolver)
        settings.contactSolver = *options.contactSolver;
    if (options.friction)
        settings.friction = *options.friction;
    if (options.staticFriction)
        settings.staticFriction = *options.staticFriction;

    // then --set, in order, each checked as it is applied so that a message names the one at fault
    for (const SceneOverride &set : options.sets)
        if (const QString problem = applyOverride(set, scene); !problem.isEmpty())
            return problem;

    // the options were checked one by one; the scene as a whole is checked once more
    if (const auto problem = core::findProblem(scene))
        return options.scenePath + u": "_s + QString::fromStdString(problem->path) + u": "_s +
               QString::fromStdString(problem->message);
    return {};
}

std::optional<std::uint64_t> stepsToRun(const SimOptions &options, const core::Settings &settings, QString &error)
{
    if (options.steps)
        return *options.steps;
    if (!options.duration)
        return kDefaultSteps;
    const double steps = std::round(*options.duration / settings.timeStep);
    if (!(steps <= kMaxSteps)) {
        error = optionError(
            u"duration"_s,
            u"%1 s at a time step of %2 s is too many steps"_s.arg(*options.duration).arg(settings.timeStep));
        return std::nullopt;
    }
    return static_cast<std::uint64_t>(steps);
}

}  // namespace app
