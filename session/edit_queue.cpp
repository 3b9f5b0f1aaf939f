#include "edit_queue.h"

namespace ui {

std::uint64_t EditQueue::push(Edit edit)
{
    std::lock_guard lock(m_mutex);
    m_pending.push_back(std::move(edit));
    return ++m_pushed;
}

EditQueue::Batch EditQueue::drain()
{
    Batch batch;
    std::lock_guard lock(m_mutex);
    batch.edits.swap(m_pending);
    batch.lastSequence = m_pushed;
    return batch;
}

bool EditQueue::empty() const
{
    std::lock_guard lock(m_mutex);
    return m_pending.empty();
}

}  // namespace ui
