#!/usr/bin/env python3
"""Compares two `edgefit bench --out_json` files fit by fit: the runs of the
same asset, posture, label and weighting side by side (the largest revolute
error and its joint, the verdict, the base against the truth in the survey's
frame, the largest prismatic error), then the revolute mean / p95 / max and
the largest base error of each file over the fits both hold. Joints a fit
called unobservable are left out, as in the bench's tables.

    python3 benchmarks/compare_bench.py BEFORE.json AFTER.json
"""
import json
import math
import sys


def load(path):
    with open(path) as f:
        runs = json.load(f)
    return {(r["asset"], r["posture"], r["label"], r["weighting"]): r for r in runs}


def errors(run):
    prismatic = set(run.get("prismatic_joints", []))
    revolute = {j: math.degrees(e) for j, e in run["joint_errors"].items() if j not in prismatic}
    slides = {j: 1e3 * e for j, e in run["joint_errors"].items() if j in prismatic}
    return revolute, slides


def base(run):
    return 1e3 * run["base_survey_translation_m"], math.degrees(run["base_survey_rotation_rad"])


def stats(values):
    values = sorted(values)
    if not values:
        return "-"
    p95 = values[min(len(values) - 1, math.ceil(0.95 * len(values)) - 1)]
    return "%.4f / %.4f / %.4f" % (sum(values) / len(values), p95, values[-1])


def largest(named):
    if not named:
        return "-"
    joint = max(named, key=named.get)
    return "%.4f (%s)" % (named[joint], joint)


def main(before_path, after_path):
    before, after = load(before_path), load(after_path)
    keys = sorted(set(before) & set(after), key=lambda k: (k[0], len(k[1]), k[1], k[2], k[3]))
    if not keys:
        sys.exit("no fit is in both files")
    print("| asset | posture | label | weights | largest revolute error before -> after [deg] "
          "| ok | base before -> after [mm, deg] | largest prismatic error [mm] |")
    print("|---|---|---|---|---|---|---|---|")
    pooled = {"before": ([], [], []), "after": ([], [], [])}
    for key in keys:
        row = []
        for name, runs in (("before", before), ("after", after)):
            revolute, slides = errors(runs[key])
            pooled[name][0].extend(revolute.values())
            pooled[name][1].extend(slides.values())
            pooled[name][2].append(base(runs[key]))
            row.append((revolute, slides, runs[key]["ok"], base(runs[key])))
        (rb, sb, okb, bb), (ra, sa, oka, ba) = row
        prismatic = "-" if not sb else "%.3f -> %.3f" % (max(sb.values()), max(sa.values()))
        print("| %s | %s | %s | %s | %s -> %s | %s -> %s | %.3f, %.4f -> %.3f, %.4f | %s |" %
              (key[0], key[1], key[2] or "-", key[3], largest(rb), largest(ra),
               "ok" if okb else "NOT OK", "ok" if oka else "NOT OK", bb[0], bb[1], ba[0], ba[1],
               prismatic))
    print()
    for name in ("before", "after"):
        revolute, slides, bases = pooled[name]
        print("%s: %d fits, revolute mean / p95 / max %s deg; prismatic %s mm; base max %.3f mm, "
              "%.4f deg; not ok %d" %
              (name, len(keys), stats(revolute), stats(slides), max(b[0] for b in bases),
               max(b[1] for b in bases),
               sum(1 for k in keys if not (before if name == "before" else after)[k]["ok"])))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
