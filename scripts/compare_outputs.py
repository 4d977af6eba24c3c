#!/usr/bin/env python3
"""Compares two output folders of `dyncontact solve` (scripts/check_same_results.sh).

summary.json: every value equal, timings (keys ending in time_s, seconds or ms, and
`threads`) aside; numbers equal to REL (default 0: bit-identical) relative. CSV and .dat
files: equal line by line under the same rule. Prints one line per difference; exit 1 when
there is any, 0 otherwise.
usage: compare_outputs.py OLD_DIR NEW_DIR [--rel REL] [--trajectory TOL]

--trajectory TOL: the same answers to a solver's tolerance, not bit for bit (a change of
iterative method, e.g. another Newton start): every number of a CSV/.dat column within TOL of
that column's largest magnitude (a value that should be 0 is compared on its column's scale),
numbers in JSON lists likewise on the list's scale, other numbers within TOL relative;
`balances` (themselves relative errors) within TOL absolute; the work counts and certificates
(`solver`, `normal_solver`, `newton_iterations` and the `outer_*` counts and residuals of the
kappa loop, in the summary and its steps) and the table columns `newton_iterations`,
`contact_solves`, `alternations` and `certificate` are not compared (they are what such a change
changes; a newer table's added work columns are dropped); numbers both below 1e-9 in magnitude
(SI units) are round-off of a zero and compare equal; a vector's components in a table (Fx, Fy,
Fz) on the vector's scale, and the ratios creepage and stick_fraction on a scale of at least 1.
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


def compare_json(a, b, path, rel, out, trajectory=0.0):
    if trajectory > 0:
        return compare_json_trajectory(a, b, path, trajectory, out)
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


def is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def compare_json_trajectory(a, b, path, tol, out, scale=None):
    """compare_json under --trajectory TOL (see the module's doc)."""
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if is_timing(k) or k in WORK_KEYS:
                continue
            if k not in a or k not in b:
                out.append(f"{path}.{k}: only in {'new' if k in b else 'old'}")
            elif k == "balances":
                for key in sorted(set(a[k]) | set(b[k])):
                    x, y = a[k].get(key), b[k].get(key)
                    if not (is_number(x) and is_number(y) and abs(x - y) <= tol):
                        out.append(f"{path}.{k}.{key}: {x!r} -> {y!r}")
            else:
                compare_json_trajectory(a[k], b[k], f"{path}.{k}", tol, out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{path}: {len(a)} entries -> {len(b)}")
            return
        numbers = [abs(v) for v in a + b if is_number(v)]
        list_scale = max(numbers) if numbers else None
        for i, (x, y) in enumerate(zip(a, b)):
            compare_json_trajectory(x, y, f"{path}[{i}]", tol, out, list_scale)
    elif is_number(a) and is_number(b):
        s = scale if scale is not None else max(abs(a), abs(b))
        if abs(a - b) > tol * s and max(abs(a), abs(b)) > ROUND_OFF:
            out.append(f"{path}: {a!r} -> {b!r}")
    elif a != b:
        out.append(f"{path}: {str(a)[:80]!r} -> {str(b)[:80]!r}")


# Under --trajectory, numbers both below this (SI units: nm, nN, nrad/s, ...) are round-off of a
# quantity that is zero (the spin of a ball that has none, the lateral drift of a straight roll),
# however their column's or list's own scale compares.
ROUND_OFF = 1e-9

# Dimensionless ratios (slip over speed, stick over contact area): compared on a scale of at
# least 1, their natural unit (a creepage is a small difference of two speeds).
RATIO_COLUMNS = {"creepage", "stick_fraction"}

# Keys of summary.json that report a solver's work or residuals (wherever they are: the run's,
# a history step's): what another iterative method changes (not compared under --trajectory).
WORK_KEYS = {"solver", "normal_solver", "newton_iterations", "outer_iterations", "outer_last_change",
             "outer_coupling_residual"}

# Columns of a table that count work or measure a solver's residual: what another iterative
# method changes (not compared under --trajectory).
WORK_COLUMNS = {"newton_iterations", "contact_solves", "alternations", "certificate"}


def read_line_pairs(old, new, name, out):
    """Both files' lines, or None (and the difference said) when their counts differ."""
    with open(old) as f:
        a = f.read().splitlines()
    with open(new) as f:
        b = f.read().splitlines()
    if len(a) != len(b):
        out.append(f"{name}: {len(a)} lines -> {len(b)}")
        return None
    return a, b


def compare_table_trajectory(old, new, name, tol, out):
    """Columns of numbers within tol of the column's largest magnitude (the header may differ in nothing)."""
    lines = read_line_pairs(old, new, name, out)
    if lines is None:
        return
    a, b = without_added_work_columns(*lines)
    header = a[0].replace(",", " ").split() if a and isinstance(numbers_or_text(a[0]), str) else []
    skipped = {c for c, column in enumerate(header) if column in WORK_COLUMNS}
    rows = []
    for i, (x, y) in enumerate(zip(a, b)):
        nx, ny = numbers_or_text(x), numbers_or_text(y)
        if isinstance(nx, list) and isinstance(ny, list) and len(nx) == len(ny):
            rows.append((i, nx, ny))
        elif x != y:
            out.append(f"{name}:{i + 1}: {x[:80]!r} -> {y[:80]!r}")
            return
    if not rows:
        return
    width = max(len(r[1]) for r in rows)
    scale = [0.0] * width
    for _, nx, ny in rows:
        for c, (p, q) in enumerate(zip(nx, ny)):
            scale[c] = max(scale[c], abs(p), abs(q))
    # A vector's components (Fx, Fy, Fz; x, y, z) on the vector's scale: a component that is zero
    # by symmetry carries the solver's noise of the whole vector. Ratios on a scale of at least 1.
    groups = {}
    for c, column in enumerate(header[:width]):
        if len(column) <= 2 and column[-1:] in ("x", "y", "z"):
            groups.setdefault(column[:-1], []).append(c)
    for members in groups.values():
        group_scale = max(scale[c] for c in members)
        for c in members:
            scale[c] = group_scale
    for c, column in enumerate(header[:width]):
        if column in RATIO_COLUMNS:
            scale[c] = max(scale[c], 1.0)
    for i, nx, ny in rows:
        for c, (p, q) in enumerate(zip(nx, ny)):
            if c in skipped:
                continue
            if not (abs(p - q) <= tol * scale[c] or max(abs(p), abs(q)) <= ROUND_OFF or (math.isnan(p) and math.isnan(q))):
                out.append(f"{name}:{i + 1}: column {c + 1}: {p!r} -> {q!r} (scale {scale[c]:.6g})")
                return


def without_added_work_columns(a, b):
    """The new table without the work-count columns a newer version added (same order otherwise):
    an output that gained a column of counts still compares with the one before it."""
    def columns(lines):
        return lines[0].split(",") if lines and isinstance(numbers_or_text(lines[0]), str) else []
    ha, hb = columns(a), columns(b)
    if not ha or ha == hb or [c for c in hb if c in ha] != ha or any(c not in WORK_COLUMNS for c in hb if c not in ha):
        return a, b
    keep = [i for i, c in enumerate(hb) if c in ha]
    return a, [",".join(line.split(",")[i] for i in keep) for line in b]


def numbers_or_text(line):
    fields = line.replace(",", " ").split()
    try:
        return [float(f) for f in fields]
    except ValueError:
        return line


def compare_table(old, new, name, rel, out):
    lines = read_line_pairs(old, new, name, out)
    if lines is None:
        return
    a, b = lines
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
    ap.add_argument("--trajectory", type=float, default=0.0)
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
                    compare_json(json.load(f), json.load(g), rel_name, args.rel, out, args.trajectory)
            elif args.trajectory > 0:
                compare_table_trajectory(old, new, rel_name, args.trajectory, out)
            else:
                compare_table(old, new, rel_name, args.rel, out)
    for line in out:
        print(line)
    return 1 if out else 0


if __name__ == "__main__":
    sys.exit(main())
