#!/usr/bin/env bash
# ctest: a sweep as a SLURM job array (scripts/slurm-sweep.sh, as README shows) on a
# one-node cluster started here from Debian's slurm-wlm (scripts/slurm-cluster.sh):
#   1. two shards of a solved sweep give the same runs, byte for byte, and the same
#      summary.csv as the sweep run locally;
#   2. a task cancelled half way (scancel) and the array submitted again complete the
#      sweep, and no run finished before the cancel is run again;
#   0. first, a slurmctld that fails to start (a stand-in, as one whose port is taken) is
#      one line naming it and its log, exit 1, and no slurm.conf left to use.
# The cluster is stopped and its files removed at the end, also on failure. Skipped
# (exit 77) only where slurm-wlm is not installed.
#   tests/slurm/test_slurm_sweep.sh SOURCE_DIR GRAINMESH
set -euo pipefail
source_dir=$1
export GRAINMESH=$2
for program in slurmctld slurmd sbatch; do
  if ! command -v "$program" >/dev/null; then
    echo "SKIP: $program is not installed (Debian package slurm-wlm; scripts/install-deps.sh installs it)"
    exit 77
  fi
done
work=$(mktemp -d /tmp/grainmesh-slurm.XXXXXX)
cleanup() {
  "$source_dir/scripts/slurm-cluster.sh" stop "$work/cluster" || true
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
# 0. A slurmctld that cannot start.
mkdir "$work/bin"
printf '#!/bin/sh\necho "slurmctld: fatal: Unable to bind listen port: Address already in use" >&2\nexit 1\n' \
  > "$work/bin/slurmctld"
chmod +x "$work/bin/slurmctld"
status=0
PATH="$work/bin:$PATH" "$source_dir/scripts/slurm-cluster.sh" start "$work/broken" 2> "$work/broken.err" || status=$?
broken=$(cd "$work/broken" && pwd)
[[ $status -eq 1 ]] || fail "a failed slurmctld start exited $status, not 1"
[[ "$(cat "$work/broken.err")" == "slurm-cluster: slurmctld did not start (exit code 1); see $broken/slurmctld.log" ]] ||
  fail "a failed slurmctld start said: $(cat "$work/broken.err")"
grep -q "Address already in use" "$broken/slurmctld.log" || fail "slurmctld's own words are not in its log"
[[ ! -e "$broken/slurm.conf" ]] || fail "a failed start left a slurm.conf to use"
echo "a slurmctld that cannot start: one line naming it and its log, exit 1"

"$source_dir/scripts/slurm-cluster.sh" start "$work/cluster"
export SLURM_CONF="$work/cluster/slurm.conf"
cd "$work"

# A small solved sweep: 2 matrix fractions x 2 realisations of a 30-grain cell.
{ cat "$source_dir/data/default.ini"
  printf '\n[output]\npictures = none\n[sweep]\ntessellation.grains = 30\nphase.matrix.fraction = 0.1, 0.2\nrealisations = 2\n'
} > sweep.ini
sbatch --wait --quiet --array=1-2 --output="$work/task-%a.log" \
  "$source_dir/scripts/slurm-sweep.sh" sweep.ini "$work/cluster-out" 2 --solve ||
  { cat "$work"/task-*.log >&2; fail "the array job failed"; }
"$GRAINMESH" sweep --collect cluster-out > /dev/null
"$GRAINMESH" sweep sweep.ini -o local --jobs 2 --solve > /dev/null
"$GRAINMESH" sweep --collect local > /dev/null
cmp cluster-out/summary.csv local/summary.csv || fail "summary.csv differs from the local sweep's"
cmp cluster-out/plan.json local/plan.json || fail "plan.json differs"
runs=0
for run in local/p*-r*; do
  name=$(basename "$run")
  [[ -f "cluster-out/$name/report.json" ]] || fail "$name is missing from the cluster's sweep"
  # Everything but the report (timings) and the logs, byte for byte.
  while IFS= read -r file; do
    cmp -s "$run/$file" "cluster-out/$name/$file" || fail "$name/$file differs from the local run's"
  done < <(cd "$run" && find . -type f ! -name report.json ! -name 'log.*' | sort)
  runs=$((runs + 1))
done
[[ $runs -eq 4 ]] || fail "expected 4 runs, found $runs"
echo "array of 2 shards: 4 runs, identical to the local sweep"

# A task cancelled half way: 6 runs in two shards of one core each; shard 2 is cancelled
# once a run of the sweep is complete, then the array is submitted again.
sed -i 's/^realisations = 2/realisations = 3/' sweep.ini
job=$(sbatch --parsable --array=1-2 --cpus-per-task=1 --output="$work/again-%a.log" \
  "$source_dir/scripts/slurm-sweep.sh" sweep.ini "$work/resumed" 2 --solve)
complete() { find resumed -name report.json -path '*/p*-r*/report.json' 2>/dev/null | sort; }
for _ in $(seq 600); do
  [[ -n "$(complete)" ]] && break
  sleep 0.1
done
scancel "${job}_2"
for _ in $(seq 600); do
  [[ -z "$(squeue -h -j "$job" 2>/dev/null)" ]] && break
  sleep 0.1
done
before=$(complete | xargs -r stat -c '%n %i %Y')
done_before=$(complete | wc -l)
[[ $done_before -lt 6 ]] || fail "the cancelled task had already finished its runs: nothing to resume"
sbatch --wait --quiet --array=1-2 --cpus-per-task=1 --output="$work/resubmit-%a.log" \
  "$source_dir/scripts/slurm-sweep.sh" sweep.ini "$work/resumed" 2 --solve ||
  { cat "$work"/resubmit-*.log >&2; fail "the resubmitted array failed"; }
[[ $(complete | wc -l) -eq 6 ]] || fail "the resubmitted array left runs missing"
after=$(complete | xargs -r stat -c '%n %i %Y')
while IFS= read -r line; do
  [[ -z "$line" ]] && continue
  grep -qxF "$line" <<< "$after" || fail "a run finished before the cancel was run again: $line"
done <<< "$before"
"$GRAINMESH" sweep --collect resumed > /dev/null
echo "cancelled with $done_before of 6 runs complete; resubmitted: 6 complete, none of the $done_before run again"
