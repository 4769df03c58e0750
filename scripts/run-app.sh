#!/usr/bin/env bash
# The README's run command: installs what is missing (Debian 12), builds the two
# programs (the app and rbw, not the test suite: scripts/run-tests.sh builds that), and
# starts the app on lesson 1. Extra arguments go to the app, e.g. --lesson 01-one-step.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh rigid-workbook rbw
exec ./build/app/gui/shell/rigid-workbook "$@"
