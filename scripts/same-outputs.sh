#!/usr/bin/env bash
# Shows that a change of code leaves every output the same, byte for byte: builds grainmesh
# at BASE (a commit, default HEAD) beside the working tree's build/grainmesh, runs both on
# the default cell (solved: the mixed load, and the periodic one with the thermal load),
# every data/examples/*.ini (grain configs through run and through tessellate, mesh and
# export; 3D configs through run, mixed and periodic, and through tessellate and mesh;
# domain configs through domain) and a solved sweep with its summary, and compares
# the output trees. Only what differs between two runs of one binary is left out:
# report.json's seconds, memory and config path, OpenFOAM's and the sweep's logs. Exit 0
# when all match.
#   scripts/same-outputs.sh [BASE]
set -euo pipefail
cd "$(dirname "$0")/.."
# The commit itself, resolved here: inside the worktree, HEAD would name the worktree's own.
base=$(git rev-parse --verify "${1:-HEAD}^{commit}")
root=$PWD
work=$root/scratch/same-outputs
rm -rf "$work/out"
mkdir -p "$work/out"

# The base's grainmesh, built in a worktree of its own (ccache makes repeated builds cheap).
if [ ! -d "$work/src" ]; then git worktree add -q --detach "$work/src" "$base"; fi
git -C "$work/src" checkout -q --detach "$base"
cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j "$(nproc)" --target grainmesh > "$work/build.log" 2>&1 ||
  { tail -30 "$work/build.log"; exit 1; }
make -s build > /dev/null

export WM_PROJECT_DIR=${WM_PROJECT_DIR:-/usr/share/openfoam}
# Every output of one binary ($1) into $2.
outputs() {
  local gm=$1 out=$2
  mkdir -p "$out"
  "$gm" run -o "$out/default" -q --solve
  "$gm" run -o "$out/default-cyclic" -q --solve --set homogenise.boundary=periodic --set load.delta_T=-1000 \
    --set phase.particulate.alpha=5e-6 --set phase.matrix.alpha=14e-6
  for f in data/examples/*.ini; do
    local name
    name=$(basename "$f" .ini)
    if grep -q '^depth *=' "$f"; then
      # 3D cells: through run (the mixed case, and the periodic load cases on one mesh) and
      # through the stage commands.
      "$gm" run "$f" -o "$out/$name" -q 2> /dev/null
      "$gm" run "$f" -o "$out/$name-periodic" -q --set homogenise.boundary=periodic 2> /dev/null
      "$gm" tessellate "$f" -o "$out/$name-t" > /dev/null
      "$gm" mesh "$out/$name-t/tessellation.json" -o "$out/$name-m" > /dev/null
    elif grep -q '^shape *=' "$f"; then
      "$gm" domain "$f" -o "$out/$name" > /dev/null
    else
      "$gm" run "$f" -o "$out/$name" -q 2> /dev/null
      "$gm" tessellate "$f" -o "$out/$name-t" > /dev/null
      "$gm" mesh "$out/$name-t/tessellation.json" -o "$out/$name-m" > /dev/null
      "$gm" export "$out/$name-m/mesh.vtu" -o "$out/$name-e" > /dev/null
    fi
  done
  # A sweep of two points and two realisations, solved, and its summary.
  { cat data/default.ini; printf '\n[sweep]\nphase.matrix.fraction = 0.2, 0.3\nrealisations = 2\n'; } > "$out/sweep.ini"
  "$gm" sweep "$out/sweep.ini" -o "$out/sweep" --solve --jobs 2 --set mesh.triangles_per_grain=30 > /dev/null
  "$gm" sweep --collect "$out/sweep" > /dev/null
  # What two runs of one binary do not share: timings, memory, and paths of the output.
  find "$out" -name report.json | while read -r r; do
    python3 - "$r" "$out" << 'EOF'
import json, sys
path, out = sys.argv[1], sys.argv[2]
r = json.load(open(path))
def strip(d):
    if isinstance(d, dict):
        return {k: strip(v) for k, v in d.items() if k not in ("seconds", "memory_mib", "peak_memory_mib", "config") and not k.endswith("_seconds")}
    if isinstance(d, list):
        return [strip(v) for v in d]
    return d.replace(out, "OUT") if isinstance(d, str) else d
json.dump(strip(r), open(path, "w"), indent=2, sort_keys=True)
EOF
  done
}
for side in base new; do
  gm=$work/build/grainmesh
  [ $side = new ] && gm=$root/build/grainmesh
  outputs "$gm" "$work/out/$side" > "$work/$side.log" 2>&1 || { echo "same-outputs: the $side binary failed:"; tail -5 "$work/$side.log"; exit 1; }
done
if diff -r -x 'log.*' -x logs "$work/out/base" "$work/out/new" > "$work/diff.txt"; then
  echo "same-outputs: every output of $(git rev-parse --short "$base") and the working tree is the same ($(find "$work/out/new" -type f | wc -l) files)"
else
  echo "same-outputs: outputs differ from $(git rev-parse --short "$base"); see $work/diff.txt"
  head -40 "$work/diff.txt"
  exit 1
fi
