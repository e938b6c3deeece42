#!/bin/bash
# CPU (user + sys) seconds of `raycast render` at one thread for each scene of this folder, best of
# N runs, for one or more raycast binaries run alternately (so machine load hits them alike).
# Usage: bench/algebraic_scenes/time_renders.sh N raycast_a [raycast_b ...]
set -e
dir=$(cd "$(dirname "$0")" && pwd)
n=$1; shift
printf '%-16s' scene; for b in "$@"; do printf ' %12s' "$(basename "$(dirname "$b")")"; done; echo
for scene in gyroid sincos heart heart_implicit torus torus_algebraic degree8 all; do
  declare -A best=()
  for ((i = 0; i < n; ++i)); do
    for b in "$@"; do
      /usr/bin/time -o /tmp/time_renders.txt -f "%U %S" "$b" render "$dir/$scene.yaml" \
        -o /tmp/time_renders.png --threads 1 >/dev/null 2>&1
      t=$(awk "{print \$1 + \$2}" /tmp/time_renders.txt)
      if [[ -z ${best[$b]} ]] || awk "BEGIN{exit !($t < ${best[$b]})}"; then best[$b]=$t; fi
    done
  done
  printf '%-16s' "$scene"; for b in "$@"; do printf ' %12s' "${best[$b]}"; done; echo
  unset best
done
