#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer:
# builds the tests into build-asan/ (DENOISING_SANITIZE=ON) and runs them.
# Any sanitizer report aborts the test that hit it, so CTest fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
# -O1 -g1: line tables for the reports, and a much cheaper compile than -O2 -g
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DDENOISING_SANITIZE=ON \
      -DDENOISING_BUILD_EXAMPLES=OFF -DDENOISING_BUILD_TOOLS=OFF -DDENOISING_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-asan -j"$(nproc)" --target denoising_tests
cd build-asan
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --output-on-failure -j"$(nproc)"
