#!/usr/bin/env python3
"""How many ASL-LEX 2.0 signs have a dominant handshape the handshape library can form.

A development tool, not part of the build, tests or run: it reads a copy of ASL-LEX 2.0's
signdata.csv that you supply (the project does not ship it; CC BY-NC 4.0, cite Caselli et al.
2017 and Sehyr et al. 2021 as docs/hand.md does) and a handshape file, and counts the signs whose
`Handshape.2.0` equals the `aslLex` label of some handshape in the file.

    python3 scripts/dev/asllex_coverage.py SIGNDATA.csv [scenes/handshapes.json]
"""
import collections
import csv
import json
import sys


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    shapes_file = sys.argv[2] if len(sys.argv) == 3 else "scenes/handshapes.json"
    with open(sys.argv[1], encoding="utf-8-sig", newline="") as f:
        labels = collections.Counter(row["Handshape.2.0"] for row in csv.DictReader(f))
    with open(shapes_file, encoding="utf-8") as f:
        formed = {s["aslLex"] for s in json.load(f)["handshapes"] if s.get("aslLex")}
    total = sum(labels.values())
    covered = sum(n for label, n in labels.items() if label in formed)
    print(f"{covered} of {total} signs ({100.0 * covered / total:.1f} %): dominant handshape formed")
    print(f"labels formed: {len(formed & set(labels))} of {len(labels)} in ASL-LEX 2.0")
    unknown = sorted(formed - set(labels))
    if unknown:
        print("labels in the handshape file that ASL-LEX 2.0 does not use:", " ".join(unknown))
    missing = sorted(((n, label) for label, n in labels.items() if label not in formed), reverse=True)
    print("not formed:", ", ".join(f"{label} ({n})" for n, label in missing))


if __name__ == "__main__":
    main()
