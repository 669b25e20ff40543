#!/usr/bin/env python3
"""One exercise, one grade (docs/architecture.md §5, docs/architecture.md "Exercises"), checked on one build.

Usage: check_exercise_isolation.py TEST_DIR CATALOG.tsv [--jobs N] [--work DIR] [--exclude REGEX] [--skip-label L]

TEST_DIR holds the ctest lists of a build whose tests run the switchable tree's physics library
(tools/student_release.sh --switchable; tools/check_student_release.sh puts it on LD_LIBRARY_PATH): every
solution sits behind a run-time switch, so a test process runs tag T's stub when PBA_STUB_EXERCISES
names T, and appends each tag whose code it runs to the file PBA_EXERCISE_TRACE names.

1. Trace run: every test of the build runs once with every solution in place and its own trace file.
   Every test must pass. An exercise test of tag A must run A's code and no other exercise's code.
2. For each tag T, with only T stubbed, the tests that can notice are rerun: T's own tests, which must
   all fail, and every test whose trace shows it ran T's code, which must all pass. A test that never
   ran T's code is unaffected by T's switch (the switch is consulted only inside T's functions, and
   runs are deterministic), so it passes with T stubbed exactly as it passed in the trace run.
Start-up probes (which call every exercise on purpose to show the lab's banner) are not traced.

Cost: one run of the suite plus, per tag, the tests that run that tag, instead of one run of the whole
suite per tag. Exit status: 0 when isolation holds, 1 when it does not, 2 on bad usage.
"""
import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import time


def load_catalog(path):
    tags = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f):
            cols = line.rstrip("\n").split("\t")
            if n == 0 or not cols[0]:
                continue
            tags.append((cols[0], cols[2] if len(cols) > 2 else ""))
    return tags


def load_tests(build):
    out = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1"], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"isolation: ctest --show-only failed in {build}: {out.stderr.strip()}")
    tests = []
    for t in json.loads(out.stdout).get("tests", []):
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        if props.get("DISABLED") or not t.get("command"):
            continue
        tests.append({"name": t["name"], "command": t["command"], "props": props})
    return tests


def tag_of(name, tags):
    hits = [tag for tag, _ in tags if name.startswith(tag.replace("-", "_") + "_")]
    return max(hits, key=len) if hits else None


def run_test(test, work, phase, extra_env):
    props = test["props"]
    env = dict(os.environ)
    env.pop("PBA_STUB_EXERCISES", None)
    for item in props.get("ENVIRONMENT", []):
        key, _, value = item.partition("=")
        env[key] = value
    env.update(extra_env)
    safe = re.sub(r"[^A-Za-z0-9_.-]", "_", test["name"])[:150]
    trace = os.path.join(work, f"{phase}.{safe}.trace")
    log = os.path.join(work, f"{phase}.{safe}.log")
    if os.path.exists(trace):
        os.remove(trace)
    env["PBA_EXERCISE_TRACE"] = trace
    start = time.monotonic()
    try:
        proc = subprocess.run(test["command"], cwd=props.get("WORKING_DIRECTORY") or None, env=env,
                              stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              timeout=float(props.get("TIMEOUT") or 1500))
        output, code = proc.stdout.decode(errors="replace"), proc.returncode
    except subprocess.TimeoutExpired as e:
        output, code = (e.stdout or b"").decode(errors="replace") + "\n[timed out]", -1
    with open(log, "w", encoding="utf-8") as f:
        f.write(output)
    skipped = code == props.get("SKIP_RETURN_CODE", -999) or any(
        re.search(p, output) for p in props.get("SKIP_REGULAR_EXPRESSION", []))
    ran = set()
    if os.path.exists(trace):
        with open(trace, encoding="utf-8") as f:
            ran = {line.strip() for line in f if line.strip()}
    return {"passed": code == 0 or skipped, "skipped": skipped, "ran": ran, "log": log,
            "seconds": time.monotonic() - start}


def run_all(tests, work, phase, extra_env, jobs):
    """Runs tests (RUN_SERIAL ones alone, after the others) and returns {name: result}."""
    results = {}
    parallel = [t for t in tests if not t["props"].get("RUN_SERIAL")]
    serial = [t for t in tests if t["props"].get("RUN_SERIAL")]
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(run_test, t, work, phase, extra_env): t["name"] for t in parallel}
        for future in concurrent.futures.as_completed(futures):
            results[futures[future]] = future.result()
    for t in serial:
        results[t["name"]] = run_test(t, work, phase, extra_env)
    return results


def tail(path, lines=15):
    with open(path, encoding="utf-8", errors="replace") as f:
        return "".join(f.readlines()[-lines:])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("catalog")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("PBA_JOBS", os.cpu_count() or 2)))
    ap.add_argument("--skip-label", action="append", default=[], help="leave out tests with this ctest label")
    ap.add_argument("--exclude", default=None, help="leave out tests whose name matches this regular expression")
    ap.add_argument("--work", default=None, help="folder for trace files and logs (default BUILD/isolation)")
    args = ap.parse_args()
    if not os.path.isdir(args.build) or not os.path.isfile(args.catalog):
        print(f"isolation: no build directory {args.build} or no catalog {args.catalog}", file=sys.stderr)
        return 2
    tags = load_catalog(args.catalog)
    known = {tag for tag, _ in tags}
    work = os.path.abspath(args.work or os.path.join(args.build, "isolation"))
    os.makedirs(work, exist_ok=True)
    excluded = re.compile(args.exclude) if args.exclude else None
    tests = [t for t in load_tests(args.build)
             if not set(t["props"].get("LABELS", [])) & set(args.skip_label)
             and not (excluded and excluded.search(t["name"]))]
    by_name = {t["name"]: t for t in tests}
    problems = []

    print(f"== trace run: {len(tests)} tests, every solution in place", flush=True)
    started = time.monotonic()
    traced = run_all(tests, work, "trace", {}, args.jobs)
    with open(os.path.join(work, "trace.json"), "w", encoding="utf-8") as f:
        json.dump({n: {"passed": r["passed"], "seconds": round(r["seconds"], 3), "ran": sorted(r["ran"])}
                   for n, r in sorted(traced.items())}, f, indent=1)
    print(f"   {time.monotonic() - started:.0f} s; traces in {work}/trace.json", flush=True)
    for name, r in sorted(traced.items()):
        if not r["passed"]:
            problems.append(f"{name} fails with every solution in place (log {r['log']}):\n{tail(r['log'])}")
        own = tag_of(name, tags)
        # Coursework tasks (CW1-1, ...) are not exercises: their switches trace them, and they stay solved.
        unknown = {t for t in r["ran"] - known if not re.match(r"CW[0-9]+-[0-9]+$", t)}
        if unknown:
            problems.append(f"{name} ran exercise code whose tag is not in the catalog: {', '.join(sorted(unknown))}")
        if own and r["ran"] - {own}:
            problems.append(f"{name} (an {own} test) also runs the code of {', '.join(sorted(r['ran'] - {own}))}: "
                            "use reference-only library code for everything that is not its own exercise")
    for tag, title in tags:
        if not any(tag_of(n, tags) == tag for n in by_name):
            problems.append(f"{tag} ({title}) has no tests named {tag.replace('-', '_')}_*")

    print("== each tag alone stubbed: its own tests must fail, every test that runs its code must pass")
    for tag, _ in tags:
        own = [t for t in tests if tag_of(t["name"], tags) == tag]
        touching = [t for t in tests if t not in own and tag in traced[t["name"]]["ran"]]
        tag_start = time.monotonic()
        results = run_all(own + touching, work, f"stub-{tag}", {"PBA_STUB_EXERCISES": tag}, args.jobs)
        still_pass = sorted(n for n in (t["name"] for t in own) if results[n]["passed"])
        broken = sorted(n for n in (t["name"] for t in touching) if not results[n]["passed"])
        for n in still_pass:
            problems.append(f"{n} passes with {tag} stubbed: it does not test its exercise")
        for n in broken:
            problems.append(f"{n} fails when only {tag} is stubbed (log {results[n]['log']}):\n"
                            f"{tail(results[n]['log'])}")
        state = "ok" if not still_pass and not broken else "FAIL"
        print(f"{tag:8s} {state:4s}  {len(own) - len(still_pass)}/{len(own)} own tests fail, "
              f"{len(touching) - len(broken)}/{len(touching)} other tests that run {tag} pass "
              f"({time.monotonic() - tag_start:.0f} s)", flush=True)

    total = sum(r["seconds"] for r in traced.values())
    print(f"trace run: {len(traced)} tests, {total:.0f} s of test time")
    if problems:
        print(f"\nisolation: {len(problems)} problem(s)")
        for p in problems:
            print(f"- {p}")
        return 1
    print("isolation: every exercise is graded by its own tests alone")
    return 0


if __name__ == "__main__":
    sys.exit(main())
