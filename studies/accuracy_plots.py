#!/usr/bin/env python3
"""The PNG plots of `girtd accuracy` (matplotlib, Debian python3-matplotlib).

    python3 studies/accuracy_plots.py DIR      # reads DIR/accuracy.json

- time_error_vs_wall.png: each timing level's |modeled-time error| against
  rtl over its wall time, log-log, one point per input, the level means as
  large markers joined along the Pareto front (rtl sits on the floor line:
  exact by definition);
- for every configuration key the run varied (--vary):
  picture_error_<key>.png, the frame's error against the reference (max and
  mean |LSB|, and coverage differences) over the key's values, 1 LSB drawn
  as a line (several keys: picture_error_variant.png, one point per
  combination); and, where timed levels ran,
  picture_vs_time_<key>.png, picture error against modeled frame time.
Why matplotlib: it is a Debian package (offline, no bundling), writes PNG
headless (Agg), and does log-log axes and annotations in a few lines; the
sweep's plots reuse it.
"""

import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FLOOR = 1e-6  # where an exact (zero) error is drawn on a log axis


def level_colours(levels):
    cmap = plt.get_cmap("tab10")
    return {lv: cmap(i % 10) for i, lv in enumerate(levels)}


def plot_time_error(doc, out_dir):
    rows = [r for r in doc["rows"] if r.get("time_error") is not None and r.get("wall_s")]
    if not rows:
        return None
    levels = list(dict.fromkeys(r["level"] for r in rows))
    colour = level_colours(levels)
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for lv in levels:
        pts = [(r["wall_s"], max(abs(r["time_error"]), FLOOR)) for r in rows if r["level"] == lv]
        ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=18, alpha=0.6, color=colour[lv])
    summary = {s["level"]: s for s in doc.get("levels", [])}
    front = []
    for lv in levels:
        s = summary.get(lv)
        if not s:
            continue
        y = max(s["time_error_max_abs"], FLOOR)
        ax.scatter([s["wall_s_mean"]], [y], s=120, marker="D", color=colour[lv], edgecolor="black",
                   label="%s (mean wall, max error %.2g %%)" % (lv, 100 * s["time_error_max_abs"]))
        if s.get("on_front"):
            front.append((s["wall_s_mean"], y))
    front.sort()
    if len(front) > 1:
        ax.plot([p[0] for p in front], [p[1] for p in front], "k--", lw=1, label="Pareto front (wall vs max error)")
    ax.axhline(FLOOR, color="grey", lw=0.8)
    ax.text(0.01, FLOOR * 1.3, "exact (rtl)", color="grey", fontsize=8, transform=ax.get_yaxis_transform())
    ax.axhline(0.01, color="tab:green", lw=0.8, ls=":")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time per run (s)")
    ax.set_ylabel("|modeled time - rtl's| / rtl's")
    ax.set_title("Timing estimate: error against run time (one point per input)")
    ax.legend(fontsize=7, loc="upper right")
    ax.grid(True, which="both", alpha=0.3)
    path = os.path.join(out_dir, "time_error_vs_wall.png")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def varied_keys(rows):
    keys = []
    for r in rows:
        for k in r.get("settings", {}):
            if k not in keys:
                keys.append(k)
    return keys


def level_kinds(doc):
    """What each level is (accuracy.json's level_kinds), by its name: never read from the name."""
    return {k["level"]: k for k in doc["level_kinds"]}


def plot_picture(doc, out_dir, key):
    """key: the one varied key; None when several vary (x is then the variant's label)."""
    value = (lambda r: r["settings"][key]) if key else (lambda r: r["variant"])
    kinds = level_kinds(doc)
    rows = [r for r in doc["rows"] if r.get("image") and not kinds[r["level"]]["picture_yardstick"] and
            (key is None or key in r.get("settings", {}))]
    if not rows:
        return []
    made = []
    key = key or "variant"
    inputs = list(dict.fromkeys(r["input"] for r in rows))
    numeric = all(isinstance(value(r), (int, float)) and not isinstance(value(r), bool) for r in rows)
    values = sorted(set(value(r) for r in rows), key=lambda v: (str(type(v)), v))
    xpos = (lambda v: v) if numeric else (lambda v: values.index(v))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    cmap = plt.get_cmap("tab10")
    for i, inp in enumerate(inputs):
        # one level's picture per input (they all draw the same one)
        pts = {}
        for r in rows:
            if r["input"] == inp and value(r) not in pts:
                pts[value(r)] = r["image"]
        vs = [v for v in values if v in pts]
        name = os.path.basename(inp)
        ax1.plot([xpos(v) for v in vs], [max(pts[v]["max_abs"], 1e-3) for v in vs], "o-", color=cmap(i % 10),
                 label=name)
        ax1.plot([xpos(v) for v in vs], [max(pts[v]["mean_abs"], 1e-3) for v in vs], "s:", color=cmap(i % 10))
        ax2.plot([xpos(v) for v in vs], [max(pts[v]["coverage_diff"], 0.5) for v in vs], "o-", color=cmap(i % 10),
                 label=name)
    ax1.axhline(1, color="red", lw=1, ls="--", label="1 LSB")
    ax1.set_yscale("log")
    ax1.set_xlabel(key)
    ax1.set_ylabel("|frame - reference| (LSB of 255)")
    ax1.set_title("Colour error: max (solid), mean (dotted)")
    ax1.legend(fontsize=6, loc="center right")
    ax2.set_yscale("log")
    ax2.set_xlabel(key)
    ax2.set_ylabel("pixels covered differently")
    ax2.set_title("Coverage against the reference (0 drawn at 0.5)")
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
        if not numeric:
            ax.set_xticks(range(len(values)))
            ax.set_xticklabels([str(v) for v in values])
    fig.tight_layout()
    path = os.path.join(out_dir, "picture_error_%s.png" % key.replace(".", "_"))
    fig.savefig(path, dpi=110)
    plt.close(fig)
    made.append(path)

    timed = [r for r in rows if r.get("modeled_time_s")]
    if timed:
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for i, inp in enumerate(inputs):
            pts = sorted({(r["modeled_time_s"], r["image"]["mean_abs"], str(value(r)))
                          for r in timed if r["input"] == inp and not kinds[r["level"]]["estimator"]})
            if not pts:
                continue
            ax.plot([p[0] * 1e3 for p in pts], [p[1] for p in pts], "o", color=cmap(i % 10), label=os.path.basename(inp))
            for p in pts:
                ax.annotate(p[2], (p[0] * 1e3, p[1]), fontsize=6, xytext=(3, 3), textcoords="offset points")
        ax.set_xlabel("modeled frame time (ms)")
        ax.set_ylabel("mean |frame - reference| (LSB)")
        ax.set_title("Picture error against modeled time: %s" % key)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        path = os.path.join(out_dir, "picture_vs_time_%s.png" % key.replace(".", "_"))
        fig.savefig(path, dpi=110)
        plt.close(fig)
        made.append(path)
    return made


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out_dir = sys.argv[1]
    with open(os.path.join(out_dir, "accuracy.json")) as f:
        doc = json.load(f)
    made = [p for p in [plot_time_error(doc, out_dir)] if p]
    keys = varied_keys(doc["rows"])
    if len(keys) == 1:
        made += plot_picture(doc, out_dir, keys[0])
    elif keys:  # several keys vary together: one point per combination
        made += plot_picture(doc, out_dir, None)
    for p in made:
        print("  plot       %s" % p)


if __name__ == "__main__":
    main()
