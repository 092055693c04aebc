#!/usr/bin/env bash
# Runs one libFuzzer target of the sanitizer build:
#   scripts/fuzz.sh BUILD_DIR TARGET SECONDS          a long run (make fuzz)
#   scripts/fuzz.sh BUILD_DIR TARGET SECONDS RUNS     a repeatable run (make test)
# TARGET is config, tessellation_json or polygon_distance. A run starts from the seeds
# (data/ for config, tests/fuzz/seeds/TARGET otherwise) and every earlier failure in
# tests/fuzz/regressions/TARGET.
#
# The long run draws a new libFuzzer seed each time, keeps the corpus it grows in
# BUILD_DIR/fuzz-corpus/TARGET and goes on for SECONDS.
# The repeatable run uses libFuzzer seed 1, an empty corpus, no corpus reloading and stops
# after RUNS inputs, so it does the same work on every machine however fast (SECONDS only
# bounds it) and nearly the same inputs (thread scheduling can shift coverage a little).
#
# A failing input is written to BUILD_DIR/fuzz-artifacts/TARGET-* and the script exits
# non-zero: add that file to tests/fuzz/regressions/TARGET once fixed. libFuzzer's
# progress lines go to BUILD_DIR/fuzz-logs/TARGET.log; the script prints the final
# statistics, or on a failure the sanitizer's report without the progress lines (which
# would bury it beyond ctest's output limit).
set -euo pipefail
build=$1 target=$2 seconds=$3 runs=${4:-}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$build" && pwd)

case "$target" in
  config) seeds=$root/data ;;
  tessellation_json|polygon_distance) seeds=$root/tests/fuzz/seeds/$target ;;
  *) echo "fuzz.sh: unknown target '$target' (config, tessellation_json, polygon_distance)" >&2; exit 2 ;;
esac
program=$build/fuzz_$target
[[ -x "$program" ]] || { echo "fuzz.sh: $program not built (make san-build)" >&2; exit 2; }

if [[ -n "$runs" ]]; then
  corpus=$build/fuzz-corpus-repeatable/$target
  rm -rf "$corpus"
  limits=(-seed=1 -runs="$runs" -max_total_time="$seconds" -reload=0)
else
  corpus=$build/fuzz-corpus/$target
  limits=(-seed=0 -max_total_time="$seconds")
fi
mkdir -p "$corpus" "$build/fuzz-artifacts" "$build/fuzz-logs"
dirs=("$corpus" "$seeds")
[[ -d "$root/tests/fuzz/regressions/$target" ]] && dirs+=("$root/tests/fuzz/regressions/$target")

log=$build/fuzz-logs/$target.log
echo "fuzz.sh: $target ${limits[*]}, log in $log"
status=0
"$program" "${limits[@]}" -timeout=20 -rss_limit_mb=3000 -print_final_stats=1 \
  -artifact_prefix="$build/fuzz-artifacts/$target-" "${dirs[@]}" >"$log" 2>&1 || status=$?
progress='^#[0-9]+[[:space:]]+(NEW|REDUCE|pulse|INITED|RELOAD)|^[[:space:]]+NEW_FUNC'
if (( status == 0 )); then
  grep -E '^(stat::|Done|INFO: Seed)' "$log" || true
else
  grep -E -v "$progress" "$log" | tail -n 150
  echo "fuzz.sh: $target failed (exit $status); the input is in $build/fuzz-artifacts/"
fi
exit "$status"
