#!/bin/sh
# A grainmesh sweep as a SLURM job array, one shard per array task:
#   sbatch --array=1-N scripts/slurm-sweep.sh SWEEP.ini OUT N [grainmesh sweep options...]
# e.g. sbatch --array=1-10 scripts/slurm-sweep.sh sweep.ini /scratch/$USER/sweep 10 --solve
# Each task runs `grainmesh sweep SWEEP.ini -o OUT --shard TASK/N` on the cores SLURM gave
# it; the shards cover the sweep exactly once, into the same OUT. A task that is killed
# or fails leaves its runs to the next submission, which skips what is complete. Then,
# once: grainmesh sweep --collect OUT. GRAINMESH names the program (default grainmesh
# on PATH).
#SBATCH --cpus-per-task=2
#SBATCH --job-name=grainmesh-sweep
set -eu
if [ $# -lt 3 ] || [ -z "${SLURM_ARRAY_TASK_ID:-}" ]; then
  echo "usage: sbatch --array=1-N slurm-sweep.sh SWEEP.ini OUT N [grainmesh sweep options...]" >&2
  exit 2
fi
sweep=$1
out=$2
shards=$3
shift 3
exec "${GRAINMESH:-grainmesh}" sweep "$sweep" -o "$out" --jobs "${SLURM_CPUS_PER_TASK:-1}" \
  --shard "$SLURM_ARRAY_TASK_ID/$shards" "$@"
