#!/usr/bin/env python3
"""The negative set: scans that do not hold the model as given, each fitted
with `edgefit fit`; every one must end not ok, with its reason. Beside each
robot's negatives, its positive control (the same scan, the right model)
must end ok and not off. Per robot of ../shared/robots, bare, at 4 mm, ideal sensor:

  positive          the robot's scan, its own URDF
  without_asset     the scan with the robot's points removed (--out_background
                    of the positive fit): the place without the robot
  another_robot     the scan fitted with the next robot's URDF
  other_effector    the robot carrying the X16005 gun, fitted with the
                    bundled weld gun attached instead
  half_window       the scan with every point beyond the vertical plane
                    through the base (world x) blanked: half the robot out
                    of every station's window; ok is right only when no
                    joint is off (0.5 deg, 5 mm) and the base within 5 mm
  millimetres       the scan fitted with the URDF written in millimetres
                    (every origin and mesh scale times 1000)
  base_only         a scan of the base link alone (clutter shaped like the
                    base), fitted with the whole robot

    python3 benchmarks/negative_set.py EDGEFIT OUT_DIR [robot ...]

Writes OUT_DIR/negative_set.json (one record per fit) and prints a Markdown
table. Needs ../shared/robots.
"""
import json
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.path.join(HERE, "..", "..", "shared", "robots")
ASSETS = os.path.join(HERE, "..", "assets")
GUN = os.path.join(SHARED, "weld_gun_x16005_botrail", "weld_gun_x16005_botrail.urdf") + "@tool0"
ROBOTS = ["kuka_kr150r3100_2", "abb_irb6700_200_260", "fanuc_m900ib700"]
SCAN = ["--spacing_mm=4", "--seed=3", "--random_pose"]
PRISMATIC = {}  # result path -> its independent prismatic joints (none on these robots)


def urdf(robot):
    return os.path.join(SHARED, robot, robot + ".urdf")


def run(args):
    return subprocess.run(args, capture_output=True, text=True)


def scan(edgefit, model, out, attach=None):
    args = [edgefit, "scan", "--urdf=" + model, "--out=" + out, "--truth=" + out + ".truth.json"] + SCAN
    if attach:
        args.append("--attach=" + attach)
    r = run(args)
    if r.returncode != 0:
        sys.exit("negative_set: scan failed: " + r.stderr)


def fit(edgefit, model, scan_path, out, extra=()):
    r = run([edgefit, "fit", "--urdf=" + model, "--scan=" + scan_path, "--out=" + out] + list(extra))
    if r.returncode != 0:
        return {"exit": r.returncode, "ok": False, "message": r.stderr.strip()}
    with open(out) as f:
        result = json.load(f)
    q = result["quality"]
    return {"exit": 0, "ok": q["ok"], "message": q["message"],
            "verdicts": {j: v["verdict"] for j, v in result["joint_status"].items()}}


def absolute_meshes(root, urdf_dir):
    for mesh in root.iter("mesh"):
        name = mesh.get("filename")
        if name and not name.startswith("/") and "://" not in name:
            mesh.set("filename", os.path.normpath(os.path.join(urdf_dir, name)))


def write_millimetres(model, out):
    """The URDF with every length in millimetres."""
    tree = ET.parse(model)
    root = tree.getroot()
    absolute_meshes(root, os.path.dirname(model))
    scale = lambda text: " ".join(repr(1000.0 * float(v)) for v in text.split())
    for origin in root.iter("origin"):
        if origin.get("xyz"):
            origin.set("xyz", scale(origin.get("xyz")))
    for mesh in root.iter("mesh"):
        mesh.set("scale", scale(mesh.get("scale", "1 1 1")))
    for box in root.iter("box"):
        box.set("size", scale(box.get("size")))
    for tag in ("cylinder", "sphere"):
        for e in root.iter(tag):
            for attribute in ("radius", "length"):
                if e.get(attribute):
                    e.set(attribute, scale(e.get(attribute)))
    for joint in root.iter("joint"):
        limit = joint.find("limit")
        if joint.get("type") == "prismatic" and limit is not None:
            for attribute in ("lower", "upper"):
                limit.set(attribute, scale(limit.get(attribute)))
    tree.write(out)


def write_base_only(model, out):
    """The URDF's root link alone."""
    tree = ET.parse(model)
    root = tree.getroot()
    absolute_meshes(root, os.path.dirname(model))
    children = {j.find("child").get("link") for j in root.iter("joint")}
    base = next(l.get("name") for l in root.findall("link") if l.get("name") not in children)
    for e in list(root):
        if e.tag != "link" or e.get("name") != base:
            root.remove(e)
    tree.write(out)


def blank_half_window(ptx_in, ptx_out, x_cut):
    """Every station's points beyond the vertical plane world x = x_cut set
    to missing (0 0 0): the asset half out of every station's window."""
    with open(ptx_in) as f, open(ptx_out, "w") as g:
        while True:
            cols_line = f.readline()
            if not cols_line.strip():
                break
            rows_line = f.readline()
            header = [f.readline() for _ in range(8)]
            g.write(cols_line + rows_line + "".join(header))
            m = [[float(v) for v in line.split()] for line in header[4:]]  # row vectors
            for _ in range(int(cols_line) * int(rows_line)):
                line = f.readline()
                x, y, z = (float(v) for v in line.split()[:3])
                missing = x == 0.0 and y == 0.0 and z == 0.0
                x_world = x * m[0][0] + y * m[1][0] + z * m[2][0] + m[3][0]
                g.write(line if missing or x_world <= x_cut else "0 0 0 0\n")


def off(result_path):
    """Whether an independent joint the fit did not call unobservable is off
    by more than 0.5 deg or 5 mm, or the base by more than 5 mm."""
    with open(result_path) as f:
        result = json.load(f)
    errors = result["errors"]
    for joint, verdict in result["joint_status"].items():
        if verdict["verdict"] == "unobservable":
            continue
        error = errors["joints"][joint]
        if error > (0.005 if joint in PRISMATIC.get(result_path, ()) else math.radians(0.5)):
            return True
    return errors["base_translation_m"] > 0.005


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    edgefit, out_dir = os.path.abspath(argv[1]), argv[2]
    robots = argv[3:] or ROBOTS
    os.makedirs(out_dir, exist_ok=True)
    records = []

    def record(robot, case, expected_ok, result):
        """expected_ok None: ok is right when the fit is not off."""
        if expected_ok is None:
            expected_ok = result["ok"] and not result.get("off")
        result.update({"robot": robot, "case": case, "expected_ok": expected_ok})
        records.append(result)
        print("%-20s %-14s %-6s %s" % (robot, case, "ok" if result["ok"] else "not ok",
                                        result["message"][:160]), flush=True)

    for robot in robots:
        d = os.path.join(out_dir, robot)
        os.makedirs(d, exist_ok=True)
        p = lambda name: os.path.join(d, name)
        scan(edgefit, urdf(robot), p("scan.ptx"))
        truth = "--truth=" + p("scan.ptx") + ".truth.json"
        result = fit(edgefit, urdf(robot), p("scan.ptx"), p("positive.json"),
                     ["--out_background=" + p("background.ptx"), truth])
        result["off"] = off(p("positive.json")) if result["exit"] == 0 else None
        record(robot, "positive", True, result)
        record(robot, "without_asset", False,
               fit(edgefit, urdf(robot), p("background.ptx"), p("without_asset.json")))
        other = ROBOTS[(ROBOTS.index(robot) + 1) % len(ROBOTS)]
        record(robot, "another_robot", False,
               fit(edgefit, urdf(other), p("scan.ptx"), p("another_robot.json")))
        scan(edgefit, urdf(robot), p("gun.ptx"), attach=GUN)
        record(robot, "other_effector", False,
               fit(edgefit, urdf(robot), p("gun.ptx"), p("other_effector.json"),
                   ["--attach=" + os.path.join(ASSETS, "robot", "weld_gun.urdf") + "@tool0"]))
        with open(p("scan.ptx") + ".truth.json") as f:
            x_base = json.load(f)["T_world_base"][0][3]
        blank_half_window(p("scan.ptx"), p("half.ptx"), x_base)
        result = fit(edgefit, urdf(robot), p("half.ptx"), p("half_window.json"), [truth])
        result["off"] = off(p("half_window.json")) if result["exit"] == 0 else None
        record(robot, "half_window", None, result)
        write_millimetres(urdf(robot), p("millimetres.urdf"))
        record(robot, "millimetres", False,
               fit(edgefit, p("millimetres.urdf"), p("scan.ptx"), p("millimetres.json")))
        write_base_only(urdf(robot), p("base_only.urdf"))
        scan(edgefit, p("base_only.urdf"), p("base_only.ptx"))
        record(robot, "base_only", False,
               fit(edgefit, urdf(robot), p("base_only.ptx"), p("base_only.json")))

    with open(os.path.join(out_dir, "negative_set.json"), "w") as f:
        json.dump(records, f, indent=1)
    print("\n| robot | case | right verdict | verdict | off | exit | message |\n"
          "|---|---|---|---|---|---|---|")
    for r in records:
        message = re.sub(r"\s+", " ", r["message"]).replace("|", "/")
        print("| %s | %s | %s | %s | %s | %d | %s |" % (
            r["robot"], r["case"], "ok" if r["expected_ok"] else "not ok",
            "**ok**" if r["ok"] and not r["expected_ok"] else ("ok" if r["ok"] else "not ok"),
            {None: "-", True: "yes", False: "no"}[r.get("off")], r["exit"], message[:200]))
    wrong = [r for r in records if r["ok"] != r["expected_ok"] or r["exit"] not in (0, 2)]
    print("\n%d fits, %d with the wrong verdict or a crash (exit other than 0 and 2)"
          % (len(records), len(wrong)))
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
