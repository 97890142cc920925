#!/bin/sh
# Prints the MD5 of heights.gsf and the SHA-1 of heights.exr's pixels (iinfo --hash;
# the file itself carries its creation date) for the built-in default job and every
# examples/*.json, simulated by ./build/scallop into a temporary folder. A change that
# must not alter behaviour (a refactoring) keeps this output identical: run it before
# and after, and compare (`scripts/example-heights.sh > before.txt`, ..., `diff`).
# Pass --check to compare with scripts/example-heights.md5 instead.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run() {
  name=$1
  shift
  ./build/scallop simulate "$@" -o "$out/$name" --json >/dev/null 2>&1
  echo "$(md5sum <"$out/$name/heights.gsf" | cut -d' ' -f1)  $name/heights.gsf"
  echo "$(iinfo --hash "$out/$name/heights.exr" | sed -n 's/.*SHA-1: *//p')  $name/heights.exr"
}
{
  run default
  for job in examples/*.json; do
    run "$(basename "$job" .json)" "$job"
  done
} >"$out/md5.txt"
if [ "${1:-}" = "--check" ]; then
  diff -u scripts/example-heights.md5 "$out/md5.txt"
  echo "example heights: identical to scripts/example-heights.md5"
else
  cat "$out/md5.txt"
fi
