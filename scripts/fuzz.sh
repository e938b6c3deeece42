#!/usr/bin/env bash
# Builds the libFuzzer targets (in the `asan` preset: clang 14, ASan + UBSan) and runs each for a
# bounded time from its seed corpus in tests/fuzz/corpus/ (the loader also from scenes/*.yaml).
# Fails on any crash, leak, timeout or out-of-memory. Findings land in build/asan/fuzz/findings/.
# Usage: scripts/fuzz.sh [seconds per target, default $FUZZ_SECONDS or 30] [target ...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-${FUZZ_SECONDS:-30}}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(loader_fuzz formula_fuzz mesh_fuzz rays_fuzz volume_fuzz pov_fuzz)

cmake --preset asan >/dev/null 2>&1 || { rm -rf build/asan; cmake --preset asan >/dev/null; }
cmake --build --preset asan -j "$(nproc)" --target "${targets[@]}"

work=build/asan/fuzz/work
findings=build/asan/fuzz/findings
mkdir -p "$findings"
status=0
for t in "${targets[@]}"; do
  name=${t%_fuzz}
  corpus="$work/$name"
  rm -rf "$corpus" && mkdir -p "$corpus"
  cp tests/fuzz/corpus/"$name"/* "$corpus"/
  [ "$name" = loader ] && cp scenes/*.yaml "$corpus"/
  max_len=4096
  [ "$name" = formula ] && max_len=512
  echo "fuzz: $t for ${seconds}s"
  if ! ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" \
       UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
       build/asan/fuzz/"$t" "$corpus" -seed=1 -max_total_time="$seconds" \
         -timeout=10 -rss_limit_mb=4096 -max_len="$max_len" -print_final_stats=1 \
         -artifact_prefix="$findings/$name-" >"$work/$name.log" 2>&1; then
    echo "fuzz: $t FAILED; the input is in $findings/, the log in $work/$name.log"
    tail -40 "$work/$name.log"
    status=1
  else
    grep -E "stat::number_of_executed_units|cov:" "$work/$name.log" | tail -2 | sed 's/^/  /'
  fi
done
exit $status
