#!/usr/bin/env bash
# Times POV-Ray on bench/povray/csg.pov against raycast on scenes/csg.yaml (the same scene) at the
# same resolution and number of threads, one sample per pixel (POV-Ray: +W +H -A +WT; raycast:
# --spp 1 --threads), and prints the ratio.
#   bench/compare_povray.sh [WIDTH [HEIGHT [THREADS]]]   (RAYCAST=path/to/raycast to choose the
#   binary; THREADS defaults to the number of cores)
# When `raycast render` is not built yet, the raycast side answers the camera's primary rays with
# `raycast cast --binary` instead (ray queries only: no shading, no shadow rays), and says so.
set -euo pipefail
cd "$(dirname "$0")/.."
width=${1:-640}
height=${2:-480}
threads=${3:-$(nproc)}
raycast=${RAYCAST:-build/release/raycast}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
TIMEFORMAT='%R %U %S'  # wall, user, system seconds

seconds() {  # runs "$@" quietly, prints "wall user system" seconds; stops the script if it fails
  local log="$tmp/log" status=0
  { time "$@" >"$log" 2>&1; } 2>"$tmp/time" || status=$?
  if [ "$status" -ne 0 ]; then
    echo "failed ($status): $*" >&2
    cat "$log" >&2
    exit 1
  fi
  tail -1 "$tmp/time"
}

pov=$(seconds povray +Ibench/povray/csg.pov +O"$tmp/pov.png" +W"$width" +H"$height" -A +WT"$threads" -D +FN)
if "$raycast" --help | grep -Eq '^ +render +'; then
  what="raycast render (whitted, spp 1)"
  ours=$(seconds "$raycast" render scenes/csg.yaml -o "$tmp/raycast.png" --width "$width" --height "$height" --spp 1 --threads "$threads")
else
  what="raycast cast --binary on the camera rays (no render command in this build: queries only)"
  python3 bench/povray/camera_rays.py scenes/csg.yaml "$width" "$height" >"$tmp/rays.bin"
  ours=$(seconds "$raycast" cast scenes/csg.yaml --binary --rays "$tmp/rays.bin")
fi
read -r pov_wall pov_user pov_sys <<<"$pov"
read -r our_wall our_user our_sys <<<"$ours"
echo "resolution: ${width}x${height}, 1 sample per pixel, $threads threads (machine load: $(cut -d' ' -f1 /proc/loadavg))"
echo "povray:  wall ${pov_wall} s, cpu $(awk -v u="$pov_user" -v s="$pov_sys" 'BEGIN { print u + s }') s (render, no antialiasing)"
echo "raycast: wall ${our_wall} s, cpu $(awk -v u="$our_user" -v s="$our_sys" 'BEGIN { print u + s }') s (${what})"
awk -v pw="$pov_wall" -v pu="$pov_user" -v ps="$pov_sys" -v rw="$our_wall" -v ru="$our_user" -v rs="$our_sys" 'BEGIN {
  if (rw > 0) printf "ratio povray / raycast: wall %.2f", pw / rw
  if (ru + rs > 0) printf ", cpu %.2f", (pu + ps) / (ru + rs)
  printf "\n"
}'
