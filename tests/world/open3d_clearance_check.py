#!/usr/bin/env python3
"""edgefit clearance against an independent library.

A world of the bundled robot before a fence of points and a pillar, written by
`edgefit world`; `edgefit clearance --json` at several postures. Open3D
(Debian's python3-open3d; its RaycastingScene is Embree's, not FCL) loads the
exported files itself: cell.urdf's joints (posed here by their own origins and
axes, not edgefit's kinematics), the links' STL meshes and background.ply, and
measures the distance from dense samples of the moving links' surfaces to the
background mesh. The two agree within the sampling: Open3D's distance, from
samples 2 mm apart, is at most 3 mm longer than edgefit's between surfaces,
never shorter by more than 0.1 mm; where edgefit says colliding, Open3D finds a
sample on or inside the closed background.

  open3d_clearance_check.py EDGEFIT SOURCE_DIR      exit 77 (skip) without open3d
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

try:
    import numpy as np
    import open3d as o3d
except ImportError:
    print("python3-open3d not installed: skipped")
    sys.exit(77)

SAMPLE_SPACING = 0.002  # [m] between samples of the links' surfaces
LONGER = 0.003          # [m] Open3D's distance may exceed edgefit's by this
SHORTER = 1e-4          # [m] and fall short of it by this


def rpy_matrix(r, p, y):
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def axis_angle(axis, angle):
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def numbers(text, default):
    return [float(v) for v in text.split()] if text else default


def forward_kinematics(urdf_path, q):
    """T_world_link of every link of cell.urdf for joint values q (by name)."""
    root = ET.parse(urdf_path).getroot()
    joints = {}
    for j in root.findall("joint"):
        origin = j.find("origin")
        axis = j.find("axis")
        joints[j.find("child").get("link")] = dict(
            name=j.get("name"), type=j.get("type"), parent=j.find("parent").get("link"),
            xyz=numbers(origin.get("xyz") if origin is not None else "", [0, 0, 0]),
            rpy=numbers(origin.get("rpy") if origin is not None else "", [0, 0, 0]),
            axis=numbers(axis.get("xyz") if axis is not None else "", [1, 0, 0]))
    poses = {}

    def pose(link):
        if link in poses:
            return poses[link]
        if link not in joints:
            poses[link] = np.eye(4)
            return poses[link]
        j = joints[link]
        t = np.eye(4)
        t[:3, :3] = rpy_matrix(*j["rpy"])
        t[:3, 3] = j["xyz"]
        m = np.eye(4)
        value = q.get(j["name"], 0.0)
        if j["type"] in ("revolute", "continuous"):
            m[:3, :3] = axis_angle(j["axis"], value)
        elif j["type"] == "prismatic":
            m[:3, 3] = np.asarray(j["axis"]) * value
        poses[link] = pose(j["parent"]) @ t @ m
        return poses[link]

    for link in root.findall("link"):
        pose(link.get("name"))
    return poses, joints


def moving_links(joints, machine):
    """The machine's links with a moving joint between them and its base."""
    moving = []
    for link in joints:
        l, moves = link, False
        while l in joints and joints[l]["name"] != "world_to_" + machine:
            moves = moves or joints[l]["type"] != "fixed"
            l = joints[l]["parent"]
        if moves:
            moving.append(link)
    return moving


def joint_states(path):
    """name: position of a joint_states.yaml as edgefit writes it."""
    text = open(path).read()
    names = text.split("name: [", 1)[1].split("]", 1)[0]
    positions = text.split("position: [", 1)[1].split("]", 1)[0]
    return dict(zip([n.strip() for n in names.split(",")], [float(v) for v in positions.split(",")]))


def write_scene(path):
    """A fence (x = 1.9 m) and a pillar's faces (0.3 m square at y = -1.3 m), 5 mm apart."""
    points = []
    for i in range(int(2.4 / 0.005)):
        for k in range(int(2.4 / 0.005)):
            points.append((1.9, -1.2 + 0.005 * i, 0.005 * k))
    for k in range(int(2.4 / 0.005)):
        for i in range(60):
            s = -0.15 + 0.005 * i
            for x, y in ((s, -1.45), (s, -1.15), (-0.15, -1.3 + s), (0.15, -1.3 + s)):
                points.append((0.6 + x, y, 0.005 * k))
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                "property float z\nend_header\n" % len(points))
        f.write("".join("%.4f %.4f %.4f\n" % p for p in points))


def surface_samples(vertices, triangles):
    """Seeded uniform samples of a mesh's surface, SAMPLE_SPACING apart on average, and its vertices."""
    a, b, c = (vertices[triangles[:, i]] for i in range(3))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    count = max(1000, int(area.sum() / SAMPLE_SPACING ** 2))
    rng = np.random.default_rng(1)
    pick = rng.choice(len(triangles), size=count, p=area / area.sum())
    u, v = rng.random(count), rng.random(count)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    points = a[pick] + u[:, None] * (b[pick] - a[pick]) + v[:, None] * (c[pick] - a[pick])
    return np.vstack([points, vertices])


def open3d_distance(world, machine, q):
    """Least signed distance from the machine's moving links to background.ply."""
    poses, joints = forward_kinematics(os.path.join(world, "cell.urdf"), q)
    background = o3d.io.read_triangle_mesh(os.path.join(world, "background.ply"))
    scene = o3d.t.geometry.RaycastingScene()
    scene.add_triangles(o3d.t.geometry.TriangleMesh.from_legacy(background))
    best = math.inf
    for link in moving_links(joints, machine):
        path = os.path.join(world, "meshes", link + ".stl")
        if not os.path.exists(path):
            continue
        mesh = o3d.io.read_triangle_mesh(path)
        mesh.transform(poses[link])
        samples = surface_samples(np.asarray(mesh.vertices), np.asarray(mesh.triangles))
        d = scene.compute_signed_distance(o3d.core.Tensor(samples, dtype=o3d.core.Dtype.Float32))
        best = min(best, float(d.min().item()))
    return best


def main():
    edgefit, source = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp(prefix="edgefit_open3d_")
    result = os.path.join(work, "robot.json")
    with open(result, "w") as f:
        json.dump({"inputs": {"urdf": os.path.join(source, "assets/robot/robot.urdf"), "attach": [],
                              "scan": []},
                   "joints": {"joint_1": 0.0, "joint_2": 0.1, "joint_3": 0.0, "joint_4": 0.0,
                              "joint_5": 0.3, "joint_6": 0.0, "balancer_cylinder_joint": 0.0,
                              "balancer_piston_joint": 0.0},
                   "base": {"T_world_base": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}}, f)
    scene = os.path.join(work, "scene.ply")
    write_scene(scene)
    world = os.path.join(work, "world")
    subprocess.run([edgefit, "world", "--result=" + result, "--name=robot", "--scan=" + scene,
                    "--out_dir=" + world], check=True, stdout=subprocess.DEVNULL)
    scanned = joint_states(os.path.join(world, "joint_states.yaml"))
    # Postures that leave joint_2 (which drives the balancer's loop) as scanned.
    postures = [{}, {"joint_1": 0.4}, {"joint_1": -0.6}, {"joint_1": -1.0, "joint_3": -0.4},
                {"joint_4": 1.0, "joint_5": 1.2}, {"joint_1": 0.1, "joint_3": -0.9}]
    failures = 0
    print("%-34s %12s %12s %9s" % ("posture", "edgefit[mm]", "open3d[mm]", "colliding"))
    for posture in postures:
        text = ",".join("%s=%r" % kv for kv in posture.items())
        out = subprocess.run([edgefit, "clearance", "--world=" + world, "--machine=robot",
                              "--joints=" + text, "--json"], check=True, capture_output=True, text=True)
        waypoint = json.loads(out.stdout)["waypoints"][0]
        d_edgefit, colliding = waypoint["distance_to_background"], waypoint["colliding"]
        q = dict(scanned)
        q.update({"robot_" + k: v for k, v in posture.items()})
        d_open3d = open3d_distance(world, "robot", q)
        print("%-34s %12.2f %12.2f %9s" % (text or "as scanned", 1e3 * d_edgefit, 1e3 * d_open3d, colliding))
        if colliding and waypoint["pair"][1] == "background":
            ok = d_open3d <= LONGER
        elif colliding:
            ok = True  # with itself: not Open3D's measure here
        else:
            ok = d_edgefit - SHORTER <= d_open3d <= d_edgefit + LONGER
        if not ok:
            print("  disagree")
            failures += 1
    subprocess.run(["rm", "-rf", work])
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
