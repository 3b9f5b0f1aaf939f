#pragma once
// The words a scene file's messages use for JSON values and for the names a setting takes, shared
// by the scene reader and springlab-sim's command line (--integrator, --set), so that a value is
// refused in the same words wherever it comes from.

#include "core/model/scene.h"

#include <QJsonValue>
#include <QString>
#include <QStringView>

#include <optional>

namespace io {

// what a JSON value is, for "expected a number, got a string": "a number", "a boolean", "null", ...
QString describe(const QJsonValue &value);

// why a number as the text spells it is no double a scene can hold: "the number 1e400 is too large
// for a double: JSON has no infinity or NaN", "nan is not a JSON number: JSON has no NaN or
// infinity"; empty when the token is none of those
QString unholdableNumber(QStringView token);

// "symplectic-euler, explicit-euler, ...", in the order menus list them
QString knownIntegrators();
QString knownContactSolvers();

// the integrator or contact solver of that name; nullopt with error set to
// "unknown integrator \"x\" (known: ...)" when there is none
std::optional<core::Integrator> integratorNamed(const QString &name, QString &error);
std::optional<core::ContactSolver> contactSolverNamed(const QString &name, QString &error);

}  // namespace io
