#!/usr/bin/env bash
# Regenerates the pictures in docs/images/ that README.md and docs/ show, with the built tool.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for name in union_polygon_circle graded_hole fibres_6 fibres_20; do
  ./build/grainmesh domain "data/examples/$name.ini" -o "$tmp/$name" --set output.picture_width=480 > /dev/null
  cp "$tmp/$name/mesh.png" "docs/images/$name.png"
done
for name in grains_wc_co grains_binder; do
  ./build/grainmesh tessellate "data/examples/$name.ini" -o "$tmp/$name" --set output.picture_width=480 > /dev/null
  cp "$tmp/$name/tessellation.png" "docs/images/$name.png"
  ./build/grainmesh mesh "$tmp/$name/tessellation.json" -o "$tmp/${name}_mesh" --set output.picture_width=480 > /dev/null
  cp "$tmp/${name}_mesh/mesh.png" "docs/images/${name}_mesh.png"
  cp "$tmp/${name}_mesh/mesh_detail.png" "docs/images/${name}_mesh_detail.png"
done
./build/grainmesh tessellate data/examples/grains_3d_wc_co.ini -o "$tmp/3d" --set output.picture_width=480 > /dev/null
cp "$tmp/3d/tessellation.png" docs/images/grains_3d_wc_co.png
./build/grainmesh mesh "$tmp/3d/tessellation.json" -o "$tmp/3d_mesh" --set output.picture_width=480 > /dev/null 2>&1
cp "$tmp/3d_mesh/mesh.png" docs/images/grains_3d_wc_co_mesh.png
cp "$tmp/3d_mesh/mesh_view.png" docs/images/grains_3d_wc_co_view.png
./build/grainmesh tessellate data/examples/grains_3d_wc_co_binder.ini -o "$tmp/3d_binder" --set output.picture_width=900 > /dev/null
cp "$tmp/3d_binder/tessellation_view.png" docs/images/grains_3d_wc_co_binder_view.png
./build/grainmesh run data/examples/grains_3d_wc_co.ini -o "$tmp/3d_run" --solve --set homogenise.boundary=periodic \
  --set export.convert_to_meters=1e-6 --set load.delta_T=-1000 --set phase.WC.alpha=5.2e-6 \
  --set phase.Co.alpha=13.8e-6 --set output.picture_width=600 > /dev/null 2>&1
cp "$tmp/3d_run/von_mises.png" docs/images/grains_3d_wc_co_von_mises.png
cp "$tmp/3d_run/stress_xx.png" docs/images/grains_3d_wc_co_stress_xx.png
cp "$tmp/3d_run/von_mises_thermal.png" docs/images/grains_3d_wc_co_von_mises_thermal.png
cp "$tmp/3d_run/von_mises_view_thermal.png" docs/images/grains_3d_wc_co_von_mises_view_thermal.png
./build/grainmesh run -o "$tmp/run" --solve --set output.picture_width=800 > /dev/null
cp "$tmp/run/stress_xx.png" docs/images/default_stress_xx.png
cp "$tmp/run/stress_histogram.png" docs/images/default_stress_histogram.png
./build/grainmesh run -o "$tmp/thermal" --solve --set homogenise.boundary=periodic --set load.delta_T=-1000 \
  --set phase.particulate.alpha=5e-6 --set phase.matrix.alpha=14e-6 --set output.pictures=basic > /dev/null
cp "$tmp/thermal/stress_histogram_thermal.png" docs/images/default_residual_stress_histogram.png
echo "pictures written to docs/images/"
