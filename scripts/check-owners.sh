#!/bin/sh
# Fails when a value that has one owner is spelt out somewhere else in the production
# code (sweep/, raycast/, analysis/, tools/):
#   - pi (3.14159..., M_PI): base/constants.h owns kPi and kRadPerDeg;
#   - the version: CMakeLists.txt's project(VERSION ...) owns it; code reads
#     kScallopVersion from base/version.h (generated);
#   - the mm -> m factor: base/constants.h owns kMetrePerMm.
# Run by .ci/run; prints each offending line.
set -eu
cd "$(dirname "$0")/.."
version=$(sed -n 's/^project(scallop VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
[ -n "$version" ] || { echo "check-owners: no project(scallop VERSION ...) in CMakeLists.txt" >&2; exit 1; }
escaped=$(printf '%s' "$version" | sed 's/\./\\./g')
status=0
check() {
  what=$1
  pattern=$2
  hits=$(grep -rnE --include='*.cpp' --include='*.h' --include='*.py' "$pattern" \
    sweep raycast analysis tools || true)
  if [ -n "$hits" ]; then
    echo "check-owners: $what is spelt out outside its owner:" >&2
    echo "$hits" >&2
    status=1
  fi
}
check "pi (use kPi or kRadPerDeg from base/constants.h)" '3\.14159|M_PI\b'
check "the version $version (use kScallopVersion from base/version.h)" "[\"' ]$escaped([\"' ]|\$)"
check "the mm -> m factor (use kMetrePerMm from base/constants.h)" 'kMetrePerMm *='
[ "$status" -eq 0 ] && echo "check-owners: pi, the version and the unit factors have one owner each"
exit "$status"
