// Linked into every test and program of the sanitizer builds. Mesa unloads its software driver as
// the GL context goes at exit, and two sanitizers then lose track of it:
// - ThreadSanitizer: tests/sanitizers/tsan.supp names the driver in a called_from_lib suppression,
//   and ThreadSanitizer stops the program with an error when such a library is unloaded;
// - LeakSanitizer, which runs after that: the few blocks the driver's globals still point to (112
//   bytes, the same after 1 cycle of tests/ui/test_lifecycle.cpp as after 1000) are then reachable
//   from nothing, and reported as leaks from an unknown module.
// Opening the driver once more with RTLD_NODELETE keeps it loaded until the process ends. Where the
// driver is not installed this does nothing: those tests draw nothing anyway.

#include <dlfcn.h>

namespace {

const bool kDriverPinned = [] {
    return dlopen("/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so", RTLD_NOW | RTLD_NODELETE) != nullptr;
}();

}  // namespace
