#include "core/integrators/error_estimate.h"

#include "core/step.h"

#include <cmath>

namespace core {

void StepDoubling::prepare(const std::shared_ptr<const Model> &model)
{
    if (m_source == model)
        return;
    m_source = model;
    m_single = *model;
    m_single.timeStep = model->subStep();
    m_single.substeps = 1;
    m_double = m_single;
    m_double.substeps = 2;
}

std::optional<double> StepDoubling::estimate(const std::shared_ptr<const Model> &model, const State &state)
{
    const std::optional<LocalError> error = estimateLocalError(model, state);
    if (!error)
        return std::nullopt;
    return error->position;
}

std::optional<LocalError> StepDoubling::estimateLocalError(const std::shared_ptr<const Model> &model,
                                                           const State &state)
{
    prepare(model);
    m_one = state;
    m_two = state;
    m_oneWork.blowup.reset();
    m_twoWork.blowup.reset();
    m_oneWork.interrupted = m_twoWork.interrupted = false;
    if (!step(m_single, m_one, m_oneWork) || !step(m_double, m_two, m_twoWork))
        return std::nullopt;
    // the differences, scaled from "h against h/2" to the error of the h step
    const int order = integratorOrder(model->integrator);
    const double share = 1.0 - std::pow(2.0, -order);
    LocalError error;
    if (m_one.position.cols() > 0) {
        error.position = (m_one.position - m_two.position).cwiseAbs().maxCoeff() / share;
        error.velocity = (m_one.velocity - m_two.velocity).cwiseAbs().maxCoeff() / share;
    }
    return error;
}

}  // namespace core
