#!/usr/bin/env python3
"""Runs each back-end unit's bench and reports its coverage (tools/girtd coverage).

    coverage.py BUILD [--seeds N] [--ticks N] [--out DIR] [UNIT...]

A unit is a folder testbench/units/UNIT with UNIT_bench.cpp (built as
BUILD/bin/UNIT_bench) measuring the RTL under hw/UNIT. Each bench runs once
per seed with Verilator's coverage on; the runs are merged with
verilator_coverage (DIR/merged.dat, and DIR/annotated for reading) and each
unit gets one line:

    coverage: UNIT lines=NN.N% points=HIT/TOTAL

lines: of the source lines of hw/UNIT/*.sv that carry a line or branch
coverage point, those some run reached (a line reached in any of the unit's
builds counts); points: the unit's SystemVerilog cover points (its bind
file, testbench/units/UNIT/*_cover.sv), each hit at least once by one of
the unit's builds. A second line gives the
toggle coverage. Lines excluded are not counted, and each is listed with
its reason: lines between `verilator coverage_off` and `coverage_on` in a
unit's source (the reason in the comment on the line above), and lines
testbench/units/UNIT/coverage_exclusions.json names by a pattern (a file
beside the bench, so that the synthesised RTL carries no bench markings;
each entry states how many lines it matches, and a count that no longer
holds is an error).
Exit 1 when a bench disagrees with its model, a unit is under 95 % of its
lines or a cover point is never hit.
"""
import argparse
import collections
import json
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
UNITS = ROOT / "testbench" / "units"
LINE_BAR = 95.0


def units():
    return sorted(d.name for d in UNITS.iterdir() if (d / (d.name + "_bench.cpp")).exists())


def read_points(path):
    """coverage.dat: C '<\\001key\\002value...>' count, one line per point."""
    points = []
    for line in path.read_text(errors="replace").splitlines():
        if not line.startswith("C '"):
            continue
        close = line.rindex("'")
        keys = dict(kv.split("\002", 1) for kv in line[3:close].split("\001") if "\002" in kv)
        points.append((keys, int(line[close + 1:])))
    return points


def excluded_spans(source):
    """(first, last, why) for each coverage_off ... coverage_on span of a
    source; why is the comment on the line above coverage_off."""
    spans, start, why, previous = [], None, "", ""
    for n, text in enumerate(source.read_text().splitlines(), 1):
        if "verilator coverage_off" in text:
            start, why = n, previous.strip().lstrip("/ ") if previous.strip().startswith("//") else ""
        elif "verilator coverage_on" in text and start is not None:
            spans.append((start, n, why))
            start = None
        previous = text
    return spans


def listed_exclusions(unit, sources):
    """(source, first, last, why) for each line testbench/units/UNIT/coverage_exclusions.json
    excludes: {"file", "lines_matching" (a regular expression), "count" (how many
    lines it must match: a stale entry is an error), "why"}."""
    path = UNITS / unit / "coverage_exclusions.json"
    if not path.exists():
        return []
    out = []
    for e in json.loads(path.read_text()):
        if e["file"] not in sources:
            raise SystemExit("%s: %s is not a source of hw/%s" % (path.relative_to(ROOT), e["file"], unit))
        lines = [n for n, text in enumerate(sources[e["file"]].read_text().splitlines(), 1)
                 if re.search(e["lines_matching"], text)]
        if len(lines) != e["count"]:
            raise SystemExit("%s: %r matches %d line(s) of %s, not %d: update the exclusion"
                             % (path.relative_to(ROOT), e["lines_matching"], len(lines), e["file"], e["count"]))
        out += [(e["file"], n, n, e["why"]) for n in lines]
    return out


def report(unit, points):
    sources = {str(p.relative_to(ROOT)): p for p in sorted((ROOT / "hw" / unit).glob("*.sv"))}
    spans = {name: excluded_spans(path) for name, path in sources.items()}
    for name, first, last, why in listed_exclusions(unit, sources):
        spans[name].append((first, last, why))

    def source_of(keys):
        f = keys.get("f", "")
        return next((name for name in sources if f.endswith(name)), None)

    lines = collections.defaultdict(int)  # (source, line) -> hits over every build
    toggles = collections.defaultdict(int)
    cover = collections.defaultdict(int)  # (hierarchy, file, line, column) -> hits
    for keys, count in points:
        kind = keys.get("page", "").split("/")[0]
        if kind == "v_user":
            if "testbench/units/%s/" % unit not in keys.get("f", ""):
                continue  # another unit's cover points
            cover[(keys.get("h", ""), keys.get("f", ""), keys.get("l", ""), keys.get("n", ""))] += count
            continue
        name = source_of(keys)
        if name is None:
            continue
        line = int(keys.get("l", 0))
        if any(a <= line <= b for a, b, _ in spans[name]):
            continue
        if kind in ("v_line", "v_branch"):
            lines[(name, line)] += count
        elif kind == "v_toggle":
            toggles[(keys.get("h", ""), keys.get("o", ""), line)] += count
    reached = sum(1 for c in lines.values() if c)
    hit = sum(1 for c in cover.values() if c)
    pct = 100.0 * reached / len(lines) if lines else 0.0
    print("coverage: %s lines=%.1f%% points=%d/%d" % (unit, pct, hit, len(cover)))
    if toggles:
        print("  %s toggles=%.1f%% (%d of %d bits toggled both ways)"
              % (unit, 100.0 * sum(1 for c in toggles.values() if c) / len(toggles),
                 sum(1 for c in toggles.values() if c), len(toggles)))
    for name, s in spans.items():
        for a, b, why in s:
            print("  %s excluded: %s:%d-%d: %s" % (unit, name, a, b, why or "(no reason given)"))
    ok = pct >= LINE_BAR and hit == len(cover) and bool(lines)
    for (name, line), c in sorted(lines.items()):
        if not c:
            print("  %s never reached: %s:%d" % (unit, name, line))
    for (h, f, l, n), c in sorted(cover.items()):
        if not c:
            print("  %s cover point never hit: %s:%s (%s)" % (unit, pathlib.Path(f).name, l, h))
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("build")
    ap.add_argument("units", nargs="*", help="default: every folder of testbench/units with a bench")
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--ticks", type=int, default=200000)
    ap.add_argument("--out", default=None, help="default BUILD/coverage")
    a = ap.parse_args()
    build = pathlib.Path(a.build).resolve()
    out = pathlib.Path(a.out or build / "coverage").resolve()
    out.mkdir(parents=True, exist_ok=True)
    chosen = a.units or units()
    unknown = sorted(set(chosen) - set(units()))
    if unknown:
        print("coverage.py: no bench for %s (units: %s)" % (", ".join(unknown), ", ".join(units())), file=sys.stderr)
        return 2
    ok = True
    data = []
    for unit in chosen:
        bench = build / "bin" / (unit + "_bench")
        points = []
        for seed in range(1, a.seeds + 1):
            dat = out / ("%s_%d.dat" % (unit, seed))
            run = subprocess.run([str(bench), "--seed", str(seed), "--ticks", str(a.ticks), "--coverage", str(dat)],
                                 capture_output=True, text=True)
            sys.stdout.write(run.stdout)
            sys.stderr.write(run.stderr)
            if run.returncode != 0 or not dat.exists():
                print("coverage: %s bench failed (seed %d, exit %d)" % (unit, seed, run.returncode))
                ok = False
                continue
            points += read_points(dat)
            data.append(str(dat))
        ok = report(unit, points) and ok
    if data:
        subprocess.run(["verilator_coverage", "--write", str(out / "merged.dat")] + data, check=True,
                       capture_output=True)
        subprocess.run(["verilator_coverage", "--annotate", str(out / "annotated"), str(out / "merged.dat")],
                       check=True, capture_output=True)
        print("merged coverage: %s (annotated sources: %s)" % (out / "merged.dat", out / "annotated"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
