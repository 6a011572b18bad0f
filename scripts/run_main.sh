#!/usr/bin/env bash
# The main job: install dependencies, build, denoise CGAL's fandisk with seeded
# Gaussian noise (sigma_E = 0.3) and report E_n, E_v, time and the output files.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh --target denoise_and_report
mkdir -p build/output
cd build/output
../examples/Polygon_mesh_processing/denoise_and_report "$@"
echo "output directory: $(pwd)"
