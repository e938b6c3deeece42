#!/usr/bin/env bash
# The mesh table against Embree (docs/performance.md): every cell of the grid below run RUNS
# times with `raycast bench --vs embree --json`, then one markdown row per cell with the median
# ratio by wall time, the median CPU-time ratio and its range, the median run's Mrays/s, the
# build CPU ratio (Embree / raycast) and raycast's bytes per triangle.
#   bench/embree_table.sh [OUT.jsonl]     (the raw JSON lines are kept in OUT.jsonl if given)
# Environment:
#   RUNS     runs per cell (default 5; the median is the middle run's ratio)
#   CELLS    "mesh:rays:threads[:packets[:width]]" list (default: the 18 cells below)
#   RAYCAST  (default build/release/raycast); RAYCAST_ISA pins a kernel path as usual
# Run on an idle machine: the ratio is taken in one process, but both sides are timed by wall
# clock (the CPU ratio is printed beside it). The rounds are interleaved (each round runs every
# cell once) so that a slow spell of the machine spreads over the cells instead of hitting one.
set -euo pipefail
cd "$(dirname "$0")/.."
raycast=${RAYCAST:-build/release/raycast}
runs=${RUNS:-5}
default_cells="sphere:1000000:primary:1 sphere:1000000:primary:2
sphere:1000000:incoherent:1 sphere:1000000:incoherent:2
sphere:1000000:shadow:1 sphere:1000000:shadow:2
forest:1000000:primary:1 forest:1000000:primary:2
forest:1000000:incoherent:1 forest:1000000:incoherent:2
forest:1000000:shadow:1 forest:1000000:shadow:2
sphere:1000000:primary:1:packets:8 sphere:1000000:primary:1:packets:16
sphere:1000000:primary:2:packets:8 sphere:1000000:primary:2:packets:16
sphere:10000000:primary:2 sphere:10000000:incoherent:2"
cells=${CELLS:-$default_cells}
[ -x "$raycast" ] || { echo "missing: $raycast" >&2; exit 2; }
out=${1:-$(mktemp)}
: >"$out"
echo "$($raycast --version 2>/dev/null | head -1), $runs runs per cell, $(date -u +%H:%M) UTC," \
  "load average $(cut -d' ' -f1-3 /proc/loadavg)" >&2
for ((round = 1; round <= runs; round++)); do
  for cell in $cells; do
    IFS=: read -r kind size rays threads packets width <<<"$cell"
    repeat=3
    [ "$size" -ge 10000000 ] && repeat=2
    args=(bench --procedural "$kind:$size" --rays "$rays" --threads "$threads" --vs embree
      --repeat "$repeat" --json)
    [ "${packets:-}" = packets ] && args+=(--packets --packet-width "${width:-8}")
    "$raycast" "${args[@]}" 2>/dev/null | tail -1 |
      /usr/bin/python3 -c 'import json,sys; d=json.load(sys.stdin); d["cell"]=sys.argv[1]; print(json.dumps(d))' "$cell" >>"$out"
  done
  echo "round $round done, $(date -u +%H:%M) UTC, load average $(cut -d' ' -f1-3 /proc/loadavg)" >&2
done
/usr/bin/python3 - "$out" <<'EOF'
import json, sys, collections
by_cell = collections.OrderedDict()
for line in open(sys.argv[1]):
    d = json.loads(line)
    by_cell.setdefault(d["cell"], []).append(d)
print("| mesh | rays | threads | ratio wall, median | ratio CPU, median (range) "
      "| raycast / Embree Mrays/s (median run) | build CPU Embree/raycast, median | raycast B/tri |")
print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |")
def median(xs):
    return sorted(xs)[len(xs) // 2]
for cell, ds in by_cell.items():
    parts = cell.split(":")
    rays = parts[2] + (f", packets of {parts[5] if len(parts) > 5 else 8}" if len(parts) > 4 else "")
    mid = sorted(ds, key=lambda d: d["ratio"])[len(ds) // 2]
    cpu = [d["ratio_cpu"] for d in ds]
    print(f"| {parts[0]}:{parts[1]} | {rays} | {parts[3]} | {mid['ratio']:.2f} "
          f"| {median(cpu):.2f} ({min(cpu):.2f}-{max(cpu):.2f}) "
          f"| {mid['raycast_mrays']:.2f} / {mid['embree_mrays']:.2f} "
          f"| {median([d['build_ratio_cpu'] for d in ds]):.2f} | {mid['raycast_bytes_per_tri']:.1f} |")
EOF
