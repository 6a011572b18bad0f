#!/usr/bin/env bash
# Regenerates the pictures of README.md and of the manual
# (doc/Polygon_mesh_processing/fig/*.png) and the sample comparison page
# (doc/Polygon_mesh_processing/sample_report.html) from benchmark outputs:
#   1. table1_benchmark --models fandisk,prism --meshes --report: every method's
#      best output (grid search by E_n, seeded noise), its per-face normal
#      error, and one comparison page per model;
#   2. geodesic_vs_square_pattern on fandisk: the two path strategies' results;
#   3. tools/render/render.mjs draws each page's meshes with three.js in
#      headless chromium into a contact sheet, flat shaded, and again with the
#      per-face normal error heat map.
# Needs the build (scripts/build.sh) and scripts/install_render_deps.sh.
# Takes a few minutes (the grid search). Work files go to build/figures/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_render_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 --target table1_benchmark geodesic_vs_square_pattern
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
cp "$work/reports/prism.html" doc/Polygon_mesh_processing/sample_report.html
cp "$work/reports/prism.csv" doc/Polygon_mesh_processing/sample_report.csv
ls -l "$fig" doc/Polygon_mesh_processing/sample_report.html
