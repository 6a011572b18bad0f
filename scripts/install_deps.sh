#!/usr/bin/env bash
# Installs the Debian packages the project needs (run as root on Debian 12).
set -euo pipefail
packages=(g++ cmake make ccache libcgal-dev libcgal-demo libeigen3-dev libboost-dev
          libboost-program-options-dev libtbb-dev libgtest-dev libbenchmark-dev doxygen
          dpkg-dev libjs-mathjax python3-dev pybind11-dev python3-numpy python3-pytest
          clang-format)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
