#!/usr/bin/env bash
# The rendering benchmark suite against POV-Ray 3.7 (docs/performance.md): every scene
# rendered by both at the same size on each thread count, at 1 sample per pixel and with
# antialiasing, reporting POV-Ray's own "Trace Time" (and the CPU-seconds it prints beside it)
# against raycast's render time (the pixel loop's wall and CPU time from its summary line), the
# ratios POV-Ray / raycast (above 1: raycast faster), and with antialiasing the RMSE of both images
# against a raycast reference of REF_SPP samples per pixel (bench/povray/rmse.py).
#   bench/povray/suite.sh [SCENE...]      (default: whitted csg surfaces mesh textured glass)
# Environment:
#   THREADS   thread counts to run (default "1 2"): POV-Ray +WTn, raycast --threads n
#   WIDTH, HEIGHT (default 640 480); REPEATS (default 1: the best of REPEATS runs is kept)
#   MODES     "1spp aa" (default), or one of them
#   POV_AA    POV-Ray's antialiasing options (default "+A0.3": method 1, depth 3, no jitter)
#   RAYCAST_AA raycast's (default "--antialias 1,0.3,3": the same method; docs/rendering.md)
#   REF_SPP   samples per pixel of the reference (default 256, rendered with render.bailout 0:
#             every ray traced to max_depth); REF_DIR caches the references
#             (default /tmp/raycast-suite-ref; delete it after changing the renderer's output)
#   RAYCAST   (default build/release/raycast); KEEP=dir keeps every image there
# Each run's times come from the programs' own reports: POV-Ray's "Trace Time: ... (S seconds)"
# and "using N thread(s) with C CPU-seconds total"; raycast's "... threads: S s (cpu C s), ...".
set -euo pipefail
cd "$(dirname "$0")/../.."
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(whitted csg surfaces mesh textured glass)
threads=${THREADS:-"1 2"}
width=${WIDTH:-640}
height=${HEIGHT:-480}
repeats=${REPEATS:-1}
modes=${MODES:-"1spp aa"}
pov_aa=${POV_AA:-"+A0.3"}
raycast_aa=${RAYCAST_AA:-"--antialias 1,0.3,3"}
ref_spp=${REF_SPP:-256}
ref_dir=${REF_DIR:-/tmp/raycast-suite-ref}
raycast=${RAYCAST:-build/release/raycast}
command -v povray >/dev/null || { echo "povray is not installed (scripts/setup.sh)" >&2; exit 2; }
[ -x "$raycast" ] || { echo "missing: $raycast" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source bench/timing.sh  # best
mkdir -p "$ref_dir"

yaml_of() {  # the raycast scene of a suite name
  if [ -e "bench/scenes/$1.yaml" ]; then echo "bench/scenes/$1.yaml"; else echo "scenes/$1.yaml"; fi
}

pov_run() {  # pov_run OUT THREADS [options...]: prints "trace_seconds cpu_seconds"
  local out=$1 n=$2
  shift 2
  povray +I"bench/povray/$scene.pov" +O"$out" +W"$width" +H"$height" -D +FN +WT"$n" \
    +Lbench/povray +L/usr/share/povray-3.7/include File_Gamma=sRGB "$@" >"$tmp/pov.log" 2>&1 ||
    { cat "$tmp/pov.log" >&2; exit 1; }
  awk '/Trace Time:/ { getline cpu; gsub(/[()]/, "", $0); t = $(NF - 1);
                       split(cpu, w, " with "); split(w[2], c, " "); print t, c[1] }' "$tmp/pov.log"
}

our_run() {  # our_run OUT THREADS [options...]: prints "seconds cpu_seconds"
  local out=$1 n=$2
  shift 2
  "$raycast" render "$(yaml_of "$scene")" -o "$out" --width "$width" --height "$height" \
    --threads "$n" "$@" >"$tmp/our.log" 2>&1 || { cat "$tmp/our.log" >&2; exit 1; }
  sed -n 's/.* threads: \([0-9.]*\) s (cpu \([0-9.]*\) s).*/\1 \2/p' "$tmp/our.log"
}

echo "raycast suite against $(povray --version 2>&1 | grep -m1 '^POV-Ray'), ${width}x${height}," \
  "best of $repeats, $(date -u +%H:%M) UTC, load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "POV-Ray AA: $pov_aa; raycast AA: $raycast_aa; reference: raycast --spp $ref_spp"
printf '| %-8s | %s | %-4s | %9s | %8s | %9s | %8s | %11s | %9s | %8s | %8s |\n' scene thr mode \
  "pov trace" "pov cpu" "rc render" "rc cpu" "ratio trace" "ratio cpu" "pov rmse" "rc rmse"
echo "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
for scene in "${scenes[@]}"; do
  [ -e "bench/povray/$scene.pov" ] || { echo "missing: bench/povray/$scene.pov" >&2; exit 2; }
  ref="$ref_dir/$scene-${width}x$height-$ref_spp.png"
  for n in $threads; do
    for mode in $modes; do
      if [ "$mode" = 1spp ]; then pov_opts=(-A); our_opts=(--spp 1); else
        read -r -a pov_opts <<<"$pov_aa"; read -r -a our_opts <<<"$raycast_aa"; fi
      : >"$tmp/p"; : >"$tmp/o"
      for ((i = 1; i <= repeats; ++i)); do  # interleaved, so a burst of load hits both alike
        pov_run "$tmp/pov.png" "$n" "${pov_opts[@]}" >>"$tmp/p"
        our_run "$tmp/our.png" "$n" "${our_opts[@]}" >>"$tmp/o"
      done
      read -r pt pc < <(best <"$tmp/p")
      read -r rt rc < <(best <"$tmp/o")
      pov_rmse=- our_rmse=-
      if [ "$mode" = aa ]; then
        if [ ! -e "$ref" ]; then  # the exact image: a copy of the scene with render.bailout 0
          yaml=$(yaml_of "$scene")
          exact="$(dirname "$yaml")/.exact-$scene.yaml"  # beside it: relative paths still resolve
          grep -q '^render: {' "$yaml" || { echo "$yaml: no 'render: {' line" >&2; exit 2; }
          sed 's/^render: {/render: {bailout: 0, /' "$yaml" >"$exact"
          "$raycast" render "$exact" -o "$ref" --width "$width" --height "$height" \
            --spp "$ref_spp" >/dev/null 2>&1 || { rm -f "$exact"; exit 1; }
          rm -f "$exact"
        fi
        pov_rmse=$(bench/povray/rmse.py "$tmp/pov.png" "$ref")
        our_rmse=$(bench/povray/rmse.py "$tmp/our.png" "$ref")
      fi
      if [ -n "${KEEP:-}" ]; then
        mkdir -p "$KEEP"
        cp "$tmp/pov.png" "$KEEP/$scene-$n-$mode-povray.png"
        cp "$tmp/our.png" "$KEEP/$scene-$n-$mode-raycast.png"
      fi
      awk -v s="$scene" -v n="$n" -v m="$mode" -v pt="$pt" -v pc="$pc" -v rt="$rt" -v rc="$rc" \
        -v pr="$pov_rmse" -v rr="$our_rmse" 'BEGIN {
        printf "| %-8s | %d | %-4s | %9.3f | %8.3f | %9.3f | %8.3f | %11.2f | %9.2f | %8s | %8s |\n",
          s, n, m, pt, pc, rt, rc, (rt > 0 ? pt / rt : 0), (rc > 0 ? pc / rc : 0), pr, rr }'
    done
  done
done
