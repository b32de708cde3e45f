#!/usr/bin/env bash
# Edge detection quality against the virtual scanner's true-edge flags:
# precision and recall of w_high points on the modelled links, and
# the share of accessory points that get w_high, for the bundled robot and
# conveyor and two robots of ../shared/robots, without and with accessories,
# noise 1 mm, 3 scanners, 1.7 mm spacing. Prints a Markdown table.
#   benchmarks/edge_quality.sh [build-dir] [extra edgefit edges flags, e.g. --tau_dot=0.9]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
shift || true
edgefit=$build/tools/edgefit
work=${EDGEFIT_BENCH_DIR:-$build/edge_quality}
mkdir -p "$work"
robots=../shared/robots

cases=(
  "robot|assets/robot/robot.urdf|--attach=assets/robot/weld_gun.urdf@tool0 --posture=assets/robot/postures.json:weld_low"
  "conveyor|assets/conveyor/conveyor.urdf|--posture=assets/conveyor/postures.json:transfer"
)
if [[ -d $robots ]]; then
  cases+=("kuka_kr150+gun|$robots/kuka_kr150r3100_2/kuka_kr150r3100_2.urdf|--attach=$robots/weld_gun_x16005_botrail/weld_gun_x16005_botrail.urdf@tool0 --random_pose")
  cases+=("abb_irb6700|$robots/abb_irb6700_200_260/abb_irb6700_200_260.urdf|--random_pose")
fi

echo "| model | accessories | points | true edges | precision | recall | accessory share | edges time [s] |"
echo "|---|---|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  IFS='|' read -r name urdf args <<<"$c"
  for acc in no yes; do
    flag=""; [[ $acc == yes ]] && flag="--accessories"
    tag="$work/${name//[^a-zA-Z0-9_]/_}_$acc"
    # shellcheck disable=SC2086
    "$edgefit" scan --urdf="$urdf" $args $flag --seed=11 --out="$tag.ptx" --truth="$tag.json" \
      --labels="$tag.labels" >/dev/null
    "$edgefit" edges --scan="$tag.ptx" --labels="$tag.labels" --out_weights="$tag.w" \
      --out_json="$tag.edges.json" "$@" >/dev/null
    python3 - "$tag.edges.json" "$name" "$acc" <<'PY'
import json, sys
e = json.load(open(sys.argv[1])); m = e["metrics"]
acc = f'{m["accessory_share"]:.3f}' if m["accessory_points"] else "-"
print(f'| {sys.argv[2]} | {sys.argv[3]} | {e["points"]} | {m["true_edges"]} | {m["precision"]:.3f} | '
      f'{m["recall"]:.3f} | {acc} | {e["timing_s"]["edges"]:.2f} |')
PY
    rm -f "$tag.ptx"
  done
done
