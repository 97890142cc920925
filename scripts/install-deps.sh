#!/bin/sh
# Installs the Debian 12 packages scallop builds and tests with. Idempotent: does
# nothing when they are already there. Needs root (or sudo).
set -eu
PACKAGES="cmake ninja-build g++ ccache pkg-config \
  libembree-dev libtbb-dev libeigen3-dev libopenimageio-dev openimageio-tools \
  libcli11-dev nlohmann-json3-dev libfmt-dev libgtest-dev libbenchmark-dev \
  libzip-dev nettle-dev libpugixml-dev libfreetype-dev fonts-dejavu-core gwyddion xvfb xauth clang libclang-rt-14-dev \
  slurm-wlm munge valgrind"
# valgrind: the performance guard (scripts/perf-guard.sh) counts instructions with callgrind.
# The Python module (tools/python), its tests and examples/python.
PACKAGES="$PACKAGES pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib"

missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0

echo "scallop: installing Debian packages:$missing" >&2
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends $missing
