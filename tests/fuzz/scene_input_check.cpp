#include "scene_input_check.h"

#include "core/io/scene_file.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "core/step.h"
#include "core/model/validate.h"

#include <algorithm>
#include <cmath>

namespace fuzz {

namespace {

using namespace Qt::Literals::StringLiterals;

// small enough that one input cannot take long or allocate much, large enough for real examples
io::LoadLimits fuzzLimits()
{
    io::LoadLimits limits;
    limits.fileBytes = qint64(1) << 20;
    limits.particles = 2000;
    limits.springs = 20000;
    limits.planes = 100;
    limits.nestingDepth = 32;
    return limits;
}

constexpr int kSteps = 3;
// floating-point work (in "particle updates", roughly 10 ns each under the sanitizers) an input may
// ask for; above it the scene is compiled but not stepped, so no input runs much over 10 ms
constexpr double kWorkBudget = 2e5;

// how fast the stiffest spring or damper moves, 1/s: an explicit adaptive scheme needs steps
// shorter than its inverse (a bound, not the eigenvalue, so cheap)
double fastestRate(const core::Model &model)
{
    double rate = 0.0;
    for (int k = 0; k < model.springCount(); ++k) {
        const double w = model.invMass[model.springA[std::size_t(k)]] + model.invMass[model.springB[std::size_t(k)]];
        rate = std::max(rate, std::sqrt(model.stiffness[k] * w) + model.damping[k] * w);
    }
    for (int i : model.freeParticles)
        rate = std::max(rate, model.viscosity * model.invMass[i]);
    return rate;
}

// force evaluations of one sub-step, at most
double evaluationsPerSubStep(const core::Model &model)
{
    switch (model.integrator) {
    case core::Integrator::SymplecticEuler:
    case core::Integrator::ExplicitEuler: return 1.0;
    case core::Integrator::Xpbd: return model.xpbdIterations;  // a pass over the springs each, as one evaluation
    case core::Integrator::Projective:
    case core::Integrator::Vbd: return 2.0 * model.solverIterations;  // a pass over the springs and a solve each
    case core::Integrator::VelocityVerlet: return 2.0;
    case core::Integrator::Rk4: return 4.0;
    case core::Integrator::ImplicitEuler: return 1000.0;  // its conjugate-gradient solve stops at 1000 iterations
    case core::Integrator::AdaptiveRk45: {
        // 7 stages per trial; trials grow with stiffness times the step, and with the fifth root
        // of (largest value / tolerance); twice that for rejected trials
        const double stiffness = 1.0 + model.subStep() * fastestRate(model);
        return 2.0 * 7.0 * stiffness * std::pow(1e9 / model.tolerance, 0.2);
    }
    }
    return 1.0;
}

// the work of stepping kSteps, in the units of kWorkBudget
double steppingWork(const core::Model &model)
{
    const double n = model.particleCount();
    double perEvaluation = n + model.springCount() + n * model.planeCount();
    if (model.plan.particleCollisions)
        perEvaluation += n * n / 2.0;  // worst case: every pair touches
    return kSteps * double(model.substeps) * (evaluationsPerSubStep(model) * perEvaluation + 20.0);
}

QString fromStd(const std::string &text)
{
    return QString::fromStdString(text);
}

}  // namespace

QString checkSceneInput(const QByteArray &bytes)
{
    const QString source = QString::fromLatin1(kSourceName);
    const io::LoadLimits limits = fuzzLimits();

    // 1. loading returns, with a message that names the file when it fails
    const io::LoadResult loaded = io::parseScene(bytes, source, limits);
    if (!loaded.ok()) {
        if (!loaded.error.startsWith(source + u": "_s) || loaded.error.size() <= source.size() + 2)
            return u"refused without a proper message: \""_s + loaded.error + u'"';
        return {};
    }
    const core::SceneDesc &scene = *loaded.scene;

    // 2. what loads is what the core accepts
    if (const auto problem = core::findProblem(scene))
        return u"loaded a scene the core refuses: "_s + fromStd(problem->path) + u": "_s + fromStd(problem->message);
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        if (!(std::abs(scene.planes[i].normal.squaredNorm() - 1.0) <= 1e-12))
            return u"planes["_s + QString::number(i) + u"].normal is not unit length after loading"_s;

    // 3. save, load, save gives the same bytes
    const QByteArray saved = io::sceneToJson(scene);
    const io::LoadResult reloaded = io::parseScene(saved, source, limits);
    if (!reloaded.ok())
        return u"the saved scene does not load again: "_s + reloaded.error;
    if (!reloaded.warnings.isEmpty())
        return u"the saved scene loads with a warning: "_s + reloaded.warnings.first();
    const QByteArray savedAgain = io::sceneToJson(*reloaded.scene);
    if (savedAgain != saved)
        return u"save, load, save changes the file:\n"_s + QString::fromUtf8(saved) + u"\nbecomes\n"_s +
               QString::fromUtf8(savedAgain);

    // 4. it compiles and steps; a blow-up is a result, not a failure
    const double units = double(scene.particles.size() + scene.springs.size() + scene.planes.size());
    if (scene.settings.autoSubsteps && units * 300.0 > kWorkBudget)
        return {};  // compiling runs the stability analysis: up to 300 power iterations
    const auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    core::Workspace work;
    if (steppingWork(*model) > kWorkBudget)
        return {};
    for (int i = 0; i < kSteps && core::step(*model, state, work); ++i) {
    }
    return {};
}

}  // namespace fuzz
