#!/usr/bin/env bash
# Sets everything up, then builds and runs the whole test suite in the release and the
# sanitizer (AddressSanitizer + UndefinedBehaviorSanitizer) builds (the release run includes the
# Python tests), then installs the release build into a scratch prefix and builds and runs the
# examples against it, with CMake's find_package and with pkg-config, then a bounded run of every
# fuzz target (scripts/fuzz.sh; FUZZ_SECONDS per target, default 30).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --tests release asan
jobs=$(nproc)
ctest --preset release -j "$jobs"
ctest --preset asan -j "$jobs"

prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install build/release --prefix "$prefix/usr" >/dev/null
cmake -S examples -B "$prefix/build" -DCMAKE_PREFIX_PATH="$prefix/usr" >/dev/null
cmake --build "$prefix/build" -j "$jobs"
"$prefix/build/cast_mesh"
"$prefix/build/render_scene" "$prefix/scene.ppm"
PKG_CONFIG_PATH="$prefix/usr/lib/pkgconfig" bash -c \
  'g++ examples/cast_mesh.cpp -o "$0/cast_mesh_pc" $(pkg-config --cflags --libs raycast)' "$prefix"
"$prefix/cast_mesh_pc"
echo "test: the examples build and run against the installed package"

scripts/fuzz.sh
