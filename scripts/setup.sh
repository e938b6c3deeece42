#!/usr/bin/env bash
# Installs the Debian packages that the library, the CLI and the Python module need (idempotent),
# then configures and builds them in the given presets (default: release). With --tests, also the
# packages and targets of the test suite, the benchmarks and the fuzz targets (what
# scripts/test.sh uses). The Python module is built for Debian's /usr/bin/python3 (which sees
# Debian's numpy), whatever python3 is first on PATH.
# Usage: scripts/setup.sh [--tests] [preset ...]
set -euo pipefail
cd "$(dirname "$0")/.."

tests=OFF
if [ "${1:-}" = "--tests" ]; then
  tests=ON
  shift
fi
lists=(build)
if [ "$tests" = ON ]; then
  for f in scripts/packages/test*.txt; do lists+=("$(basename "$f" .txt)"); done
fi
scripts/install-packages.sh "${lists[@]}"

presets=("$@")
[ ${#presets[@]} -eq 0 ] && presets=(release)
for preset in "${presets[@]}"; do
  bench=$tests
  [ "$preset" = asan ] && bench=OFF  # the benchmarks are timed in release builds only
  options=(-DPYTHON_EXECUTABLE=/usr/bin/python3 -DRAYCAST_TESTS=$tests -DRAYCAST_BENCH=$bench)
  # A build directory configured by an older preset (another compiler) is configured afresh.
  cmake --preset "$preset" "${options[@]}" >/dev/null 2>&1 || {
    rm -rf "build/$preset"
    cmake --preset "$preset" "${options[@]}" >/dev/null
  }
  cmake --build --preset "$preset" -j "$(nproc)"
done
