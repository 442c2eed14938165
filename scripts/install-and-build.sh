#!/usr/bin/env bash
# Installs the Debian packages nsm-bar needs (only the missing ones), then
# configures and builds it (Release) in build/. Sourced by run.sh and test.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(cmake g++ make ninja-build libdeal.ii-dev openmpi-bin libgtest-dev python3-matplotlib python3-vtk9 python3-numpy
          python3-scipy valgrind libfftw3-dev)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$package")
done
if ((${#missing[@]})); then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo > /dev/null || {
      echo "missing Debian packages: ${missing[*]}; run as root (or install sudo): apt-get install ${missing[*]}" >&2
      exit 1
    }
    sudo=sudo
  fi
  echo "installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi

# The generator of a new build directory: Ninja keeps both cores busy while
# the precompiled header builds and across the modules (93 % of the build's
# compile work ran two at a time, against 81 % with Make: 205 s against 231 s
# on 2 cores). A build directory keeps the generator it was made with.
generator() {
  if [ ! -f "$1/CMakeCache.txt" ] && command -v ninja > /dev/null; then echo "-GNinja"; fi
}

# The targets to build: NSM_BUILD_TARGETS (run.sh: the program; test.sh: the
# program and the unit tests), or all of them (the benchmark programs too).
# Progress is shown one line per step; the whole log is in build.log.
targets=()
for target in ${NSM_BUILD_TARGETS:-}; do targets+=(--target "$target"); done
echo "building ${NSM_BUILD_TARGETS:-everything} in build/ (a first build takes minutes; log in build.log)"
cmake -S . -B build $(generator build) -DCMAKE_BUILD_TYPE=Release -DNSM_FAST_START=ON > build.log 2>&1 \
  || { cat build.log; exit 1; }
set +o pipefail
cmake --build build -j "$(nproc)" "${targets[@]}" 2>&1 | tee -a build.log \
  | grep --line-buffered -E '^\[ *[0-9]+(%|/[0-9]+)\] (Building|Linking)' | sed -u 's/ CXX object.*\/source\// /'
status=${PIPESTATUS[0]}
set -o pipefail
[ "$status" -eq 0 ] || { tail -50 build.log; exit 1; }
