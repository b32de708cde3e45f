#!/usr/bin/python3
"""Error against an ablation setting, from `edgefit bench --out_json`.

    benchmarks/plot_ablation.py --json=bench.json --setting=w_high --out=w_high.png

One panel for revolute joints (mean error, degrees) and one for prismatic
joints (mean error, mm); a line per asset, accessories and weighting (and
per value of any other varied setting), the 95th percentile dashed. The
x axis is logarithmic when every value is positive, the y axis when the
errors span more than a factor of 10. Needs Debian's
python3-matplotlib (apt-get install python3-matplotlib).
"""

import argparse
import collections
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SETTINGS = ("noise_mm", "scanners", "w_high", "lambda", "loss", "sweep_step_deg", "search",
            "refine_chain")


def p95(values):
    ordered = sorted(values)
    k = max(1, math.ceil(0.95 * len(ordered)))
    return ordered[k - 1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", required=True, help="edgefit bench --out_json file")
    parser.add_argument("--setting", required=True, choices=SETTINGS)
    parser.add_argument("--out", required=True, help="PNG to write")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    with open(args.json, encoding="utf-8") as f:
        runs = json.load(f)
    if not runs:
        sys.exit(f"{args.json}: no runs")
    # The other settings that vary split the lines.
    others = [s for s in SETTINGS if s != args.setting and
              len({json.dumps(r["settings"][s]) for r in runs}) > 1 and s != "repeat"]
    # (line key) -> setting value -> revolute errors [deg], prismatic errors [mm]
    revolute = collections.defaultdict(lambda: collections.defaultdict(list))
    prismatic = collections.defaultdict(lambda: collections.defaultdict(list))
    for run in runs:
        key = " ".join([run["asset"], run["accessories"], run["weighting"]] +
                       [f"{s}={run['settings'][s]}" for s in others])
        value = run["settings"][args.setting]
        for joint, error in run["joint_errors"].items():
            if joint in run["prismatic_joints"]:
                prismatic[key][value].append(1e3 * error)
            else:
                revolute[key][value].append(math.degrees(error))

    values = sorted({run["settings"][args.setting] for run in runs})
    numeric = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for axis, data, unit in ((axes[0], revolute, "deg"), (axes[1], prismatic, "mm")):
        for key in sorted(data):
            xs = sorted(data[key])
            line = axis.plot(xs, [sum(data[key][x]) / len(data[key][x]) for x in xs], "o-",
                             label=key)
            axis.plot(xs, [p95(data[key][x]) for x in xs], "--", color=line[0].get_color(),
                      alpha=0.6)
        axis.set_xlabel(args.setting)
        axis.set_ylabel(f"{'revolute' if unit == 'deg' else 'prismatic'} joint error [{unit}]")
        if numeric and all(v > 0 for v in values):
            axis.set_xscale("log")
            axis.set_xticks(values)
            axis.set_xticklabels([f"{v:g}" for v in values])
        plotted = [v for key in data for x in data[key] for v in data[key][x]]
        if plotted and min(plotted) > 0 and max(plotted) > 10 * min(plotted):
            axis.set_yscale("log")  # assets whose errors differ by orders of magnitude
        axis.grid(True, alpha=0.3, which="both")
        if data:
            axis.legend(fontsize=7)
    fig.suptitle(args.title or f"edgefit bench: error against {args.setting} "
                 "(mean solid, 95th percentile dashed)")
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
