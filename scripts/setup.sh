#!/usr/bin/env bash
# Installs every Debian package that raycast needs to build, test and benchmark (idempotent),
# then configures and builds the given presets (default: release). The Python module is built
# for Debian's /usr/bin/python3 (which sees Debian's numpy), whatever python3 is first on PATH.
# Usage: scripts/setup.sh [preset ...]
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make pkg-config git
  libyaml-cpp-dev libcli11-dev libtbb-dev libpng-dev libopenexr-dev libassimp-dev
  libgtest-dev libgmock-dev libbenchmark-dev libembree-dev povray
  pybind11-dev python3-dev python3-numpy python3-pytest
  clang-14 libclang-rt-14-dev
  libopenmpi-dev openmpi-bin
  libcpp-httplib-dev chromium
  libopenvdb-dev libboost-dev)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}" >/dev/null
fi

presets=("$@")
[ ${#presets[@]} -eq 0 ] && presets=(release)
jobs=$(nproc)
for preset in "${presets[@]}"; do
  # A build directory configured by an older preset (another compiler) is configured afresh.
  cmake --preset "$preset" -DPYTHON_EXECUTABLE=/usr/bin/python3 >/dev/null 2>&1 || {
    rm -rf "build/$preset"
    cmake --preset "$preset" -DPYTHON_EXECUTABLE=/usr/bin/python3 >/dev/null
  }
  cmake --build --preset "$preset" -j "$jobs"
done
