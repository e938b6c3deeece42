#!/usr/bin/env bash
# Sets everything up, then builds and runs the whole test suite in the release and the
# sanitizer (AddressSanitizer + UndefinedBehaviorSanitizer) builds, then a bounded run of every
# fuzz target (scripts/fuzz.sh; FUZZ_SECONDS per target, default 30).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh release asan
jobs=$(nproc)
ctest --preset release -j "$jobs"
ctest --preset asan -j "$jobs"
scripts/fuzz.sh
