#!/usr/bin/env python3
"""Compares two output folders of `dyncontact solve` (scripts/check_same_results.sh).

summary.json: every value equal, timings (keys ending in time_s, seconds or ms, and
`threads`) aside; numbers equal to REL (default 0: bit-identical) relative. CSV and .dat
files: equal line by line under the same rule. Prints one line per difference; exit 1 when
there is any, 0 otherwise.
usage: compare_outputs.py OLD_DIR NEW_DIR [--rel REL]
"""
import argparse
import json
import math
import os
import sys

TIMING_SUFFIXES = ("time_s", "_seconds", "_ms", "per_step_s")
IGNORED_KEYS = {"threads", "version"}


def is_timing(key):
    return key in IGNORED_KEYS or key.endswith(TIMING_SUFFIXES)


def same_number(a, b, rel):
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    if a == b:
        return True
    return rel > 0 and abs(a - b) <= rel * max(abs(a), abs(b))


def compare_json(a, b, path, rel, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if is_timing(k):
                continue
            if k not in a or k not in b:
                out.append(f"{path}.{k}: only in {'new' if k in b else 'old'}")
            else:
                compare_json(a[k], b[k], f"{path}.{k}", rel, out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{path}: {len(a)} entries -> {len(b)}")
        for i, (x, y) in enumerate(zip(a, b)):
            compare_json(x, y, f"{path}[{i}]", rel, out)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        if not same_number(a, b, rel):
            out.append(f"{path}: {a!r} -> {b!r}")
    elif a != b:
        out.append(f"{path}: {str(a)[:80]!r} -> {str(b)[:80]!r}")


def numbers_or_text(line):
    fields = line.replace(",", " ").split()
    try:
        return [float(f) for f in fields]
    except ValueError:
        return line


def compare_table(old, new, name, rel, out):
    with open(old) as f:
        a = f.read().splitlines()
    with open(new) as f:
        b = f.read().splitlines()
    if len(a) != len(b):
        out.append(f"{name}: {len(a)} lines -> {len(b)}")
        return
    for i, (x, y) in enumerate(zip(a, b)):
        if x == y:
            continue
        nx, ny = numbers_or_text(x), numbers_or_text(y)
        if isinstance(nx, list) and isinstance(ny, list) and len(nx) == len(ny) and all(
                same_number(p, q, rel) for p, q in zip(nx, ny)):
            continue
        out.append(f"{name}:{i + 1}: {x[:80]!r} -> {y[:80]!r}")
        return  # the first differing line of a table is enough


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--rel", type=float, default=0.0)
    args = ap.parse_args()
    out = []
    for d in (args.old, args.new):
        if not os.path.isfile(os.path.join(d, "summary.json")):
            out.append(f"{d}: no summary.json (the run failed: see its .err beside it)")
    for root, _, files in os.walk(args.old):
        for name in sorted(files):
            old = os.path.join(root, name)
            rel_name = os.path.relpath(old, args.old)
            new = os.path.join(args.new, rel_name)
            if not name.endswith((".json", ".csv", ".dat")):
                continue
            if not os.path.exists(new):
                out.append(f"{rel_name}: only in old")
            elif name.endswith(".json"):
                with open(old) as f, open(new) as g:
                    compare_json(json.load(f), json.load(g), rel_name, args.rel, out)
            else:
                compare_table(old, new, rel_name, args.rel, out)
    for line in out:
        print(line)
    return 1 if out else 0


if __name__ == "__main__":
    sys.exit(main())
