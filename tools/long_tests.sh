#!/usr/bin/env bash
# The runs too long for CI (docs/reliability.md says what each proves). Run tools/dev.sh test
# first: it installs the packages these need.
#
#   tools/long_tests.sh
#
# 1. ThreadSanitizer build (build/tsan): every ui test (the monkey with 1000 events per example:
#    ThreadSanitizer slows it tenfold), and the live-edit stress for 60 s.
# 2. AddressSanitizer + UBSan build (build/asan), leak checking on: 1000 cycles of start, run,
#    load another scene and close while running; the monkey's 10 000 events per example.
# 3. The core built for the kernels' avx2 clone alone (preset avx2, build/avx2): every unit test,
#    the editor's included, so that the clone a CPU without AVX-512 runs gives the same bits (a
#    machine with AVX-512 picks that clone; tools/dev.sh test runs only the core's tests there).
# 4. The scene loader fuzzed for an hour.
# 5. The contact invariants on 10⁵ random scenes of each kind (energy, momentum, overlaps,
#    colliders), and on 10⁴ with every invariant and the handout's passes (known to fail: a few
#    swap in an elastic row struck at 155 m/s, and the handout's pass gains energy;
#    see tests/core/test_contact_invariants.cpp); the last is reported, not required.
set -euo pipefail
cd "$(dirname "$0")/.."

export QT_QPA_PLATFORM=xcb
# Qt Test stops a test function after 5 minutes; the long runs take far longer (250 lifecycle
# cycles under AddressSanitizer already pass that mark)
export QTEST_FUNCTION_TIMEOUT=7200000
# the worker and Qt's own threads: report every race, stop at the first. No lock-order detector:
# Mesa's shader compiler (LLVM) holds more locks at once than it can track, and it stops the
# program. Forks are QProcess's, which execs at once.
export TSAN_OPTIONS="halt_on_error=1 detect_deadlocks=0 die_after_fork=0 suppressions=$PWD/tests/sanitizers/tsan.supp ${TSAN_OPTIONS:-}"
export ASAN_OPTIONS="detect_leaks=1 ${ASAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp ${LSAN_OPTIONS:-}"

cmake --preset tsan >/dev/null
cmake --build --preset tsan
SPRINGLAB_MONKEY_EVENTS=1000 ctest --preset tsan --timeout 7200 -L ui
SPRINGLAB_STRESS_SECONDS=60 ctest --preset tsan -R '^test_live_edit_stress$'

cmake --preset asan >/dev/null
cmake --build build/asan  # every target: the asan build preset builds the unit tests alone
SPRINGLAB_LIFECYCLE_CYCLES=1000 ctest --preset asan --timeout 7200 -R '^test_lifecycle$'
SPRINGLAB_MONKEY_EVENTS=10000 ctest --preset asan --timeout 7200 -R '^test_monkey(_[23])?$'

cmake --preset avx2 >/dev/null
cmake --build build/avx2
ctest --test-dir build/avx2 --output-on-failure -j 2 -L unit

bash tools/fuzz.sh 3600

SPRINGLAB_INVARIANT_SCENES=100000 build/ci/tests/core/test_contact_invariants impactsKeepTheInvariants
SPRINGLAB_INVARIANT_SCENES=100000 build/ci/tests/core/test_contact_invariants underGravityKeepTheEnergy
SPRINGLAB_INVARIANT_SCENES=100000 build/ci/tests/core/test_contact_invariants nothingPassesThroughAnything
# the handout's passes break them by design: run to see how, not to pass
SPRINGLAB_INVARIANT_HANDOUT=1 SPRINGLAB_INVARIANT_SCENES=10000 \
  build/ci/tests/core/test_contact_invariants handoutPassesKeepTheInvariants || true
