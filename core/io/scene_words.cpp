#include "scene_words.h"

#include "core/contacts/solver_names.h"

#include <QStringList>

#include <charconv>
#include <string_view>
#include <system_error>

namespace io {

using namespace Qt::Literals::StringLiterals;

namespace {

QString fromView(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

}  // namespace

QString describe(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null: return u"null"_s;
    case QJsonValue::Bool: return u"a boolean"_s;
    case QJsonValue::Double: return u"a number"_s;
    case QJsonValue::String: return u"a string"_s;
    case QJsonValue::Array: return u"an array"_s;
    case QJsonValue::Object: return u"an object"_s;
    case QJsonValue::Undefined: break;
    }
    return u"nothing"_s;
}

QString unholdableNumber(QStringView token)
{
    // a number past a double's range, one way or the other
    const auto digit = [](QChar c) { return c >= u'0' && c <= u'9'; };
    const QString text = token.toString();
    if (!token.isEmpty() && (digit(token[0]) || (token.size() > 1 && token[0] == u'-' && digit(token[1])))) {
        const QByteArray bytes = text.toLatin1();
        double value = 0.0;
        const auto parsed = std::from_chars(bytes.constData(), bytes.constData() + bytes.size(), value);
        if (parsed.ec != std::errc::result_out_of_range)
            return {};
        const bool tiny = text.contains(u"e-"_s, Qt::CaseInsensitive);
        return u"the number "_s + text +
               (tiny ? u" is too close to zero for a double"_s : u" is too large for a double: JSON has no infinity or NaN"_s);
    }
    // a NaN or an infinity as other languages spell them
    if (text.contains(u"nan"_s, Qt::CaseInsensitive) || text.contains(u"inf"_s, Qt::CaseInsensitive))
        return text + u" is not a JSON number: JSON has no NaN or infinity"_s;
    return {};
}

QString knownIntegrators()
{
    QStringList names;
    for (core::Integrator integrator : core::kIntegrators)
        names += fromView(core::integratorName(integrator));
    return names.join(u", "_s);
}

QString knownContactSolvers()
{
    QStringList names;
    for (core::ContactSolver solver : core::kContactSolvers)
        names += fromView(core::contactSolverName(solver));
    return names.join(u", "_s);
}

std::optional<core::Integrator> integratorNamed(const QString &name, QString &error)
{
    const auto integrator = core::integratorFromName(name.toStdString());
    if (!integrator)
        error = u"unknown integrator \""_s + name + u"\" (known: "_s + knownIntegrators() + u")"_s;
    return integrator;
}

std::optional<core::ContactSolver> contactSolverNamed(const QString &name, QString &error)
{
    const auto solver = core::contactSolverFromName(name.toStdString());
    if (!solver)
        error = u"unknown contact solver \""_s + name + u"\" (known: "_s + knownContactSolvers() + u")"_s;
    return solver;
}

}  // namespace io
