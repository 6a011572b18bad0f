#!/usr/bin/env bash
# Installs the package from the build tree (build/) into a temporary prefix,
# builds the downstream project test/downstream against it, from its own
# build tree, and runs it on fandisk. Run after scripts/build.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install build --prefix "$work/prefix" > "$work/install.log"
test -x "$work/prefix/bin/denoise"
test -f "$work/prefix/include/CGAL_intrinsic_denoising/CGAL/Polygon_mesh_processing/intrinsic_denoising.h"
"$work/prefix/bin/denoise" --help > /dev/null
cmake -S test/downstream -B "$work/downstream" -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/downstream" > "$work/build.log"
"$work/downstream/downstream" "$root/build/cgal_data/data/meshes/fandisk.off"
# the Python module, if built, denoises from the prefix too
if ls build/python/cgal_intrinsic_denoising*.so > /dev/null 2>&1; then
  PYTHONPATH="$work/prefix/lib/python3/dist-packages" /usr/bin/python3 -c "
import sys, cgal_intrinsic_denoising as dn
assert dn.__file__.startswith('$work/prefix'), dn.__file__
V, F = dn.read_mesh(sys.argv[1])
W, report = dn.denoise(dn.add_gaussian_noise(V, F, 0.3, seed=1), F)
print('python from the prefix: E_n', dn.face_normal_error(W, F, V))
" "$root/build/cgal_data/data/meshes/fandisk.off"
fi
echo "install: headers, package config and denoise under a fresh prefix; downstream project built and run"
