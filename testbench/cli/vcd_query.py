#!/usr/bin/env python3
"""Reads a VCD (from fst2vcd) for the waveform tests.

  vcd_query.py FILE names                 every signal's full dotted name (with its range)
  vcd_query.py FILE times                 the first and last timestamps
  vcd_query.py FILE value SIGNAL TIME     the signal's value (decimal) at TIME (its last change at or before)
"""
import sys


def parse(path):
    ids, scope, changes, times, t = {}, [], {}, [], None
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "$scope":
                scope.append(w[2])
            elif w[0] == "$upscope":
                scope.pop()
            elif w[0] == "$var":
                name = ".".join(scope + [w[4]]) + (w[5] if len(w) > 6 and w[5].startswith("[") else "")
                ids.setdefault(w[3], []).append(name)
            elif w[0].startswith("#"):
                t = int(w[0][1:])
                times.append(t)
            elif t is not None and w[0][0] in "01xzXZ" and len(w) == 1:
                changes.setdefault(w[0][1:], []).append((t, w[0][0]))
            elif t is not None and w[0][0] in "bB" and len(w) == 2:
                changes.setdefault(w[1], []).append((t, w[0][1:]))
    return ids, changes, times


def main():
    path, what = sys.argv[1], sys.argv[2]
    ids, changes, times = parse(path)
    if what == "names":
        for names in ids.values():
            print("\n".join(names))
    elif what == "times":
        print(min(times), max(times))
    elif what == "value":
        signal, at = sys.argv[3], int(sys.argv[4])
        code = next((c for c, names in ids.items() if signal in names or any(n.split("[")[0] == signal for n in names)), None)
        if code is None:
            sys.exit("no signal " + signal)
        value = None
        for t, v in changes.get(code, []):
            if t > at:
                break
            value = v
        print(int(value, 2) if value is not None and all(ch in "01" for ch in value) else value)


main()
