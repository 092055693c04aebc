#!/usr/bin/env bash
# ctest: a sweep as a SLURM job array on a one-node cluster started here from Debian's
# slurm-wlm (scripts/slurm-cluster.sh), with grainmesh installed as `make install` does
# (cmake --install of the build into a DESTDIR, its bin/ on PATH):
#   1. docs/sweep.md's recipe, run as written, gives the same runs, byte for byte, and the same
#      summary.csv as the sweep run locally;
#   2. a task cancelled half way (scancel) and the array submitted again complete the
#      sweep, and no run finished before the cancel is run again;
#   3. a task that cannot find grainmesh fails the array job visibly: sbatch --wait
#      exits with its exit code (127), its log says why;
#   0. first, a slurmctld that fails to start (a stand-in, as one whose port is taken) is
#      one line naming it and its log, exit 1, and no slurm.conf left to use.
# The cluster is stopped and its files removed at the end, also on failure. Skipped
# (exit 77) only where slurm-wlm is not installed.
#   tests/slurm/test_slurm_sweep.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1
build_dir=$2
for program in slurmctld slurmd sbatch; do
  if ! command -v "$program" >/dev/null; then
    echo "SKIP: $program is not installed (Debian package slurm-wlm; scripts/install-deps.sh installs it)"
    exit 77
  fi
done
work=$(mktemp -d /tmp/grainmesh-slurm.XXXXXX)
# make install DESTDIR=$work/root: the install step alone (the build is ctest's own).
DESTDIR="$work/root" cmake --install "$build_dir" --prefix /usr/local > /dev/null
installed="$work/root/usr/local/bin"
for program in grainmesh grainmesh-slurm-sweep grainmesh-slurm-cluster; do
  [[ -x "$installed/$program" ]] || { echo "FAIL: make install put no $program in PREFIX/bin" >&2; rm -rf "$work"; exit 1; }
done
export PATH="$installed:$PATH"
GRAINMESH=grainmesh
cleanup() {
  "$source_dir/scripts/slurm-cluster.sh" stop "$work/cluster" || true
  # The reports, for the schema check after every test (tests/pipelines/validate_reports.py).
  mkdir -p "$build_dir/test-reports"
  find "$work" -name report.json -not -path "$work/root/*" 2>/dev/null | while read -r r; do
    rel=${r#"$work"/}
    cp "$r" "$build_dir/test-reports/slurm-$$-${rel//\//_}.json"
  done
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
# docs/sweep.md's recipe, its lines between the markers, run as they are written.
recipe=$(sed -n '/^# the recipe: submit$/,/^# the recipe: end$/p' "$source_dir/docs/sweep.md" | grep -v '^#')
[[ -n "$recipe" ]] || fail "docs/sweep.md has no recipe between '# the recipe: submit' and '# the recipe: end'"
submitted=$(bash -c "$recipe") || fail "docs/sweep.md's recipe failed: $recipe"
job=$(grep -o '[0-9][0-9]*' <<< "$submitted" | tail -1)
[[ -n "$job" ]] || fail "docs/sweep.md's recipe submitted no job: $submitted"
for _ in $(seq 1200); do
  [[ -z "$(squeue -h -j "$job" 2>/dev/null)" ]] && break
  sleep 0.1
done
[[ -z "$(squeue -h -j "$job" 2>/dev/null)" ]] || fail "the recipe's array job did not finish in 120 s"
out=$(awk '{for (i = 1; i < NF; ++i) if ($i == "sweep.ini") print $(i + 1)}' <<< "$recipe" | head -1)
[[ -f "$out/summary.csv" ]] || { cat slurm-*.out >&2 2>/dev/null; fail "the recipe's array job wrote no $out/summary.csv"; }
"$GRAINMESH" sweep --collect "$out" > /dev/null
"$GRAINMESH" sweep sweep.ini -o local --jobs 2 --solve > /dev/null 2>&1
"$GRAINMESH" sweep --collect local > /dev/null
cmp "$out/summary.csv" local/summary.csv || fail "summary.csv differs from the local sweep's"
cmp "$out/plan.json" local/plan.json || fail "plan.json differs"
runs=0
for run in local/*-r[0-9][0-9]; do
  name=$(basename "$run")
  [[ -f "$out/$name/report.json" ]] || fail "$name is missing from the cluster's sweep"
  # Everything but the report (timings) and the logs, byte for byte.
  while IFS= read -r file; do
    cmp -s "$run/$file" "$out/$name/$file" || fail "$name/$file differs from the local run's"
  done < <(cd "$run" && find . -type f ! -name report.json ! -name 'log.*' | sort)
  runs=$((runs + 1))
done
[[ $runs -eq 4 ]] || fail "expected 4 runs, found $runs"
echo "docs/sweep.md's recipe: 4 runs, identical to the local sweep"

# A task cancelled half way: 6 runs in two shards of one core each; shard 2 is cancelled
# once a run of the sweep is complete, then the array is submitted again.
sed -i 's/^realisations = 2/realisations = 3/' sweep.ini
job=$(sbatch --parsable --array=1-2 --cpus-per-task=1 --output="$work/again-%a.log" \
  "$(command -v grainmesh-slurm-sweep)" sweep.ini "$work/resumed" 2 --solve)
complete() { find resumed -name report.json -path '*-r[0-9][0-9]/report.json' 2>/dev/null | sort; }
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
  "$(command -v grainmesh-slurm-sweep)" sweep.ini "$work/resumed" 2 --solve ||
  { cat "$work"/resubmit-*.log >&2; fail "the resubmitted array failed"; }
[[ $(complete | wc -l) -eq 6 ]] || fail "the resubmitted array left runs missing"
after=$(complete | xargs -r stat -c '%n %i %Y')
while IFS= read -r line; do
  [[ -z "$line" ]] && continue
  grep -qxF "$line" <<< "$after" || fail "a run finished before the cancel was run again: $line"
done <<< "$before"
"$GRAINMESH" sweep --collect resumed > /dev/null
echo "cancelled with $done_before of 6 runs complete; resubmitted: 6 complete, none of the $done_before run again"

# 3. A task that cannot find grainmesh (a PATH with the script alone): the array job fails
# where a user sees it.
mkdir "$work/only-script"
cp "$installed/grainmesh-slurm-sweep" "$work/only-script/"
status=0
PATH="$work/only-script:/usr/bin:/bin" sbatch --wait --parsable --array=1-1 --output="$work/lost-%a.log" \
  "$work/only-script/grainmesh-slurm-sweep" sweep.ini "$work/lost" 1 > "$work/lost.id" || status=$?
[[ $status -ne 0 ]] || fail "an array task without grainmesh left sbatch --wait with exit 0"
grep -q "grainmesh is not on PATH" "$work/lost-1.log" || fail "the task's log does not say why: $(cat "$work/lost-1.log")"
# The job's own record (this cluster keeps no accounting database for sacct): FAILED, 127.
lost=$(head -1 "$work/lost.id" | cut -d';' -f1)
record=$(scontrol show job "$lost" 2>/dev/null || true)
grep -q "JobState=FAILED" <<< "$record" || fail "the job of a task without grainmesh is not FAILED: $record"
grep -q "ExitCode=127:0" <<< "$record" || fail "the job of a task without grainmesh did not exit 127: $record"
echo "a task without grainmesh: sbatch --wait exit $status, the job FAILED with 127, its log says grainmesh is not on PATH"
