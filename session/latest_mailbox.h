#pragma once
// A latest-wins mailbox between one producer thread and one consumer thread. The producer
// publishes immutable values as shared pointers; the consumer takes the newest one. The mutex is
// held only for a pointer swap, so neither side ever waits for the other's work, and a value is
// never seen half-written because it is never written after it is published.

#include <memory>
#include <mutex>

namespace ui {

template <typename T>
class LatestMailbox {
public:
    // replaces whatever was waiting; returns true if the box was empty, i.e. the consumer has
    // taken the previous value and needs telling that there is a new one
    bool publish(std::shared_ptr<const T> value)
    {
        std::shared_ptr<const T> replaced;  // released outside the lock
        std::lock_guard lock(m_mutex);
        replaced.swap(m_value);
        m_value = std::move(value);
        return replaced == nullptr;
    }

    // whether the consumer has taken the last value published (or none was)
    bool empty()
    {
        std::lock_guard lock(m_mutex);
        return m_value == nullptr;
    }

    // the newest value, leaving the box empty; null if nothing new was published
    std::shared_ptr<const T> take()
    {
        std::shared_ptr<const T> value;
        std::lock_guard lock(m_mutex);
        value.swap(m_value);
        return value;
    }

private:
    std::mutex m_mutex;
    std::shared_ptr<const T> m_value;
};

}  // namespace ui
