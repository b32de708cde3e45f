#!/usr/bin/env python3
"""Makes a set of virtual depth-camera frames of any URDF robot, in the real-frame layout.

The real depth frames are few (../shared/data/real); this makes as many as wanted of any robot,
seen by a virtual depth camera (`edgefit scan --camera_info`: one ray per pixel, depth noise that
grows with depth^2 and is correlated over a stereo matcher's window, flying pixels at silhouettes)
so that scripts/real_frames.py fits and scores them exactly as it does real frames:

  set/frames/NNN.pcd       the organized frame, VIEWPOINT = the camera's pose (z up)
  set/truth/NNN.json       "joints" (the posture scanned), "T_world_base_reference" (the true base)
  set/robot -> the URDF's folder
  set/camera_info.yaml     the camera (--camera_info, or a 960 x 540 camera with a 84 deg field)

Each frame: a random posture above the floor (seeded), the camera at a random place on a ring
around the robot at --distance metres (the robot's height scales nothing: give the distance),
1.0-1.8 m high, looking at the robot.

  scripts/depth_sim_set.py --urdf=../shared/robots/kuka_kr150r3100_2/kuka_kr150r3100_2.urdf \\
      --out=/tmp/kr150_set --frames=4 --distance=3.5,4.5 --noise_mm=1.5
  scripts/real_frames.py /tmp/kr150_set --edgefit=build/release/tools/edgefit --turn_deg=30
"""
import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys

DEFAULT_CAMERA = """image_width: 960
image_height: 540
camera_name: virtual_depth
camera_matrix:
  rows: 3
  cols: 3
  data: [534.6, 0.0, 479.5, 0.0, 534.6, 269.5, 0.0, 0.0, 1.0]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [0.0, 0.0, 0.0, 0.0, 0.0]
"""


def main():
  parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
  parser.add_argument("--urdf", required=True)
  parser.add_argument("--out", required=True, help="the set's folder (created; must not exist)")
  parser.add_argument("--edgefit", default="build/release/tools/edgefit")
  parser.add_argument("--camera_info", default="", help="the camera (default: 960 x 540, fx 534.6)")
  parser.add_argument("--frames", type=int, default=4)
  parser.add_argument("--distance", default="2.0,3.0", help="min,max camera distance [m]")
  parser.add_argument("--noise_mm", type=float, default=2.5, help="depth noise at 1 m [mm]")
  parser.add_argument("--max_range_m", type=float, default=6.0)
  parser.add_argument("--clutter", type=int, default=4)
  parser.add_argument("--seed", type=int, default=1)
  args = parser.parse_args()

  if os.path.exists(args.out):
    sys.exit("%s: exists; give a new folder" % args.out)
  if not os.access(args.edgefit, os.X_OK):
    sys.exit("%s: no edgefit binary there (--edgefit=PATH)" % args.edgefit)
  lo, hi = (float(v) for v in args.distance.split(","))
  for sub in ("frames", "truth"):
    os.makedirs(os.path.join(args.out, sub))
  os.symlink(os.path.dirname(os.path.abspath(args.urdf)), os.path.join(args.out, "robot"))
  camera_info = os.path.join(args.out, "camera_info.yaml")
  if args.camera_info:
    shutil.copyfile(args.camera_info, camera_info)
  else:
    with open(camera_info, "w") as f:
      f.write(DEFAULT_CAMERA)

  rng = random.Random(args.seed)
  for i in range(args.frames):
    angle = rng.uniform(0, 2 * math.pi)
    distance = rng.uniform(lo, hi)
    at = (distance * math.cos(angle), distance * math.sin(angle), rng.uniform(1.0, 1.8))
    frame = os.path.join(args.out, "frames", "%03d.pcd" % i)
    scan_truth = os.path.join(args.out, "truth", "%03d_scan.json" % i)
    cmd = [args.edgefit, "scan", "--urdf=" + args.urdf, "--random_pose", "--seed=%d" % (args.seed * 1000 + i),
           "--camera_info=" + camera_info, "--scanner_at=%.4f,%.4f,%.4f" % at,
           "--noise_mm=%g" % args.noise_mm, "--max_range_m=%g" % args.max_range_m,
           "--clutter=%d" % args.clutter, "--out=" + frame, "--truth=" + scan_truth]
    run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if run.returncode != 0:
      sys.exit("frame %d: edgefit scan failed (exit %d):\n%s" % (i, run.returncode, run.stdout[-2000:]))
    with open(scan_truth) as f:
      truth = json.load(f)
    os.remove(scan_truth)
    with open(os.path.join(args.out, "truth", "%03d.json" % i), "w") as f:
      json.dump({"frame": i, "joints": truth["joints"], "T_world_base_reference": truth["T_world_base"],
                 "reference_method": "truth", "camera_at": at,
                 "source": "scripts/depth_sim_set.py " + " ".join(sys.argv[1:])}, f, indent=1)
    print("frame %03d: camera at (%.2f, %.2f, %.2f) m, %.1f m away" % (i, at[0], at[1], at[2], distance))


if __name__ == "__main__":
  main()
