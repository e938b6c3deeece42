#!/bin/bash
# Instructions of the render loop, for comparing two builds where wall times are too noisy:
#   bench/render_instructions.sh BINARY SCENE [extra render options...]
# runs `BINARY render` under callgrind at 320x240, 1 spp, 1 thread (extra options such as
# `--antialias 1,0.3,3` come last and win), and prints the inclusive instruction count of
# raycast::render (raycast::render_recorded with --aov or --stats) and the first 8 hex digits of the image's md5 (equal md5: the same image).
# SCENE is a name in bench/scenes/ or scenes/ (whitted, csg, surfaces, textured, glass, mesh...).
# Run from the repository root (RAYCAST_DIR=DIR to run from another checkout). Needs valgrind.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,8p' "$0" >&2; exit 2; }
binary=$(realpath "$1")
scene=$2
shift 2
cd "${RAYCAST_DIR:-.}"
yaml=bench/scenes/$scene.yaml
[ -e "$yaml" ] || yaml=scenes/$scene.yaml
[ -e "$yaml" ] || { echo "no scene '$scene' in bench/scenes/ or scenes/" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
valgrind --tool=callgrind --callgrind-out-file="$tmp/out" "$binary" render "$yaml" \
  -o "$tmp/image.png" --threads 1 --spp 1 --width 320 --height 240 "$@" >/dev/null 2>&1
callgrind_annotate --inclusive=yes "$tmp/out" >"$tmp/annotated" 2>/dev/null
grep -m1 -E "raycast::render(_recorded)?\(" "$tmp/annotated" | awk '{print $1}'
md5sum <"$tmp/image.png" | cut -c1-8
