#!/usr/bin/env bash
# Lists what breaks the size rules of the libraries (tests and bench aside): functions over
# 80 lines, files over 500 lines. Function extents from universal-ctags (lambdas count in
# the function that holds them). Exit 1 when something does, 0 when nothing does.
#   scripts/code-size.sh [MAX_FUNCTION_LINES [MAX_FILE_LINES]]
set -euo pipefail
cd "$(dirname "$0")/.."
max_fn=${1:-80}
max_file=${2:-500}
dirs="common domain tessellate mesh grains grains3d export view analysis pipelines"
files=$(for d in $dirs; do [ -d "$d" ] && find "$d" -name '*.cpp' -o -name '*.hpp' -o -name '*.hpp.in'; done | sort)
found=0
for f in $files; do
  n=$(wc -l < "$f")
  if [ "$n" -gt "$max_file" ]; then echo "file $f: $n lines"; found=1; fi
done
long=$(ctags --c++-kinds=f --fields=+ne --output-format=u-ctags -f - $files 2>/dev/null |
  awk -F'\t' -v max="$max_fn" '{
    line = ""; end = "";
    for (i = 4; i <= NF; ++i) { if ($i ~ /^line:/) line = substr($i, 6); if ($i ~ /^end:/) end = substr($i, 5) }
    if (line != "" && end != "" && end - line + 1 > max) printf "function %s:%s %s: %d lines\n", $2, line, $1, end - line + 1
  }')
if [ -n "$long" ]; then echo "$long"; found=1; fi
exit $found
