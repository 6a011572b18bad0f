#!/usr/bin/env bash
# The tools of the pictures, the HTML report and its browser test
# (tools/render): Debian's chromium, node/npm when absent, and the pinned node
# modules (three, playwright-core) from tools/render/package-lock.json.
# Run as root on Debian 12 (or with sudo). Never downloads a browser: the
# tests drive /usr/bin/chromium. Measured on the development machine (Debian 12,
# most of chromium's libraries already present): apt-get update + install of
# chromium 16 s (17 packages), npm ci 4 s (2 packages, 38 MB).
set -euo pipefail
cd "$(dirname "$0")/.."
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
missing=()
command -v chromium >/dev/null 2>&1 || missing+=(chromium)
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  start=$(date +%s)
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  echo "apt install of ${missing[*]}: $(( $(date +%s) - start )) s"
fi
if [ ! -f tools/render/node_modules/three/build/three.module.min.js ] ||
   [ ! -d tools/render/node_modules/playwright-core ]; then
  start=$(date +%s)
  (cd tools/render && npm ci --no-audit --no-fund --loglevel=error)
  echo "npm ci in tools/render: $(( $(date +%s) - start )) s"
fi
