#!/usr/bin/env bash
# Installs the peers and data that the benchmarks compare against (scripts/packages/bench.txt:
# Embree, POV-Ray with its include files and example scenes, Open3D), then builds the release
# preset with the tests, benchmarks and the Embree peer of `raycast bench`.
# Usage: scripts/bench-setup.sh
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-packages.sh bench
scripts/setup.sh --tests release
