#!/usr/bin/env bash
# Runs every command of commands.txt with the program BINARY, each in an empty folder of its
# own, and writes one file per command into OUTDIR: the command, its exit status, stdout,
# stderr and every file it wrote. Two snapshots of two builds compare with `diff -r`: a
# refactoring that changes no behaviour leaves them byte-identical.
# Usage: tests/cli/snapshot/snapshot.sh BINARY OUTDIR
set -euo pipefail
binary=$(realpath "$1")
out=$2
here=$(cd "$(dirname "$0")" && pwd)
robot=$(realpath "$here/../../../examples/robot.toml")
mkdir -p "$out"
n=0
while IFS= read -r line; do
  [[ -z "$line" || "$line" == \#* ]] && continue
  n=$((n + 1))
  command=${line//\$ROBOT/$robot}
  work=$(mktemp -d)
  record="$out/$(printf '%03d' "$n").txt"
  status=0
  (cd "$work" && eval "timeout 120 \"$binary\" $command" >"$work/.stdout" 2>"$work/.stderr") ||
    status=$?
  {
    echo "command: $line"
    echo "status: $status"
    echo "--- stdout"
    cat "$work/.stdout"
    echo "--- stderr"
    cat "$work/.stderr"
    for f in "$work"/*; do
      [[ -e "$f" ]] || continue
      echo "--- file $(basename "$f")"
      cat "$f"
    done
  } >"$record"
  rm -rf "$work"
done <"$here/commands.txt"
echo "$n commands recorded in $out"
