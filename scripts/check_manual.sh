#!/usr/bin/env bash
# The manual's formulas render offline: the manual page and the reference page
# in headless chromium (tools/render/check_manual.mjs) show no LaTeX source.
# The same check must fail on a copy of the manual without its MathJax copy.
# Run after the target `doc`; needs node, chromium and tools/render's modules
# (scripts/install_render_deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
html=build/doc/Polygon_mesh_processing/html
pages=("$html/PkgIntrinsicDenoising.html" "$html/group__PMP__denoising__grp.html")
node tools/render/check_manual.mjs "${pages[@]}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$html" "$work/html"
rm -rf "$work/html/mathjax"
if node tools/render/check_manual.mjs "$work/html/PkgIntrinsicDenoising.html" 2> "$work/err.txt"; then
  echo "check_manual: passed on a manual without MathJax; it cannot fail" >&2
  exit 1
fi
grep -q "LaTeX source shown" "$work/err.txt"
echo "manual: formulas typeset offline; the check fails without MathJax, as it must"
