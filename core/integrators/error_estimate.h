#pragma once
// Step doubling: the local error of one sub-step estimated by comparing one sub-step of h with
// two of h/2 from the same state. For a scheme of order p the local error of the h step is
// C h^(p+1) and the two half steps leave 1/2^p of it, so the difference is (1 - 2^-p) of the
// error. The estimate runs on copies: the state being simulated is not touched.

#include "core/model/model.h"
#include "core/model/state.h"
#include "core/model/workspace.h"

#include <atomic>
#include <memory>
#include <optional>

namespace core {

// the local error of one sub-step, the largest component of each
struct LocalError {
    double position = 0.0;  // m
    double velocity = 0.0;  // m/s
};

class StepDoubling {
public:
    // the estimated local position error of one sub-step (m, the largest component), or nullopt
    // if either trial blew up or was interrupted
    std::optional<double> estimate(const std::shared_ptr<const Model> &model, const State &state);

    // the same estimate for the positions and the velocities
    std::optional<LocalError> estimateLocalError(const std::shared_ptr<const Model> &model, const State &state);

    // a flag that stops the trial steps between sub-steps (null: never); interrupted() then says
    // why the estimate is missing
    void setInterrupt(const std::atomic<bool> *flag)
    {
        m_oneWork.interrupt = flag;
        m_twoWork.interrupt = flag;
    }
    bool interrupted() const { return m_oneWork.interrupted || m_twoWork.interrupted; }

private:
    void prepare(const std::shared_ptr<const Model> &model);

    std::shared_ptr<const Model> m_source;  // the model m_single and m_double were made from
    Model m_single;                          // one step of h
    Model m_double;                          // two steps of h/2
    State m_one;  // copies of the state (assignment reuses their memory once sized)
    State m_two;
    Workspace m_oneWork;
    Workspace m_twoWork;
};

}  // namespace core
