#include "simulation_runner.h"

#include "carry_across_edit.h"

#include "core/model/state_hash.h"

#include "core/step.h"
#include "core/threads.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <new>
#include <random>
#include <string>
#include <utility>

namespace ui {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// a uniform number in [-1, 1) from the generator's bits, the same on every standard library
double symmetricUnit(std::mt19937_64 &random)
{
    const double unit = static_cast<double>(random() >> 11) * 0x1.0p-53;  // [0, 1)
    return 2.0 * unit - 1.0;
}

// the visitor that dispatches each kind of message
template <typename... Handlers>
struct Overloaded : Handlers... {
    using Handlers::operator()...;
};
template <typename... Handlers>
Overloaded(Handlers...) -> Overloaded<Handlers...>;

// what changes the run: applied while a recorded step is shown, it goes on from that step
bool changesTheRun(const Message &message)
{
    return std::holds_alternative<SetSceneEdit>(message) || std::holds_alternative<Play>(message) ||
           std::holds_alternative<TiltEdit>(message) || std::holds_alternative<SteerEdit>(message) ||
           std::holds_alternative<GrabEdit>(message) || std::holds_alternative<StrikeEdit>(message) ||
           std::holds_alternative<StartRecording>(message);
}

// what a session recording keeps: the edits and run control; requests for copies and plans, the
// recording's own start and stop, and moves through the timeline are not
bool isRecorded(const Message &message)
{
    return !std::holds_alternative<Sync>(message) && !std::holds_alternative<PlanAccuracy>(message) &&
           !std::holds_alternative<CaptureState>(message) && !std::holds_alternative<StartRecording>(message) &&
           !std::holds_alternative<StopRecording>(message) && !std::holds_alternative<Scrub>(message) &&
           !std::holds_alternative<StepBack>(message) && !std::holds_alternative<SetTimelineBudget>(message);
}

// an edit that starts a keyframe: replays after it use the new model and forces
bool startsAKeyframe(const Message &message)
{
    return std::holds_alternative<SetSceneEdit>(message) || std::holds_alternative<Reset>(message) ||
           std::holds_alternative<TiltEdit>(message) || std::holds_alternative<SteerEdit>(message) ||
           std::holds_alternative<GrabEdit>(message) || std::holds_alternative<StrikeEdit>(message);
}

// the messages after which a step asked for and cut short is no longer wanted: Pause, Play (the
// run takes over), Reset, another scene, and moving through the timeline
bool stopsOwedSteps(const Message &message)
{
    if (const auto *edit = std::get_if<SetSceneEdit>(&message))
        return edit->change == SceneChange::Replace;
    return std::holds_alternative<Pause>(message) || std::holds_alternative<Play>(message) ||
           std::holds_alternative<Reset>(message) || std::holds_alternative<Scrub>(message) ||
           std::holds_alternative<StepBack>(message);
}

}  // namespace

void SimulationRunner::apply(const Message &message)
{
    if (stopsOwedSteps(message))
        m_stepsOwed = 0;
    if (m_scrubber.isScrubbing() && changesTheRun(message))
        resumeFromScrub();

    if (m_recording && isRecorded(message))
        m_recording->entries.push_back({m_stepsTaken - m_recordingFrom, message});
    std::visit(Overloaded{
                   [this](const SetSceneEdit &e) { setScene(e); },
                   [this](const TiltEdit &e) { tilt(e); },
                   [this](const SteerEdit &e) { steer(e); },
                   [this](const GrabEdit &e) { grab(e); },
                   [this](const StrikeEdit &e) { strike(e); },
                   [this](const Play &) {
                       m_running = hasScene();
                       m_threads.startOver();  // what the last run measured says nothing of this one
                   },
                   [this](const Pause &) { m_running = false; },
                   [this](const StepOnce &) { stepOnceMessage(); },
                   [this](const Reset &) { reset(); },
                   [](const Sync &) {},
                   [this](const PlanAccuracy &e) {
                       m_replies.push_back(AccuracyPlanReply{
                           e.request, RunDiagnostics::planAccuracy(m_model, m_state, m_work.profile, e.tolerance,
                                                                   m_planStop)});
                   },
                   [this](const CaptureState &e) { captureState(e); },
                   [this](const StartRecording &) { startRecording(); },
                   [this](const StopRecording &e) { m_replies.push_back(RecordingReply{e.request, stopRecording()}); },
                   [this](const Scrub &e) { scrubTo(e.step); },
                   [this](const StepBack &) { stepBack(); },
                   [this](const SetTimelineBudget &e) { m_scrubber.timeline().setBudget(e.bytes); },
               },
               message);

    if (hasScene() && startsAKeyframe(message)) {
        keyframe();
        sample();
    }
}

void SimulationRunner::stepOnceMessage()
{
    m_running = false;
    // behind a step cut short: one more owed, taken in order after it
    if (m_stepsOwed > 0) {
        ++m_stepsOwed;
        return;
    }
    // inside the recording: one step on through it; at its end, a new step
    // (from the step asked for, as stepBack)
    const std::optional<std::uint64_t> pending = m_scrubber.pendingStep();
    const std::optional<std::uint64_t> shown = pending ? pending : m_scrubber.scrubStep();
    if (shown && *shown < m_scrubber.timeline().lastStep()) {
        scrubTo(*shown + 1);
        return;
    }
    if (m_scrubber.isScrubbing())
        resumeFromScrub();
    // a slow step is owed, not taken here: the worker answers the Step first (a frame saying so
    // within milliseconds) and then takes it, where a later message may cut it (takeOwedSteps)
    if (hasScene() && m_interrupt && stepsAreSlow()) {
        m_stepsOwed = 1;
        return;
    }
    if (hasScene()) {
        m_lastGood = m_state;
        if (interruptibleStep(&m_lastGood))
            ++m_stepsTaken;
        else if (m_work.interrupted)
            m_stepsOwed = 1;
        m_diagnostics.stepped();
    }
}

void SimulationRunner::setInterrupt(const std::atomic<bool> *flag)
{
    m_interrupt = flag;
    m_diagnostics.setInterrupt(flag);
}

bool SimulationRunner::takeOwedSteps()
{
    bool taken = false;
    while (m_stepsOwed > 0 && hasScene()) {
        m_lastGood = m_state;
        if (!interruptibleStep(&m_lastGood)) {
            if (!m_work.interrupted)
                m_stepsOwed = 0;  // blown up: the run stops there
            break;
        }
        --m_stepsOwed;
        ++m_stepsTaken;
        taken = true;
        m_diagnostics.stepped();
    }
    return taken;
}

bool SimulationRunner::interruptibleStep(const core::State *start)
{
    core::setThreadCount(m_threads.threads());
    const auto began = Clock::now();
    m_work.interrupt = start ? m_interrupt : nullptr;
    const bool taken = stepOnce();
    m_work.interrupt = nullptr;
    m_lastStepSeconds = secondsSince(began);
    if (taken)
        m_threads.stepped(m_lastStepSeconds);
    if (!taken && m_work.interrupted) {
        m_state = *start;
        // cut short: whatever it took so far, it is slow enough to be cut again when retaken
        m_lastStepSeconds = std::max(m_lastStepSeconds, kInterruptibleStepSeconds);
    }
    return taken;
}

HeldForces SimulationRunner::heldForces() const
{
    return HeldForces{m_grabParticle, m_grabTarget, m_steerParticle, m_steerForce};
}

void SimulationRunner::keyframe()
{
    m_scrubber.timeline().afterEdit(m_model, m_scene, m_state, heldForces());
}

void SimulationRunner::sample()
{
    m_samples.add(*m_model, m_state, m_diagnostics.initialEnergies());
}

bool SimulationRunner::scrubTo(std::uint64_t step)
{
    if (!hasScene() || m_recording || !m_scrubber.canShow(step))
        return false;
    m_running = false;
    m_owed = 0.0;
    // slow steps: the keyframe at once, then a replayed step a tick, each shown (continueScrub)
    return m_scrubber.show(step, m_work, m_interrupt, stepsAreSlow() ? 0 : std::numeric_limits<int>::max());
}

bool SimulationRunner::continueScrub()
{
    return hasScene() && m_scrubber.pendingStep() &&
           m_scrubber.goOn(m_work, m_interrupt, stepsAreSlow() ? 1 : std::numeric_limits<int>::max());
}

void SimulationRunner::stepBack()
{
    // from the step asked for, not the one shown on the way there: a second step back while the
    // first still replays from its keyframe (step 20, back to 19 from keyframe 10) went to 9
    const std::uint64_t shown = m_scrubber.pendingStep().value_or(m_scrubber.scrubStep().value_or(m_state.step));
    if (shown > 0)
        scrubTo(shown - 1);
}

// the step shown becomes the run's: under the scene it was recorded with, then the scene as it is
// now in the editor takes over (as an edit would), and what was recorded after it is gone
void SimulationRunner::resumeFromScrub()
{
    ScrubbedStep scrub = m_scrubber.resume();
    const std::shared_ptr<const core::SceneDesc> current = m_scene;
    m_samples.dropAfter(scrub.state.step);
    m_state = std::move(scrub.state);
    // the held forces are the editor's own now, not the recorded ones
    m_state.applied.resize(3, 0);
    m_state.appliedCount = 0;
    m_owed = 0.0;
    m_scene = scrub.scene;
    m_model = scrub.model;
    if (current != m_scene) {
        setScene(SetSceneEdit{current, sameStructure(*m_scene, *current) ? SceneChange::Parameters
                                                                         : SceneChange::Structure});
    } else {
        applySteering();
        m_diagnostics.stateChanged();
        m_diagnostics.checkPairSpeed(*m_model, m_state);
    }
    keyframe();
    sample();
}

void SimulationRunner::setScene(const SetSceneEdit &edit)
{
    const std::shared_ptr<const core::SceneDesc> previous = m_scene;
    const std::shared_ptr<const core::Model> previousModel = m_model;
    // the energy before the edit, where a run goes on through it: what the edit changes is the
    // user's work, which the drift leaves out (an undone transform read ΔE = -97 %)
    const bool running = previousModel && edit.change != SceneChange::Replace && m_state.step > 0;
    const core::Energies before = running ? core::energies(*previousModel, m_state) : core::Energies{};
    m_scene = edit.scene;
    if (edit.change == SceneChange::Replace)
        m_threads.startOver();  // another scene: its steps cost what they cost
    // another scene is compiled afresh; an edit keeps the spring triangles if it left the springs
    m_model = core::compileModel(*m_scene, edit.change == SceneChange::Replace ? nullptr : m_model.get());
    // the run goes on through the edit as far as it can (carry_across_edit.h), else starts afresh
    if (!carryAcrossEdit(previous.get(), *m_scene, *m_model, edit.change, m_state))
        restart();
    else if (m_state.step == 0)
        m_diagnostics.restarted(*m_model, m_state);  // nothing ran yet: the drift is measured from the edited scene
    else {
        m_model = core::autoSubstepsAlsoFor(m_model, *m_scene, m_state);  // the run goes on from this state
        if (running)
            m_diagnostics.editedBy(before, core::energies(*m_model, m_state));
    }
    // another scene, or the same one from its start: the recording belongs to the old run
    if (edit.change == SceneChange::Replace || m_state.step == 0)
        m_scrubber.timeline().clear();
    if (edit.change == SceneChange::Replace) {
        // another scene: nothing of the old one's steering survives, and its costs start afresh
        m_running = false;
        m_steerParticle = -1;
        m_steerForce.setZero();
        m_grabParticle = -1;
        m_diagnostics.resetCosts();
    }
    applySteering();
    m_diagnostics.modelChanged();
    m_diagnostics.checkPairSpeed(*m_model, m_state);
}

// the scene's initial conditions, and the energy the drift is measured from
void SimulationRunner::restart()
{
    m_state = core::makeState(*m_model, *m_scene);
    m_owed = 0.0;
    m_diagnostics.restarted(*m_model, m_state);
    m_samples.clear();  // the plots start over with this run
}

void SimulationRunner::reset()
{
    if (!hasScene())
        return;
    m_scrubber.clear();
    restart();
    applySteering();
    m_diagnostics.stateChanged();
    m_diagnostics.checkPairSpeed(*m_model, m_state);
}

void SimulationRunner::tilt(const TiltEdit &edit)
{
    if (!hasScene())
        return;
    // every free particle gets a kick of up to `speed` per component, from one seeded generator
    const core::Energies before = core::energies(*m_model, m_state);
    std::mt19937_64 random(edit.seed);
    for (int i : m_model->freeParticles)
        for (int axis = 0; axis < 3; ++axis)
            m_state.velocity(axis, i) += edit.speed * symmetricUnit(random);
    // the kick is work done on the scene: neither drift nor a runaway
    m_diagnostics.editedBy(before, core::energies(*m_model, m_state));
    m_diagnostics.stateChanged();
}

void SimulationRunner::strike(const StrikeEdit &edit)
{
    if (!hasScene() || edit.particle < 0 || edit.particle >= m_model->particleCount())
        return;
    const core::Energies before = core::energies(*m_model, m_state);
    // a pinned particle does not move, but turns if spun (a post spun in place)
    if (!m_model->isPinned(edit.particle))
        m_state.velocity.col(edit.particle) += edit.velocityChange;
    // a scene that cannot turn keeps no spins (StepPlan::spin): there the blow moves the particle alone
    if (m_state.angularVelocity.cols() == m_model->particleCount())
        m_state.angularVelocity.col(edit.particle) += edit.spinChange;
    // the blow is work done on the scene, as a kick is
    m_diagnostics.editedBy(before, core::energies(*m_model, m_state));
    m_diagnostics.stateChanged();
}

void SimulationRunner::steer(const SteerEdit &edit)
{
    // clear the old particle's force before moving it to another one
    if (hasScene() && m_steerParticle >= 0 && m_steerParticle < m_model->particleCount())
        core::setAppliedForce(m_state, m_steerParticle, Eigen::Vector3d::Zero());
    m_steerParticle = edit.particle;
    m_steerForce = edit.force;
    applySteering();
    m_diagnostics.stateChanged();
}

void SimulationRunner::applySteering()
{
    if (hasScene() && m_steerParticle >= 0 && m_steerParticle < m_model->particleCount())
        core::setAppliedForce(m_state, m_steerParticle, m_steerForce);
}

void SimulationRunner::grab(const GrabEdit &edit)
{
    const bool valid = hasScene() && edit.particle >= 0 && edit.particle < m_model->particleCount();
    // let go of the old particle: steering alone acts on it again
    if (m_grabParticle >= 0 && m_grabParticle < m_state.position.cols()) {
        core::setAppliedForce(m_state, m_grabParticle, Eigen::Vector3d::Zero());
        applySteering();
    }
    m_grabParticle = valid ? edit.particle : -1;
    m_grabTarget = edit.target;
    applyGrab();
}

void SimulationRunner::applyGrab()
{
    if (hasScene())
        applyGrabForce(*m_model, m_state, heldForces());
}

bool SimulationRunner::stepOnce()
{
    applyGrab();
    bool taken = false;
    try {
        taken = core::step(*m_model, m_state, m_work);
    } catch (const std::bad_alloc &) {
        // a step that needs more memory than there is (a crowd of overlapping particles, a cap
        // set with ulimit -v): the scratch arrays are let go, and the run stops like a blow-up
        core::Workspace fresh;
        fresh.profile = m_work.profile;
        fresh.interrupt = m_work.interrupt;
        m_work = std::move(fresh);
        m_diagnostics.ranOutOfMemory("Out of memory in step " + std::to_string(m_lastGood.step + 1) + " (" +
                                     std::to_string(m_model->particleCount()) +
                                     " particles): the step needs more memory than is free. Paused at the "
                                     "last good state.");
        return stopAtLastGood();
    }
    if (taken) {
        m_scrubber.timeline().afterStep(m_model, m_scene, m_state, heldForces());
        sample();
        return true;
    }
    if (m_work.interrupted)
        return false;  // not taken: the caller goes back to where it began
    // blown up: stop, keep the report, and go back to the last good state
    m_diagnostics.blewUp(std::exchange(m_work.blowup, std::nullopt));
    return stopAtLastGood();
}

bool SimulationRunner::stopAtLastGood()
{
    m_running = false;
    m_owed = 0.0;
    m_state = m_lastGood;
    m_scrubber.timeline().truncateAfter(m_state.step);
    m_samples.dropAfter(m_state.step);
    m_diagnostics.stateChanged();
    return false;
}

SimulationRunner::Advance SimulationRunner::advance(double wallSeconds, double budgetSeconds, double speed)
{
    Advance result;
    if (!m_running || !hasScene())
        return result;

    m_diagnostics.addWallTime(wallSeconds);
    const double h = m_model->timeStep;
    // as fast as it goes: a step is always owed, until the budget is spent
    const bool asFast = !(speed > kAsFastAsItGoes);
    m_owed = asFast ? std::max(m_owed, h) : m_owed + wallSeconds * speed;
    if (m_owed < h)
        return result;
    m_lastGood = m_state;
    const auto start = Clock::now();
    bool blewUp = false;
    const core::State *stepStart = &m_lastGood;  // null: the next step cannot be cut short
    while (m_owed >= h) {
        if (!interruptibleStep(stepStart)) {
            if (m_work.interrupted) {
                // messages wait: they go first, and the step is taken again after them
                result.interrupted = true;
                result.droppedSeconds = m_owed - h;
                m_owed = h;
                break;
            }
            blewUp = true;
            m_stepsTaken -= static_cast<std::uint64_t>(result.steps);  // back at the tick's start
            break;
        }
        m_owed = asFast ? h : m_owed - h;
        ++result.steps;
        ++m_stepsTaken;
        // out of time for this tick: give up what is still owed (as fast as it goes owes nothing)
        if (secondsSince(start) > budgetSeconds) {
            result.droppedSeconds = asFast ? 0.0 : m_owed;
            m_owed = 0.0;
            break;
        }
        stepStart = nullptr;
        if (m_interrupt && stepsAreSlow()) {
            m_stepStart = m_state;
            stepStart = &m_stepStart;
        }
    }
    // a run whose energy ran away with every value still finite has blown up all the same: it
    // stops at the tick's start, the last state the check passed
    if (!blewUp && result.steps > 0) {
        const HeldForces held = heldForces();
        const bool outside = held.grabParticle >= 0 || (held.steerParticle >= 0 && !held.steerForce.isZero());
        if (std::optional<core::Blowup> runaway = m_diagnostics.watchEnergy(*m_model, m_state, outside)) {
            m_diagnostics.blewUp(std::move(runaway));
            m_stepsTaken -= static_cast<std::uint64_t>(result.steps);
            stopAtLastGood();
            blewUp = true;
        }
    }
    m_diagnostics.afterSteps(secondsSince(start), blewUp, m_model, m_state);
    return result;
}

void SimulationRunner::captureState(const CaptureState &request)
{
    // a copy in doubles: the scene's initial conditions get exactly what the run has
    // (while scrubbing, the step shown)
    auto captured = std::make_shared<CapturedState>();
    if (hasScene()) {
        captured->state = shownState();
        captured->scene = shownScene();
    }
    m_replies.push_back(CapturedStateReply{request.request, std::move(captured)});
}

const core::State &SimulationRunner::shownState() const
{
    const ScrubbedStep *shown = m_scrubber.shown();
    return shown ? shown->state : m_state;
}

std::shared_ptr<const core::Model> SimulationRunner::shownModel() const
{
    const ScrubbedStep *shown = m_scrubber.shown();
    return shown ? shown->model : m_model;
}

std::shared_ptr<const core::SceneDesc> SimulationRunner::shownScene() const
{
    const ScrubbedStep *shown = m_scrubber.shown();
    return shown ? shown->scene : m_scene;
}

std::shared_ptr<const core::Snapshot> SimulationRunner::snapshot() const
{
    if (!hasScene())
        return nullptr;
    return core::makeSnapshot(*shownModel(), shownState());
}

void SimulationRunner::fillSnapshot(core::Snapshot &into) const
{
    if (hasScene())
        core::fillSnapshot(into, *shownModel(), shownState());
}

std::optional<std::string> SimulationRunner::takeBlowupMessage()
{
    if (!hasScene())
        return std::nullopt;
    return m_diagnostics.takeBlowupMessage(*m_model, m_state);
}

void SimulationRunner::startRecording()
{
    if (!hasScene())
        return;
    auto recording = std::make_shared<SessionRecording>();
    recording->scene = m_scene;
    recording->start = m_state;
    // forces held on from before the start
    if (m_steerParticle >= 0)
        recording->entries.push_back({0, SteerEdit{m_steerParticle, m_steerForce}});
    if (m_grabParticle >= 0)
        recording->entries.push_back({0, GrabEdit{m_grabParticle, m_grabTarget}});
    m_recording = std::move(recording);
    m_recordingFrom = m_stepsTaken;
}

std::shared_ptr<const SessionRecording> SimulationRunner::stopRecording()
{
    if (!m_recording)
        return nullptr;
    m_recording->steps = m_stepsTaken - m_recordingFrom;
    m_recording->finalHash = core::stateHash(m_state);
    return std::exchange(m_recording, nullptr);
}

bool SimulationRunner::restoreRecordedStart(const SessionRecording &recording)
{
    const core::State &start = recording.start;
    if (!hasScene() || start.particleCount() != m_state.particleCount() ||
        start.velocity.cols() != start.position.cols() ||
        (start.appliedCount > 0 && start.applied.cols() != start.position.cols()) ||
        (!start.springBroken.empty() && static_cast<int>(start.springBroken.size()) != m_model->springCount()))
        return false;
    m_state = start;
    core::fitSpringBreaks(*m_model, m_state);  // the capacity for every break
    core::fitSpin(*m_model, m_state);
    m_stepsTaken = 0;
    m_diagnostics.stateChanged();
    m_scrubber.clear();
    keyframe();
    return true;
}

bool SimulationRunner::stepForReplay()
{
    if (!hasScene())
        return false;
    m_lastGood = m_state;
    if (!stepOnce())
        return false;
    ++m_stepsTaken;
    return true;
}

}  // namespace ui
