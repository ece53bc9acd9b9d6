#!/usr/bin/env python3
"""Black-box mutation run against the command line, as a hostile user or a
broken pipeline would feed it: the rerun of issue 15's table. Not part of the
suite (random, and minutes long); run by hand, see docs/hostile-input.md.

Usage: tests/hostile/cli_mutation.py WORKBENCH [--minutes M] [--seed S]

Each case runs the executable under a timeout and is classed by how it ended:
  ran      exit 0 (the input was usable, e.g. a mutated number still valid);
  refused  exit 2 with errors on stderr, one line each, each naming the
           command ("sdf-workbench render: FILE: json.path: ...");
  crash    killed by a signal (SIGSEGV, SIGABRT, ...);
  hang     still running at the timeout;
  other    any other exit (1 from an uncaught exception, a bare bad_alloc,
           ...), or exit 2 without such messages.
Classes: mutated scenes on the CPU and GL backends, formulas inside scenes,
implicitize and groebner inputs. Prints a table and the inputs of every case
not ok (kept in the work folder)."""

import argparse
import json
import os
import random
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TIMEOUT = 60  # seconds per case: the issue counted a case over 20-60 s as a hang
ARGUMENT_LIMIT = 100000  # bytes: Linux refuses one argument of 128 KiB or more

FORMULAS = ["length(p) - 1", "sin(x) + cos(y) + z", "max(abs(x), abs(y)) - 0.5", "x^2 + y^2 - z^2 - 1",
            "let q = abs(p) - vec3(1, 1, 1); length(max(q, 0.0)) - 0.1", "pow(x, 3) - y * exp(z) - log(1 + x*x)"]
PARAMETRICS = ["x = u*v; y = v; z = u^2", "x = cos(u); y = sin(u); z = v", "x = u^2 - v^2; y = 2*u*v; z = u",
               "x = u/(1+u^2); y = v; z = u*v"]
IDEALS = [("x^2 - y; x*y - 1", "x,y"), ("x^2 + y^2 + z^2 - 1; x - y*z; z^2 - x", "x,y,z"),
          ("x*y - z; y*z - x; x*z - y", "x,y,z")]


def scene_files():
    for folder, _, names in os.walk(os.path.join(ROOT, "scenes")):
        for name in names:
            if name.endswith(".json"):
                yield os.path.join(folder, name)


def mutate_bytes(data, rng):
    data = bytearray(data)
    for _ in range(rng.randint(1, 8)):
        kind = rng.randrange(6)
        at = rng.randrange(len(data) + 1)
        if kind == 0 and data:  # flip a byte
            data[min(at, len(data) - 1)] = rng.randrange(256)
        elif kind == 1:  # insert a burst of structure
            data[at:at] = rng.choice([b"[" * 3000, b"{\"a\":" * 2000, b"-" * 5000, b"9" * 400, b"\x00", b"1e999"])
        elif kind == 2 and data:  # delete a span (a truncated file)
            del data[at:at + rng.randint(1, 200)]
        elif kind == 3:  # duplicate a span
            span = data[at:at + rng.randint(1, 400)]
            data[at:at] = span * rng.randint(2, 50)
        elif kind == 4:
            data = data[:at]  # cut short
        else:  # a hostile number
            data[at:at] = rng.choice([b"1e308", b"-0", b"NaN", b"4294967297", b"0.0000000000001", b"65536"])
    return bytes(data)


def mutate_value(value, rng):
    """Hostile leaves of a parsed scene: huge or odd numbers, long strings."""
    if isinstance(value, dict):
        for key in list(value):
            if rng.random() < 0.15:
                value[key] = mutate_value(value[key], rng)
    elif isinstance(value, list):
        return [mutate_value(v, rng) if rng.random() < 0.3 else v for v in value]
    elif isinstance(value, bool):
        return not value
    elif isinstance(value, (int, float)):
        return rng.choice([0, -1, 1e300, -1e300, 1e-300, 2 ** 31, 65536, 1e6, value * 1e6, 0.5])
    elif isinstance(value, str):
        return rng.choice([value, value[:100] * 1000, "", "nonexistent", "x" * 70000, value[:1000] + "(" * 3000])
    return value


def mutate_tree(scene, rng):
    """The scene's text with one hostile shape of node tree: a root with
    thousands of children, or a chain thousands deep (written as text: too
    deep for Python's own JSON writer)."""
    leaf = '{"kind": "sphere"}'
    if rng.random() < 0.5:
        children = ", ".join([leaf] * rng.choice([50, 500, 3000]))
        root = '{"kind": "%s", "children": [%s]}' % (rng.choice(["union", "smooth_union"]), children)
    else:
        depth = rng.choice([100, 1100, 5000])
        chain = '{"kind": "translate", "offset": [0.1, 0, 0], "children": [' * depth + leaf + "]}" * depth
        root = '{"kind": "union", "children": [%s, %s]}' % (json.dumps(scene.get("root", {})), chain)
    scene["root"] = "@ROOT@"
    return json.dumps(scene).replace('"@ROOT@"', root)


def formula_scene(formula):
    return json.dumps({"format": "sdf-workbench-scene", "version": 1, "root": {"kind": "sdf", "formula": formula}})


def mutate_formula(text, rng):
    choice = rng.randrange(6)
    if choice == 0:
        return "(" * rng.choice([100, 3000, 30000]) + text + ")" * rng.choice([0, 100, 3000])
    if choice == 1:
        return "-" * rng.choice([1000, 50000]) + text
    if choice == 2:
        return " + ".join([text] * rng.choice([100, 5000]))
    if choice == 3:
        return "(" + text + ")^" + rng.choice(["600", "65536", "1e9", "-3", "0.5", "99999999999999999999"])
    if choice == 4:
        return text + "9" * rng.choice([50, 5000, 100000])
    # a command line cannot hold a NUL byte; a scene file can
    return mutate_bytes(text.encode(), rng).decode("latin-1").replace("\0", " ")


def run(command):
    start = time.monotonic()
    process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               start_new_session=True)
    try:
        out, err = process.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        return "hang", time.monotonic() - start, ""
    code = process.returncode
    err = err.decode("utf-8", "replace").strip()
    if code < 0:
        return "crash", time.monotonic() - start, signal.Signals(-code).name
    named = err and all(line.startswith("sdf-workbench ") and ": " in line for line in err.splitlines())
    if code == 0:
        return "ran", time.monotonic() - start, err
    if code == 2 and named:
        return "refused", time.monotonic() - start, err
    return "other", time.monotonic() - start, "exit %d: %s" % (code, err[-300:])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("workbench")
    parser.add_argument("--minutes", type=float, default=10)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    work = tempfile.mkdtemp(prefix="sdfwb_mutation_")
    scenes = sorted(scene_files())
    classes = ["scene, cpu", "scene, gl", "formula in scene", "implicitize", "groebner"]
    table = {c: {"tried": 0, "ran": 0, "refused": 0, "crash": 0, "hang": 0, "other": 0} for c in classes}
    findings = []
    deadline = time.monotonic() + args.minutes * 60
    case = 0
    while time.monotonic() < deadline:
        case += 1
        cls = classes[case % len(classes)]
        path = os.path.join(work, "case%d.json" % case)
        output = os.path.join(work, "out%d.png" % case)
        if cls.startswith("scene"):
            source = open(rng.choice(scenes), "rb").read()
            choice = rng.random()
            if choice < 0.5:
                data = mutate_bytes(source, rng)
            elif choice < 0.8:
                data = json.dumps(mutate_value(json.loads(source), rng)).encode()
            else:
                data = mutate_tree(json.loads(source), rng).encode()
            open(path, "wb").write(data)
            backend = "gl" if cls.endswith("gl") else "cpu"
            command = [args.workbench, "render", path, "-o", output, "--size", "64x36", "--backend", backend]
        elif cls == "formula in scene":
            open(path, "w").write(formula_scene(mutate_formula(rng.choice(FORMULAS), rng)))
            command = [args.workbench, "render", path, "-o", output, "--size", "64x36", "--backend", "cpu"]
        elif cls == "implicitize":
            equations = mutate_formula(rng.choice(PARAMETRICS), rng)[:ARGUMENT_LIMIT]
            command = [args.workbench, "implicitize", equations, "--timeout", "5"]
        else:
            ideal, variables = rng.choice(IDEALS)
            polynomials = mutate_formula(ideal, rng)[:ARGUMENT_LIMIT]
            command = [args.workbench, "groebner", polynomials, "--vars", variables, "--timeout", "5"]
        outcome, seconds, detail = run(command)
        table[cls]["tried"] += 1
        table[cls][outcome] += 1
        if outcome not in ("ran", "refused"):
            findings.append((cls, outcome, "%.1f s" % seconds, detail, " ".join(command)[:400]))
        else:
            for leftover in (path, output):
                if os.path.exists(leftover):
                    os.remove(leftover)
    print("| input class | tried | ran | refused | crash | hang | other |")
    print("|---|---|---|---|---|---|---|")
    for c in classes:
        t = table[c]
        print("| %s | %d | %d | %d | %d | %d | %d |" % (c, t["tried"], t["ran"], t["refused"], t["crash"], t["hang"],
                                                       t["other"]))
    for cls, outcome, seconds, detail, command in findings:
        print("not ok: %s | %s | %s | %s | %s" % (cls, outcome, seconds, detail.splitlines()[0][:200] if detail else "",
                                                  command[:200]))
    print("inputs kept in", work)
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
