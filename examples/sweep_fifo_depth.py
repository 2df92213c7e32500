#!/usr/bin/env python3
"""Sweep one knob over the sample scenes and plot the rate against it.

    tools/girtd python examples/sweep_fifo_depth.py [--out DIR] [--knob fifo.dda_had_depth] [--values 1,2,4,8,16,32]

Each point renders every scene in traces/scenes on the approx back end with
the knob set, and reads the rate from the report: the sustained rate of an
animation (several frames), the modeled rate of a single frame. The plot and a
CSV go to DIR (default out/examples). Copy it and change the knob.
"""
import argparse
import csv
import glob
import os

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt

import girtd

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))


def knob_patch(dotted, value):
    """"fifo.dda_had_depth", 4 -> {"fifo": {"dda_had_depth": 4}}: a config dict."""
    patch = value
    for key in reversed(dotted.split(".")):
        patch = {key: patch}
    return patch


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", default=os.path.join(ROOT, "out", "examples"))
    p.add_argument("--knob", default="fifo.dda_had_depth")
    p.add_argument("--values", default="1,2,4,8,16,32")
    p.add_argument("--backend", default="approx")
    a = p.parse_args()
    values = [float(v) if "." in v else int(v) for v in a.values.split(",")]
    scenes = sorted(glob.glob(os.path.join(ROOT, "traces", "scenes", "*.json")))
    rates = {}
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        # The sustained rate when the report has one (several frames), else the modeled one.
        rates[name] = []
        warnings = []
        for v in values:
            r = girtd.render(scene, backend=a.backend, config=knob_patch(a.knob, v), print_warnings=False)
            rates[name].append(r["sustained_mpixels_per_s"] or r["modeled_mpixels_per_s"])
            warnings += [w for w in r["warnings"] if w not in warnings]
        for w in warnings:  # once per scene, not once per point
            print("warning:", w)
        print("%-16s %s" % (name, "  ".join("%6.2f" % x for x in rates[name])))

    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "sweep.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene"] + ["%s=%s" % (a.knob, v) for v in values])
        for name, row in rates.items():
            w.writerow([name] + row)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, row in rates.items():
        ax.plot(values, row, marker="o", label=name)
    ax.set_xscale("log", base=2)
    ax.set_xlabel(a.knob)
    ax.set_ylabel("Mpixel/s (%s back end)" % a.backend)
    ax.axhline(girtd.merged_config()["targets"]["mpixels_per_s"], color="grey", linestyle="--", label="target")
    ax.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5))
    ax.set_title("Rate against %s, every sample scene" % a.knob)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "sweep.png"), dpi=100)
    print("wrote", os.path.join(a.out, "sweep.png"), "and sweep.csv")


if __name__ == "__main__":
    main()
