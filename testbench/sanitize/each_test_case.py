#!/usr/bin/env python3
"""Runs every Catch2 test case of BINARY in a process of its own, as CTest runs
the main build's (catch_discover_tests): SystemC elaborates once per process.

Usage: each_test_case.py BINARY [--jobs N]
Prints each failing case with the end of its output and a closing line
`N test cases, N failed`; exit 1 when any failed (or none ran).
"""
import argparse
import concurrent.futures
import subprocess
import sys


def escaped(name):
    """A test name as a Catch2 test spec that matches it alone."""
    for special in "\\,[]*":
        name = name.replace(special, "\\" + special)
    return name


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("binary")
    ap.add_argument("--jobs", type=int, default=1)
    args = ap.parse_args()
    # Catch2 v2 exits with the number of cases listed: the list itself is the check.
    listed = subprocess.run([args.binary, "--list-test-names-only"], capture_output=True, text=True)
    names = [n for n in listed.stdout.splitlines() if n.strip()]
    if not names:
        print(f"{args.binary}: no test cases", file=sys.stderr)
        return 1

    def run(name):
        p = subprocess.run([args.binary, "--warn", "NoTests", escaped(name)], capture_output=True, text=True)
        return name, p.returncode, p.stdout + p.stderr

    failed = 0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for name, rc, output in pool.map(run, names):
            if rc:
                failed += 1
                print(f"FAILED ({rc}): {name}\n" + "\n".join(output.splitlines()[-40:]) + "\n")
    print(f"{len(names)} test cases, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
