#!/usr/bin/env bash
# The whole test suite: install dependencies, check the formatting, build
# everything (tests, examples, benchmarks), run the tests with CTest, check
# the installed package (a prefix, then the Debian package) with a downstream
# project, build the manual and check in chromium that its formulas render.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
# every C++ file formatted by .clang-format (fails fast, before the build)
bash scripts/check_format.sh
# chromium, node and tools/render's node modules: the HTML report's browser tests
bash scripts/install_render_deps.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)"
cd ..
# install into a temporary prefix; build and run test/downstream against it;
# then the same through the Debian package (CPack, apt-get install)
bash scripts/test_install.sh
bash scripts/test_deb.sh
cd build
# The manual (doc/Polygon_mesh_processing): Doxygen with WARN_AS_ERROR, so any
# warning fails CI. Doxygen is installed by install_deps.sh; skipped without it.
if command -v doxygen >/dev/null 2>&1; then
  cmake --build . --target doc
  echo "manual: built with 0 Doxygen warnings: build/doc/Polygon_mesh_processing/html/index.html"
  # its formulas render offline (MathJax copied beside the HTML), in chromium
  bash ../scripts/check_manual.sh
else
  echo "doxygen not found: manual not built"
fi
