#include "messages.h"

namespace ui {

std::uint64_t MessageQueue::push(Message message)
{
    std::lock_guard lock(m_mutex);
    m_pending.push_back(std::move(message));
    m_waiting.store(true, std::memory_order_relaxed);
    return ++m_pushed;
}

MessageQueue::Batch MessageQueue::drain()
{
    Batch batch;
    std::lock_guard lock(m_mutex);
    batch.messages.swap(m_pending);
    m_waiting.store(false, std::memory_order_relaxed);
    batch.lastSequence = m_pushed;
    return batch;
}

bool MessageQueue::empty() const
{
    std::lock_guard lock(m_mutex);
    return m_pending.empty();
}

}  // namespace ui
