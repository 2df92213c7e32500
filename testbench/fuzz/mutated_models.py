#!/usr/bin/env python3
"""A black-box campaign at the model front door: mutated glTF, GLB, Collada
and 3DS files through `girtd render`, as a user would hand them over.

Every run must end in one of two ways: exit 0 with a report (stderr only
`warning: ` lines), or exit 2 with one stderr line naming the file and no
output directory. Anything else is a finding: a crash (a signal, or an
exit code other than 0 and 2), a hang (past --timeout, 90 s: the import's
own limit is 60 s), a refusal of several lines, or one that does not name
the file, or output left behind. Findings' inputs are kept in OUT/findings/.

Seeds are the files of those formats in Debian's assimp-testmodels under
2 MB (each mutated in a copy of its folder, so that its .bin, textures and
material files are found) and traces/models/file_scenes/two_materials.gltf.
Mutations are deterministic (--seed): bytes flipped, inserted, deleted,
duplicated, the file cut short, a number of a text file replaced by an
extreme one, two files of the same format spliced.

Usage: mutated_models.py GIRTD_BINARY OUT [--runs 10000] [--jobs 2] [--seed 1]
Prints progress with an ETA, then a table per format (Markdown, also
OUT/summary.md); exit 1 on any finding. testbench/fuzz/README.md has the
last campaign's table.
"""
import argparse
import collections
import concurrent.futures
import os
import random
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ASSIMP_MODELS = "/usr/share/assimp/models"
FORMATS = {".gltf": "glTF", ".glb": "GLB", ".dae": "Collada", ".3ds": "3DS"}
SEED_FOLDERS = ["glTF2", "glTF", "Collada", "3DS"]
MAX_SEED_BYTES = 2 << 20
EXTREME = [b"0", b"-1", b"1e308", b"-1e308", b"1e-320", b"4294967295", b"2147483648", b"-2147483649", b"nan",
           b"inf", b"999999999999999999999", b"65536", b"1000000000"]
NUMBER = re.compile(rb"-?\d+(\.\d+)?([eE][-+]?\d+)?")


def seeds():
    found = []
    for folder in SEED_FOLDERS:
        for base, _, names in os.walk(os.path.join(ASSIMP_MODELS, folder)):
            for n in sorted(names):
                path = os.path.join(base, n)
                if os.path.splitext(n)[1].lower() in FORMATS and os.path.getsize(path) <= MAX_SEED_BYTES:
                    found.append(path)
    found.append(os.path.join(ROOT, "traces", "models", "file_scenes", "two_materials.gltf"))
    return sorted(found)


# Mutation kinds and their weights: a text file (glTF, Collada) mostly gets
# its numbers and lines changed, so that it still parses and reaches the
# importer's logic; a binary one its bytes.
TEXT_WEIGHTS = [1, 1, 1, 1, 0.5, 8, 0.5]
BINARY_WEIGHTS = [4, 1, 1, 1, 1, 0, 1]


def mutate(data, rng, same_format):
    """One to three mutations of `data` (bytes)."""
    text = data[:1] in (b"{", b"<") or data[:3] == b"\xef\xbb\xbf"
    data = bytearray(data)
    for _ in range(rng.randint(1, 3)):
        kind = rng.choices(range(7), TEXT_WEIGHTS if text else BINARY_WEIGHTS)[0]
        n = len(data)
        if n == 0:
            data += bytes(rng.randrange(256) for _ in range(rng.randint(1, 64)))
            continue
        at = rng.randrange(n)
        if kind == 0:  # flip bytes
            for _ in range(rng.choice([1, 1, 2, 4, 16])):
                data[rng.randrange(n)] = rng.randrange(256)
        elif kind == 1:  # insert random bytes
            data[at:at] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 64)))
        elif kind == 2:  # delete a range (a text file: whole lines)
            end = at + rng.randint(1, max(1, n // 8))
            if text:
                at, end = data.rfind(b"\n", 0, at) + 1, data.find(b"\n", end)
                end = n if end < 0 else end + 1
            del data[at:end]
        elif kind == 3:  # duplicate a range (a text file: whole lines)
            end = at + rng.randint(1, max(1, n // 8))
            if text:
                at, end = data.rfind(b"\n", 0, at) + 1, data.find(b"\n", end)
                end = n if end < 0 else end + 1
            data[at:at] = data[at:end]
        elif kind == 4:  # cut short
            del data[at:]
        elif kind == 5:  # a number replaced by an extreme one (text formats)
            numbers = [m for m in NUMBER.finditer(bytes(data[max(0, at - 4096):at + 4096]))]
            if numbers:
                m = rng.choice(numbers)
                start = max(0, at - 4096)
                json = data[:1] == b"{"  # nan and inf are no JSON: the file would not reach the importer
                data[start + m.start():start + m.end()] = rng.choice([e for e in EXTREME if not (json and e in (b"nan", b"inf"))])
        else:  # splice with another file of the same format
            other = rng.choice(same_format)
            with open(other, "rb") as f:
                tail = f.read()
            data[at:] = tail[rng.randrange(len(tail)):] if tail else b""
    return bytes(data)


def run_one(girtd, index, seed_path, data, work, timeout):
    """Renders the mutated file in a copy of its seed's folder; returns (outcome, detail)."""
    folder = os.path.join(work, "run%06d" % index)
    os.makedirs(folder)
    src = os.path.dirname(seed_path)
    for n in os.listdir(src):  # the files it may name, as links
        if n != os.path.basename(seed_path) and os.path.isfile(os.path.join(src, n)):
            os.symlink(os.path.join(src, n), os.path.join(folder, n))
    path = os.path.join(folder, os.path.basename(seed_path))
    with open(path, "wb") as f:
        f.write(data)
    out = os.path.join(folder, "out")
    try:
        p = subprocess.run([girtd, "render", path, "--out", out, "--quiet"], capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "hang", "no answer in %d s" % timeout, path
    err = p.stderr.decode(errors="replace").splitlines()
    if p.returncode == 0:
        if not os.path.isfile(os.path.join(out, "report.json")):
            return "finding", "exit 0 without report.json", path
        if any(not l.startswith("warning: ") for l in err):
            return "finding", "exit 0 with a line that is no warning: " + next(l for l in err if not l.startswith("warning: ")), path
        return "rendered", "", path
    if p.returncode == 2:
        if len(err) != 1:
            return "finding", "exit 2 with %d lines: %s" % (len(err), " | ".join(err)[:300]), path
        if path not in err[0] and os.path.basename(path) not in err[0]:
            return "finding", "exit 2 without the file's name: " + err[0][:300], path
        if os.path.exists(out):
            return "finding", "exit 2 left " + out, path
        return "refused", err[0], path
    what = "signal %d" % -p.returncode if p.returncode < 0 else "exit %d" % p.returncode
    return "crash", what + ": " + " | ".join(err)[:300], path


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("girtd")
    ap.add_argument("out")
    ap.add_argument("--runs", type=int, default=10000)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=int, default=90)
    args = ap.parse_args()
    girtd = os.path.abspath(args.girtd)
    all_seeds = seeds()
    if not all_seeds:
        sys.exit("no seeds: install assimp-testmodels (tools/girtd installs it)")
    by_format = collections.defaultdict(list)
    for s in all_seeds:
        by_format[os.path.splitext(s)[1].lower()].append(s)
    shutil.rmtree(args.out, ignore_errors=True)
    work, findings = os.path.join(args.out, "work"), os.path.join(args.out, "findings")
    os.makedirs(work)
    os.makedirs(findings)
    rng = random.Random(args.seed)
    counts = collections.defaultdict(collections.Counter)
    reasons = collections.defaultdict(collections.Counter)
    found = []
    start = time.time()

    def jobs():
        for i in range(args.runs):
            seed = all_seeds[i % len(all_seeds)]
            with open(seed, "rb") as f:
                data = mutate(f.read(), rng, by_format[os.path.splitext(seed)[1].lower()])
            yield i, seed, data

    def record(fut):
        seed, (outcome, detail, path) = fut.result()
        fmt = FORMATS[os.path.splitext(seed)[1].lower()]
        counts[fmt][outcome] += 1
        if outcome == "refused":
            reasons[fmt][re.sub(r"^.*?: ", "", detail)[:60]] += 1
        if outcome in ("crash", "hang", "finding"):
            kept = os.path.join(findings, "%s_%d%s" % (outcome, len(found), os.path.splitext(path)[1]))
            shutil.copy(path, kept)
            found.append("%s %s: %s (seed %s)" % (outcome, kept, detail, seed))
            print("FINDING:", found[-1], flush=True)
        shutil.rmtree(os.path.dirname(path), ignore_errors=True)

    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        pending = set()
        done = 0
        for i, seed, data in jobs():
            pending.add(pool.submit(lambda a: (a[1], run_one(girtd, *a, work, args.timeout)), (i, seed, data)))
            if len(pending) < 2 * args.jobs:
                continue
            finished, pending = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for fut in finished:
                record(fut)
                done += 1
                if done % 200 == 0:
                    rate = done / (time.time() - start)
                    print("%d / %d runs, %.1f runs/s, ETA %d s, %d findings" %
                          (done, args.runs, rate, (args.runs - done) / rate, len(found)), flush=True)
        for fut in concurrent.futures.as_completed(pending):
            record(fut)

    lines = ["| format | seeds | runs | rendered | refused (one line, exit 2) | crashes | hangs | other findings | commonest refusals |",
             "|---|---|---|---|---|---|---|---|---|"]
    for ext, fmt in FORMATS.items():
        c = counts[fmt]
        top = "; ".join("`%s` (%d)" % (r.replace("|", "/"), n) for r, n in reasons[fmt].most_common(2))
        lines.append("| %s | %d | %d | %d | %d | %d | %d | %d | %s |" % (
            fmt, len(by_format[ext]), sum(c.values()), c["rendered"], c["refused"], c["crash"], c["hang"],
            c["finding"], top))
    summary = "\n".join(lines) + "\n\n%d runs in %d s (%d jobs, seed %d); %d findings.\n" % (
        args.runs, time.time() - start, args.jobs, args.seed, len(found))
    summary += "".join("- %s\n" % f for f in found)
    with open(os.path.join(args.out, "summary.md"), "w") as f:
        f.write(summary)
    shutil.rmtree(work, ignore_errors=True)
    print(summary)
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()
