#include "scene_words.h"

#include "core/contacts/solver_names.h"

#include <QStringList>

#include <string_view>

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
