#!/usr/bin/env bash
# Measures the app as docs/performance.md reports it: cold start to the first frame
# with typeset math, frames per second while playing, and the memory of the whole
# process tree. Runs under Xvfb (llvmpipe) with a fresh settings folder, so the
# default 1366x768 layout is measured.
#   scripts/measure-app.sh [LESSON [SECONDS]]   e.g. 04-many-boxes/fifty-boxes 10
set -euo pipefail
cd "$(dirname "$0")/.."
lesson=${1:-01-one-step}
seconds=${2:-5}
app=./build/app/gui/shell/rigid-workbook
[ -x "$app" ] || { echo "build the app first (scripts/build.sh)" >&2; exit 1; }
config=$(mktemp -d)
trap 'rm -rf "$config"' EXIT
export XDG_CONFIG_HOME=$config QTWEBENGINE_DISABLE_SANDBOX=1 RBW_LESSONS_DIR=$PWD/lessons
xvfb-run -a -s "-screen 0 1366x768x24" bash -c '
  start=$(date +%s%3N)
  out=$("$0" -platform xcb --lesson "$1" --measure "$2" 2>/dev/null | tail -1)
  echo "{\"launch_epoch_ms\": $start, \"lesson\": \"$1\", \"result\": $out}"
' "$app" "$lesson" "$seconds" | python3 -c '
import json, sys
d = json.load(sys.stdin); r = d["result"]
print(json.dumps({"lesson": d["lesson"], "startup_ms": r["ready_epoch_ms"] - d["launch_epoch_ms"],
                  "fps": round(r["fps"], 1), "steps_per_s": round(r["steps_per_s"], 1), "bodies": r["bodies"],
                  "view": "%dx%d" % (r["view_width"], r["view_height"]), "rss_mb": round(r["rss_mb"]), "gl": r["gl"]}))'
