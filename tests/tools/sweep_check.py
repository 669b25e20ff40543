#!/usr/bin/env python3
"""ctest tools.sweep: a small sweep of the particles lab's oscillator, checked from outside.
The CSV has one row per combination and seed with the expected columns; a bad value is reported in its
row and does not stop the sweep; each reported metric equals that of the same run made directly with
the lab (options after "--" reach every run: here --dt); the plot is a PNG that is not blank. Usage: sweep_check.py SWEEP_PY BIN_DIR WORK_DIR"""
import csv
import json
import os
import shutil
import subprocess
import sys

sweep, bin_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
out = os.path.join(work, "out")
args = [sys.executable, sweep, "particles", "--scene", "oscillator", "--set", "h=0.02,0.04",
        "--set", "integrator=rk4,euler,no-such-integrator", "--seeds", "2", "--metric", "error",
        "--seconds", "3", "--jobs", "2", "--bin-dir", bin_dir, "--out", out, "--", "--dt", "0.005"]
done = subprocess.run(args, capture_output=True, text=True)
print(done.stdout)
print(done.stderr[-2000:])
failures = []
def expect(ok, what):
    if not ok:
        failures.append(what)

expect(done.returncode == 0, f"the sweep exited {done.returncode}")
with open(os.path.join(out, "sweep.csv"), newline="", encoding="utf-8") as f:
    rows = list(csv.DictReader(f))
expect(len(rows) == 2 * 3 * 2, f"{len(rows)} rows, expected 12 (2 h x 3 integrators x 2 seeds)")
for column in ("h", "integrator", "seed", "status", "message", "particles.error", "sim_time_s"):
    expect(column in rows[0], f"no column {column}")
combos = {(r["h"], r["integrator"], r["seed"]) for r in rows}
expect(len(combos) == 12, "a combination is missing or repeated")
for r in rows:
    if r["integrator"] == "no-such-integrator":
        expect(r["status"] == "exit 2" and "no-such-integrator" in r["message"],
               f"the bad value's row says {r['status']!r} {r['message']!r}")
        continue
    expect(r["status"] == "ok", f"run {r['h']} {r['integrator']} {r['seed']}: {r['status']} {r['message']}")
    expect(float(r.get("dt") or "nan") == 0.005, f"run {r['h']} {r['integrator']}: dt {r.get('dt')}, expected 0.005")
    direct = subprocess.run([os.path.join(bin_dir, "pba-particles"), "--headless", "--scene", "oscillator",
                             "--seconds", "3", "--dt", "0.005", "--seed", r["seed"], "--set", f"h={r['h']}",
                             "--set", f"integrator={r['integrator']}", "--metrics", "-"],
                            capture_output=True, text=True, check=True)
    want = json.loads(direct.stdout)["particles"]["error"]
    expect(float(r["particles.error"]) == want,
           f"run {r['h']} {r['integrator']}: the CSV says error {r['particles.error']}, the lab {want}")
png = os.path.join(out, "sweep.png")
try:
    import matplotlib.image
    image = matplotlib.image.imread(png)
    expect(image.shape[0] > 100 and image.shape[1] > 100, f"the plot is {image.shape}")
    expect(float(image[..., :3].std()) > 0.05, "the plot is blank")
except ImportError:
    failures.append("python3-matplotlib is missing (./pba doctor installs it)")
except OSError as e:
    failures.append(f"no plot: {e}")
for f in failures:
    print("FAIL:", f)
print("ok: sweep CSV, failures in rows, metrics as the lab reports them, plot" if not failures else "")
sys.exit(1 if failures else 0)
