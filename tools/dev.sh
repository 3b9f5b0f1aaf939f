#!/usr/bin/env bash
# Springlab's entry point on a fresh Debian 12 machine: installs what is missing (once, quietly),
# builds, then either launches the editor or runs the whole test suite.
#
#   tools/dev.sh run [SCENE.json]   build in Release and open the editor (default: the springs example)
#   tools/dev.sh test               build with warnings as errors and run every test, then the unit
#                                   tests under AddressSanitizer + UBSan, and a minute of fuzzing
set -euo pipefail
cd "$(dirname "$0")/.."

# what Springlab needs from Debian; libqt6opengl6-dev and xauth are only "recommended" by others
packages=(g++ cmake ninja-build qt6-base-dev libqt6opengl6-dev libeigen3-dev
          xvfb xauth libgl1-mesa-dri libegl-mesa0)

source tools/install_missing.sh

build() {
  cmake --preset "$1" >/dev/null
  cmake --build --preset "$1"
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
    # ffmpeg too, so that the MP4 export is tested rather than skipped
    install_missing "${packages[@]}" ffmpeg
    build ci
    ctest --preset ci
    # the unit tests again under AddressSanitizer and UndefinedBehaviorSanitizer (leaks included)
    build asan
    ctest --preset asan -L unit
    # the scene loader fuzzed for a minute (installs clang-14 and libFuzzer if missing)
    bash tools/fuzz.sh 60
    ;;
  *)
    echo "usage: tools/dev.sh run [SCENE.json] | tools/dev.sh test" >&2
    exit 2
    ;;
esac
