#!/usr/bin/env bash
# Installs the Debian 12 packages that building and testing Rigid Body Workbook needs,
# and only those that are missing. Safe to run again: with everything present it
# touches nothing and does not call apt-get at all.
#   scripts/install-deps.sh          what the build, the app and the test suite need
#   scripts/install-deps.sh --fuzz   also clang and libFuzzer, for the fuzz preset
#                                    (scripts/run-fuzz.sh; the asan preset needs only g++)
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev
  libboost-math-dev
  qt6-base-dev libqt6opengl6-dev   # libqt6opengl6-dev is only a recommendation of qt6-base-dev
  qt6-charts-dev
  qt6-webengine-dev
  libjs-katex fonts-katex
  libbenchmark-dev
  libbullet-dev                    # bench/bench_contact.cpp: the box rain in Bullet 3.24 beside ours
  libgl1-mesa-dri xvfb xauth       # widget and GL tests run under xvfb-run on llvmpipe
  dpkg-dev file desktop-file-utils appstream groff-base   # tst_install: dpkg-shlibdeps and file for cpack's .deb, the validators, man
)
if [ "${1:-}" = "--fuzz" ]; then
  # clang 16, not Debian's default 14: clang 14 cannot compile libstdc++ 12's
  # <source_location> (no __builtin_source_location), which the physics uses.
  # libclang-rt-16-dev (libFuzzer, the sanitizer runtimes) is only a recommendation.
  packages+=(clang-16 libclang-rt-16-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" apt-get update
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
