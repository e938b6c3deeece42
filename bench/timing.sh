# Timing helpers shared by the benchmark scripts (sourced, not run). The caller has made a
# scratch directory "$tmp" (removed on exit) and set TIMEFORMAT='%R %U %S'.

seconds() {  # runs "$@" quietly, prints "wall cpu" seconds; stops the script if it fails
  local log="$tmp/log" status=0
  { time "$@" >"$log" 2>&1; } 2>"$tmp/time" || status=$?
  if [ "$status" -ne 0 ]; then
    echo "failed ($status): $*" >&2
    cat "$log" >&2
    exit 1
  fi
  tail -1 "$tmp/time" | awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }'
}

best() {  # best [FILE]: the smallest of each of two columns over the lines of FILE (or stdin)
  awk 'NR == 1 || $1 < a { a = $1 } NR == 1 || $2 < b { b = $2 } END { printf "%.3f %.3f\n", a, b }' "$@"
}
