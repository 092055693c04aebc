#!/usr/bin/env bash
# Runs one libFuzzer target of the sanitizer build for a while:
#   scripts/fuzz.sh BUILD_DIR TARGET SECONDS [SEED]
# TARGET is config, tessellation_json or polygon_distance. The run starts from the seeds
# (data/ for config, tests/fuzz/seeds/TARGET otherwise), every earlier failure in
# tests/fuzz/regressions/TARGET and the corpus it grew before (BUILD_DIR/fuzz-corpus/TARGET,
# where new inputs go). A failing input is written to BUILD_DIR/fuzz-artifacts/TARGET-*
# and the run exits non-zero: add that file to tests/fuzz/regressions/TARGET once fixed.
# SEED fixes libFuzzer's random choices (make test uses 1; 0, the default, draws a new seed
# each run, as make fuzz wants). How far a run gets still depends on the machine's speed.
# libFuzzer's progress lines go to BUILD_DIR/fuzz-logs/TARGET.log; this prints the final
# statistics, and on a failure the sanitizer's report without the progress lines (which
# would bury it beyond ctest's output limit).
set -euo pipefail
build=$1 target=$2 seconds=$3 seed=${4:-0}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$build" && pwd)

case "$target" in
  config) seeds=$root/data ;;
  tessellation_json|polygon_distance) seeds=$root/tests/fuzz/seeds/$target ;;
  *) echo "fuzz.sh: unknown target '$target' (config, tessellation_json, polygon_distance)" >&2; exit 2 ;;
esac
program=$build/fuzz_$target
[[ -x "$program" ]] || { echo "fuzz.sh: $program not built (make san-build)" >&2; exit 2; }

corpus=$build/fuzz-corpus/$target
mkdir -p "$corpus" "$build/fuzz-artifacts"
dirs=("$corpus" "$seeds")
[[ -d "$root/tests/fuzz/regressions/$target" ]] && dirs+=("$root/tests/fuzz/regressions/$target")

log=$build/fuzz-logs/$target.log
mkdir -p "$build/fuzz-logs"
echo "fuzz.sh: $target for $seconds s (seed $seed), log in $log"
status=0
"$program" -seed="$seed" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=3000 \
  -print_final_stats=1 -artifact_prefix="$build/fuzz-artifacts/$target-" "${dirs[@]}" >"$log" 2>&1 || status=$?
progress='^#[0-9]+[[:space:]]+(NEW|REDUCE|pulse|INITED|RELOAD)|^[[:space:]]+NEW_FUNC'
if (( status == 0 )); then
  grep -E '^(stat::|Done|INFO: Seed)' "$log" || true
else
  grep -E -v "$progress" "$log" | tail -n 150
  echo "fuzz.sh: $target failed (exit $status); the input is in $build/fuzz-artifacts/"
fi
exit "$status"
