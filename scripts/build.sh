#!/usr/bin/env bash
# Configures and builds edgefit. Used by demo.sh and test.sh.
#   scripts/build.sh <build-dir> <build-type> [extra cmake args...] [-- targets...]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=$1
build_type=$2
shift 2
cmake_args=()
targets=()
while [[ $# -gt 0 ]]; do
  if [[ "$1" == "--" ]]; then shift; targets=("$@"); break; fi
  cmake_args+=("$1"); shift
done
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Paths relative to the checkout, and the build folder left out of the
  # hash: a fresh clone elsewhere (CI's) reuses the objects built here.
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
fi
generator=()
if command -v ninja >/dev/null && [[ ! -f "$build_dir/Makefile" ]]; then generator=(-G Ninja); fi
mkdir -p "$build_dir"
log="$build_dir/configure.log"
cmake -S . -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE="$build_type" "${launcher[@]}" \
  "${cmake_args[@]}" >"$log" 2>&1 || {
  cat "$log" >&2; echo "build: cmake configure failed (log above)" >&2; exit 1; }
target_args=()
if [[ ${#targets[@]} -gt 0 ]]; then target_args=(--target "${targets[@]}"); fi
cmake --build "$build_dir" -j"$(nproc)" "${target_args[@]}"
