# How the vectorised spring kernels (core/springs/springs.cpp, core/springs/spring_blocks.cpp) are built, carried by
# the interface library springlab_kernel_flags that springlab_core links publicly:
#
#   SPRINGLAB_KERNEL_CLONES=ON   (default) one copy of each kernel per CPU family, chosen when the
#                                program loads (GCC/Clang target_clones, an ifunc): x86-64-v4
#                                (AVX-512), avx2 and default (plain x86-64). On only where the
#                                configure check below builds and runs such a function.
#   SPRINGLAB_KERNEL_ARCH=NAME   instead, springlab_core and all that links it built for one of
#                                those clones alone: x86-64 (the default clone's code), avx2 or
#                                x86-64-v4. That is how a machine tests a clone it would not pick
#                                (presets baseline, avx2).
#
# With neither, the kernels are built once for the compiler's own target.

include(CheckCXXCompilerFlag)
include(CheckCXXSourceRuns)

add_library(springlab_kernel_flags INTERFACE)

# single architecture: the clone's own target, as the target_clones attribute names it (the avx2
# clone is the default target plus AVX2, not all of x86-64-v3)
set(springlab_kernel_arches x86-64 avx2 x86-64-v4)
set_property(CACHE SPRINGLAB_KERNEL_ARCH PROPERTY STRINGS "" ${springlab_kernel_arches})
if(SPRINGLAB_KERNEL_ARCH)
  if(NOT SPRINGLAB_KERNEL_ARCH IN_LIST springlab_kernel_arches)
    message(FATAL_ERROR "SPRINGLAB_KERNEL_ARCH=${SPRINGLAB_KERNEL_ARCH}: expected one of "
                        "${springlab_kernel_arches}, or empty for the clones")
  endif()
  if(SPRINGLAB_KERNEL_ARCH STREQUAL "avx2")
    set(springlab_arch_flags -march=x86-64 -mavx2)
  else()
    set(springlab_arch_flags -march=${SPRINGLAB_KERNEL_ARCH})
  endif()
  string(MAKE_C_IDENTIFIER "${SPRINGLAB_KERNEL_ARCH}" springlab_arch_id)
  check_cxx_compiler_flag("${springlab_arch_flags}" SPRINGLAB_HAVE_ARCH_${springlab_arch_id})
  if(NOT SPRINGLAB_HAVE_ARCH_${springlab_arch_id})
    message(FATAL_ERROR "SPRINGLAB_KERNEL_ARCH=${SPRINGLAB_KERNEL_ARCH}: the compiler rejects "
                        "${springlab_arch_flags}")
  endif()
  # for every target that links the core, not the core alone: Eigen's alignment is part of its ABI
  # (16 bytes below AVX, 32 with it), and an Eigen buffer allocated in a core file built for AVX2
  # and freed in a test built without (or the other way round) corrupts the heap
  target_compile_options(springlab_kernel_flags INTERFACE ${springlab_arch_flags})
  message(STATUS "Spring kernels: springlab_core and what links it built for "
                 "${SPRINGLAB_KERNEL_ARCH} alone (SPRINGLAB_KERNEL_ARCH; no target clones)")
  return()
endif()

if(NOT SPRINGLAB_KERNEL_CLONES)
  message(STATUS "Spring kernels: one version for the compiler's target (SPRINGLAB_KERNEL_CLONES=OFF)")
  return()
endif()

# not under ThreadSanitizer: the clones' resolver runs while the program is being loaded, before
# the sanitizer's runtime is up, and its instrumented code crashes there
if(SPRINGLAB_SANITIZE MATCHES "thread")
  message(STATUS "Spring kernels: one version for the compiler's target (no target clones under "
                 "ThreadSanitizer: their resolver would run before its runtime is up)")
  return()
endif()

# a function template with the kernels' clones (some kernels are templates, which clang 14 cannot
# clone), built and run: proves that the compiler takes the list and that the assembler and the
# loader handle the ifunc that picks a clone (keep the list the same as core/springs/spring_kernels.h's)
check_cxx_source_runs([[
template <bool kTwice>
__attribute__((target_clones("arch=x86-64-v4", "avx2", "default"))) int scaled(int x) { return kTwice ? 2 * x : x; }
int main(int argc, char **) { return scaled<true>(argc) == 2 ? 0 : 1; }
]] SPRINGLAB_HAVE_KERNEL_CLONES)
if(SPRINGLAB_HAVE_KERNEL_CLONES)
  target_compile_definitions(springlab_kernel_flags INTERFACE SPRINGLAB_KERNEL_CLONES)
  message(STATUS "Spring kernels: target clones x86-64-v4, avx2 and default")
else()
  message(STATUS "Spring kernels: one version for the compiler's target (this compiler, assembler "
                 "or loader cannot build and run the kernels' target clones)")
endif()
