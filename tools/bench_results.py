#!/usr/bin/env python3
"""The figures of one `./pba bench` run as JSON, and the change of every figure against an earlier run.

  bench_results.py write FIGURES.tsv OUT.json --commit C --preset P --date D
      FIGURES.tsv: one figure a line, NAME<TAB>VALUE<TAB>UNIT (ns, us, ms or s; every one a time).
      Writes {"commit", "preset", "date", "figures": {NAME: milliseconds}}.
  bench_results.py check REF.json
      Exit 2 with a one-line message naming the file and what is wrong when REF.json is not such a file.
  bench_results.py compare REF.json NOW.json [--threshold PERCENT]
      Prints every figure of either run: the earlier value, this run's, the change in per cent, and
      "slower" or "faster" where the change is beyond the threshold (default 10 %). Every figure is a time,
      so a positive change is a regression. Figures only one run has are listed as added or removed.
      The exit status is 0: the table is for review, as timings move with the machine's load.
"""
import argparse
import json
import math
import sys

from bench_run import read_json

TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def write(args):
    figures = {}
    with open(args.figures, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            parts = line.rstrip("\n").split("\t")
            if len(parts) != 3:
                continue
            name, value, unit = parts
            try:
                ms = float(value) * TO_MS[unit]
            except (ValueError, KeyError):
                print(f"bench_results: {args.figures}:{n}: '{value} {unit}' is not a time", file=sys.stderr)
                continue
            if math.isfinite(ms):
                figures[name] = ms
    with open(args.out, "w", encoding="utf-8") as f:
        json.dump({"commit": args.commit, "preset": args.preset, "date": args.date, "figures": figures}, f,
                  indent=1, sort_keys=True)
        f.write("\n")


def load(path):
    """The figures of a results file, or a one-line error naming the file and the field."""
    data = read_json(path)
    if not isinstance(data, dict) or not isinstance(data.get("figures"), dict):
        raise ValueError(f"{path}: field 'figures': missing or not an object (is it a bench-results.json?)")
    for name, value in data["figures"].items():
        if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value) or value < 0:
            raise ValueError(f"{path}: field 'figures.{name}': {value!r} is not a time in milliseconds")
    return data


def fmt(ms):
    return "—" if ms is None else f"{ms:.4g}"


def compare(args):
    ref, now = load(args.ref), load(args.now)
    names = sorted(set(ref["figures"]) | set(now["figures"]))
    rows, slower, faster = [], 0, 0
    for name in names:
        a, b = ref["figures"].get(name), now["figures"].get(name)
        if a is None or b is None:
            rows.append((name, fmt(a), fmt(b), "", "added" if a is None else "removed"))
            continue
        change = (b - a) / a * 100.0 if a > 0 else (0.0 if b == 0 else math.inf)
        mark = ""
        if change > args.threshold:
            mark, slower = "slower", slower + 1
        elif change < -args.threshold:
            mark, faster = "faster", faster + 1
        rows.append((name, fmt(a), fmt(b), f"{change:+.1f} %", mark))
    width = max([len(r[0]) for r in rows] + [6])
    print(f"Against {args.ref} (commit {ref.get('commit', '?')}, {ref.get('preset', '?')}, {ref.get('date', '?')}); "
          f"ms; beyond ±{args.threshold:g} % marked")
    print(f"{'figure':<{width}}  {'before':>10}  {'now':>10}  {'change':>9}")
    for name, a, b, change, mark in rows:
        print(f"{name:<{width}}  {a:>10}  {b:>10}  {change:>9}  {mark}".rstrip())
    print(f"bench compare: {len(rows)} figures, {slower} slower and {faster} faster by more than "
          f"{args.threshold:g} %")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", required=True)
    w = sub.add_parser("write")
    w.add_argument("figures")
    w.add_argument("out")
    w.add_argument("--commit", default="unknown")
    w.add_argument("--preset", default="release")
    w.add_argument("--date", default="")
    c = sub.add_parser("check")
    c.add_argument("ref")
    m = sub.add_parser("compare")
    m.add_argument("ref")
    m.add_argument("now")
    m.add_argument("--threshold", type=float, default=10.0)
    args = ap.parse_args()
    try:
        if args.command == "write":
            write(args)
        elif args.command == "check":
            load(args.ref)
        else:
            compare(args)
    except ValueError as e:
        print(f"pba bench: --compare: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
