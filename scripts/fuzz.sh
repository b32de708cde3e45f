#!/usr/bin/env bash
# Fuzzes the readers with libFuzzer (clang from Debian), each under ASan and
# UBSan: any input must parse or fail with a Status.
#   ./scripts/fuzz.sh READER SECONDS     READER: ptx, pcd, ply, e57, urdf or all
# Starts from the kept corpus (fuzz/corpus/READER, read only) and the inputs
# found before (build/fuzz/corpus/READER). A crash, leak or undefined
# behaviour stops the run with exit 1 and leaves the input in
# build/fuzz/crashes/READER/: make it a regression test (tests/io or
# tests/model) and add it to the kept corpus once fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
usage="usage: scripts/fuzz.sh ptx|pcd|ply|e57|urdf|all SECONDS"
reader=${1:?$usage}
seconds=${2:?$usage}
all=(ptx pcd ply e57 urdf)
if [[ $reader == all ]]; then readers=("${all[@]}"); else readers=("$reader"); fi
for r in "${readers[@]}"; do
  [[ " ${all[*]} " == *" $r "* ]] || { echo "fuzz: unknown reader '$r'; $usage" >&2; exit 2; }
done
[[ $seconds =~ ^[0-9]+$ && $seconds -gt 0 ]] || { echo "fuzz: SECONDS must be > 0; $usage" >&2; exit 2; }
./scripts/install-deps.sh
targets=()
for r in "${readers[@]}"; do targets+=("${r}_fuzzer"); done
CC=clang CXX=clang++ ./scripts/build.sh build/fuzz RelWithDebInfo -DEDGEFIT_BUILD_FUZZERS=ON \
  -DEDGEFIT_BUILD_TESTS=OFF -DEDGEFIT_BUILD_TOOLS=OFF -- "${targets[@]}"
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1
for r in "${readers[@]}"; do
  mkdir -p "build/fuzz/corpus/$r" "build/fuzz/crashes/$r"
  echo "fuzz: $r for $seconds s"
  if ! "build/fuzz/fuzz/${r}_fuzzer" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 \
      -timeout=10 -print_final_stats=1 -artifact_prefix="build/fuzz/crashes/$r/" \
      "build/fuzz/corpus/$r" "fuzz/corpus/$r" >"build/fuzz/$r.log" 2>&1; then
    tail -n 40 "build/fuzz/$r.log" >&2
    echo "fuzz: $r FAILED: input in build/fuzz/crashes/$r/, log build/fuzz/$r.log" >&2
    exit 1
  fi
  grep -E "^stat::number_of_executed_units|^Done" "build/fuzz/$r.log" | tr '\n' ' '
  echo
done
