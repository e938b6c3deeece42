#!/usr/bin/env bash
# Times POV-Ray on bench/povray/SCENE.pov against `raycast render` on scenes/SCENE.yaml (the same
# scene) at the same resolution, one sample per pixel (POV-Ray: -A; raycast: --spp 1), the same
# number of threads (POV-Ray: +WTn; raycast: --threads n), REPEATS runs each, and prints the best
# wall and CPU (user + system) times and the ratios POV-Ray / raycast.
#   bench/compare_povray.sh [SCENE] [WIDTH [HEIGHT]]
# SCENE: csg (the default, 640x480, as this script's first form `[WIDTH [HEIGHT]]` did) or analytic
# (1280x720 unless given). Environment: THREADS (default: nproc, on both sides), REPEATS (default 3),
# RAYCAST (default build/release/raycast), KEEP=dir to keep both images (dir/SCENE-raycast.png,
# dir/SCENE-povray.png).
# Both times cover the whole process (parsing, building, rendering, writing the PNG). On a
# shared machine the CPU time is the steadier figure; the best of the repeats is reported.
set -euo pipefail
cd "$(dirname "$0")/.."
scene=csg
if [ $# -gt 0 ] && ! [[ $1 =~ ^[0-9]+$ ]]; then
  scene=$1
  shift
fi
if [ "$scene" = csg ]; then
  width=${1:-640}
  height=${2:-480}
else
  width=${1:-1280}
  height=${2:-720}
fi
threads=${THREADS:-$(nproc)}
repeats=${REPEATS:-3}
raycast=${RAYCAST:-build/release/raycast}
pov_file=bench/povray/$scene.pov
yaml_file=scenes/$scene.yaml
for f in "$pov_file" "$yaml_file" "$raycast"; do
  [ -e "$f" ] || { echo "missing: $f" >&2; exit 2; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
TIMEFORMAT='%R %U %S'  # wall, user, system seconds
source bench/timing.sh  # seconds, best


pov_cmd=(povray +I"$pov_file" +O"$tmp/povray.png" +W"$width" +H"$height" -A -D +FN +WT"$threads"
         +L/usr/share/povray-3.7/include File_Gamma=sRGB)
our_cmd=("$raycast" render "$yaml_file" -o "$tmp/raycast.png" --width "$width" --height "$height"
         --spp 1 --threads "$threads")
: >"$tmp/pov.times"
: >"$tmp/our.times"
for ((i = 1; i <= repeats; ++i)); do  # interleaved, so a burst of load hits both alike
  seconds "${pov_cmd[@]}" >>"$tmp/pov.times"
  seconds "${our_cmd[@]}" >>"$tmp/our.times"
done
read -r pov_wall pov_cpu < <(best <"$tmp/pov.times")
read -r our_wall our_cpu < <(best <"$tmp/our.times")
if [ -n "${KEEP:-}" ]; then
  mkdir -p "$KEEP"
  cp "$tmp/povray.png" "$KEEP/$scene-povray.png"
  cp "$tmp/raycast.png" "$KEEP/$scene-raycast.png"
fi
echo "scene: $scene ($yaml_file vs $pov_file), ${width}x${height}, 1 sample per pixel, $threads thread(s)"
echo "best of $repeats runs (load average at the end: $(cut -d' ' -f1 /proc/loadavg)):"
echo "povray:  wall ${pov_wall} s, cpu ${pov_cpu} s   ($(povray --version 2>&1 | grep -m1 "^POV-Ray"))"
echo "raycast: wall ${our_wall} s, cpu ${our_cpu} s   (raycast render, $scene)"
awk -v pw="$pov_wall" -v pc="$pov_cpu" -v rw="$our_wall" -v rc="$our_cpu" 'BEGIN {
  printf "ratio povray / raycast:"
  if (rw > 0) printf " wall %.2f", pw / rw
  if (rc > 0) printf ", cpu %.2f", pc / rc
  printf "\n"
}'
