#!/usr/bin/env bash
# Speed-up of `mpirun -np RANKS raycast render` against one process, for one image cut into tiles
# and for a sequence of frames (docs/distributed.md, "Figures"). Three runs of each, interleaved
# so that a burst of load hits them alike, REPEATS times:
#   1 process, 1 thread (--threads 1)  the work of one core: the baseline
#   1 process, all threads             today's default on one machine
#   mpirun -np RANKS                   OpenMPI binds each rank to one core (np <= 2): 1 thread each
# Prints the best wall and CPU (user + system, every process of the job: mpirun included) times,
# the wall-clock speed-up over the baseline, and the CPU-time ratio to the baseline (the cost of
# distribution: MPI start-up, messages, each rank loading the scene), also without the CPU time
# of an empty job (mpirun around an 8x8 render: the fixed start-up cost). Checks that the outputs
# of the three runs are identical byte for byte. On a loaded machine the CPU times are the figure
# to read: the wall times then depend on the share of the cores the OS gives each process (ranks
# that mpirun binds to a core fare differently from unbound threads).
#   bench/distributed_speedup.sh [tiles|frames|both]
# Environment: RANKS (default 2), REPEATS (default 3), RAYCAST (default build/release/raycast),
# MPIRUN (default mpirun), SCENE (default scenes/demo.yaml), TILES_ARGS / FRAMES_ARGS (override the
# render options below).
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-both}
ranks=${RANKS:-2}
repeats=${REPEATS:-3}
raycast=$(realpath "${RAYCAST:-build/release/raycast}")
mpirun=${MPIRUN:-mpirun}
scene=${SCENE:-scenes/demo.yaml}
tiles_args=${TILES_ARGS:-"--width 1280 --height 960 --spp 8"}
frames_args=${FRAMES_ARGS:-"--frames 0-7 --width 640 --height 480 --spp 4"}
launcher=("$mpirun" -np "$ranks")
[ "$(id -u)" -eq 0 ] && launcher+=(--allow-run-as-root)
[ "$ranks" -gt "$(nproc)" ] && launcher+=(--oversubscribe)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
TIMEFORMAT='%R %U %S'  # wall, user, system seconds
source bench/timing.sh  # seconds, best


# The fixed cost of a job: mpirun, MPI_Init and MPI_Finalize on every rank, around an 8 x 8 render.
: >"$tmp/empty.t"
for ((i = 1; i <= repeats; ++i)); do
  seconds "${launcher[@]}" "$raycast" render -o "$tmp/empty.png" --width 8 --height 8 >>"$tmp/empty.t"
done
read -r we ce < <(best "$tmp/empty.t")
echo "empty job (mpirun -np $ranks, an 8x8 render): wall $we s, cpu $ce s (best of $repeats)"

run_case() {  # name, output file name (with {frame} for frames), render options...
  local name=$1 out=$2
  shift 2
  local -a args=("$@")
  : >"$tmp/one1.t"
  : >"$tmp/oneN.t"
  : >"$tmp/mpi.t"
  for ((i = 1; i <= repeats; ++i)); do
    seconds "$raycast" render "$scene" "${args[@]}" --threads 1 -o "$tmp/one1_$out" >>"$tmp/one1.t"
    seconds "$raycast" render "$scene" "${args[@]}" -o "$tmp/oneN_$out" >>"$tmp/oneN.t"
    seconds "${launcher[@]}" "$raycast" render "$scene" "${args[@]}" -o "$tmp/mpi_$out" >>"$tmp/mpi.t"
  done
  # The last run was mpirun's: how the work was shared (rank 0's summary and per-frame lines).
  local shares
  shares=$(grep -o 'tiles per rank [0-9 +]*' "$tmp/log" ||
    grep -o ', rank [0-9]*)' "$tmp/log" | sort | uniq -c | awk '{ printf "%srank %s: %d", (NR > 1 ? ", " : "frames per rank: "), $4, $1 }' | tr -d ')' || true)
  for f in "$tmp"/one1_*; do
    cmp -s "$f" "${f/one1_/oneN_}" && cmp -s "$f" "${f/one1_/mpi_}" ||
      { echo "$name: outputs differ: $f" >&2; exit 1; }
  done
  read -r w1 c1 < <(best "$tmp/one1.t")
  read -r wn cn < <(best "$tmp/oneN.t")
  read -r wm cm < <(best "$tmp/mpi.t")
  echo "$name: $scene ${args[*]} (best of $repeats, $(nproc) cores, load average $(cut -d' ' -f1 /proc/loadavg))"
  printf '  %-28s wall %8.3f s  cpu %8.3f s\n' "1 process, 1 thread" "$w1" "$c1" \
    "1 process, $(nproc) threads" "$wn" "$cn" "mpirun -np $ranks" "$wm" "$cm"
  awk -v w1="$w1" -v c1="$c1" -v wn="$wn" -v wm="$wm" -v cm="$cm" -v ce="$ce" -v r="$ranks" 'BEGIN {
    printf "  wall speed-up of %d ranks: %.2f over 1 thread, %.2f over 1 process with all threads\n",
      r, w1 / wm, wn / wm
    printf "  cpu ratio %d ranks / 1 thread: %.3f (%.3f without the empty job'"'"'s cpu)\n",
      r, cm / c1, (cm - ce) / c1 }'
  echo "  last mpirun: $shares"
  rm -f "$tmp"/one1_* "$tmp"/oneN_* "$tmp"/mpi_*
}

if [ "$what" = tiles ] || [ "$what" = both ]; then
  # shellcheck disable=SC2086
  run_case tiles image.png $tiles_args
fi
if [ "$what" = frames ] || [ "$what" = both ]; then
  # shellcheck disable=SC2086
  run_case frames 'frame_{frame}.png' $frames_args
fi
