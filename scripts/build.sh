#!/usr/bin/env bash
# Configures and builds Rigid Body Workbook in build/ (CMake preset "default").
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)"
