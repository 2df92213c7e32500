#!/usr/bin/env python3
"""Prints config/README.md's table of the design's fixed constants from
config/constants.json (tools/generated_docs.py puts it there and checks it is
current). Usage: constants_table.py BUILD_DIR (unused: the file is the source)."""
import json
import pathlib

ROOT = pathlib.Path(__file__).resolve().parent.parent


def leaves(node, prefix=""):
    for key, value in node.items():
        if "value" in value:
            yield prefix + key, value["value"], value["why"]
        else:
            yield from leaves(value, prefix + key + ".")


print("| constant | value | why |")
print("|---|---|---|")
for key, value, why in leaves(json.loads((ROOT / "config/constants.json").read_text())):
    print(f"| `{key}` | {value} | {why} |")
