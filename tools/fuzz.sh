#!/usr/bin/env bash
# Fuzzes the scene loader with libFuzzer for SECONDS (default 60), on one core.
#
#   tools/fuzz.sh [SECONDS]
#
# Builds build/fuzz with clang (AddressSanitizer, UndefinedBehaviorSanitizer), seeds the corpus
# build/fuzz/corpus from the example scenes and the regression inputs in tests/io/corpus, and
# exits non-zero when an input crashes or breaks a property of tests/fuzz/scene_input_check.h.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${1:-60}"
build=build/fuzz
packages=(clang-14 libfuzzer-14-dev)

source tools/install_missing.sh

install_missing "${packages[@]}"
# OpenMP off: one input is small, and threads would only blur the coverage signal
CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSPRINGLAB_FUZZ=ON -DSPRINGLAB_BUILD_BENCH=OFF -DSPRINGLAB_OPENMP=OFF >/dev/null
cmake --build "$build" --target fuzz_scene_loader -j2

# the working corpus grows here; the examples and regression inputs are read-only seeds
mkdir -p "$build/corpus" "$build/artifacts"
seeds=(resources/scenes tests/io/corpus)
mapfile -t seed_dirs < <(find "${seeds[@]}" -type d | sort)

status=0
# -max_len: room for the small examples; the large ones still run whole as seeds
"$build/tests/fuzz/fuzz_scene_loader" "$build/corpus" "${seed_dirs[@]}" \
  -dict=tests/fuzz/scene.dict -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len=16384 -artifact_prefix="$build/artifacts/" -print_final_stats=1 || status=$?

if [ "$status" -ne 0 ]; then
  cat >&2 <<MSG

The fuzzer found an input that crashes, hangs or breaks a property (exit $status); it is in
$build/artifacts/. To keep it as a regression input:
  cp $build/artifacts/crash-... tests/io/corpus/WHAT-IT-DOES.json
then fix the loader or the core until test_fuzz_corpus passes with it:
  $build/tests/fuzz/fuzz_scene_loader tests/io/corpus/WHAT-IT-DOES.json
MSG
  exit 1
fi
