#!/usr/bin/env python3
"""How well the fits' standard deviations cover their errors: for each
`edgefit bench --out_json` file (runs that record `joint_std`), per asset,
the joints' z = |error| / std with the whole `joint_std` and with its
residuals' part alone (`joint_std_residuals`): the share within 1, 2 and 3
std, the median and the largest z. For a Gaussian error with the right
std: 68 / 95 / 99.7 %. Joints a fit called unobservable are left out.
Runs that record `base_std` add the base: its error in the survey's frame
by world axis against the std of that axis, rotation and translation (the
residuals' part of base_std is not recorded).

    python3 benchmarks/std_coverage.py R.json [R2.json ...]
"""
import json
import statistics
import sys


def rows(paths):
    by_asset = {}
    for path in paths:
        with open(path) as f:
            for run in json.load(f):
                if run.get("failed") or not run.get("joint_std"):
                    continue
                key = (run["asset"], run["settings"]["sensor"])
                prismatic = set(run.get("prismatic_joints", []))
                for joint, error in run["joint_errors"].items():
                    std = run["joint_std"].get(joint)
                    residual = run.get("joint_std_residuals", {}).get(joint)
                    if not std:
                        continue
                    kind = "prismatic" if joint in prismatic else "revolute"
                    by_asset.setdefault(key + (kind,), []).append(
                        (error / std, error / residual if residual else float("nan")))
                base_std = run.get("base_std")
                if not base_std:
                    continue
                for kind, errors, stds in (
                        ("base rotation", run["base_survey_rotation_world_rad"],
                         base_std["rotation_rad"]),
                        ("base translation", run["base_survey_translation_world_m"],
                         base_std["xyz_m"])):
                    for error, std in zip(errors, stds):
                        if std:
                            by_asset.setdefault(key + (kind,), []).append(
                                (abs(error) / std, float("nan")))
    return by_asset


def describe(z):
    z = sorted(z)
    share = lambda k: 100.0 * sum(1 for v in z if v <= k) / len(z)
    return "%3.0f / %3.0f / %3.0f %% | %.2f | %.1f" % (
        share(1), share(2), share(3), statistics.median(z), z[-1])


def main(paths):
    print("| asset | sensor | joints | n | within 1 / 2 / 3 std | median z | max z "
          "| residuals alone: within 1 / 2 / 3 | median z | max z |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for (asset, sensor, kind), pairs in sorted(rows(paths).items()):
        full = [p[0] for p in pairs]
        residual = [p[1] for p in pairs if p[1] == p[1]]
        print("| %s | %s | %s | %d | %s | %s |" % (
            asset, sensor, kind, len(pairs), describe(full),
            describe(residual) if residual else "- | - | -"))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
