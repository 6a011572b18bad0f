#!/usr/bin/env bash
# The main job: install dependencies, build the command-line tool `denoise`,
# denoise CGAL's fandisk with seeded Gaussian noise (sigma_E = 0.3) in the
# default, automatic mode and report what was chosen, E_n, E_v, time and the
# output files. With arguments (input [reference]), denoise that mesh instead:
# the result goes next to it as <input>_denoised.off.
set -euo pipefail
caller=$(pwd)
absolute() { case "$1" in /*) echo "$1" ;; *) echo "$caller/$1" ;; esac; }
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh --target denoise
denoise=$(pwd)/build/tools/denoise/denoise
mkdir -p build/output
cd build/output
if [ $# -eq 0 ]; then
  fandisk=$(cd ../cgal_data/data/meshes && pwd)/fandisk.off
  "$denoise" "$fandisk" --noise 0.3 --seed 1 --noisy-output fandisk_noisy.off --reference "$fandisk" \
             -o fandisk_noisy_denoised.off
  echo "output directory: $(pwd)"
elif [ $# -eq 1 ]; then
  "$denoise" "$(absolute "$1")"
else
  "$denoise" "$(absolute "$1")" --reference "$(absolute "$2")"
fi
