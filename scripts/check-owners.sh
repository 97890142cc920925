#!/bin/sh
# Fails when a value or a helper that has one owner is written again elsewhere, when a
# reference page outgrows its size, or when history leaks into the reference:
#   - pi (3.14159..., M_PI) and degree conversions: base/constants.h owns kPi,
#     kRadPerDeg, degToRad, radToDeg (tests use them too);
#   - the version: CMakeLists.txt's project(VERSION ...) owns it; code reads
#     kScallopVersion from base/version.h (generated);
#   - the mm -> m factor: base/constants.h owns kMetrePerMm;
#   - the 1 km bound: base/constants.h owns kMaxMagnitudeMm (no bare 1e6 in sweep/,
#     raycast/, analysis/ outside a named constant);
#   - numbers in messages: base/number_text.h owns formatNumber (no private %g or
#     stream-precision formatter in sweep/, raycast/, analysis/);
#   - the angle check: one requireAngle (sweep/profile_chain.h);
#   - the hash: base/fnv1a.h owns FNV-1a's constants;
#   - sizes: README.md <= 20 KB, docs/performance.md <= 15 KB;
#   - no stop, round or issue numbers in docs (but docs/performance-history.md) or in
#     code comments: history belongs in git.
# Run by .ci/run; prints each offending line.
set -eu
cd "$(dirname "$0")/.."
version=$(sed -n 's/^project(scallop VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
[ -n "$version" ] || { echo "check-owners: no project(scallop VERSION ...) in CMakeLists.txt" >&2; exit 1; }
escaped=$(printf '%s' "$version" | sed 's/\./\\./g')
status=0
code="sweep raycast analysis tools tests examples"
fail() {
  echo "check-owners: $1" >&2
  echo "$2" >&2
  status=1
}
# check WHAT PATTERN FOLDERS...: the pattern in C++ and Python sources.
check() {
  what=$1
  pattern=$2
  shift 2
  hits=$(grep -rnE --include='*.cpp' --include='*.h' --include='*.py' "$pattern" "$@" || true)
  [ -z "$hits" ] || fail "$what is spelt out outside its owner:" "$hits"
}
check "pi (use kPi, kRadPerDeg or degToRad from base/constants.h)" '3\.14159|M_PI\b' $code
check "a degree conversion (use kRadPerDeg, degToRad or radToDeg from base/constants.h)" \
  'kPi */ *180|180(\.0)? */ *kPi' $code
check "the version $version (use kScallopVersion from base/version.h)" \
  "[\"' ]$escaped([\"' ]|\$)" sweep raycast analysis tools
check "the mm -> m factor (use kMetrePerMm from base/constants.h)" 'kMetrePerMm *=' $code
check "FNV-1a's constants (use Fnv1a from base/fnv1a.h)" \
  '1099511628211|1469598103934665603|14695981039346656037' $code
check "a private number formatter (use formatNumber from base/number_text.h)" \
  'snprintf\(.*"%[-+ #0-9.]*g"|\.precision\(([0-9]|1[0-6])\)' sweep raycast analysis

# The 1 km bound: a bare 1e6 (outside string literals and constexpr declarations).
hits=$(find sweep raycast analysis -name '*.cpp' -o -name '*.h' | sort | xargs perl -ne '
  my $line = $_;
  s/"(?:\\.|[^"\\])*"//g;
  s{//.*}{};
  print "$ARGV:$.: $line" if /\b1e6\b/ && !/constexpr/;
  close ARGV if eof;')
[ -z "$hits" ] || fail "the 1 km bound is spelt 1e6 (use kMaxMagnitudeMm from base/constants.h):" "$hits"

# One requireAngle.
defs=$(grep -rnE --include='*.cpp' '^(static )?void requireAngle\(.*\{' $code base || true)
[ "$(printf '%s\n' "$defs" | grep -c .)" -le 1 ] ||
  fail "requireAngle is defined more than once (use sweep/profile_chain.h's):" "$defs"

# Sizes of the reference pages.
size_limit() {
  bytes=$(wc -c <"$1")
  [ "$bytes" -le "$2" ] || fail "$1 is $bytes bytes, more than its $2 (move detail to docs/)" ""
}
size_limit README.md 20480
size_limit docs/performance.md 15360

# History in the reference: stop, round or issue numbers in docs or code comments.
history='\b(stops?|rounds?|issues?) #?[0-9]+'
hits=$(find README.md docs -name '*.md' ! -name performance-history.md | sort |
  xargs grep -nEi "$history" || true)
[ -z "$hits" ] || fail "docs cite stops, rounds or issues (history belongs in git):" "$hits"
hits=$(grep -rnEi --include='*.cpp' --include='*.h' --include='*.py' --include='*.sh' \
  --include='*.cmake' --include='CMakeLists.txt' "(//|#).*$history" \
  $code base scripts CMakeLists.txt .ci || true)
[ -z "$hits" ] || fail "code comments cite stops, rounds or issues (history belongs in git):" "$hits"

[ "$status" -eq 0 ] && echo "check-owners: every owned value and helper has one owner; sizes and docs in bounds"
exit "$status"
