#!/usr/bin/env bash
# Runs one libFuzzer target of the sanitizer build for a while:
#   scripts/fuzz.sh BUILD_DIR TARGET SECONDS [SEED]
# TARGET is config, tessellation_json or polygon_distance. The run starts from the seeds
# (data/ for config, tests/fuzz/seeds/TARGET otherwise), every earlier failure in
# tests/fuzz/regressions/TARGET and the corpus it grew before (BUILD_DIR/fuzz-corpus/TARGET,
# where new inputs go). A failing input is written to BUILD_DIR/fuzz-artifacts/TARGET-*
# and the run exits non-zero: add that file to tests/fuzz/regressions/TARGET once fixed.
# SEED fixes libFuzzer's random choices (make test uses 1, so it is repeatable; 0, the
# default, draws a new seed each run, as make fuzz wants).
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

echo "fuzz.sh: $target for $seconds s"
exec "$program" -seed="$seed" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=3000 \
  -print_final_stats=1 -artifact_prefix="$build/fuzz-artifacts/$target-" "${dirs[@]}"
