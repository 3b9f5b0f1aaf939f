#pragma once
// SimulationRunner: the worker's Qt-free half. It owns the compiled Model and the State, applies
// edits between steps, and turns wall time into whole steps of the model's time step. It has no
// thread and no timer of its own: SimulationWorker calls it from its tick, and the unit tests call
// it directly, one edit or one advance at a time.

#include "edit_queue.h"

#include "core/model.h"
#include "core/snapshot.h"
#include "core/state.h"

#include <memory>
#include <optional>

namespace ui {

class SimulationRunner {
public:
    struct Advance {
        int steps = 0;                // steps taken
        double droppedSeconds = 0.0;  // s of wall time left unsimulated (the run fell behind)
    };

    // applies one edit between two steps
    void apply(const Edit &edit);

    // advances simulated time by wallSeconds (already capped by the caller) in whole steps; the
    // remainder is owed to the next call. Stops early when the steps have taken budgetSeconds of
    // computing, dropping what is still owed, so a slow scene runs slower than real time instead
    // of piling up a backlog. Does nothing while paused.
    Advance advance(double wallSeconds, double budgetSeconds);

    bool hasScene() const { return m_model != nullptr; }
    bool isRunning() const { return m_running; }
    const core::State &state() const { return m_state; }
    std::shared_ptr<const core::Model> model() const { return m_model; }
    std::shared_ptr<const core::SceneDesc> scene() const { return m_scene; }

    // the current state, packed for drawing
    std::shared_ptr<const core::Snapshot> snapshot() const;

    // the blow-up that stopped the run, once: the caller reports it
    std::optional<core::Blowup> takeBlowup();

private:
    void setScene(const SetSceneEdit &edit);
    void reset();
    void tilt(const TiltEdit &edit);
    void steer(const SteerEdit &edit);
    void applySteering();
    bool stepOnce();

    std::shared_ptr<const core::SceneDesc> m_scene;
    std::shared_ptr<const core::Model> m_model;
    core::State m_state;
    core::State m_lastGood;  // the state before the latest steps, restored if they blow up
    bool m_running = false;
    double m_owed = 0.0;  // s of simulated time not yet covered by a whole step
    std::optional<core::Blowup> m_blowup;

    // the steering force, kept across resets and parameter changes
    int m_steerParticle = -1;
    Eigen::Vector3d m_steerForce = Eigen::Vector3d::Zero();  // N
};

// "particle 12's velocity reached 1.2e+10 at step 345 (t = 3.44 s)"
std::string describeBlowup(const core::Blowup &blowup);

}  // namespace ui
