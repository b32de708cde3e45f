#!/usr/bin/env bash
# Installs what is missing, builds (warnings are errors) and runs the whole
# suite with ctest, then each reader's libFuzzer harness for a few seconds
# on the kept corpus (scripts/fuzz.sh). With --sanitize: the suite under
# ASan + UBSan (the harnesses run under them already).
#   ./scripts/test.sh [--sanitize] [ctest args...]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
mode=release
if [[ "${1:-}" == "--sanitize" ]]; then mode=sanitize; shift; fi
if [[ $mode == release ]]; then
  build_dir=build/test
  ./scripts/build.sh "$build_dir" Release -DEDGEFIT_WERROR=ON -DEDGEFIT_BUILD_BENCHMARKS=ON
else
  build_dir=build/sanitize
  ./scripts/build.sh "$build_dir" RelWithDebInfo -DEDGEFIT_WERROR=ON -DEDGEFIT_SANITIZE=ON
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
fi
(cd "$build_dir" && ctest --output-on-failure -j"$(nproc)" "$@")
if [[ $mode == release ]]; then ./scripts/fuzz.sh all 5; fi
