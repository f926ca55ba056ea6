#!/usr/bin/env bash
# Installs the Debian 12 packages mkbool builds, tests and benchmarks with (as root, or via
# sudo when it is available). Safe to run again.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config git
  libgmp-dev libmpfr-dev libboost-dev libcgal-dev
  libgtest-dev libbenchmark-dev nlohmann-json3-dev libcli11-dev
  libgeos-dev libpolyclipping-dev zlib1g-dev
  python3-matplotlib
  pybind11-dev python3-pybind11 python3-dev python3-numpy python3-pytest python3-shapely python3-pandas
  python3-setuptools python3-wheel python3-pip python3-venv
  clang libclang-rt-14-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi
sudo=""
if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
