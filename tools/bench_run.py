#!/usr/bin/env python3
"""What one `./pba bench` run measured, merged into the results of the earlier runs (build/PRESET/bench-run.json).

  bench_run.py load
      Prints the machine's 1-minute load average (or "n/a" where the system has none).
  bench_run.py record RUN.json --scenes DIR --kernels DIR --build BUILD_DIR --commit C --preset P --date D
                      --load-start L [--filter REGEX] [--seconds S] [--frames N]
      Reads the labs' metrics reports (DIR/NNNN.json in the labs' scene order, `--metrics` of a headless
      run) and the Google Benchmark JSON files (DIR/BINARY.json, with the seconds it ran in
      DIR/BINARY.seconds), and merges them into RUN.json: a scene or a benchmark binary measured now
      replaces its earlier rows, the others keep theirs with the run they come from, so a filtered run
      (--filter) keeps the rest of the page. Runs no row refers to any more are dropped.
  bench_run.py figures RUN.json
      Prints this run's figures as NAME<TAB>VALUE<TAB>UNIT lines for bench_results.py (scene medians and
      p95s in ms, every benchmark's time in its own unit).

RUN.json: {"runs": [{"id", "date", "commit", "preset", "build_type", "flags", "compiler", "cpu", "cores",
"load_start", "load_end", "seconds", "frames", "filter"}], "scenes": {"LAB/SCENE": {"lab", "scene", "frames",
"median_ms", "p95_ms", "max_ms", "heavy", "run", "order"}}, "kernels": {"BINARY": {"run", "seconds",
"benchmarks": [{"name", "time", "unit", "items_per_second", "label", "counters", "error"}]}}}. The time of a
benchmark is its manual time where it sets one (the name ends in /manual_time), else its CPU time.
"""
import argparse
import glob
import json
import os
import platform
import re
import subprocess
import sys

# Keys of a Google Benchmark JSON row that are not user counters.
BENCHMARK_FIELDS = {"name", "family_index", "per_family_instance_index", "run_name", "run_type", "repetitions",
                    "repetition_index", "threads", "iterations", "real_time", "cpu_time", "time_unit",
                    "bytes_per_second", "items_per_second", "label", "error_occurred", "error_message",
                    "aggregate_name", "aggregate_unit"}


def load_average():
    try:
        return round(os.getloadavg()[0], 2)
    except (AttributeError, OSError):  # Windows has no load average
        return None


def print_load_average(_args):
    load = load_average()
    print("n/a" if load is None else load)


def cpu_model():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    if platform.system() == "Darwin":
        try:
            return subprocess.run(["sysctl", "-n", "machdep.cpu.brand_string"], capture_output=True, text=True,
                                  check=True).stdout.strip()
        except (OSError, subprocess.CalledProcessError):
            pass
    return platform.processor() or platform.machine() or "unknown"


def cmake_cache(build):
    cache = {}
    try:
        with open(os.path.join(build, "CMakeCache.txt"), encoding="utf-8") as f:
            for line in f:
                m = re.match(r"^([A-Za-z_0-9-]+):[A-Z]+=(.*)$", line.rstrip("\n"))
                if m:
                    cache[m.group(1)] = m.group(2)
    except OSError:
        pass
    return cache


def compiler(cache):
    exe = cache.get("CMAKE_CXX_COMPILER", "")
    if not exe:
        return "unknown"
    try:
        first = subprocess.run([exe, "--version"], capture_output=True, text=True, check=True).stdout.splitlines()
        return first[0].strip() if first else exe
    except (OSError, subprocess.CalledProcessError):
        return exe


def read_json(path, what=""):
    """The JSON value of a file, or a ValueError whose one line names the file (and line), then `what`."""
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        raise ValueError(f"{path}: cannot be read ({e.strerror})")
    except json.JSONDecodeError as e:
        raise ValueError(f"{path}:{e.lineno}: not JSON ({e.msg})" + (f"; {what}" if what else ""))


def scene_rows(directory, run_id):
    rows = {}
    for path in sorted(glob.glob(os.path.join(directory, "*.json"))):
        report = read_json(path, "expected a lab's --metrics report")
        try:
            step = report["step_ms"]
            row = {"lab": str(report["lab"]), "scene": str(report["scene"]), "frames": int(report["frames"]),
                   "median_ms": float(step["median"]), "p95_ms": float(step["p95"]), "max_ms": float(step["max"]),
                   "heavy": bool(report.get("heavy", False)), "run": run_id,
                   "order": int(re.sub(r"\D", "", os.path.basename(path)) or 0)}
        except (KeyError, TypeError, ValueError) as e:
            raise ValueError(f"{path}: field {e}: missing or not a number (expected a lab's --metrics report)")
        rows[f"{row['lab']}/{row['scene']}"] = row
    return rows


def benchmark_rows(data):
    """The rows of one binary: medians where it ran repetitions, else every run."""
    rows = data.get("benchmarks", [])
    medians = [r for r in rows if r.get("run_type") == "aggregate" and r.get("aggregate_name") == "median"]
    out = []
    for r in medians or [r for r in rows if r.get("run_type", "iteration") == "iteration"]:
        name = r.get("run_name", r["name"]) if medians else r["name"]
        manual = "/manual_time" in name
        counters = {k: v for k, v in r.items()
                    if k not in BENCHMARK_FIELDS and isinstance(v, (int, float)) and not isinstance(v, bool)}
        out.append({"name": name, "time": r.get("real_time" if manual else "cpu_time"),
                    "unit": r.get("time_unit", "ns"), "items_per_second": r.get("items_per_second"),
                    "label": r.get("label", ""), "counters": counters,
                    "error": r.get("error_message", "") if r.get("error_occurred") else ""})
    return out


def seconds_of(path):
    """The wall time a binary ran [s] (BINARY.seconds beside its JSON), or None."""
    try:
        with open(path, encoding="utf-8") as f:
            return float(f.read().strip())
    except (OSError, ValueError):
        return None


def record(args):
    try:
        run = read_json(args.run, "delete it to start afresh") if os.path.exists(args.run) else {}
    except ValueError as e:
        print(f"bench_run: {e}: starting afresh", file=sys.stderr)
        run = {}
    runs = run.get("runs", []) if isinstance(run.get("runs"), list) else []
    run_id = max([r.get("id", 0) for r in runs] + [0]) + 1
    cache = cmake_cache(args.build)
    build_type = cache.get("CMAKE_BUILD_TYPE", "")
    runs.append({"id": run_id, "date": args.date, "commit": args.commit, "preset": args.preset,
                 "build_type": build_type, "flags": cache.get(f"CMAKE_CXX_FLAGS_{build_type.upper()}", ""),
                 "compiler": compiler(cache), "cpu": cpu_model(), "cores": os.cpu_count(),
                 "load_start": args.load_start, "load_end": load_average(), "seconds": args.seconds,
                 "frames": args.frames, "filter": args.filter})
    scenes = dict(run.get("scenes", {}))
    scenes.update(scene_rows(args.scenes, run_id))
    kernels = dict(run.get("kernels", {}))
    for path in sorted(glob.glob(os.path.join(args.kernels, "*.json"))):
        binary = os.path.splitext(os.path.basename(path))[0]
        rows = benchmark_rows(read_json(path, "expected Google Benchmark JSON"))
        kernels[binary] = {"run": run_id, "benchmarks": rows,
                           "seconds": seconds_of(os.path.splitext(path)[0] + ".seconds")}
    used = {row["run"] for row in scenes.values()} | {k["run"] for k in kernels.values()} | {run_id}
    out = {"runs": [r for r in runs if r.get("id") in used], "scenes": scenes, "kernels": kernels}
    with open(args.run, "w", encoding="utf-8") as f:
        json.dump(out, f, indent=1, sort_keys=True)
        f.write("\n")


def figures(args):
    run = read_json(args.run, "written by bench_run.py record")
    latest = max(r["id"] for r in run["runs"])
    for key, row in sorted(run["scenes"].items()):
        if row["run"] == latest:
            print(f"scene/{key} median\t{row['median_ms']}\tms\nscene/{key} p95\t{row['p95_ms']}\tms")
    for binary, k in sorted(run["kernels"].items()):
        if k["run"] == latest:
            for b in k["benchmarks"]:
                if b["time"] is not None and not b["error"]:
                    print(f"kernel/{binary}/{b['name']}\t{b['time']}\t{b['unit']}")


def optional_number(text):
    """A number, or None for "n/a" (a system without a load average)."""
    return None if text == "n/a" else float(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", required=True)
    sub.add_parser("load")
    r = sub.add_parser("record")
    r.add_argument("run")
    for name in ("--scenes", "--kernels", "--build", "--commit", "--preset", "--date"):
        r.add_argument(name, required=True)
    r.add_argument("--load-start", type=optional_number, default=None)
    r.add_argument("--filter", default="")
    r.add_argument("--seconds", type=float, default=None)
    r.add_argument("--frames", type=int, default=None)
    f = sub.add_parser("figures")
    f.add_argument("run")
    args = ap.parse_args()
    commands = {"load": print_load_average, "record": record, "figures": figures}
    try:
        commands[args.command](args)
    except ValueError as e:
        print(f"pba bench: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
