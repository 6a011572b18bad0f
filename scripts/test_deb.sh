#!/usr/bin/env bash
# Builds the Debian package with CPack from the build tree (build/, after
# scripts/build.sh), installs it with apt-get in a clean folder, runs
# `denoise --help`, checks the manual page, builds test/downstream against the
# installed package (no prefix given: it is found under /usr) and runs it on
# fandisk; then removes the package again. Needs root (or sudo).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
work=$(mktemp -d)
cleanup() {
  $SUDO apt-get remove -y -qq libcgal-intrinsic-denoising-dev > /dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
(cd build && cpack -G DEB > "$work/cpack.log") || { cat "$work/cpack.log"; exit 1; }
deb=$(ls build/libcgal-intrinsic-denoising-dev_*.deb | head -n 1)
cp "$deb" "$work/"
cd "$work"
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "./$(basename "$deb")" > apt.log
command -v denoise
denoise --help > /dev/null
test -f /usr/share/man/man1/denoise.1.gz
test -f /usr/include/CGAL_intrinsic_denoising/CGAL/Polygon_mesh_processing/intrinsic_denoising.h
cmake -S "$root/test/downstream" -B downstream > configure.log
cmake --build downstream > build.log
./downstream/downstream "$root/build/cgal_data/data/meshes/fandisk.off"
if ls "$root"/build/python/cgal_intrinsic_denoising*.so > /dev/null 2>&1; then
  /usr/bin/python3 -c "
import sys, cgal_intrinsic_denoising as dn
assert dn.__file__.startswith('/usr/lib/python3/dist-packages/'), dn.__file__
V, F = dn.read_mesh(sys.argv[1])
W, report = dn.denoise(dn.add_gaussian_noise(V, F, 0.3, seed=1), F)
print('python from the package: E_n', dn.face_normal_error(W, F, V))
" "$root/build/cgal_data/data/meshes/fandisk.off"
fi
echo "Debian package $(basename "$deb"): installed with apt-get, denoise --help runs, downstream project built and run"
