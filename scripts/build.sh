#!/usr/bin/env bash
# Configures and builds Rigid Body Workbook in build/ (CMake preset "default").
#   scripts/build.sh                  everything: the programs, the test suite, the benchmarks
#   scripts/build.sh TARGET...        only those targets and what they need
#                                     (run-app.sh: rigid-workbook and rbw)
set -euo pipefail
cd "$(dirname "$0")/.."
targets=()
if [ $# -gt 0 ]; then targets=(--target "$@"); fi
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)" "${targets[@]}"
