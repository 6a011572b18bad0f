#!/usr/bin/env bash
# Fuzzes the command-line program's mesh-file entry (file bytes -> read,
# validate, denoise) with libFuzzer under ASan + UBSan, SECONDS seconds
# (default 300) for each FORMAT given (default: off obj ply stl):
#   bash scripts/run_fuzz.sh [SECONDS [FORMAT...]]
# Installs clang if needed, builds into build-fuzz/, keeps one corpus per
# format in build-fuzz/corpus-FORMAT (seeded with the files of that extension
# in fuzz/Polygon_mesh_processing/corpus and CGAL's small meshes). A crash is
# saved as build-fuzz/crash-* and the script fails. Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-300}"
shift || true
formats=("$@")
[ ${#formats[@]} -eq 0 ] && formats=(off obj ply stl)
bash scripts/install_deps.sh
fuzz_packages=(clang libclang-rt-14-dev)
missing=()
for p in "${fuzz_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
      -DDENOISING_BUILD_FUZZERS=ON -DDENOISING_BUILD_TESTS=OFF -DDENOISING_BUILD_EXAMPLES=OFF -DDENOISING_BUILD_TOOLS=OFF \
      -DDENOISING_BUILD_BENCHMARKS=OFF >/dev/null
targets=()
for f in "${formats[@]}"; do targets+=("fuzz_denoise_$f"); done
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for f in "${formats[@]}"; do
  corpus=build-fuzz/corpus-$f
  mkdir -p "$corpus"
  find fuzz/Polygon_mesh_processing/corpus build-fuzz/cgal_data/data/meshes -name "*.$f" -size -8k \
       -exec cp -n {} "$corpus/" \; 2>/dev/null || true
  echo "fuzzing $f for $seconds s"
  (cd build-fuzz && "./fuzz/Polygon_mesh_processing/fuzz_denoise_$f" "corpus-$f" -max_total_time="$seconds" \
       -max_len=16384 -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=./)
done
