#!/usr/bin/env bash
# A sweep of restitution x time step with GNU parallel: one springlab-sim run per pair, each writing
# its summary as JSON and as one CSV row, then the rows gathered under one header into
# OUT_DIR/sweep.csv (docs/batch.md).
#
#   tools/sweep_parallel.sh OUT_DIR [SCENE.json [SPRINGLAB-SIM ARGUMENTS...]]
#
# Without a scene it sweeps the pool example with the cue ball shot at the other ball for 1.5 s.
# The environment chooses the rest:
#   RESTITUTIONS  values of settings.restitution (default "0.2 0.5 0.8 1")
#   TIME_STEPS    values of settings.timeStep in s (default "0.01 0.005 0.002")
#   SIM           the springlab-sim to run (default: the one on PATH)
#   JOBS          runs at once (default: one per core)
# Exit code: 0 when every run ended with 0; otherwise parallel's count of failed runs (at most 101).
# Every run writes its row all the same, and the table's status column says which failed and why.
set -euo pipefail

out=${1:?usage: tools/sweep_parallel.sh OUT_DIR [SCENE.json [SPRINGLAB-SIM ARGUMENTS...]]}
shift
if [ $# -eq 0 ]; then
  here=$(dirname "$0")
  set -- "$here/../resources/scenes/pool.json" --duration 1.5 --set 'particles[0].velocity=[6,0,0.5]'
fi
sim=${SIM:-springlab-sim}
mkdir -p "$out/runs"

# a run is one thread: the cores go to the runs (the results do not depend on the thread count)
export OMP_NUM_THREADS=1

# one job per pair ({1}, {2}); -q quotes each argument, so [6,0,0.5] reaches springlab-sim as written;
# --halt never keeps the sweep going past a run that blew up (exit 3) or was refused (exit 2)
status=0
parallel -q --jobs "${JOBS:-100%}" --halt never \
  "$sim" "$@" --quiet --set settings.restitution={1} --set settings.timeStep={2} \
  --summary-json "$out/runs/r{1}-h{2}.json" --summary-csv "$out/runs/r{1}-h{2}.csv" \
  ::: ${RESTITUTIONS:-0.2 0.5 0.8 1} ::: ${TIME_STEPS:-0.01 0.005 0.002} || status=$?

# the table: springlab-sim's header, then every run's row
{ "$sim" --summary-csv-header; cat "$out"/runs/*.csv; } > "$out/sweep.csv"
exit "$status"
