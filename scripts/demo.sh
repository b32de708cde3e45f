#!/usr/bin/env bash
# Installs what is missing, builds edgefit (Release) and runs the main job on
# the bundled data: the bundled spot-welding robot with its weld gun,
# non-modelled accessories and protective jackets is scanned from 3 scanners
# by the virtual scanner's realistic sensor (mixed pixels, incidence noise
# and dropouts, station residuals, as-built surfaces), its
# edges are detected and scored against the scanner's ground truth, and the
# robot is fitted to the scan (base pose and every joint), truth against fit,
# with an HTML report of the fit.
# Then the bundled conveyor (paper Sec. 6) the same way: scanned in its
# `transfer` posture with accessories, fitted with --kind=auto (conveyance).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh build/release Release -DEDGEFIT_BUILD_TESTS=OFF -- edgefit >/dev/null
edgefit=build/release/tools/edgefit
out=build/demo
mkdir -p "$out"

echo "== the bundled robot with its weld gun"
"$edgefit" info --urdf=assets/robot/robot.urdf --attach=assets/robot/weld_gun.urdf@tool0
echo
echo "== edgefit scan: posture weld_low, accessories, jackets, 3 scanners, 1.7 mm spacing, 1 mm noise,"
echo "   realistic sensor: mixed pixels, incidence noise and dropouts, station residuals, as-built surfaces"
"$edgefit" scan --urdf=assets/robot/robot.urdf --attach=assets/robot/weld_gun.urdf@tool0 \
  --posture=assets/robot/postures.json:weld_low --base=0.5,-0.2,15 --accessories --seed=7 \
  --sensor=realistic --jackets \
  --out="$out/robot.ptx" --truth="$out/robot_truth.json" --labels="$out/robot_labels.bin"
echo
echo "== ground truth ($out/robot_truth.json)"
python3 - "$out/robot_truth.json" <<'PY' 2>/dev/null || cat "$out/robot_truth.json"
import json, math, sys
t = json.load(open(sys.argv[1]))
for name, value in t["joints"].items():
    print(f"  {name:22s} {value:+.6f}" + (f"  ({math.degrees(value):+.3f} deg)" if "gun" not in name and "piston" not in name else ""))
c = t["counts"]
print(f"  points: {c['valid']} valid of {c['cells']} cells; link {c['link']}, accessory {c['accessory']}, "
      f"background {c['background']}, true-edge {c['true_edge']}")
if "sensor" in t:
    s = t["sensor"]
    print(f"  sensor {s['name']}: {s['counts']['mixed_pixel']} mixed pixels, {s['counts']['jacket']} jacket points "
          f"(jackets on {', '.join(s['jackets'])})")
PY
echo
echo "== edgefit info --scan: the scan read back, lattice estimated from the points"
"$edgefit" info --scan="$out/robot.ptx"
echo
echo "== edgefit edges: paper Sec. 4 on the scan lattice, scored against the true edges"
"$edgefit" edges --scan="$out/robot.ptx" --labels="$out/robot_labels.bin" \
  --out_weights="$out/robot_weights.bin" --out_json="$out/robot_edges.json" \
  --out_ply="$out/robot_edges.ply"
echo "(open $out/robot_edges.ply in CloudCompare or MeshLab: red = w_high)"
echo
echo "== edgefit fit: base (cross-section corners + RANSAC, weighted ICP), then every joint"
echo "   (Eq. 9 sweep + joint-constrained weighted ICP), the stations registered to the model,"
echo "   the whole chain refined without the jackets; truth against fit"
"$edgefit" fit --urdf=assets/robot/robot.urdf --attach=assets/robot/weld_gun.urdf@tool0 \
  --scan="$out/robot.ptx" --truth="$out/robot_truth.json" --out="$out/result.json" \
  --out_joint_states="$out/joint_states.yaml" --out_urdf="$out/robot_fitted.urdf" \
  --out_report="$out/robot_report.html"
echo "(result: $out/result.json; joint states: $out/joint_states.yaml; calibrated URDF: $out/robot_fitted.urdf;"
echo " open $out/robot_report.html in a browser: the scan against the fitted model, every joint's verdict)"
echo
echo "== edgefit world: the fitted robot as a world that planners load (cell.urdf and .srdf, joint states,"
echo "   what rides on it as extra collision meshes, the scan less the robot as voxels and an OctoMap)"
"$edgefit" world --result="$out/result.json" --name=robot --out_dir="$out/world"
printf '# joint_2 leans the arm forward from where it stands (0.45 rad)\njoint_2\n0.45\n0.50\n0.55\n0.60\n0.65\n0.70\n' \
  > "$out/trajectory.csv"
echo
echo "== edgefit clearance: that motion in the world (FCL); the gun meets the floor"
"$edgefit" clearance --world="$out/world" --trajectory="$out/trajectory.csv" --out_report="$out/clearance.html"
echo "(open $out/clearance.html: the world, the arm along the motion on a slider, the clearance plotted)"
echo
echo "== the bundled conveyor (paper Sec. 6): posture transfer, accessories, 3 scanners, 3 mm spacing"
"$edgefit" scan --urdf=assets/conveyor/conveyor.urdf --posture=assets/conveyor/postures.json:transfer \
  --base=0.3,-0.4,-25 --accessories --spacing_mm=3 --seed=7 \
  --out="$out/conveyor.ptx" --truth="$out/conveyor_truth.json"
echo
echo "== edgefit fit --kind=auto (conveyance: prismatic joints only): base from the arm tips"
echo "   (height map, convex tips, symmetry axis), then every prismatic joint; truth against fit"
"$edgefit" fit --urdf=assets/conveyor/conveyor.urdf --scan="$out/conveyor.ptx" \
  --truth="$out/conveyor_truth.json" --out="$out/conveyor_result.json"
echo "(result: $out/conveyor_result.json)"
