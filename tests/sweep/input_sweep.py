#!/usr/bin/env python3
"""The generated bad-input sweep: every numeric value of every bundled example set to NaN, inf,
-1, 0 and 1e300, run through the command line (validate, then solve when validate accepts it)
or the Python module (solve), each run checked for what a user may rely on:

- bad input is exit 2 (Python: InputError) with a message naming a key, never a crash (a
  signal, exit 4, a Python exception of another kind) or a hang (a time limit per run);
- exit 0 (Python: a returned result) carries finite numbers only;
- exit 3 (not converged) and 2 (a result limit) leave a whole summary.json.

Usage: input_sweep.py cli|python BINARY_OR_MODULE_DIR [--only EXAMPLE ...] [--budget SECONDS].
Prints one line per failure and a count; exit 1 when a run failed. Runs are shortened (plots off,
a dynamic run at most 40 steps), so the sweep tests input handling, not accuracy. With a budget
(the CI's slow tests: 900 s), the command line's runs are taken in turn from every example and
the Python module's examples share the time, so a slow machine covers a sample of every example
rather than the first examples whole; what was left is printed.
"""
import argparse
import copy
import json
import math
import os
import subprocess
import sys
import tempfile
import time

SOURCE = os.environ.get("DYNCONTACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
VALUES = [("nan", float("nan")), ("inf", float("inf")), ("-1", -1.0), ("0", 0.0), ("1e300", 1e300)]
SECONDS_PER_RUN = 120


def examples(only):
    folder = os.path.join(SOURCE, "examples")
    names = sorted(f[:-5] for f in os.listdir(folder) if f.endswith(".json"))
    return [n for n in names if not only or n in only]


def numeric_paths(node, path=()):
    """(path, value) of every number (bools excluded) in a JSON document."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from numeric_paths(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from numeric_paths(v, path + (i,))
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield path, node


def with_value(doc, path, value):
    out = copy.deepcopy(doc)
    node = out
    for p in path[:-1]:
        node = node[p]
    node[path[-1]] = value
    return out


def shortened(doc):
    """Plots off, output fields off; a dynamic run at most 40 steps."""
    out = copy.deepcopy(doc)
    out.setdefault("output", {})
    if isinstance(out["output"], dict):
        out["output"]["plots"] = False
    time = out.get("time")
    if isinstance(time, dict):
        dt, t_end = time.get("dt"), time.get("t_end")
        if isinstance(dt, (int, float)) and isinstance(t_end, (int, float)) and dt > 0 and math.isfinite(dt):
            if t_end > 40 * dt:
                time["t_end"] = 40 * dt
    return out


def dotted(path):
    return ".".join(str(p) for p in path)


def finite_numbers(node):
    if isinstance(node, dict):
        return all(finite_numbers(v) for v in node.values())
    if isinstance(node, list):
        return all(finite_numbers(v) for v in node)
    if isinstance(node, float):
        return math.isfinite(node)
    return True


def json_text(doc):
    """NaN and infinities as JSON cannot hold them: the tokens a user would type (the reader refuses them)."""
    return json.dumps(doc, allow_nan=True)


def check_cli(binary, name, doc, path, label, work):
    """A failure message, or None."""
    key = dotted(path)
    case = os.path.join(work, "case.json")
    with open(case, "w") as f:
        f.write(json_text(shortened(with_value(doc, path, dict(VALUES)[label]))))
    try:
        v = subprocess.run([binary, "validate", case], capture_output=True, text=True, timeout=SECONDS_PER_RUN)
    except subprocess.TimeoutExpired:
        return f"{name} {key}={label}: validate did not finish in {SECONDS_PER_RUN} s"
    if v.returncode == 2:
        return None if "error: " in v.stderr else f"{name} {key}={label}: validate exit 2 without an error line"
    if v.returncode != 0:
        return f"{name} {key}={label}: validate exit {v.returncode}: {v.stderr.strip()[-300:]}"
    out = os.path.join(work, "out")
    try:
        s = subprocess.run([binary, "solve", case, "-q", "--out", out], capture_output=True, text=True,
                           timeout=SECONDS_PER_RUN)
    except subprocess.TimeoutExpired:
        return f"{name} {key}={label}: solve did not finish in {SECONDS_PER_RUN} s"
    if s.returncode not in (0, 2, 3):
        return f"{name} {key}={label}: solve exit {s.returncode}: {s.stderr.strip()[-300:]}"
    if s.returncode == 2 and "error: " not in s.stderr:
        return f"{name} {key}={label}: solve exit 2 without an error line"
    summary_path = os.path.join(out, "summary.json")
    if not os.path.exists(summary_path):
        return None if s.returncode == 2 else f"{name} {key}={label}: exit {s.returncode} without summary.json"
    try:
        with open(summary_path) as f:
            summary = json.load(f)
    except ValueError as e:
        return f"{name} {key}={label}: summary.json is not whole JSON ({e})"
    if s.returncode == 0 and not finite_numbers(summary):
        return f"{name} {key}={label}: exit 0 with a number that is not finite in summary.json"
    return None


def interleaved(runs_by_example):
    """Runs taken in turn from every example: the first of each, then the second of each, ..."""
    out, k = [], 0
    while any(k < len(r) for r in runs_by_example):
        out += [r[k] for r in runs_by_example if k < len(r)]
        k += 1
    return out


def cli(binary, only, budget):
    failures, runs, start = [], 0, time.monotonic()
    docs, plan = {}, []
    for name in examples(only):
        with open(os.path.join(SOURCE, "examples", name + ".json")) as f:
            docs[name] = json.load(f)
        plan.append([(name, path, label) for path, _ in numeric_paths(docs[name]) for label, _ in VALUES])
    plan = interleaved(plan)
    with tempfile.TemporaryDirectory() as work:
        for name, path, label in plan:
            if budget and time.monotonic() - start > budget:
                left = sorted({n for n, _, _ in plan[runs:]})
                print(f"budget of {budget:g} s reached: {len(plan) - runs} of {len(plan)} runs left "
                      f"(examples with runs left: {', '.join(left)})")
                break
            runs += 1
            failure = check_cli(binary, name, docs[name], path, label, work)
            if failure:
                failures.append(failure)
                print("FAIL", failure, flush=True)
    print(f"{runs} runs, {len(failures)} failed")
    return 1 if failures else 0


# One child process per example: a crash of the module ends that child only, and is reported.
CHILD = r"""
import json, math, sys, time, warnings
import dyncontact
sys.path.insert(0, sys.argv[1])
import input_sweep as sweep
name = sys.argv[2]
with open(sys.argv[3]) as f:
    doc = json.load(f)
deadline = float(sys.argv[4])  # time.time() after which no run starts (0: none)
warnings.simplefilter("ignore")
problem = doc.get("problem")
for path, _ in sweep.numeric_paths(doc):
    for label, value in sweep.VALUES:
        key = sweep.dotted(path)
        if deadline and time.time() > deadline:
            print("LEFT", flush=True)
            continue
        print("START", key, label, flush=True)
        try:
            r = dyncontact.solve(sweep.shortened(sweep.with_value(doc, path, value)))
            if not sweep.finite_numbers({k: v for k, v in r.items() if k not in ("fields", "timeseries")}):
                print("FAIL", name, key + "=" + label, "a returned result with a number that is not finite", flush=True)
        except dyncontact.InputError as e:  # ResultLimitError too
            if not getattr(e, "key", ""):
                print("FAIL", name, key + "=" + label, "InputError without .key:", e, flush=True)
        except Exception as e:
            print("FAIL", name, key + "=" + label, type(e).__name__ + ":", str(e)[:300], flush=True)
        print("END", flush=True)
"""


def python(module_dir, only, budget):
    failures, runs, left = [], 0, 0
    env = dict(os.environ, PYTHONPATH=module_dir + os.pathsep + os.environ.get("PYTHONPATH", ""))
    here = os.path.dirname(os.path.abspath(__file__))
    names = []
    for name in examples(only):
        with open(os.path.join(SOURCE, "examples", name + ".json")) as f:
            if json.load(f).get("problem") != "finite":  # run by the command line only
                names.append(name)
    start = time.time()
    for k, name in enumerate(names):
        path = os.path.join(SOURCE, "examples", name + ".json")
        # With a budget each example may run until its share of it is used up (what an earlier
        # example left over goes to the later ones).
        deadline = start + budget * (k + 1) / len(names) if budget else 0.0
        child = subprocess.Popen([sys.executable, "-c", CHILD, here, name, path, repr(deadline)], env=env,
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            out, err = child.communicate(timeout=SECONDS_PER_RUN * 10)
        except subprocess.TimeoutExpired:
            child.kill()
            out, err = child.communicate()
            failures.append(f"{name}: did not finish in {SECONDS_PER_RUN * 10} s")
        last = None
        for line in out.splitlines():
            if line.startswith("START"):
                last, runs = line, runs + 1
            elif line.startswith("END"):
                last = None
            elif line.startswith("FAIL"):
                failures.append(line[5:])
            elif line.startswith("LEFT"):
                left += 1
        if child.returncode != 0:
            failures.append(f"{name}: the child ended with {child.returncode} at {last}: {err.strip()[-300:]}")
    for f in failures:
        print("FAIL", f)
    if left:
        print(f"budget of {budget:g} s reached: {left} runs left")
    print(f"{runs} runs, {len(failures)} failed")
    return 1 if failures else 0


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("mode", choices=["cli", "python"])
    p.add_argument("target", help="the dyncontact program (cli) or the folder of the Python module (python)")
    p.add_argument("--only", nargs="*", default=[])
    p.add_argument("--budget", type=float, default=0.0, help="seconds after which no run starts (0: none)")
    a = p.parse_args()
    return cli(a.target, a.only, a.budget) if a.mode == "cli" else python(a.target, a.only, a.budget)


if __name__ == "__main__":
    sys.exit(main())
