#!/usr/bin/env bash
# Times POV-Ray against `raycast render` on scenes/fluid.yaml (the splash iso-surface) at the same
# resolution, one sample per pixel, the same thread count, REPEATS runs each (interleaved), and
# prints the best wall and CPU times and the ratios POV-Ray / raycast.
#   bench/fluid_povray.sh [WIDTH [HEIGHT]]     (default 400x300)
# Environment: THREADS (default nproc), REPEATS (default 3), RAYCAST (build/release/raycast),
# ISO_BENCH (build/release/bench/iso_bench), KEEP=dir to keep both images.
# POV-Ray gets the same density grid: raycast's own splatting of the same particles, written as a
# 16-bit df3 by `iso_bench --export-df3`, as `isosurface { function { iso - density(x, y, z) } }`
# over `pattern { density_file df3 ... interpolate 1 }` (trilinear), contained by the grid's box,
# with max_gradient set to the field's exact largest trilinear gradient (computed by the export:
# POV-Ray otherwise needs it tuned by hand, and too small a value leaves holes). raycast's time
# includes reading the particles and splatting them; POV-Ray's includes reading the df3.
set -euo pipefail
cd "$(dirname "$0")/.."
width=${1:-400}
height=${2:-300}
threads=${THREADS:-$(nproc)}
repeats=${REPEATS:-3}
raycast=${RAYCAST:-build/release/raycast}
iso_bench=${ISO_BENCH:-build/release/bench/iso_bench}
for f in scenes/fluid.yaml scenes/fluid/splash_0000.ply "$raycast" "$iso_bench"; do
  [ -e "$f" ] || { echo "missing: $f" >&2; exit 2; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
TIMEFORMAT='%R %U %S'
source bench/timing.sh  # seconds, best

"$iso_bench" --export-df3 scenes/fluid/splash_0000.ply 0.02 "$tmp/fluid.df3" >"$tmp/params"
read -r _ lx ly lz < <(grep '^min' "$tmp/params")
read -r _ hx hy hz < <(grep '^max' "$tmp/params")
iso=$(awk '/^iso/ { print $2 }' "$tmp/params")
grad=$(awk '/^max_gradient/ { print $2 * 1.01 }' "$tmp/params")

cat >"$tmp/fluid.pov" <<POV
// POV-Ray twin of scenes/fluid.yaml (right-handed frame as bench/povray/csg.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 8 }
camera {
  perspective location <0, 0.75, -1.75> look_at <0, 0.14, 0> sky y up y
  right -x*image_width/image_height
  angle 2*degrees(atan(tan(radians(20))*image_width/image_height))
}
background { rgb <0.55, 0.7, 0.95> }
light_source { <-2, 4, -3> color rgb 1 }
light_source { <3, 3, 1> color rgb <0.4, 0.4, 0.45> }
plane { <0, 1, 0>, -0.01
  texture { pigment { checker rgb <0.9, 0.9, 0.85> rgb <0.15, 0.35, 0.55> scale 0.2 }
            finish { ambient 0.12 diffuse 0.85 } }
}
#declare Density = function { pattern { density_file df3 "$tmp/fluid.df3" interpolate 1 } }
isosurface {
  function { $iso - Density(x, y, z) }
  contained_by { box { <0, 0, 0>, <1, 1, 1> } }
  threshold 0
  max_gradient $grad
  scale <$hx - ($lx), $hy - ($ly), $hz - ($lz)>
  translate <$lx, $ly, $lz>
  texture { pigment { rgbf <0.9, 0.97, 1.0, 0.95> }
            finish { ambient 0 diffuse 0.02 specular 0.9 roughness 0.003 reflection { 0 1 fresnel on } conserve_energy } }
  interior { ior 1.33 }
}
POV
pov_cmd=(povray +I"$tmp/fluid.pov" +O"$tmp/povray.png" +W"$width" +H"$height" -A -D +FN
         +WT"$threads" +L/usr/share/povray-3.7/include File_Gamma=sRGB)
our_cmd=("$raycast" render scenes/fluid.yaml -o "$tmp/raycast.png" --width "$width"
         --height "$height" --spp 1 --threads "$threads")
: >"$tmp/pov.times"
: >"$tmp/our.times"
for ((i = 1; i <= repeats; ++i)); do
  seconds "${pov_cmd[@]}" >>"$tmp/pov.times"
  seconds "${our_cmd[@]}" >>"$tmp/our.times"
done
read -r pov_wall pov_cpu < <(best <"$tmp/pov.times")
read -r our_wall our_cpu < <(best <"$tmp/our.times")
if [ -n "${KEEP:-}" ]; then
  mkdir -p "$KEEP"
  cp "$tmp/povray.png" "$KEEP/fluid-povray.png"
  cp "$tmp/raycast.png" "$KEEP/fluid-raycast.png"
  cp "$tmp/fluid.pov" "$KEEP/fluid.pov"
fi
echo "scene: fluid (scenes/fluid.yaml; grid $(grep '^dims' "$tmp/params" | cut -d' ' -f2-), max_gradient $grad), ${width}x${height}, 1 spp, $threads thread(s)"
echo "best of $repeats runs (load average at the end: $(cut -d' ' -f1 /proc/loadavg)):"
echo "povray:  wall ${pov_wall} s, cpu ${pov_cpu} s   ($(povray --version 2>&1 | grep -m1 "^POV-Ray"))"
echo "raycast: wall ${our_wall} s, cpu ${our_cpu} s"
awk -v pw="$pov_wall" -v pc="$pov_cpu" -v rw="$our_wall" -v rc="$our_cpu" 'BEGIN {
  printf "ratio povray / raycast:"
  if (rw > 0) printf " wall %.2f", pw / rw
  if (rc > 0) printf ", cpu %.2f", pc / rc
  printf "\n"
}'
