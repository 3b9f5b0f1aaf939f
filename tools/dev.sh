#!/usr/bin/env bash
# Springlab's entry point on a fresh Debian 12 machine: installs what is missing (once, quietly),
# builds, then either launches the editor or runs the whole test suite.
#
#   tools/dev.sh run [SCENE.json]   build in Release and open the editor (default: the springs example)
#   tools/dev.sh test               build with warnings as errors and run every test, then the unit
#                                   tests under AddressSanitizer + UBSan with the spring kernels'
#                                   default clone, the kernels' tests on the avx2 clone where the
#                                   CPU would pick AVX-512, and a minute of fuzzing
set -euo pipefail
cd "$(dirname "$0")/.."

# what Springlab needs from Debian; libqt6opengl6-dev and xauth are only "recommended" by others
packages=(g++ cmake ninja-build qt6-base-dev libqt6opengl6-dev libeigen3-dev libsuitesparse-dev libassimp-dev
          xvfb xauth libgl1-mesa-dri libegl-mesa0)

source tools/install_missing.sh

build() {
  cmake --preset "$1" >/dev/null
  cmake --build --preset "$1"
}

# whether this CPU has every one of the flags named (as /proc/cpuinfo spells them)
cpu_has() {
  local flags f
  flags=" $(grep -m1 '^flags' /proc/cpuinfo 2>/dev/null | cut -d: -f2) "
  for f in "$@"; do
    [[ "$flags" == *" $f "* ]] || return 1
  done
}

# the spring kernels' clone this CPU runs in a build with target clones: the loader picks the first
# of x86-64-v4 (AVX-512 F, BW, CD, DQ and VL), avx2 and default that the CPU can run
host_clone() {
  if cpu_has avx512f avx512bw avx512cd avx512dq avx512vl avx2; then
    echo x86-64-v4
  elif cpu_has avx2; then
    echo avx2
  else
    echo default
  fi
}

case "${1:-}" in
  run)
    shift
    install_missing "${packages[@]}"
    build release
    if [ -x build/release/app/springlab ]; then
      exec build/release/app/springlab "$@"
    fi
    exec build/release/app/springlab-sim "${@:-resources/scenes/springs.json}"
    ;;
  test)
    # ffmpeg too, so that the MP4 export is tested rather than skipped, and GNU parallel for the
    # sweep of docs/batch.md (test_sim_sweep)
    install_missing "${packages[@]}" ffmpeg parallel
    build ci
    ctest --preset ci
    # the unit tests again under AddressSanitizer and UndefinedBehaviorSanitizer (leaks included),
    # with the core built for plain x86-64 alone: the spring kernels' default clone, which the ci
    # build does not run on a CPU with AVX2 or AVX-512, so the golden hash and the kernels' bits
    # are checked on it here (and the unit tests alone are built)
    build asan
    ctest --preset asan -L unit
    # on a CPU whose loader picks the AVX-512 clone, the avx2 clone gets a build of the core and
    # of the core tests that check the kernels' bits (label kernels)
    clone="$(host_clone)"
    echo "spring kernels: build/ci runs the $clone clone, build/asan the default; the avx2 clone next where it is neither"
    if [ "$clone" = x86-64-v4 ]; then
      build avx2
      ctest --preset avx2
    fi
    # the scene loader fuzzed for a minute (installs clang-14 and libFuzzer if missing)
    bash tools/fuzz.sh 60
    ;;
  *)
    echo "usage: tools/dev.sh run [SCENE.json] | tools/dev.sh test" >&2
    exit 2
    ;;
esac
