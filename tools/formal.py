#!/usr/bin/env python3
"""Proves the RTL's formal properties and checks that each seeded bug breaks one.

Usage: formal.py BUILD_DIR [--out DIR] [--jobs N] [--unit UNIT]...
       formal.py BUILD_DIR --table results/formal/formal.json   (a recorded run's tables)
(tools/girtd formal runs it; hw/README.md "Formal properties").

hw/formal.json lists what is proven: each check names a unit (hw/UNIT/),
its top module, the package instance it is elaborated with (the generated
girtd_pkg.sv with some items overridden) and the method:
- "induction": yosys-smtbmc with z3, a bounded check of the first k ticks
  from reset and a k-induction step: together an unbounded proof;
- "pdr": ABC's property-directed reachability (IC3) on the bit-level model
  (AIGER): an unbounded proof that finds its own invariants.
The properties are the labelled immediate asserts of hw/UNIT/TOP_formal.svh,
which the unit includes under `ifdef FORMAL_TOP, or of hw/UNIT/TOP_formal.sv,
a wrapper module TOP_formal, where they read only TOP's ports; the comment
after each is its row in the table. A pdr check may name wires to "cut":
each is then driven by a free input instead of its logic, so what is proven
holds whatever those wires carry; a "multiclock" pdr check models every
clock its wrapper makes from the solver's global clock (yosys clk2fflogic:
each flip-flop takes its input of the step before its clock rises), for a
top with a gated clock. An instance may start "like" another and
override more items. Each seeded bug is a one-line change to a unit; it is
caught when some property of that unit then fails.

Prints a markdown table (property, unit, instance, method, result, time)
and the seeded bugs; --out DIR also writes formal.json and formal.md there.
Exit 1 when a property is not proven or a seeded bug is not caught; exit 2
on bad usage or a hw/formal.json that no longer matches the RTL.
"""
import argparse
import concurrent.futures
import json
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
SPEC = ROOT / "hw" / "formal.json"
TIMEOUT_S = 600  # per solver run: a run past it is reported as "timeout", not proven
LABEL = re.compile(r"^\s*(?:if\s*\(.*?\)\s*)?(\w+):\s*assert\s*\(", re.M)


class SpecError(Exception):
    pass


def formal_file(unit, top):
    """hw/UNIT/TOP_formal.svh (included into TOP), else hw/UNIT/TOP_formal.sv (a wrapper module, TOP_formal)."""
    included = ROOT / "hw" / unit / f"{top}_formal.svh"
    return included if included.exists() else ROOT / "hw" / unit / f"{top}_formal.sv"


def properties(path, defines=()):
    """[(label, description)] of PATH (formal_file): each labelled assert and the comment ending it,
    leaving out those inside an `ifdef NAME block whose NAME is not in DEFINES."""
    text = path.read_text()
    found = []
    for m in LABEL.finditer(text):
        opened = re.findall(r"^`(ifdef (\w+)|endif)", text[:m.start()], re.M)
        inside = []
        for directive, name in opened:
            if directive.startswith("ifdef"):
                inside.append(name)
            elif inside:
                inside.pop()
        if any(name not in defines for name in inside):
            continue
        end = text.index(");", m.end())
        line_end = text.find("\n", end)
        comment = text[end:line_end].partition("//")[2].strip()
        if not comment:
            raise SpecError(f"{path.relative_to(ROOT)}: property {m.group(1)} has no comment to describe it")
        found.append((m.group(1), comment))
    if not found:
        raise SpecError(f"{path.relative_to(ROOT)}: no labelled assert")
    return found


def package(generated, overrides, name):
    """The generated package with OVERRIDES applied, checked for the relations the generator keeps."""
    text = generated
    for item, value in overrides.items():
        text, n = re.subn(rf"(localparam int {item} = )[^;]+;", rf"\g<1>{value};", text)
        if n != 1:
            raise SpecError(f"hw/formal.json: instance {name}: the package has no item {item}")
    v = {k: int(x) for k, x in re.findall(r"localparam int (\w+) = (-?\d+);", text)}
    try:
        slot_w = max(1, (v["CACHE_PAGES"] - 1).bit_length())
        relations = [
            ("PAGE_X_BITS + PAGE_Y_BITS <= SCREEN_BITS", v["PAGE_X_BITS"] <= v["SCREEN_BITS"] and
             v["PAGE_Y_BITS"] <= v["SCREEN_BITS"]),
            ("PAGE_PIXELS == 2^(PAGE_X_BITS + PAGE_Y_BITS)", v["PAGE_PIXELS"] == 1 << (v["PAGE_X_BITS"] + v["PAGE_Y_BITS"])),
            ("PAGE_INDEX_W == PAGE_X_BITS + PAGE_Y_BITS", v["PAGE_INDEX_W"] == v["PAGE_X_BITS"] + v["PAGE_Y_BITS"]),
            ("PAGE_NUMBER_W == 2 SCREEN_BITS - PAGE_INDEX_W", v["PAGE_NUMBER_W"] == 2 * v["SCREEN_BITS"] - v["PAGE_INDEX_W"]),
            ("CELL_W == 3 COLOR_OUT + Z_OUT", v["CELL_W"] == 3 * v["COLOR_OUT"] + v["Z_OUT"]),
            ("VRAM_W == 6 COLOR_OUT + Z_OUT", v["VRAM_W"] == 6 * v["COLOR_OUT"] + v["Z_OUT"]),
            ("VRAM fields tile the word", v["VRAM_Z_LSB"] == 0 and v["VRAM_Z_W"] == v["Z_OUT"] and
             v["VRAM_RGB1_LSB"] == v["Z_OUT"] and v["VRAM_RGB1_W"] == 3 * v["COLOR_OUT"] and
             v["VRAM_RGB0_LSB"] == v["Z_OUT"] + 3 * v["COLOR_OUT"] and v["VRAM_RGB0_W"] == 3 * v["COLOR_OUT"]),
            ("Z_CLEAR < 2^Z_OUT", 0 <= v["Z_CLEAR"] < 1 << v["Z_OUT"]),
            ("CACHE_SLOT_W == max(1, clog2(CACHE_PAGES))", v["CACHE_PAGES"] >= 1 and v["CACHE_SLOT_W"] == slot_w),
            ("TIME_W <= LONG_TIME_W", v["TIME_W"] <= v["LONG_TIME_W"]),
            ("the FIFO's X and Y hold a screen coordinate", v["FIFO_X_W"] >= v["SCREEN_BITS"] and
             v["FIFO_Y_W"] >= v["SCREEN_BITS"]),
        ]
    except KeyError as e:
        raise SpecError(f"hw/formal.json: instance {name}: the package has no item {e.args[0]}")
    for what, holds in relations:
        if not holds:
            raise SpecError(f"hw/formal.json: instance {name}: {what} does not hold")
    return text


def yosys_read(job):
    top, src_dir, prep = job["top"], job["src_dir"], job["proven_top"]
    chparam = " ".join(f"-set {k} {v}" for k, v in job["parameters"].items())
    also = " ".join(str(ROOT / f) for f in job["also"])
    wrapper = f" {src_dir}/{prep}.sv" if prep != top else ""
    defines = " ".join(f"-D{d}" for d in [f"FORMAL_{top.upper()}"] + job["defines"])
    return (f"read_verilog -sv -formal -DSYNTHESIS {defines} -I{src_dir} -I{job['generated']} {job['pkg_file']} {also} "
            f"{src_dir}/{top}.sv{wrapper}\n"
            + (f"chparam {chparam} {prep}\n" if chparam else "")
            + f"prep -top {prep}\n")


def run(argv, cwd, log):
    """ARGV's completed process (its output kept in cwd/LOG), or None past TIMEOUT_S (its solver killed too)."""
    with subprocess.Popen(argv, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          start_new_session=True) as p:
        try:
            out, _ = p.communicate(timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.communicate()
            return None
    (cwd / log).write_text(out)
    return subprocess.CompletedProcess(argv, p.returncode, out, "")


def prove_induction(job, work):
    """Every property at once: BMC of the first ticks from reset (at least k), then the k-induction step."""
    script = yosys_read(job)
    script += "tee -q -o asserts.txt select -list t:$assert\n"
    # Memories as SMT arrays where yosys 0.23 can (one-dimensional: the FIFO's), else as bits, unrolled for z3.
    script += ("" if job["smt_arrays"] else "memory_map\nopt\n") + "async2sync\ndffunmap\nwrite_smt2 -wires model.smt2\n"
    (work / "model.ys").write_text(script)
    p = run(["yosys", "-q", "model.ys"], work, "yosys.log")
    if p is None or p.returncode:
        return {"error": "yosys failed: see " + str(work / "yosys.log")}
    # Every property the table will call proven is in the model, and nothing else is.
    in_model = {line.split("/")[-1] for line in (work / "asserts.txt").read_text().split()}
    if in_model != {label for label, _ in job["labels"]}:
        return {"error": "the model's asserts %s are not the properties %s" % (
            sorted(in_model), sorted(label for label, _ in job["labels"]))}
    unroll = [] if job["smt_arrays"] else ["--unroll"]
    steps = [("base", [], job["bmc"])] + ([("induction", ["-i"], job["k"])] if job["k"] else [])
    for step, extra, depth in steps:
        p = run(["yosys-smtbmc", "-s", "z3", *unroll, *extra, "-t", str(depth), "model.smt2"], work, f"{step}.log")
        if p is None:
            return {"timeout": step}
        failed = re.search(r"Assert failed in \S+: (\S+)", p.stdout)
        if "Status: PASSED" not in p.stdout:
            if step == "base" and failed:
                return {"failed": failed.group(1)}
            # An induction step that fails has a counterexample from an unreachable state: not proven.
            return {"unproven": failed.group(1) if failed else "?", "step": step}
    return {"proven": True}


def prove_pdr(job, work, label):
    """LABEL (or, given None, every property at once) with ABC's pdr on the AIGER model."""
    script = yosys_read(job)
    script += "select -assert-count %d t:$assert\n" % len(job["labels"])
    if job["cut"]:  # named wires driven by a free input instead (hw/formal.json "cut")
        script += "flatten\n" + "".join(f"select -assert-min 1 w:{w}\n" for w in job["cut"])  # a renamed wire fails
        script += "cutpoint " + " ".join(f"w:{w}" for w in job["cut"]) + "\n"
    if label:  # this one must be there (a missing one would leave nothing to prove)
        script += f"select -assert-count 1 t:$assert {job['proven_top']}/{label} %i\n"
        script += f"chformal -assert -remove t:$assert {job['proven_top']}/{label} %d\n"
    # One clock, or every clock the wrapper makes from the global clock (flip-flops sampling on its steps).
    script += "memory_map\nopt\n" + ("clk2fflogic\n" if job["multiclock"] else "async2sync\n")
    script += ("flatten\nsetundef -undriven -anyseq\ndelete -output\n"
               "techmap\nopt -fast\ndffunmap\nabc -g AND\nopt_clean\nwrite_aiger -zinit model.aig\n")
    (work / "model.ys").write_text(script)
    p = run(["yosys", "-q", "model.ys"], work, "yosys.log")
    if p is None or p.returncode:
        return {"error": "yosys failed (or the properties are not those of the model): see " + str(work / "yosys.log")}
    p = run(["yosys-abc", "-c", "read_aiger model.aig; fold; strash; pdr"], work, "abc.log")
    if p is None:
        return {"timeout": "pdr"}
    if "Property proved" in p.stdout:
        return {"proven": True}
    frame = re.search(r"was asserted in frame (\d+)", p.stdout)
    if not frame:
        return {"error": "pdr gave no verdict: see " + str(work / "abc.log")}
    if label:
        return {"failed": label, "frame": int(frame.group(1))}
    # The AIGER model ORs the properties: each on its own names the one that failed.
    for other, _ in job["prove"]:
        (work / other).mkdir(exist_ok=True)
        named = prove_pdr(job, work / other, other)
        if "failed" in named:
            return named
    return {"error": "pdr failed at frame %s with every property, with none alone: see %s" % (frame.group(1), work)}


def run_job(job):
    work = pathlib.Path(job["work"])
    work.mkdir(parents=True, exist_ok=True)
    start = time.monotonic()
    try:
        if job["method"] == "induction":
            verdict = prove_induction(job, work)
        else:
            verdict = prove_pdr(job, work, job.get("label"))
    except (OSError, ValueError) as e:
        verdict = {"error": f"{type(e).__name__}: {e}"}
    verdict["seconds"] = round(time.monotonic() - start, 1)
    return verdict


def sources(unit, bug, work):
    """The unit's folder, with BUG's one-line change applied when given."""
    if bug is None:
        return ROOT / "hw" / unit
    copy = work / "src"
    copy.mkdir(parents=True, exist_ok=True)
    for f in (ROOT / "hw" / unit).iterdir():
        if f.suffix in (".sv", ".svh"):
            (copy / f.name).write_text(f.read_text())
    target = copy / pathlib.Path(bug["file"]).name
    text = target.read_text()
    if text.count(bug["replace"]) != 1:
        raise SpecError(f"hw/formal.json: seeded bug '{bug['bug']}': {bug['file']} no longer has "
                        f"'{bug['replace']}' exactly once")
    target.write_text(text.replace(bug["replace"], bug["with"]))
    return copy


def job(c, depth, pkg_files, src_dir, generated):
    """What every run of check C (at built DEPTH, from the sources in SRC_DIR) needs."""
    path = formal_file(c["unit"], c["top"])
    labels = properties(path, c.get("defines", []))
    prove = [(l, t) for l, t in labels if l in c.get("properties", [l])]
    if len(prove) != len(c.get("properties", prove)):
        raise SpecError(f"hw/formal.json: a check of {c['unit']} names properties its file does not have")
    for only_pdr in ("cut", "multiclock"):
        if c.get(only_pdr) and c["method"] != "pdr":
            raise SpecError(f"hw/formal.json: a check of {c['unit']} is '{only_pdr}': only a pdr check can be")
    check_instance = c["instance"] + (f", {c['note']}" if "note" in c else "")
    # The module yosys elaborates: TOP itself, or its wrapper when the properties read only TOP's ports.
    proven_top = c["top"] + ("_formal" if path.suffix == ".sv" else "")
    return dict(unit=c["unit"], top=c["top"], proven_top=proven_top, check_instance=check_instance, depth=depth,
                instance=check_instance + (f", DEPTH {depth}" if depth else ""),
                method=c["method"], k=c.get("k"), bmc=max(c.get("bmc", 0), c.get("k", 0)),
                smt_arrays=c.get("smt_arrays", False), also=c.get("also", []), defines=c.get("defines", []),
                cut=c.get("cut", []), multiclock=c.get("multiclock", False),
                parameters=dict(c.get("parameters", {}), **({"DEPTH": depth} if depth else {})),
                pkg_file=pkg_files[c["instance"]], src_dir=str(src_dir), generated=str(generated), labels=labels,
                prove=prove)


def instances(spec):
    """Each instance's overrides, an instance "like" another one taking that one's first."""
    def resolved(name, seen=()):
        if name in seen or name not in spec["instances"]:
            raise SpecError(f"hw/formal.json: instance {name}: unknown, or 'like' goes round in a circle")
        items = dict(spec["instances"][name])
        base = items.pop("like", None)
        return dict(resolved(base, seen + (name,)), **items) if base else items
    return {name: resolved(name) for name in spec["instances"]}


def plan(spec, generated_pkg, scratch, units):
    """The proof jobs and the seeded-bug jobs (one each). GENERATED_PKG: the build's girtd_pkg.sv, whose
    folder also holds the generated tables the RTL includes (the DDA's PROM)."""
    generated, include_dir = generated_pkg.read_text(), generated_pkg.resolve().parent
    pkg_files = {}
    for name, overrides in instances(spec).items():
        f = scratch / f"pkg_{name}.sv"
        f.write_text(package(generated, overrides, name))
        pkg_files[name] = str(f)
    proofs, bugs = [], []
    for index, c in enumerate(spec["checks"]):
        if units and c["unit"] not in units:
            continue
        for depth in c.get("depths", [None]):
            base = job(c, depth, pkg_files, ROOT / "hw" / c["unit"], include_dir)
            tag = re.sub(r"\W+", "_", f"check{index}_{c['unit']}_{depth or ''}")
            if c["method"] == "induction":
                proofs.append(dict(base, work=str(scratch / tag)))
            else:  # one run per property
                proofs += [dict(base, label=l, prove=[(l, t)], work=str(scratch / f"{tag}_{l}"))
                           for l, t in base["prove"]]
    for i, bug in enumerate(spec["seeded_bugs"]):
        if units and bug["unit"] not in units:
            continue
        # The first check of the bug's unit on its instance (if it names one) that proves the property
        # the bug names, else one that proves every property of the unit's file.
        c = next((c for c in spec["checks"] if c["unit"] == bug["unit"] and
                  c["instance"] == bug.get("instance", c["instance"]) and
                  (bug["property"] in c.get("properties", []) if "property" in bug else "properties" not in c)), None)
        if c is None:
            raise SpecError(f"hw/formal.json: seeded bug '{bug['bug']}': no check of {bug['unit']} to run it with")
        work = scratch / f"bug{i}"
        bugs.append(dict(job(c, c.get("depths", [None])[0], pkg_files, sources(c["unit"], bug, work), include_dir),
                         bug=bug["bug"], property=bug.get("property"), work=str(work / "run")))
    return proofs, bugs


def method_text(job):
    if job["method"] == "induction":
        return f"k-induction, k = {job['k']}, base {job['bmc']} ticks (z3)"
    return "PDR (ABC)"


def result_text(verdict, label):
    if "proven" in verdict:
        return "proven"
    if verdict.get("failed") == label:
        return "FAILED" + (f" (frame {verdict['frame']})" if "frame" in verdict else "")
    if verdict.get("unproven") == label:
        return "NOT PROVEN (induction step)"
    if "timeout" in verdict:
        return f"TIMEOUT ({TIMEOUT_S} s)"
    if "error" in verdict:
        return "ERROR"
    return "not reached"


def grouped(rows):
    """One table row per property and check: the FIFO's built depths on one line."""
    groups = {}
    for r in rows:
        groups.setdefault((r["property"], r["unit"], r["check_instance"], r["method"]), []).append(r)
    for members in groups.values():
        if len(members) == 1:
            yield members[0]
            continue
        depths = [m["depth"] for m in members]
        bad = [m for m in members if m["result"] != "proven"]
        yield dict(members[0], instance=f"{members[0]['check_instance']}, DEPTH {min(depths)} to {max(depths)} "
                                        f"({len(depths)} built depths)",
                   result=f"{bad[0]['result']} at DEPTH {bad[0]['depth']}" if bad else "proven",
                   seconds=round(sum(m["seconds"] for m in members), 1))


def render(rows, bug_rows):
    """The markdown tables and the summary line."""
    md = ["| property | what it says | unit | instance | method | result | time |",
          "|---|---|---|---|---|---|---|"]
    md += [f"| `{r['property']}` | {r['description']} | {r['unit']} | {r['instance']} | {r['method']} | "
           f"{r['result']} | {r['seconds']} s |" for r in grouped(rows)]
    md += ["", "| seeded bug | unit | instance | caught by |", "|---|---|---|---|"]
    md += [f"| {b['bug']} | {b['unit']} | {b['instance']} | "
           f"{'`' + b['caught_by'] + '`' if b['caught_by'] else 'NOT CAUGHT'} |" for b in bug_rows]
    proven = sum(r["result"] == "proven" for r in rows)
    caught = sum(b["caught_by"] is not None for b in bug_rows)
    return md, f"formal: {proven}/{len(rows)} properties proven, {caught}/{len(bug_rows)} seeded bugs caught"


def print_recorded(path):
    """The tables of a recorded run (results/formal/formal.json), for hw/README.md's generated section."""
    sys.path.insert(0, str(ROOT / "studies"))
    import recorded
    if not pathlib.Path(path).is_file():
        print(f"No recorded run ({path}): `tools/girtd formal --out out/formal && tools/girtd docs --record out/formal`.")
        return 0
    record = json.loads(pathlib.Path(path).read_text())
    md, summary = render(record["properties"], record["seeded_bugs"])
    print("\n".join(md) + "\n\n" + summary + ", recorded" +
          recorded.measured_at(str(pathlib.Path(path).resolve().parent.relative_to(recorded.RESULTS.resolve()))) + ".")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("build")
    ap.add_argument("--out")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--unit", action="append", default=[])
    ap.add_argument("--table", metavar="FORMAL_JSON", help="print the tables of a recorded run and stop")
    args = ap.parse_args()
    if args.table:
        return print_recorded(args.table)
    generated_pkg = pathlib.Path(args.build) / "generated" / "hw" / "girtd_pkg.sv"
    if not generated_pkg.is_file():
        print(f"formal.py: {generated_pkg}: no generated package (build first: tools/girtd formal)", file=sys.stderr)
        return 2
    try:
        spec = json.loads(SPEC.read_text())
    except json.JSONDecodeError as e:
        print(f"hw/formal.json:{e.lineno}: {e.msg}", file=sys.stderr)
        return 2
    unknown = set(args.unit) - {c["unit"] for c in spec["checks"]}
    if unknown:
        print(f"formal.py: no checks for unit(s) {', '.join(sorted(unknown))} in hw/formal.json", file=sys.stderr)
        return 2
    # The runs' models and logs: kept under --out (OUT/runs), else in a temporary folder.
    keep = pathlib.Path(args.out).resolve() / "runs" if args.out else None
    if keep:
        shutil.rmtree(keep, ignore_errors=True)
        keep.mkdir(parents=True)
    with tempfile.TemporaryDirectory(prefix="girtd_formal_") as tmp:
        scratch = keep or pathlib.Path(tmp)
        try:
            proofs, bugs = plan(spec, generated_pkg, scratch, set(args.unit))
        except SpecError as e:
            print(f"formal.py: {e}", file=sys.stderr)
            return 2
        total = len(proofs) + len(bugs)
        print(f"formal: {len(proofs)} proof runs and {len(bugs)} seeded bugs on {args.jobs} job(s)", file=sys.stderr)
        verdicts = {}
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            futures = {pool.submit(run_job, j): id(j) for j in proofs + bugs}
            for n, f in enumerate(concurrent.futures.as_completed(futures), 1):
                verdicts[futures[f]] = f.result()
                if sys.stderr.isatty():
                    print(f"\rformal: {n}/{total} runs done", end="", file=sys.stderr)
        if sys.stderr.isatty():
            print(file=sys.stderr)

    rows, failures = [], 0
    for proof in proofs:
        v = verdicts[id(proof)]
        for label, text in proof["prove"]:
            result = result_text(v, label)
            failures += result != "proven"
            rows.append(dict(property=label, description=text, unit=proof["unit"], instance=proof["instance"],
                             check_instance=proof["check_instance"], depth=proof["depth"],
                             method=method_text(proof), result=result, seconds=v["seconds"],
                             **({"detail": v["error"]} if "error" in v else {})))
    bug_rows = []
    for bug in bugs:
        v = verdicts[id(bug)]
        # Caught: some property of its check failed, the one it names where it names one.
        caught = v.get("failed") if bug["property"] in (None, v.get("failed")) else None
        bug_rows.append(dict(unit=bug["unit"], bug=bug["bug"], instance=bug["instance"], caught_by=caught,
                             seconds=v["seconds"], **({"detail": v["error"]} if "error" in v else {}),
                             **({"failed_instead": v["failed"]} if "failed" in v and not caught else {})))
        failures += caught is None

    md, summary = render(rows, bug_rows)
    print("\n".join(md) + "\n\n" + summary)
    for r in rows + bug_rows:
        if "detail" in r:
            print(f"formal: {r['unit']}: {r['detail']}" + ("" if keep else " (run with --out DIR to keep the logs)"),
                  file=sys.stderr)
    if args.out:
        out = pathlib.Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        (out / "formal.json").write_text(json.dumps({"properties": rows, "seeded_bugs": bug_rows,
                                                     "summary": summary}, indent=2) + "\n")
        (out / "formal.md").write_text("\n".join(md) + "\n\n" + summary + "\n")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
