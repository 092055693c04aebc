#!/bin/sh
# A grainmesh sweep as a SLURM job array, one shard per array task (installed by
# `make install` as grainmesh-slurm-sweep):
#   sbatch --array=1-N "$(command -v grainmesh-slurm-sweep)" SWEEP.ini OUT N [grainmesh sweep options...]
# Each task runs `grainmesh sweep SWEEP.ini -o OUT --shard TASK/N` on the cores SLURM gave
# it; the shards cover the sweep exactly once, into the same OUT, and each writes OUT's
# summary as it ends. A task that is killed or fails leaves its runs to the next
# submission, which skips what is complete. GRAINMESH names the program (default:
# grainmesh on the task's PATH, which sbatch passes on from where it was submitted); a
# task that cannot find it fails, saying so, with exit code 127.
#SBATCH --cpus-per-task=2
#SBATCH --job-name=grainmesh-sweep
set -eu
if [ $# -lt 3 ] || [ -z "${SLURM_ARRAY_TASK_ID:-}" ]; then
  echo "usage: sbatch --array=1-N grainmesh-slurm-sweep SWEEP.ini OUT N [grainmesh sweep options...]" >&2
  exit 2
fi
program=${GRAINMESH:-grainmesh}
if ! command -v "$program" >/dev/null 2>&1; then
  echo "grainmesh-slurm-sweep: $program is not on PATH on $(hostname) (make install puts it there; or set GRAINMESH)" >&2
  exit 127
fi
sweep=$1
out=$2
shards=$3
shift 3
exec "$program" sweep "$sweep" -o "$out" --jobs "${SLURM_CPUS_PER_TASK:-1}" --shard "$SLURM_ARRAY_TASK_ID/$shards" "$@"
