#!/bin/bash
# Loads a generated scene of N spheres (default 100,000, one object a line, about 8.5 MB) with
# `raycast info` R times (default 7) and prints the best CPU time (user + system), the best wall
# time and the peak resident memory (docs/performance.md "Loading large scenes").
#
#   bench/load/time_load.sh [RAYCAST] [N] [R]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
raycast=${1:-$here/../../build/release/raycast}
count=${2:-100000}
runs=${3:-7}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 "$here/make_spheres.py" "$tmp/big.yaml" --count "$count"
echo "scene: $count spheres, $(stat -c %s "$tmp/big.yaml") bytes"
for _ in $(seq "$runs"); do
  /usr/bin/time -f '%U %S %e %M' -o "$tmp/time" "$raycast" info "$tmp/big.yaml" >/dev/null
  cat "$tmp/time"
done | awk '{ cpu = $1 + $2 }
  NR == 1 || cpu < c { c = cpu } NR == 1 || $3 < w { w = $3 } $4 > m { m = $4 }
  END { printf "best of %d: %.2f s CPU, %.2f s wall, %.0f MB peak RSS\n", NR, c, w, m / 1024 }'
