#!/usr/bin/env bash
# The test suite under AddressSanitizer and UBSan (docs/reliability.md, "Sanitizers and
# asserts"): builds the non-GUI targets in build-asan/ (CMake preset "asan": g++, Debug
# so assertions are on, -O2 -fsanitize=address,undefined) and runs their tests with
# `ctest --preset asan`, whose environment makes any sanitizer report fail the test
# (ASAN_OPTIONS=halt_on_error=1..., UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1).
# CI runs it after the main suite. Extra arguments go to ctest, e.g. -R tst_cli.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$(nproc)"
ctest --preset asan -j "$(nproc)" "$@"
