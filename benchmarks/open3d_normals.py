#!/usr/bin/python3
"""Open3D's normal pass over a scan's points: the second reference of the fit's speed.

What a user of that library pays before any registration starts:
read_point_cloud, then estimate_normals(KDTreeSearchParamHybrid(radius, max_nn=30)).
Timed as a whole process beside `edgefit fit` (farm-bench --vs). The points come
from the same scan file, written once as PLY (valid points, world frame):

  build/release/benchmarks/kdtree_normals --scan=robot.ptx --out_ply=points.ply
  benchmarks/open3d_normals.py points.ply [--radius_mm=5]

Needs Debian's python3-open3d; exits 2 with one line when it is absent.
"""
import argparse
import sys
import time


def main():
  parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
  parser.add_argument("ply")
  parser.add_argument("--radius_mm", type=float, default=5.0)
  args = parser.parse_args()
  try:
    import open3d as o3d
  except ImportError:
    print("open3d_normals.py: needs python3-open3d (Debian)", file=sys.stderr)
    return 2
  start = time.monotonic()
  cloud = o3d.io.read_point_cloud(args.ply)
  if not cloud.has_points():
    print(f"open3d_normals.py: {args.ply}: no points read", file=sys.stderr)
    return 2
  read = time.monotonic()
  cloud.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=1e-3 * args.radius_mm, max_nn=30))
  done = time.monotonic()
  print(f"{len(cloud.points)} points; read {read - start:.2f} s, normals {done - read:.2f} s")
  return 0


if __name__ == "__main__":
  sys.exit(main())
