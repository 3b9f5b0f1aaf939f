#include "sim_summary.h"

#include "core/io/safe_write.h"
#include "core/io/scene_file.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>

namespace app {

using namespace Qt::Literals::StringLiterals;

namespace {

struct SummaryField {
    const char *name;
    bool fromRun;  // null until the run starts
    QJsonValue (*value)(const RunSummary &);
};

// every field, in the order of the JSON object and the CSV columns
constexpr SummaryField kFields[] = {
    {"scene", false, [](const RunSummary &s) { return QJsonValue(s.scene); }},
    {"overrides", false, [](const RunSummary &s) { return QJsonValue(s.overrides); }},
    {"status", false, [](const RunSummary &s) { return QJsonValue(statusWord(s.status)); }},
    {"exitCode", false, [](const RunSummary &s) { return QJsonValue(s.exitCode); }},
    {"integrator", true, [](const RunSummary &s) { return QJsonValue(s.integrator); }},
    {"contactSolver", true, [](const RunSummary &s) { return QJsonValue(s.contactSolver); }},
    {"timeStep", true, [](const RunSummary &s) { return QJsonValue(s.timeStep); }},
    {"substeps", true, [](const RunSummary &s) { return QJsonValue(s.substeps); }},
    {"stepsRequested", true, [](const RunSummary &s) { return QJsonValue(double(s.stepsRequested)); }},
    {"steps", true, [](const RunSummary &s) { return QJsonValue(double(s.steps)); }},
    {"simulatedTime", true, [](const RunSummary &s) { return QJsonValue(s.simulatedTime); }},
    {"wallTime", true, [](const RunSummary &s) { return QJsonValue(s.wallTime); }},
    {"stepsPerSecond", true,
     [](const RunSummary &s) { return s.wallTime > 0.0 ? QJsonValue(double(s.steps) / s.wallTime) : QJsonValue(); }},
    {"threads", true, [](const RunSummary &s) { return s.threads > 0 ? QJsonValue(s.threads) : QJsonValue(); }},
    {"kineticStart", true, [](const RunSummary &s) { return QJsonValue(s.start.kinetic); }},
    {"gravitationalStart", true, [](const RunSummary &s) { return QJsonValue(s.start.gravitational); }},
    {"springStart", true, [](const RunSummary &s) { return QJsonValue(s.start.spring); }},
    {"totalStart", true, [](const RunSummary &s) { return QJsonValue(s.start.total()); }},
    {"kineticEnd", true, [](const RunSummary &s) { return QJsonValue(s.end.kinetic); }},
    {"gravitationalEnd", true, [](const RunSummary &s) { return QJsonValue(s.end.gravitational); }},
    {"springEnd", true, [](const RunSummary &s) { return QJsonValue(s.end.spring); }},
    {"totalEnd", true, [](const RunSummary &s) { return QJsonValue(s.end.total()); }},
    {"springBreaks", true, [](const RunSummary &s) { return QJsonValue(double(s.springBreaks)); }},
    {"solverIterations", true, [](const RunSummary &s) { return s.solved ? QJsonValue(s.solverIterations) : QJsonValue(); }},
    {"solverIterationsMost", true,
     [](const RunSummary &s) { return s.solved ? QJsonValue(s.solverIterationsMost) : QJsonValue(); }},
    {"solverResidual", true, [](const RunSummary &s) { return s.solved ? QJsonValue(s.solverResidual) : QJsonValue(); }},
    {"solverCapHits", true,
     [](const RunSummary &s) { return s.solved ? QJsonValue(double(s.solverCapHits)) : QJsonValue(); }},
    {"warnings", false, [](const RunSummary &s) { return QJsonValue(QJsonArray::fromStringList(s.warnings)); }},
    {"error", false, [](const RunSummary &s) { return QJsonValue(s.error); }},
};

QJsonValue fieldValue(const SummaryField &field, const RunSummary &summary)
{
    return field.fromRun && !summary.ran ? QJsonValue() : field.value(summary);
}

// a JSON value as the text of one cell: numbers read back as the same double, an object as
// KEY=VALUE pairs (as --set spells them), a list joined with " | "
QString cellText(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Double:  // a value that is not finite (a blown-up run's energy) is an empty cell
        return std::isfinite(value.toDouble()) ? QString::fromLatin1(io::formatNumber(value.toDouble())) : QString();
    case QJsonValue::String: return value.toString();
    case QJsonValue::Bool: return value.toBool() ? u"true"_s : u"false"_s;
    case QJsonValue::Array: {
        QStringList items;
        for (const QJsonValue &item : value.toArray())
            items += cellText(item);
        return items.join(u" | "_s);
    }
    case QJsonValue::Object: return overridesText(value.toObject());
    case QJsonValue::Null:
    case QJsonValue::Undefined: break;
    }
    return {};
}

// RFC 4180: a cell with a comma, a quote or a line break is quoted, its quotes doubled
QByteArray csvCell(const QString &text)
{
    QByteArray cell = text.toUtf8();
    if (cell.contains(',') || cell.contains('"') || cell.contains('\n') || cell.contains('\r'))
        cell = '"' + cell.replace("\"", "\"\"") + '"';
    return cell;
}

}  // namespace

QString overridesText(const QJsonObject &overrides)
{
    QStringList pairs;
    for (auto it = overrides.begin(); it != overrides.end(); ++it)
        pairs += it.key() + u'=' +
                 (it.value().isArray() ? QString::fromUtf8(QJsonDocument(it.value().toArray()).toJson(QJsonDocument::Compact))
                                       : cellText(it.value()));
    return pairs.join(u' ');
}

QString statusWord(RunStatus status)
{
    switch (status) {
    case RunStatus::Ok: return u"ok"_s;
    case RunStatus::BadInput: return u"bad-input"_s;
    case RunStatus::OutOfMemory: return u"out-of-memory"_s;
    case RunStatus::WriteFailed: return u"write-failed"_s;
    case RunStatus::BlewUp: return u"blew-up"_s;
    case RunStatus::ReplayDiffers: return u"replay-differs"_s;
    }
    return u"failed"_s;
}

QByteArray summaryJson(const RunSummary &summary)
{
    // QJsonObject would sort the keys; written by hand they keep the fields' order
    QByteArray out = "{\n";
    for (std::size_t k = 0; k < std::size(kFields); ++k) {
        const QJsonValue value = fieldValue(kFields[k], summary);
        const QByteArray text =
            value.isDouble() ? io::formatNumber(value.toDouble())
                             : QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact).chopped(1).mid(1);
        out += "    \"" + QByteArray(kFields[k].name) + "\": " + text + (k + 1 < std::size(kFields) ? ",\n" : "\n");
    }
    return out + "}\n";
}

QByteArray summaryCsvHeader()
{
    QByteArrayList names;
    for (const SummaryField &field : kFields)
        names += field.name;
    return names.join(',') + '\n';
}

QByteArray summaryCsvRow(const RunSummary &summary)
{
    QByteArrayList cells;
    for (const SummaryField &field : kFields)
        cells += csvCell(cellText(fieldValue(field, summary)));
    return cells.join(',') + '\n';
}

QString saveSummary(const RunSummary &summary, const QString &jsonPath, const QString &csvPath)
{
    const std::pair<QString, QByteArray> files[] = {
        {jsonPath, jsonPath.isEmpty() ? QByteArray() : summaryJson(summary)},
        {csvPath, csvPath.isEmpty() ? QByteArray() : summaryCsvRow(summary)}};
    for (const auto &[path, bytes] : files)
        if (!path.isEmpty())
            if (const QString failure = io::writeFileAtomically(path, bytes); !failure.isEmpty())
                return QDir::toNativeSeparators(path) + u": cannot save: "_s + failure;
    return {};
}

}  // namespace app
