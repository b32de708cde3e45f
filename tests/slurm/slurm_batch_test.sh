#!/usr/bin/env bash
# edgefit batch and bench on a real Slurm: a one-node cluster of its own
# (scripts/slurm/local_cluster.sh: munged, slurmctld and slurmd, loopback
# only, a temporary folder), an array of 4 shards over a manifest of 8 small
# fits, one task cancelled midway, the rows --merge reports missing
# resubmitted: every row done, none lost, none done twice. Then a bench
# shared by a 2-task array, its shards joined into one report. Installs
# Debian's slurm packages when missing and it may; skips (77) only when the
# daemons cannot start here.
#   tests/slurm/slurm_batch_test.sh EDGEFIT_BINARY SOURCE_DIR
set -euo pipefail
edgefit=$1
source_dir=$2
cd "$source_dir"
export PATH=$PATH:/usr/sbin
export EDGEFIT=$edgefit

skip() {
  echo "SKIPPED: $1"
  exit 77
}
fail() {
  echo "FAILED: $1" >&2
  exit 1
}

if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null ||
  ! command -v sbatch >/dev/null || ! command -v munged >/dev/null; then
  if [[ $(id -u) == 0 ]] && command -v apt-get >/dev/null; then
    echo "installing Debian's slurmctld, slurmd, slurm-client and munge"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
      slurmctld slurmd slurm-client munge >/dev/null ||
      skip "cannot install slurmctld, slurmd, slurm-client and munge"
  else
    skip "Slurm is not installed and this user cannot install it (./scripts/install-deps.sh)"
  fi
fi

work=$(mktemp -d)
cluster=$work/cluster
teardown() {
  scripts/slurm/local_cluster.sh stop "$cluster" >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap teardown EXIT
if ! started=$(scripts/slurm/local_cluster.sh start "$cluster" 2>&1); then
  skip "the Slurm daemons cannot start here: $started; $(tail -n 3 "$cluster"/log/*.log 2>/dev/null | tr '\n' ' ')"
fi
echo "$started"
export SLURM_CONF=$cluster/slurm.conf

# Waits until job $1 has left the queue, at most $2 seconds.
wait_job() {
  local job=$1 limit=$2
  for _ in $(seq $((limit * 2))); do
    [[ -z $(squeue -h -j "$job" 2>/dev/null) ]] && return 0
    sleep 0.5
  done
  squeue
  fail "job $job still queued after $limit s"
}

# 8 small fits: the bundled balancer arm, one scan, 8 seeds.
model=$source_dir/assets/models/balancer_arm.urdf
mkdir -p "$work/fits/out" "$work/logs"
"$edgefit" scan --urdf="$model" --scanners=2 --spacing_mm=3 --accessories --quiet \
  --out="$work/fits/arm.ptx" --truth="$work/fits/truth.json" >/dev/null
manifest=$work/fits/jobs.csv
echo "name,urdf,scan,out,options" >"$manifest"
for k in $(seq 0 7); do
  echo "arm_$k,$model,arm.ptx,out/arm_$k.json,--truth=truth.json --seed=$((k + 1))" >>"$manifest"
done

# The array: 4 shards of 2 rows, one CPU each. Task 3 holds rows 3 and 7: it
# is cancelled once row 3 is written, while row 7 is being fitted.
job=$(sbatch --parsable --array=0-3 --cpus-per-task=1 --mem=1G \
  --output="$work/logs/batch_%a.log" scripts/slurm/batch.sbatch "$manifest")
echo "submitted array job $job"
for _ in $(seq 600); do
  [[ -f $work/fits/out/arm_3.json ]] && break
  sleep 0.2
done
[[ -f $work/fits/out/arm_3.json ]] || fail "row 3 was not fitted within 120 s"
scancel "${job}_3"
wait_job "$job" 300
[[ ! -f $work/fits/out/arm_7.json ]] || fail "row 7 ended before the cancel; nothing was cut"

# The table of --merge's jobs (its first), without what follows it.
jobs_table() { awk '/^## Jobs/ { on = 1; next } /^## / { on = 0 } on' <<<"$1"; }

# --merge: row 7 missing, every row once, the rows to resubmit.
set +e
merged=$("$edgefit" batch --manifest="$manifest" --merge)
code=$?
set -e
echo "$merged" | tail -n 4
[[ $code == 1 ]] || fail "--merge with a missing row should exit 1, not $code"
grep -q "merge: 8 rows: 7 done (0 not ok), 0 failed, 1 missing" <<<"$merged" ||
  fail "--merge summary: $merged"
for k in $(seq 0 7); do
  [[ $(jobs_table "$merged" | grep -c "^| $k | arm_$k |") == 1 ]] || fail "row $k not listed once"
done
jobs_table "$merged" | grep -q "^| 7 | arm_7 | missing |" || fail "row 7 not reported missing"
resubmit=$(grep "^on Slurm: sbatch" <<<"$merged" | sed 's/^on Slurm: //')
[[ $resubmit == "sbatch --array=0-0 scripts/slurm/batch.sbatch $manifest --rows=7" ]] ||
  fail "resubmission: '$resubmit'"
stamps=$(stat -c '%n %Y %s' "$work"/fits/out/arm_[0-6].json)

# Resubmitted as --merge says: the batch completes, nothing done twice.
read -r -a resubmit_args <<<"${resubmit#sbatch }"
job2=$(sbatch --parsable --cpus-per-task=1 --mem=1G --output="$work/logs/again_%a.log" \
  "${resubmit_args[@]}")
wait_job "$job2" 300
merged=$("$edgefit" batch --manifest="$manifest" --merge --out_csv="$work/merged.csv" \
  --out_report="$work/merged.html") || fail "--merge after the resubmission: $merged"
grep -q "merge: 8 rows: 8 done (0 not ok), 0 failed, 0 missing" <<<"$merged" ||
  fail "--merge summary after the resubmission: $merged"
[[ $(stat -c '%n %Y %s' "$work"/fits/out/arm_[0-6].json) == "$stamps" ]] ||
  fail "a row done before was fitted again"
for k in $(seq 0 7); do
  [[ $(jobs_table "$merged" | grep -c "^| $k | arm_$k | ok |") == 1 ]] || fail "row $k not ok once"
  [[ $(cat "$work"/logs/*.log | grep -c "] arm_$k: ok") == 1 ]] || fail "row $k fitted twice"
  grep -q '"threads": 1' "$work/fits/out/arm_$k.json" ||
    fail "row $k did not use SLURM_CPUS_PER_TASK threads"
done
# Every fit within 0.1 deg of the truth (the jobs' max error column).
max=$(jobs_table "$merged" | awk -F'|' '/^\| [0-9]+ \| arm_/ { if ($7 + 0 > m) m = $7 + 0 } END { print m + 0 }')
awk -v m="$max" 'BEGIN { exit !(m < 0.1) }' || fail "a joint off by $max deg"
[[ $(wc -l <"$work/merged.csv") == 41 ]] || fail "merged CSV: $(wc -l <"$work/merged.csv") lines"
grep -q "<td>arm_7</td><td>ok</td>" "$work/merged.html" || fail "the merge's report lacks row 7"
echo "batch: 8 of 8 rows done once, max joint error $max deg"

# The bench shared by 2 array tasks (two conveyor scans), joined again.
job3=$(sbatch --parsable --array=0-1 --cpus-per-task=1 --mem=1G \
  --output="$work/logs/bench_%a.log" scripts/slurm/bench.sbatch "$work/bench" \
  --assets=conveyor --only=load,transfer --scenes=without --weightings=edge --spacing_mm=10)
wait_job "$job3" 300
for k in 0 1; do
  [[ -s $work/bench/bench_$k.md && -s $work/bench/bench_$k.json ]] ||
    fail "bench task $k wrote no output: $(cat "$work/logs/bench_$k.log")"
done
joined=$("$edgefit" report --bench="$work/bench/bench_0.json,$work/bench/bench_1.json" \
  --out="$work/bench/bench.html")
for posture in load transfer; do
  [[ $(grep -c "^| conveyor | $posture | without | edge | - |" <<<"$joined") == 1 ]] ||
    fail "bench: $posture not run once: $joined"
done
echo "bench: 2 shards joined into $work/bench/bench.html"
echo "PASSED"
