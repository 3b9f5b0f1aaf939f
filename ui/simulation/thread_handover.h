#pragma once
// Tells ThreadSanitizer about a hand-over from one thread to another that Qt makes under its own
// locks. Debian's Qt is not built with ThreadSanitizer, so it cannot see that a posted event, or
// an object deleted after its thread's event loop ended, was handed over safely, and it would
// report every such object as a race. The UI side releases the token before it posts or shuts the
// thread down; the receiving thread acquires it before it touches what was handed over. Nothing
// is done in other builds.

#if defined(__SANITIZE_THREAD__)
#include <sanitizer/tsan_interface.h>
#endif

namespace ui {

inline void handOverRelease([[maybe_unused]] const void *token)
{
#if defined(__SANITIZE_THREAD__)
    __tsan_release(const_cast<void *>(token));
#endif
}

inline void handOverAcquire([[maybe_unused]] const void *token)
{
#if defined(__SANITIZE_THREAD__)
    __tsan_acquire(const_cast<void *>(token));
#endif
}

}  // namespace ui
