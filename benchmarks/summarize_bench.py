#!/usr/bin/env python3
"""Summarizes `edgefit bench --out_json` files: one Markdown row per sensor and
weighting (and label), with the revolute mean / p95 / max, the prismatic mean
and max, the largest base error (against the truth, and against the truth
moved into the survey's frame: the stations' mean registration residual,
which no scan of the stations can see), the fits with a joint off by more than
0.2 deg or 3 mm, and how many of those the fit called ok.

    python3 benchmarks/summarize_bench.py A.json [B.json ...]
"""
import json
import math
import sys


def p95(values):
    values = sorted(values)
    return values[min(len(values) - 1, math.ceil(0.95 * len(values)) - 1)]


def main(paths):
    runs = []
    for path in paths:
        with open(path) as f:
            runs += json.load(f)
    groups = {}
    for run in runs:
        key = (run["asset"], run["settings"].get("sensor", "ideal"), run["weighting"], run["label"])
        groups.setdefault(key, []).append(run)
    print("| asset | sensor | weights | label | fits | revolute mean / p95 / max [deg] "
          "| prismatic mean / max [mm] | base max [mm, deg] | in the survey's frame "
          "| off | off but ok |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for key in sorted(groups):
        group = groups[key]
        revolute, prismatic, off, off_ok = [], [], 0, 0
        for run in group:
            bad = False
            for joint, error in run["joint_errors"].items():
                if joint in run["prismatic_joints"]:
                    prismatic.append(1e3 * error)
                    bad |= error > 0.003
                else:
                    revolute.append(math.degrees(error))
                    bad |= math.degrees(error) > 0.2
            off += bad
            off_ok += bad and run["ok"]
        rev = "%.4f / %.4f / %.3f" % (sum(revolute) / len(revolute), p95(revolute),
                                      max(revolute)) if revolute else "-"
        pri = "%.2f / %.2f" % (sum(prismatic) / len(prismatic), max(prismatic)) if prismatic else "-"
        base = "%.2f, %.3f" % (1e3 * max(r["base_translation_m"] for r in group),
                               max(math.degrees(r["base_rotation_rad"]) for r in group))
        survey = "-"
        if all("base_survey_translation_m" in r for r in group):
            survey = "%.2f, %.3f" % (1e3 * max(r["base_survey_translation_m"] for r in group),
                                     max(math.degrees(r["base_survey_rotation_rad"]) for r in group))
        print("| %s | %s | %s | %s | %d | %s | %s | %s | %s | %d | %d |" %
              (key[0], key[1], key[2], key[3], len(group), rev, pri, base, survey, off, off_ok))


if __name__ == "__main__":
    main(sys.argv[1:])
