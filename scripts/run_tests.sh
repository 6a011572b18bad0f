#!/usr/bin/env bash
# The whole test suite: install dependencies, build everything (tests,
# examples, benchmarks), run the tests with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)"
