// Linked into every test of the ThreadSanitizer build. tests/sanitizers/tsan.supp names Mesa's
// software driver in a called_from_lib suppression, and ThreadSanitizer stops the program with an
// error when such a library is unloaded, which Mesa does as the GL context goes at exit. Opening
// the driver once more with RTLD_NODELETE keeps it loaded until the process ends. Where the
// driver is not installed this does nothing: those tests draw nothing anyway.

#include <dlfcn.h>

namespace {

const bool kDriverPinned = [] {
    return dlopen("/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so", RTLD_NOW | RTLD_NODELETE) != nullptr;
}();

}  // namespace
