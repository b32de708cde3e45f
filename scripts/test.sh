#!/usr/bin/env bash
# Installs what is missing, builds (warnings are errors) and runs the suite
# with ctest, then each reader's libFuzzer harness for a few seconds on the
# kept corpus (scripts/fuzz.sh). With --sanitize: the suite under ASan +
# UBSan without the end-to-end fits of full scenes (ctest label e2e; their
# small-scene twins run: tests/CMakeLists.txt). Prints each phase's time.
#   ./scripts/test.sh [--sanitize] [ctest args...]
set -euo pipefail
cd "$(dirname "$0")/.."
phase_start=$SECONDS
phase() {  # prints the time of the phase that just ended
  echo "test.sh: $1 done in $((SECONDS - phase_start)) s"
  phase_start=$SECONDS
}
./scripts/install-deps.sh
mode=release
if [[ "${1:-}" == "--sanitize" ]]; then mode=sanitize; shift; fi
ctest_args=()
# Unity builds (16 sources per translation unit) parse the Eigen, Ceres and
# GoogleTest headers once per batch: 265 s instead of 439 s for the release
# build from an empty compiler cache on 2 cores.
unity=(-DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16)
if [[ $mode == release ]]; then
  build_dir=build/test
  ./scripts/build.sh "$build_dir" Release -DEDGEFIT_WERROR=ON -DEDGEFIT_BUILD_BENCHMARKS=ON "${unity[@]}"
else
  build_dir=build/sanitize
  # -O1 -g1 (line tables: the sanitizers' stack traces keep file and line)
  # compiles in half the time of -O2 -g.
  ./scripts/build.sh "$build_dir" RelWithDebInfo -DEDGEFIT_WERROR=ON -DEDGEFIT_SANITIZE=ON \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "${unity[@]}"
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  ctest_args=(-LE e2e)
fi
phase "$mode build"
(cd "$build_dir" && ctest --output-on-failure -j"$(nproc)" "${ctest_args[@]}" "$@")
phase "$mode suite"
if [[ $mode == release ]]; then
  ./scripts/fuzz.sh all 5
  phase "fuzzers"
fi
