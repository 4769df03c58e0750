#!/usr/bin/env bash
# The scene fuzzer (docs/reliability.md, "Fuzzing"): builds fuzz/ with clang, libFuzzer,
# AddressSanitizer and UBSan in build-fuzz/ (CMake preset "fuzz"), then fuzzes
# fuzzOneScene() for SECONDS (default 60) from the lessons' scenes and the saved corpus,
# with the scene-key dictionary fuzz/scene.dict. CI runs it for 60 s after the suites.
#   scripts/run-fuzz.sh [SECONDS] [JOBS]    e.g. scripts/run-fuzz.sh 3600 2 for a long run
# A crash, timeout or out-of-memory input is written to build-fuzz/artifacts/ and the
# script fails: copy the file into tests/fuzz_regressions/ (tst_fuzz_regressions then
# replays it in the normal build) and fix the bug. Needs `scripts/install-deps.sh --fuzz`.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
jobs=${2:-1}

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)"

fuzzer=build-fuzz/fuzz/rbw_fuzz_scene
corpus=build-fuzz/corpus          # grows run after run; delete it to start from the seeds
artifacts=build-fuzz/artifacts
mkdir -p "$corpus" "$artifacts"
# The seeds: every lesson scene, and every input that ever crashed (kept fixed since).
for f in lessons/*/*.json; do
  cp "$f" "$corpus/lesson-$(basename "$(dirname "$f")")-$(basename "$f")"
done
find tests/fuzz_regressions -maxdepth 1 -type f ! -name README.md -exec cp {} "$corpus"/ \;

export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# Stacks with file and line: clang 16's runtime does not find llvm-symbolizer by itself.
for s in /usr/lib/llvm-16/bin/llvm-symbolizer /usr/bin/llvm-symbolizer; do
  if [ -x "$s" ] && [ -z "${ASAN_SYMBOLIZER_PATH:-}" ]; then export ASAN_SYMBOLIZER_PATH=$s; fi
done

# -max_len: the largest lesson (fifty-boxes.json) is 15 kB. -timeout: most inputs take
# milliseconds, but 4 traced steps of fifty boxes piling into the walls (dt = 5) print
# 38 MB of JSON, 17 s under the sanitizers; a minute means a hang. -rss_limit_mb: that
# input peaks near 1.4 GB; 4 GiB means unbounded growth.
args=(-dict=fuzz/scene.dict -max_total_time="$seconds" -max_len=16384 -timeout=60 -rss_limit_mb=4096
      -artifact_prefix="$artifacts"/ -print_final_stats=1)
if [ "$jobs" -gt 1 ]; then
  args+=(-fork="$jobs")
fi
log=build-fuzz/fuzz.log
echo "run-fuzz: fuzzing for ${seconds} s (${jobs} job(s)); libFuzzer's output: $log"
status=0
"$fuzzer" "${args[@]}" "$corpus" >"$log" 2>&1 || status=$?
# libFuzzer's last status line and its final statistics
grep -E '^#[0-9]+' "$log" | tail -1 || true
grep -E '^stat::' "$log" || true
if [ "$status" -ne 0 ]; then
  tail -n 80 "$log"
  echo "run-fuzz: the fuzzer found a failing input (exit $status); its file is in $artifacts/:" >&2
  ls -l "$artifacts" >&2
  echo "run-fuzz: copy it to tests/fuzz_regressions/, fix the bug, and run tst_fuzz_regressions" >&2
  exit "$status"
fi
echo "run-fuzz: no crash in ${seconds} s; corpus: $(find "$corpus" -type f | wc -l) inputs"
