#pragma once
// Replies: the one-off answers to the messages that ask for something (an accuracy plan, the
// current state, the recording that a stop ends). Each is sent once, tagged with its request's
// number, instead of riding along on every frame: the runner keeps the replies of the messages it
// applied until the worker takes them, and the worker hands them to the UI thread through a
// ReplyQueue, which the controller drains and announces one signal per kind. Qt-free.

#include "captured_state.h"
#include "session_recording.h"

#include "core/integrators/accuracy_planner.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <variant>
#include <vector>

namespace ui {

// the plan a PlanAccuracy asked for
struct AccuracyPlanReply {
    std::uint64_t request = 0;
    std::shared_ptr<const core::AccuracyPlan> plan;
};
// the state a CaptureState asked for
struct CapturedStateReply {
    std::uint64_t request = 0;
    std::shared_ptr<const CapturedState> captured;
};
// the recording a StopRecording ended (null if none was running)
struct RecordingReply {
    std::uint64_t request = 0;
    std::shared_ptr<const SessionRecording> recording;
};
using Reply = std::variant<AccuracyPlanReply, CapturedStateReply, RecordingReply>;

// the first reply of kind R among replies, nullopt if none
template <typename R>
std::optional<R> findReply(const std::vector<Reply> &replies)
{
    for (const Reply &reply : replies)
        if (const R *found = std::get_if<R>(&reply))
            return *found;
    return std::nullopt;
}

// a thread-safe first-in first-out queue of replies, from the worker to the UI thread
class ReplyQueue {
public:
    // true if the queue was empty before: the one push after which the other side is told
    bool push(Reply reply);
    // takes every pending reply, oldest first
    std::vector<Reply> drain();

private:
    std::mutex m_mutex;
    std::vector<Reply> m_pending;
};

}  // namespace ui
