#!/usr/bin/env bash
# Regenerates the pictures of README.md and of the manual
# (doc/Polygon_mesh_processing/fig/*.png) and the sample comparison page
# (doc/Polygon_mesh_processing/sample_report.html) from benchmark outputs:
#   1. table1_benchmark --models fandisk,prism --meshes --report: every method's
#      best output (grid search by E_n, seeded noise), its per-face normal
#      error, and one comparison page per model;
#   2. geodesic_vs_square_pattern on fandisk: the two path strategies' results,
#      and the command-line tool's comparison pages of a sliver plane
#      (scripts/sliver_plane.py) at two noise levels;
#   3. tools/render/render.mjs draws each page's meshes with three.js in
#      headless chromium into a contact sheet, flat shaded, and again with the
#      per-face normal error heat map.
# Needs the build (scripts/build.sh) and scripts/install_render_deps.sh.
# Takes a few minutes (the grid search). Work files go to build/figures/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_render_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 --target table1_benchmark geodesic_vs_square_pattern denoise
work=build/figures
fig=doc/Polygon_mesh_processing/fig
mkdir -p "$work" "$fig"
build/benchmark/Polygon_mesh_processing/table1_benchmark --models fandisk,prism \
  --meshes "$work/meshes" --report "$work/reports" --out "$work/table1_fandisk_prism.md"
build/examples/Polygon_mesh_processing/geodesic_vs_square_pattern \
  build/cgal_data/data/meshes/fandisk.off "$work/reports/geodesic_vs_square.html"
render="node tools/render/render.mjs"
for model in fandisk prism; do
  # noisy, 6 classic methods, ours, reference: 9 tiles in 3 rows
  $render "$work/reports/$model.html" --tile 200 --cols 5 --out "$fig/${model}_methods.png"
  $render "$work/reports/$model.html" --tile 200 --cols 5 --heat --out "$fig/${model}_methods_error.png"
done
$render "$work/reports/geodesic_vs_square.html" --tile 240 --cols 4 --out "$fig/geodesic_vs_square.png"
$render "$work/reports/geodesic_vs_square.html" --tile 240 --cols 4 --heat --out "$fig/geodesic_vs_square_error.png"
# a strip tessellation of a plane (slivers of aspect ratio 20) at sigma_E 0.05
# and 0.3, automatic mode: noisy, result, reference, per-face normal error
python3 scripts/sliver_plane.py "$work/sliver_plane.off"
for s in 0.05 0.3; do
  build/tools/denoise/denoise "$work/sliver_plane.off" --noise $s \
    --reference "$work/sliver_plane.off" --report "$work/reports/sliver_$s.html" -o "$work/sliver_denoised_$s.off"
  $render "$work/reports/sliver_$s.html" --tile 240 --cols 3 --heat --out "$fig/sliver_plane_${s}_error.png"
done
cp "$work/reports/prism.html" doc/Polygon_mesh_processing/sample_report.html
cp "$work/reports/prism.csv" doc/Polygon_mesh_processing/sample_report.csv
ls -l "$fig" doc/Polygon_mesh_processing/sample_report.html
