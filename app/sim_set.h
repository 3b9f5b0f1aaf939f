#pragma once
// springlab-sim --set KEY=VALUE: one value of the loaded scene changed before the run, for
// parameter sweeps (docs/batch.md). The value is read as a scene file would hold it (a number,
// true or false, a name, [x, y, z]), and the changed scene goes through core::findProblem, the
// check every loaded file passes, so a value is refused with the file's own ranges and words.

#include "core/model/scene.h"

#include <QJsonValue>
#include <QString>

#include <optional>

namespace app {

// a value of one of the kinds a scene file holds, converted once its type is known to fit
struct OverrideValue {
    double number = 0.0;
    int integer = 0;
    bool flag = false;
    Eigen::Vector3d vector = Eigen::Vector3d::Zero();
    core::Integrator integrator = core::Integrator::SymplecticEuler;
    core::ContactSolver contactSolver = core::ContactSolver::Iterative;
};

struct SceneOverride {
    enum class Family { Settings, Particles, Springs, Planes };

    QString argument;   // as given: "springs[12].stiffness=500"
    QString key;        // "springs[12].stiffness"
    QJsonValue value;   // as a file would hold it: 500
    OverrideValue converted;
    Family family = Family::Settings;
    int field = 0;           // the row of the family's table of keys
    qsizetype index = -1;    // the one element it changes; -1: every element
    QString indexText;       // the index as typed, for messages: "12"; past any count: as typed too
};

// "KEY=VALUE" read, its key looked up and its value's type checked; nullopt with error set to
// "--set KEY=VALUE: why"
std::optional<SceneOverride> parseOverride(const QString &argument, QString &error);

// the override written into the scene, then the scene checked as a loaded file is; empty on
// success, else "--set KEY=VALUE: particles[3].mass: must be greater than 0 kg (got -1 kg)".
// One that reaches no element (an index past the list, or a list the scene does not have) is
// refused too, "--set planes.friction=0.5: planes.friction: matches nothing: the scene has no
// planes", with its value still checked, so that a value out of range is said either way.
QString applyOverride(const SceneOverride &override, core::SceneDesc &scene);

}  // namespace app
