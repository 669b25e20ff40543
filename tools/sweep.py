#!/usr/bin/env python3
"""./pba sweep: runs a lab headless over the Cartesian product of parameter values (and seeds), in
parallel processes, and writes a tidy CSV (one row a run), a table and a plot.

  ./pba sweep particles --scene oscillator --set h=0.01,0.02,0.05,0.1 --set integrator=euler,rk4 \
      --metric error --seconds 10

Values: a comma list (`a=1,2,4`, names too: `integrator=euler,rk4`), a linear range `a=START:STOP:N`
(N values, ends included) or a geometric one `a=START:STOP:N:log`. A swept name that the lab has as a
flag (--integrator) is passed as --set like any parameter: every lab flag is also a parameter.
Each run is `pba-LAB --headless --scene S --seed K --set NAME=VALUE ... --metrics FILE`; a run that
fails (bad value: exit 2, crash, time limit) is reported in its row and the sweep goes on. A run the
instability guard paused (exit 3) keeps its metrics, with status "paused".

Outputs in --out (default build/sweeps/LAB-SCENE-TIME): sweep.csv (parameters, seed, status, message,
every metric, flattened with dots: particles.error_rk4), runs/ (each run's metrics JSON) and sweep.png
(each --metric against the first swept parameter, one line per value of the second, the mean over
seeds with their range; a log x axis where the swept values span a decade or more, a log y axis where
the metric spans two). Exit code 0 when the
sweep ran (whatever single runs did), 2 for bad arguments.
"""
import argparse
import csv
import itertools
import json
import math
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor, as_completed

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def die(message):
    print(f"pba sweep: {message}", file=sys.stderr)
    sys.exit(2)


def parse_values(spec):
    """NAME=VALUES -> (name, [strings]); ranges give numbers formatted with repr precision."""
    if "=" not in spec:
        die(f"--set {spec}: expected NAME=VALUES (a,b,c or start:stop:n[:log])")
    name, values = spec.split("=", 1)
    if not name or not values:
        die(f"--set {spec}: expected NAME=VALUES")
    if ":" in values:
        parts = values.split(":")
        if len(parts) not in (3, 4) or (len(parts) == 4 and parts[3] != "log"):
            die(f"--set {spec}: a range is start:stop:n or start:stop:n:log")
        try:
            start, stop, n = float(parts[0]), float(parts[1]), int(parts[2])
        except ValueError:
            die(f"--set {spec}: start and stop must be numbers and n an integer")
        if n < 1:
            die(f"--set {spec}: n must be at least 1")
        geometric = len(parts) == 4
        if geometric and (start <= 0 or stop <= 0):
            die(f"--set {spec}: a log range needs positive ends")
        out = []
        for i in range(n):
            u = i / (n - 1) if n > 1 else 0.0
            v = start * (stop / start) ** u if geometric else start + (stop - start) * u
            out.append(f"{v:.10g}")
        return name, out
    out = [v.strip() for v in values.split(",")]
    if any(not v for v in out):
        die(f"--set {spec}: empty value in the list")
    return name, out


def flatten(obj, prefix=""):
    """Nested metrics JSON -> {dotted.name: scalar}; lists are joined by spaces."""
    flat = {}
    for key, value in obj.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            flat.update(flatten(value, name + "."))
        elif isinstance(value, list):
            flat[name] = " ".join(str(v) for v in value)
        elif isinstance(value, bool):
            flat[name] = "true" if value else "false"
        else:
            flat[name] = value
    return flat


def resolve_metric(name, columns):
    """A metric by its dotted name or by its last part(s) when that is unique."""
    if name in columns:
        return name
    matches = [c for c in columns if c.endswith("." + name)]
    if len(matches) == 1:
        return matches[0]
    if not matches:
        return None
    die(f"--metric {name}: ambiguous, one of {', '.join(sorted(matches))}")


def run_one(exe, args, combo, seed, index, runs_dir, limit_s):
    metrics_file = os.path.join(runs_dir, f"run-{index:04d}.json")
    command = [exe, "--headless", "--seed", str(seed), "--metrics", metrics_file] + args
    for name, value in combo:
        command += ["--set", f"{name}={value}"]
    row = {"status": "ok", "message": "", "metrics": {}}
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=limit_s)
    except subprocess.TimeoutExpired:
        row.update(status="timeout", message=f"no result within {limit_s} s")
        return row
    lines = [line for line in done.stderr.splitlines() if line.strip()]
    if done.returncode not in (0, 3):
        row.update(status=f"exit {done.returncode}", message=lines[-1] if lines else "")
        return row
    if done.returncode == 3:
        row.update(status="paused", message=lines[-1] if lines else "paused by the instability guard")
    try:
        with open(metrics_file, encoding="utf-8") as f:
            row["metrics"] = flatten(json.load(f))
    except (OSError, ValueError) as e:
        row.update(status="no metrics", message=str(e))
    return row


class Progress:
    """One status line on the terminal: runs done of total, elapsed, estimated time left."""

    def __init__(self, total):
        self.total, self.done, self.start = total, 0, time.monotonic()
        self.tty = sys.stderr.isatty()

    def tick(self):
        self.done += 1
        elapsed = time.monotonic() - self.start
        left = elapsed / self.done * (self.total - self.done)
        width = 30
        bar = "#" * round(width * self.done / self.total)
        text = f"[sweep] [{bar:<{width}}] {self.done}/{self.total} runs, {elapsed:.0f} s elapsed, ~{left:.0f} s left"
        print(("\r" if self.tty else "") + text, end="" if self.tty else "\n", file=sys.stderr, flush=True)
        if self.tty and self.done == self.total:
            print(file=sys.stderr)


def is_number(text):
    try:
        return math.isfinite(float(text))
    except (TypeError, ValueError):
        return False


def spans_decades(values, ratio):
    positive = [v for v in values if v > 0]
    return len(positive) == len(values) and len(values) > 1 and max(positive) / min(positive) >= ratio


def plot(path, rows, swept, metrics, lab, scene):
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("pba sweep: no plot: python3-matplotlib is not installed (apt-get install python3-matplotlib)",
              file=sys.stderr)
        return False
    x_name = swept[0][0]
    group_name = swept[1][0] if len(swept) > 1 else None
    x_values = swept[0][1]
    numeric_x = all(is_number(v) for v in x_values)
    groups = swept[1][1] if group_name else [None]
    fig, axes = plt.subplots(len(metrics), 1, figsize=(7.5, 3.6 * len(metrics)), squeeze=False)
    for axis, metric in zip(axes[:, 0], metrics):
        all_y = []
        for group in groups:
            xs, means, lows, highs = [], [], [], []
            for i, x in enumerate(x_values):
                ys = [r["metrics"][metric] for r in rows
                      if r["params"][x_name] == x and (group is None or r["params"][group_name] == group)
                      and is_number(r["metrics"].get(metric))]
                ys = [float(y) for y in ys]
                if not ys:
                    continue
                xs.append(float(x) if numeric_x else i)
                means.append(sum(ys) / len(ys))
                lows.append(means[-1] - min(ys))
                highs.append(max(ys) - means[-1])
                all_y += ys
            if not xs:
                continue
            label = f"{group_name} = {group}" if group is not None else None
            errors = [lows, highs] if any(lows) or any(highs) else None
            axis.errorbar(xs, means, yerr=errors, marker="o", capsize=3, linewidth=2, label=label)
        if numeric_x and spans_decades([float(v) for v in x_values], 10.0):
            axis.set_xscale("log")
        if all_y and spans_decades(all_y, 100.0):
            axis.set_yscale("log")
        if not numeric_x:
            axis.set_xticks(range(len(x_values)))
            axis.set_xticklabels(x_values, rotation=20)
        axis.set_xlabel(x_name)
        axis.set_ylabel(metric)
        axis.grid(True, which="both", alpha=0.3)
        if group_name:
            axis.legend(fontsize=9)
    axes[0, 0].set_title(f"pba-{lab} {scene}: sweep of {', '.join(n for n, _ in swept)}")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def print_table(rows, swept, metrics):
    heads = [n for n, _ in swept] + ["seed", "status"] + metrics
    table = []
    for r in rows:
        cells = [r["params"][n] for n, _ in swept] + [str(r["seed"]), r["status"]]
        for m in metrics:
            v = r["metrics"].get(m, "")
            cells.append(f"{v:.6g}" if isinstance(v, float) else str(v))
        table.append(cells)
    widths = [max(len(h), *(len(row[i]) for row in table)) for i, h in enumerate(heads)]
    print("  ".join(h.ljust(w) for h, w in zip(heads, widths)))
    for cells in table:
        print("  ".join(c.ljust(w) for c, w in zip(cells, widths)))


def main():
    ap = argparse.ArgumentParser(prog="./pba sweep", description=__doc__.split("\n\n")[0])
    ap.add_argument("lab")
    ap.add_argument("--scene", help="scene name or scene file (default: the lab's first)")
    ap.add_argument("--set", action="append", default=[], metavar="NAME=VALUES", dest="sets")
    ap.add_argument("--seeds", type=int, default=1, help="seeds 1..N per combination (default 1)")
    ap.add_argument("--metric", action="append", default=[], help="metric(s) for the table and the plot")
    time_group = ap.add_mutually_exclusive_group()
    time_group.add_argument("--seconds", type=float)
    time_group.add_argument("--frames", type=int)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--out", help="output folder (default build/sweeps/LAB-SCENE-TIME)")
    ap.add_argument("--bin-dir", default=os.path.join(ROOT, "build", "release", "bin"))
    ap.add_argument("--time-limit", type=float, default=600.0, help="seconds per run before it counts as failed")
    # Everything after the first "--" goes to every run of the lab (argparse alone would read the lab's
    # options as more positional arguments after LAB and refuse them).
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    a = ap.parse_args(argv[:split])
    a.lab_args = argv[split + 1:]
    if not a.sets:
        die("nothing to sweep: give at least one --set NAME=VALUES")
    if a.seeds < 1 or a.jobs < 1:
        die("--seeds and --jobs must be at least 1")
    exe = os.path.join(a.bin_dir, f"pba-{a.lab}")
    if not os.access(exe, os.X_OK):
        die(f"no lab executable {exe} (labs: ./pba labs; build with ./pba run LAB or cmake --build)")
    swept = [parse_values(s) for s in a.sets]
    names = [n for n, _ in swept]
    if len(set(names)) != len(names):
        die("a parameter is swept twice")
    args = (["--scene", a.scene] if a.scene else []) + a.lab_args
    if a.seconds is not None:
        args += ["--seconds", f"{a.seconds:g}"]
    elif a.frames is not None:
        args += ["--frames", str(a.frames)]
    scene = a.scene or "default"
    out = a.out or os.path.join(ROOT, "build", "sweeps",
                                f"{a.lab}-{os.path.basename(scene).replace('.json', '')}-{time.strftime('%Y%m%d-%H%M%S')}")
    runs_dir = os.path.join(out, "runs")
    os.makedirs(runs_dir, exist_ok=True)

    combos = list(itertools.product(*[[(n, v) for v in values] for n, values in swept]))
    jobs = [(combo, seed) for combo in combos for seed in range(1, a.seeds + 1)]
    print(f"[sweep] pba-{a.lab} {scene}: {len(combos)} combinations x {a.seeds} seed(s) = {len(jobs)} runs, "
          f"{a.jobs} at a time, into {out}", file=sys.stderr)
    rows = [None] * len(jobs)
    progress = Progress(len(jobs))
    with ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = {pool.submit(run_one, exe, args, combo, seed, i, runs_dir, a.time_limit): i
                   for i, (combo, seed) in enumerate(jobs)}
        for future in as_completed(futures):
            i = futures[future]
            combo, seed = jobs[i]
            row = future.result()
            row.update(params=dict(combo), seed=seed)
            rows[i] = row
            progress.tick()

    metric_columns = sorted({k for r in rows for k in r["metrics"]})
    metrics = []
    for m in a.metric:
        resolved = resolve_metric(m, metric_columns)
        if resolved is None:
            print(f"pba sweep: --metric {m}: no run reported it (metrics: {', '.join(metric_columns[:12])}, ...)",
                  file=sys.stderr)
        else:
            metrics.append(resolved)
    csv_path = os.path.join(out, "sweep.csv")
    with open(csv_path, "w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f)
        writer.writerow(names + ["seed", "status", "message"] + metric_columns)
        for r in rows:
            writer.writerow([r["params"][n] for n in names] + [r["seed"], r["status"], r["message"]] +
                            [r["metrics"].get(c, "") for c in metric_columns])
    print_table(rows, swept, metrics)
    failed = sum(1 for r in rows if r["status"] not in ("ok", "paused"))
    print(f"[sweep] {len(rows)} runs, {failed} failed; {csv_path}", file=sys.stderr)
    if metrics and plot(os.path.join(out, "sweep.png"), rows, swept, metrics, a.lab, scene):
        print(f"[sweep] plot: {os.path.join(out, 'sweep.png')}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
