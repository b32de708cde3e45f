#!/usr/bin/env bash
# Times two commands as whole processes, in turn (A B A B ...), with GNU time,
# and prints each one's median wall time and peak memory and the median of the
# A/B wall ratios pair by pair: a comparison that holds while the machine's
# speed drifts. The numbers in BENCHMARK.md marked "in turn" were taken so.
#   benchmarks/time_pair.sh RUNS 'COMMAND B' COMMAND A...
#   benchmarks/time_pair.sh RUNS '' COMMAND A...      (A alone)
set -euo pipefail
if [[ $# -lt 3 ]]; then
  echo "usage: $0 RUNS 'COMMAND B' COMMAND A..." >&2
  exit 2
fi
runs=$1
b=$2
shift 2
time_cmd=/usr/bin/time
[[ -x $time_cmd ]] || { echo "$0: needs GNU time ($time_cmd; Debian package 'time')" >&2; exit 2; }
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for ((i = 0; i < runs; ++i)); do
  $time_cmd -f "A %e %M" -a -o "$log" "$@" >/dev/null 2>&1 || echo "$0: A exited non-zero" >&2
  if [[ -n $b ]]; then
    # shellcheck disable=SC2086  # B is one string split as a shell splits words
    $time_cmd -f "B %e %M" -a -o "$log" $b >/dev/null 2>&1 || echo "$0: B exited non-zero" >&2
  fi
done
awk '
  function median(v, n,   i, j, t) {
    for (i = 2; i <= n; ++i) { t = v[i]; for (j = i - 1; j >= 1 && v[j] > t; --j) v[j + 1] = v[j]; v[j + 1] = t }
    return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
  }
  $1 == "A" { aw[++na] = $2; am[na] = $3 / 1024 }
  $1 == "B" { bw[++nb] = $2; bm[nb] = $3 / 1024; r[nb] = aw[nb] / $2 }
  END {
    printf "A: wall %.2f s, peak %.0f MiB (median of %d)\n", median(aw, na), median(am, na), na
    if (nb > 0) {
      printf "B: wall %.2f s, peak %.0f MiB (median of %d)\n", median(bw, nb), median(bm, nb), nb
      printf "A/B wall: %.3f (median of the pairs)\n", median(r, nb)
    }
  }' "$log"
