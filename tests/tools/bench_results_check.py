#!/usr/bin/env python3
"""tools/bench_results.py (./pba bench's JSON and --compare) on figures written here: units are converted
to milliseconds, every figure of either run is listed with its change, changes beyond the threshold are
marked, and a malformed reference file gets exit 2 and one line naming the file and the field.
Usage: bench_results_check.py TOOL WORK_DIR"""
import json
import os
import subprocess
import sys

tool, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
failures = []


def run(*args):
    return subprocess.run([sys.executable, tool, *args], capture_output=True, text=True)


def expect(condition, what):
    if not condition:
        failures.append(what)


def results(name, rows):
    tsv, out = os.path.join(work, name + ".tsv"), os.path.join(work, name + ".json")
    with open(tsv, "w", encoding="utf-8") as f:
        f.writelines(f"{n}\t{v}\t{u}\n" for n, v, u in rows)
    r = run("write", tsv, out, "--commit", name, "--preset", "release", "--date", "2026-12-02")
    expect(r.returncode == 0, f"write {name}: exit {r.returncode}: {r.stderr}")
    return out


before = results("before", [("kernel/b/Step", "2000", "ns"), ("kernel/b/Solve", "3", "us"),
                            ("scene/lab/a median", "1.5", "ms"), ("kernel/b/Gone", "1", "s")])
with open(before, encoding="utf-8") as f:
    figures = json.load(f)["figures"]
# 2000 ns = 0.002 ms, 3 us = 0.003 ms, 1 s = 1000 ms: each a time in milliseconds.
for name, ms in [("kernel/b/Step", 0.002), ("kernel/b/Solve", 0.003), ("scene/lab/a median", 1.5),
                 ("kernel/b/Gone", 1000.0)]:
    expect(abs(figures.get(name, -1) - ms) < 1e-12 * max(ms, 1), f"{name} is {figures.get(name)} ms, not {ms}")

now = results("now", [("kernel/b/Step", "2.5", "us"), ("kernel/b/Solve", "3.1", "us"),
                      ("scene/lab/a median", "1.2", "ms"), ("kernel/b/New", "4", "ms")])
r = run("compare", before, now)
expect(r.returncode == 0, f"compare: exit {r.returncode}: {r.stderr}")
lines = {line.split()[0]: line for line in r.stdout.splitlines() if line.startswith(("kernel/", "scene/"))}
# Step 2.0 → 2.5 µs is +25 % (slower); Solve +3.3 % stays unmarked; the scene −20 % is faster.
expect("+25.0 %" in lines.get("kernel/b/Step", "") and lines["kernel/b/Step"].endswith("slower"),
       f"Step: {lines.get('kernel/b/Step')}")
expect("+3.3 %" in lines.get("kernel/b/Solve", "") and not lines["kernel/b/Solve"].endswith(("slower", "faster")),
       f"Solve: {lines.get('kernel/b/Solve')}")
expect(lines.get("scene/lab/a", "").endswith("faster") and "-20.0 %" in lines.get("scene/lab/a", ""),
       f"scene: {lines.get('scene/lab/a')}")
expect(lines.get("kernel/b/Gone", "").endswith("removed"), f"Gone: {lines.get('kernel/b/Gone')}")
expect(lines.get("kernel/b/New", "").endswith("added"), f"New: {lines.get('kernel/b/New')}")
expect("1 slower and 1 faster" in r.stdout, f"summary: {r.stdout.splitlines()[-1:]}")

for text, field in [('{"figures": {"kernel/x": "fast"}}', "figures.kernel/x"), ('{"commit": "a"}', "figures"),
                    ("[1, 2", ":1:"), ('{"figures": {"kernel/x": -1}}', "figures.kernel/x")]:
    bad = os.path.join(work, "bad.json")
    with open(bad, "w", encoding="utf-8") as f:
        f.write(text)
    r = run("check", bad)
    message = r.stderr.strip()
    expect(r.returncode == 2 and bad in message and field in message and "\n" not in message,
           f"bad reference {text!r}: exit {r.returncode}, message {message!r}")

for f in failures:
    print("FAIL:", f)
print("bench_results: " + ("ok" if not failures else f"{len(failures)} failures"))
sys.exit(1 if failures else 0)
