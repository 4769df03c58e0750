#!/usr/bin/env bash
# The README's test command: installs what is missing (Debian 12), builds, and runs
# the whole QtTest suite through CTest. Widget tests start their own Xvfb.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --preset default -j "$(nproc)"
