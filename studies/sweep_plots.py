#!/usr/bin/env python3
"""The PNG plot of `girtd sweep` (matplotlib, as studies/accuracy_plots.py).

    python3 studies/sweep_plots.py DIR      # reads DIR/results.json

rate_vs_cost.png: every valid point's rate on its slowest input (sustained
where the inputs ran as several frames) against its cost (the chip estimate
of models/cost/hardware_cost.hpp), the Pareto front joined, the target as a
line, the cheapest point meeting it ringed.
"""

import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402




def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out_dir = sys.argv[1]
    with open(os.path.join(out_dir, "results.json")) as f:
        doc = json.load(f)
    points = [p for p in doc["points"] if p["valid"] and p["min_mpixels_per_s"] is not None]
    fig, ax = plt.subplots(figsize=(8, 5.5))
    ax.scatter([p["cost"] for p in points], [p["min_mpixels_per_s"] for p in points], s=16, alpha=0.5,
               color="tab:blue", label="points (%d valid)" % len(points))
    front = sorted((p for p in points if p["on_front"]), key=lambda p: p["cost"])
    if front:
        ax.plot([p["cost"] for p in front], [p["min_mpixels_per_s"] for p in front], "k.-", lw=1,
                label="Pareto front (%d)" % len(front))
    target = doc.get("target_mpixels_per_s", 20.0)  # the base configuration's targets.mpixels_per_s
    ax.axhline(target, color="red", ls="--", lw=1, label="target %g Mpixel/s" % target)
    meeting = sorted((p for p in points if p["meets_target"]), key=lambda p: p["cost"])
    if meeting:
        best = meeting[0]
        ax.scatter([best["cost"]], [best["min_mpixels_per_s"]], s=160, facecolors="none", edgecolors="red",
                   label="cheapest meeting it: %s" % best["point"])
    ax.set_xlabel("cost (chip estimate)")
    ax.set_ylabel("Mpixel/s on the slowest input" + (" (sustained)" if doc.get("repeat", 1) > 1 else ""))
    ax.set_title("girtd sweep %s: rate against cost" % os.path.basename(doc["spec"]))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(out_dir, "rate_vs_cost.png")
    fig.savefig(path, dpi=110)
    print("  plot       %s" % path)


if __name__ == "__main__":
    main()
