#include "replies.h"

namespace ui {

bool ReplyQueue::push(Reply reply)
{
    std::lock_guard lock(m_mutex);
    m_pending.push_back(std::move(reply));
    return m_pending.size() == 1;
}

std::vector<Reply> ReplyQueue::drain()
{
    std::vector<Reply> replies;
    std::lock_guard lock(m_mutex);
    replies.swap(m_pending);
    return replies;
}

}  // namespace ui
