#!/usr/bin/env python3
"""How closely a posture explains a real depth frame: the model rendered into the frame, pixel by pixel.

For each frame of a real-frame set (scripts/real_frames.py's layout) and each of two postures, the
recorded one (truth/NNN.json: its joints on its reference base, the one "reference_method" names) and the fitted one (NNN_MODE.json
that real_frames.py --out wrote), the URDF's collision meshes are posed, sampled densely and drawn
into the camera's pixels (nearest surface wins), then compared with the frame's depth where both
have one:
  med|d|    median |measured - model depth| [mm]
  <1cm      share of those pixels within 1 cm
  inner     median signed (measured - model) over pixels 4 px inside the model's outline and
            within 5 cm [mm]: positive when the frame reads farther than the model
Same renderer and measures for both postures, each over its own pixels. Needs numpy and Open3D
(Debian's python3-open3d; only its mesh reading is used). The meshes are sampled with a seeded
generator: the same figures every run.

  benchmarks/depth_agreement.py ../shared/data/real/lbr_med7_zed2i /tmp/out unknown
"""
import glob
import json
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np
import open3d as o3d

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from real_frames import reference_poses  # noqa: E402  (the set's layout has one reader)


def rpy_matrix(r, p, y):
  cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
  return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                   [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                   [-sp, cp * sr, cp * cr]])


def origin(element):
  T = np.eye(4)
  o = element.find("origin") if element is not None else None
  if o is not None:
    T[:3, 3] = [float(v) for v in o.get("xyz", "0 0 0").split()]
    T[:3, :3] = rpy_matrix(*[float(v) for v in o.get("rpy", "0 0 0").split()])
  return T


def axis_rotation(axis, q):
  a = np.asarray(axis) / np.linalg.norm(axis)
  K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
  return np.eye(3) + math.sin(q) * K + (1 - math.cos(q)) * K @ K


class Robot:
  def __init__(self, urdf, samples_per_m2=2.5e6):
    root = ET.parse(urdf).getroot()
    folder = os.path.dirname(urdf)
    self.parts = []  # (link, T_link_mesh, points in the mesh frame)
    for link in root.findall("link"):
      for kind in ("collision", "visual"):
        geometry = link.find(kind)
        mesh = geometry.find("geometry/mesh") if geometry is not None else None
        if mesh is None:
          continue
        path = os.path.join(folder, mesh.get("filename").replace("package://", ""))
        m = o3d.io.read_triangle_mesh(path)
        if len(m.triangles) == 0:
          continue
        scale = np.array([float(v) for v in mesh.get("scale", "1 1 1").split()])
        vertices = np.asarray(m.vertices) * scale
        triangles = vertices[np.asarray(m.triangles)]
        area = 0.5 * np.linalg.norm(np.cross(triangles[:, 1] - triangles[:, 0],
                                             triangles[:, 2] - triangles[:, 0]), axis=1)
        count = max(1000, int(area.sum() * samples_per_m2))
        # Area-weighted, seeded: the same points every run.
        rng = np.random.default_rng(1)
        pick = rng.choice(len(area), size=count, p=area / area.sum())
        a, b = rng.random(count), rng.random(count)
        flip = a + b > 1.0
        a[flip], b[flip] = 1.0 - a[flip], 1.0 - b[flip]
        t = triangles[pick]
        points = t[:, 0] + a[:, None] * (t[:, 1] - t[:, 0]) + b[:, None] * (t[:, 2] - t[:, 0])
        self.parts.append((link.get("name"), origin(geometry), points))
        break
    self.joints = [(j.get("name"), j.get("type"), j.find("parent").get("link"), j.find("child").get("link"),
                    origin(j), [float(v) for v in (j.find("axis").get("xyz") if j.find("axis") is not None
                                                   else "1 0 0").split()])
                   for j in root.findall("joint")]
    children = {j[3] for j in self.joints}
    self.root = next(l.get("name") for l in root.findall("link") if l.get("name") not in children)

  def link_poses(self, T_world_base, q):
    poses = {self.root: np.asarray(T_world_base)}
    pending = list(self.joints)
    while pending:
      rest = []
      for name, kind, parent, child, T_origin, axis in pending:
        if parent not in poses:
          rest.append((name, kind, parent, child, T_origin, axis))
          continue
        M = np.eye(4)
        if kind in ("revolute", "continuous"):
          M[:3, :3] = axis_rotation(axis, q.get(name, 0.0))
        elif kind == "prismatic":
          M[:3, 3] = np.asarray(axis) / np.linalg.norm(axis) * q.get(name, 0.0)
        poses[child] = poses[parent] @ T_origin @ M
      if len(rest) == len(pending):
        break
      pending = rest
    return poses

  def depth(self, T_camera_world, T_world_base, q, K, width, height):
    poses = self.link_poses(T_world_base, q)
    z = np.full(width * height, np.inf)
    for link, T_link_mesh, points in self.parts:
      M = T_camera_world @ poses[link] @ T_link_mesh
      p = points @ M[:3, :3].T + M[:3, 3]
      front = p[:, 2] > 1e-3
      p = p[front]
      u = np.floor(K[0] * p[:, 0] / p[:, 2] + K[2] + 0.5).astype(np.int64)
      v = np.floor(K[1] * p[:, 1] / p[:, 2] + K[3] + 0.5).astype(np.int64)
      inside = (u >= 0) & (u < width) & (v >= 0) & (v < height)
      np.minimum.at(z, v[inside] * width + u[inside], p[inside, 2])
    return z.reshape(height, width)


def read_pcd(path):
  """(z image, T_world_camera) of an organized binary PCD with float x y z."""
  data = open(path, "rb").read()
  end = data.index(b"DATA binary\n") + len(b"DATA binary\n")
  header = dict(line.split(" ", 1) for line in data[:end].decode().splitlines() if " " in line)
  if header["FIELDS"].split() != ["x", "y", "z"] or header["SIZE"].split() != ["4", "4", "4"]:
    sys.exit("%s: only organized PCDs of float x y z are read here" % path)
  width, height = int(header["WIDTH"]), int(header["HEIGHT"])
  xyz = np.frombuffer(data[end:end + width * height * 12], dtype=np.float32).reshape(height, width, 3)
  v = [float(t) for t in header.get("VIEWPOINT", "0 0 0 1 0 0 0").split()]
  w, x, y, zq = v[3:7]
  T = np.eye(4)
  T[:3, :3] = [[1 - 2 * (y * y + zq * zq), 2 * (x * y - zq * w), 2 * (x * zq + y * w)],
               [2 * (x * y + zq * w), 1 - 2 * (x * x + zq * zq), 2 * (y * zq - x * w)],
               [2 * (x * zq - y * w), 2 * (y * zq + x * w), 1 - 2 * (x * x + y * y)]]
  T[:3, 3] = v[:3]
  return xyz[:, :, 2].astype(float), T


def intrinsics(camera_info):
  """(fx, fy, cx, cy) of a ROS camera_info: its k / K list, block or flow style, or camera_matrix data."""
  text = open(camera_info).read()
  match = re.search(r"^\s*(?:[kK]|data)\s*:\s*(\[[^\]]*\]|(?:\s*\n\s*-\s*[-+0-9.eE]+)+)", text, re.M)
  if match is None:
    sys.exit("%s: no camera matrix (k, K or camera_matrix data)" % camera_info)
  k = [float(t) for t in re.findall(r"[-+]?[0-9.]+(?:[eE][-+]?[0-9]+)?", match.group(1))]
  return k[0], k[4], k[2], k[5]


def erode(mask, steps):
  for _ in range(steps):
    m = mask.copy()
    m[1:] &= mask[:-1]
    m[:-1] &= mask[1:]
    m[:, 1:] &= mask[:, :-1]
    m[:, :-1] &= mask[:, 1:]
    mask = m
  return mask


def agreement(z, model):
  both = np.isfinite(z) & np.isfinite(model)
  d = (z - model)[both]
  inner = erode(np.isfinite(model), 4) & np.isfinite(z) & (np.abs(z - model) < 0.05)
  return 1e3 * np.median(np.abs(d)), np.mean(np.abs(d) < 0.01), 1e3 * np.median((z - model)[inner])


def main():
  if len(sys.argv) != 4:
    sys.exit(__doc__)
  folder, results, mode = sys.argv[1:]
  urdfs = sorted(glob.glob(os.path.join(folder, "robot", "*.urdf")))
  frames = sorted(glob.glob(os.path.join(folder, "frames", "*.pcd")))
  if not urdfs:
    sys.exit("%s: no robot/*.urdf" % folder)
  if not frames:
    sys.exit("%s: no frames/*.pcd (depth PNG frames are not read here)" % folder)
  robot = Robot(urdfs[0])
  K = intrinsics(os.path.join(folder, "camera_info.yaml"))
  print("| frame | recorded: med\\|d\\| mm, <1cm, inner mm | fitted (%s): med\\|d\\| mm, <1cm, inner mm |" % mode)
  print("|---|---|---|")
  for frame in frames:
    name = os.path.basename(frame)[:-4]
    z, T_world_camera = read_pcd(frame)
    T_camera_world = np.linalg.inv(T_world_camera)
    truth = json.load(open(os.path.join(folder, "truth", name + ".json")))
    fit = json.load(open(os.path.join(results, "%s_%s.json" % (name, mode))))
    cells = []
    references = reference_poses(truth)
    reference = references[truth.get("reference_method", next(iter(references)))]
    for T_world_base, q in ((reference, truth["joints"]),
                            (fit["base"]["T_world_base"], fit["joints"])):
      model = robot.depth(T_camera_world, np.array(T_world_base), q, K, z.shape[1], z.shape[0])
      cells.append("%.1f, %.3f, %+.1f" % agreement(z, model))
    print("| %s | %s | %s |" % (name, cells[0], cells[1]))


if __name__ == "__main__":
  main()
