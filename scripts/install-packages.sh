#!/usr/bin/env bash
# Installs the Debian packages named in the given lists of scripts/packages/ (one package a line,
# `#` starts a comment); already installed ones are skipped, so it is quick to run again.
# Usage: scripts/install-packages.sh LIST ...   e.g. build, or build test test-python
set -euo pipefail
cd "$(dirname "$0")/.."
wanted=()
for list in "$@"; do
  file="scripts/packages/$list.txt"
  [ -f "$file" ] || { echo "install-packages: no list $file" >&2; exit 2; }
  while read -r line; do
    line=${line%%#*}
    for p in $line; do wanted+=("$p"); done
  done < "$file"
done
missing=()
for p in "${wanted[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
sudo_cmd=""
[ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
echo "install-packages: ${missing[*]}"
$sudo_cmd apt-get update -qq
# The build list is installed without Debian's recommended extras (documentation, GUI tools):
# the first command's time is mostly package downloads.
recommends=()
[ "$*" = build ] && recommends=(--no-install-recommends)
DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${recommends[@]}" "${missing[@]}" \
  >/dev/null
