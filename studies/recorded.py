#!/usr/bin/env python3
"""When each recorded result under results/ was true.

    recorded.py stamp PATH COMMAND...   note that results/PATH was measured at this checkout's commit
    recorded.py check                   list the results older than the last change to what they measure

results/recorded.json maps each recorded result (a file or a folder under
results/) to the commit it was measured at, the date, the command and the
source folders it measures. `tools/girtd docs --record` stamps what it
records; the generated sections print the stamp (measured_at); `tools/girtd
docs --check` runs `check`: a result is stale when a later commit changed a
source it measures, or when it has no stamp. Exit 1 when any is stale.
"""
import datetime
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
RESULTS = ROOT / "results"
MANIFEST = RESULTS / "recorded.json"
# What a recorded result depends on: the simulator, its design values and the
# inputs it ran (a result of the report page only the page's code).
SIMULATOR = ["sim", "models", "hw", "config", "traces", "studies", "cmake", "CMakeLists.txt"]
MEASURES = {"report_page": ["sim/report"],
            "formal": ["hw", "config", "models/layout", "models/dda", "tools/formal.py"]}  # models/dda: the state codes
# What a result does not depend on in the folders it measures: their documents.
NOT_SOURCES = ":(exclude,glob)**/*.md"
# What no simulation runs in the folders a simulator's result measures: the
# formal properties (only tools/girtd formal reads them) and this bookkeeping.
NOT_SIMULATED = [":(exclude,glob)hw/**/*_formal.sv", ":(exclude,glob)hw/**/*_formal.svh", ":(exclude)hw/formal.json",
                 ":(exclude)studies/recorded.py"]
# Not results: this folder's own documents.
NOT_RESULTS = {"README.md", "recorded.json"}


def git(*args):
    return subprocess.run(["git", "-C", str(ROOT)] + list(args), check=True, capture_output=True,
                          text=True).stdout.strip()


def load():
    return json.loads(MANIFEST.read_text()) if MANIFEST.exists() else {}


def measures(path):
    return MEASURES.get(path.split("/")[0], SIMULATOR)


def not_sources(measured):
    """The pathspecs left out of MEASURED's folders."""
    return [NOT_SOURCES] + (NOT_SIMULATED if list(measured) == SIMULATOR else [])


def stamp(path, command):
    path = str(pathlib.Path(path).resolve().relative_to(RESULTS.resolve()))
    manifest = load()
    sources = measures(path)
    dirty = bool(git("status", "--porcelain", "--", *sources, *not_sources(sources)))
    manifest[path] = {"commit": git("rev-parse", "HEAD"), "uncommitted_changes": dirty,
                      "date": datetime.date.today().isoformat(), "command": command, "measures": sources}
    MANIFEST.write_text(json.dumps(dict(sorted(manifest.items())), indent=2) + "\n")
    if dirty:
        print("warning: %s recorded with uncommitted changes in %s: it will read as stale until they are "
              "committed and it is recorded again" % (path, " ".join(sources)), file=sys.stderr)


def measured_at(path):
    """' at commit abc1234 (2026-12-06)' for results/PATH, or ' (no commit recorded)'."""
    entry = load().get(str(path))
    if not entry:
        return " (no commit recorded)"
    return " at commit %s%s (%s)" % (entry["commit"][:7], " with uncommitted changes" if entry["uncommitted_changes"]
                                     else "", entry["date"])


def recorded_paths():
    """Every result under results/: a file at the top, else the first folder level's folders or files."""
    out = []
    for p in sorted(RESULTS.iterdir()):
        if p.name in NOT_RESULTS:
            continue
        if p.is_file():
            out.append(p.name)
        elif any(c.is_dir() for c in p.iterdir()):
            out += ["%s/%s" % (p.name, c.name) for c in sorted(p.iterdir())]
        else:
            out.append(p.name)
    return out


def check():
    manifest = load()
    stale = []
    for path in recorded_paths():
        entry = manifest.get(path)
        if not entry:
            stale.append("results/%s: no commit recorded (record it again: tools/girtd docs --record)" % path)
            continue
        sources = list(entry["measures"]) + not_sources(entry["measures"])
        later = git("rev-list", "--count", entry["commit"] + "..HEAD", "--", *sources)
        if int(later) or entry["uncommitted_changes"]:
            last = git("log", "-1", "--format=%h %cs", "--", *sources)
            stale.append("results/%s: measured at %s (%s); %s later commit(s) change %s, the last %s" % (
                path, entry["commit"][:7], entry["date"], later, " ".join(entry["measures"]), last))
    for line in stale:
        print(line)
    print("%d recorded result(s), %d stale" % (len(recorded_paths()), len(stale)))
    return 1 if stale else 0


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "stamp":
        stamp(sys.argv[2], " ".join(sys.argv[3:]))
        return 0
    if sys.argv[1:] == ["check"]:
        return check()
    print(__doc__.split("\n\n")[1], file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
