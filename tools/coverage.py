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
coverage point, those where every point was reached (an if's two branches
share a line) by some run of one of the unit's builds; points: the `cover
property` statements of the unit's bind file (testbench/units/UNIT/*_cover.sv),
each hit at least once by one of the unit's builds (a statement the data
lacks counts as never hit). A second line gives the
toggle coverage. Lines excluded are not counted, and each is listed with
its reason: lines between `verilator coverage_off` and `coverage_on` in a
unit's source (the reason in the comment on the line above), and lines
testbench/units/UNIT/coverage_exclusions.json names by a pattern (a file
beside the bench, so that the synthesised RTL carries no bench markings;
each entry states how many lines it matches, and a count that no longer
holds is an error). An excluded line that a run reaches fails the check:
it was excluded as unreachable (unless its entry says why it is reached
before reset, at power-up).
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
            spans.append((start, n, why, ""))
            start = None
        previous = text
    return spans


def listed_exclusions(unit, sources):
    """(source, first, last, why, before_reset) for each line
    testbench/units/UNIT/coverage_exclusions.json excludes: {"file",
    "lines_matching" (a regular expression), "count" (how many lines it must
    match: a stale entry is an error), "why", and optionally "before_reset":
    why the line is reached before reset, at power-up, where a unit's state
    is anything; those hits are then shown and allowed, and what holds after
    reset must be asserted by the unit's bind file}."""
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
        out += [(e["file"], n, n, e["why"], e.get("before_reset", "")) for n in lines]
    return out


def bind_statements(unit, keyword):
    """(bind file name, line) of every `KEYWORD property` (cover, assert) in testbench/units/UNIT/*_cover.sv."""
    out = set()
    for path in sorted((UNITS / unit).glob("*_cover.sv")):
        for n, text in enumerate(path.read_text().splitlines(), 1):
            if re.match(r"\s*%s property" % keyword, text):
                out.add((path.name, n))
    return out


def report(unit, points):
    sources = {str(p.relative_to(ROOT)): p for p in sorted((ROOT / "hw" / unit).glob("*.sv"))}
    spans = {name: excluded_spans(path) for name, path in sources.items()}
    for name, *span in listed_exclusions(unit, sources):
        spans[name].append(tuple(span))

    def source_of(keys):
        f = keys.get("f", "")
        return next((name for name in sources if f.endswith(name)), None)

    # Each coverage point's hits over every run and build (Verilator merges
    # some points across the builds of one model and keeps others apart by
    # hierarchy: key them without it, "hit by any build").
    line_points = collections.defaultdict(int)  # (source, line, kind, comment, column) -> hits
    excluded_hits = collections.defaultdict(int)
    toggles = collections.defaultdict(int)
    cover = {statement: 0 for statement in bind_statements(unit, "cover")}  # (bind file, line) -> hits
    for keys, count in points:
        kind = keys.get("page", "").split("/")[0]
        if kind == "v_user":
            f = keys.get("f", "")
            if "testbench/units/%s/" % unit in f:  # not another unit's, bound inside this one
                key = (pathlib.Path(f).name, int(keys.get("l", 0)))
                cover[key] = cover.get(key, 0) + count
            continue
        name = source_of(keys)
        if name is None:
            continue
        line = int(keys.get("l", 0))
        if kind in ("v_line", "v_branch"):
            if any(a <= line <= b for a, b, *_ in spans[name]):
                excluded_hits[(name, line)] += count
            else:
                line_points[(name, line, kind, keys.get("o", ""), keys.get("n", ""))] += count
        elif kind == "v_toggle":
            toggles[(keys.get("h", ""), keys.get("o", ""), line)] += count
    # A line is reached when every point on it was (an if's taken and untaken
    # branch carry the same line).
    lines = collections.defaultdict(list)
    for (name, line, *_), hits in line_points.items():
        lines[(name, line)].append(hits)
    reached = sum(1 for hits in lines.values() if all(hits))
    hit = sum(1 for c in cover.values() if c)
    pct = 100.0 * reached / len(lines) if lines else 0.0
    print("coverage: %s lines=%.1f%% points=%d/%d" % (unit, pct, hit, len(cover)))
    if toggles:
        print("  %s toggles=%.1f%% (%d of %d bits toggled both ways)"
              % (unit, 100.0 * sum(1 for c in toggles.values() if c) / len(toggles),
                 sum(1 for c in toggles.values() if c), len(toggles)))
    ok = pct >= LINE_BAR and bool(cover) and hit == len(cover) and bool(lines)
    for name, s in spans.items():
        for a, b, why, _ in s:
            print("  %s excluded: %s:%d-%d: %s" % (unit, name, a, b, why or "NO REASON GIVEN (an exclusion needs one)"))
            ok = ok and bool(why)
    for (name, line), c in sorted(excluded_hits.items()):
        if not c:
            continue
        before_reset = next((note for a, b, _, note in spans[name] if a <= line <= b and note), "")
        if before_reset and not bind_statements(unit, "assert"):  # what such an exclusion rests on
            print("  %s excluded but reached %d time(s): %s:%d (the entry says before reset, but no bind file of "
                  "the unit asserts what holds after)" % (unit, c, name, line))
            ok = False
        elif before_reset:
            print("  %s excluded, reached %d time(s) before reset: %s:%d: %s" % (unit, c, name, line, before_reset))
        else:  # what was excluded as unreachable was reached: the exclusion is wrong
            print("  %s excluded but reached %d time(s): %s:%d" % (unit, c, name, line))
            ok = False
    for (name, line), hits in sorted(lines.items()):
        if not all(hits):
            print("  %s never reached%s: %s:%d" % (unit, "" if not any(hits) else " (one of its branches)", name, line))
    for (f, l), c in sorted(cover.items()):
        if not c:
            print("  %s cover point never hit: %s:%d" % (unit, f, l))
    if not cover:
        print("  %s has no cover point (testbench/units/%s/*_cover.sv)" % (unit, unit))
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
