#!/bin/bash
# The sweep of tools/sweep_parallel.sh as a Slurm job array: one array task per pair of restitution
# and time step, 4 x 3 = 12 tasks (docs/batch.md). Submit it from the repository root, with the
# folder for the logs made first (Slurm does not make it):
#
#   mkdir -p sweep/logs && sbatch tools/sweep_slurm.sh
#
# then gather the rows once every task has ended, whatever its exit code:
#
#   sbatch --dependency=afterany:JOBID --wrap \
#     '{ springlab-sim --summary-csv-header; cat sweep/runs/*.csv; } > sweep/sweep.csv'
#
#SBATCH --job-name=springlab-sweep
#SBATCH --array=0-11
#SBATCH --cpus-per-task=1
#SBATCH --time=00:10:00
#SBATCH --output=sweep/logs/%A_%a.out
set -euo pipefail

restitutions=(0.2 0.5 0.8 1)
time_steps=(0.01 0.005 0.002)

# task k runs restitution k / 3 with time step k % 3: every pair once
k=${SLURM_ARRAY_TASK_ID:?run this with sbatch --array}
r=${restitutions[k / ${#time_steps[@]}]}
h=${time_steps[k % ${#time_steps[@]}]}
mkdir -p sweep/runs

# the OpenMP loops use the cores Slurm gave the task, no more (the results do not depend on it)
export OMP_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}

# the task's exit code is the run's (0 ok, 2 refused, 3 blew up): sacct -j JOBID lists them
exec springlab-sim resources/scenes/pool.json --quiet --duration 1.5 \
  --set 'particles[0].velocity=[6,0,0.5]' --set "settings.restitution=$r" --set "settings.timeStep=$h" \
  --summary-json "sweep/runs/r$r-h$h.json" --summary-csv "sweep/runs/r$r-h$h.csv"
