#!/usr/bin/env python3
"""Runs every malformed input of tests/corpora/expected.tsv through its lab and checks the answer.

Usage: run_corpus.py MANIFEST CORPUS_DIR BIN_DIR WORK_DIR [PREFIX]

Each row: input (a path under CORPUS_DIR, or gen:NAME for an input made here at run time), lab, the
command line ({input} stands for the input's path), the exit code (2) and the text the one line on
stderr must contain. A run passes when it exits with that code within the time limit, prints nothing
on stdout and exactly one line on stderr that starts with "pba-LAB: ", names the input's file and
contains the expected text. A signal (crash), the time limit (hang) or any other output fails it.
PREFIX keeps only the rows whose input starts with it (scenes/, models/).
"""
import os
import shutil
import subprocess
import sys
import time

TIME_LIMIT_S = 20


def deep_nesting(path):
    with open(path, "w") as f:
        f.write('{"lab": "hello", "scene": "drop", "params": {"mass": ' + "[" * 100000 + "]" * 100000 + "}}\n")


def long_key(path):
    with open(path, "w") as f:
        f.write('{"lab": "hello", "scene": "drop", "params": {"' + "k" * 1000000 + '": 1}}\n')


def sparse(size):
    def make(path):
        with open(path, "wb") as f:
            f.truncate(size)  # a hole: no disk space, no time to write
    return make


def directory(path):
    os.makedirs(path, exist_ok=True)


def deep_bvh(path):
    depth = 20000
    with open(path, "w") as f:
        f.write("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n")
        for i in range(depth):
            f.write(f"JOINT J{i}\n{{\n  OFFSET 0 1 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n")
        f.write("End Site\n{\n  OFFSET 0 1 0\n}\n" + "}\n" * (depth + 1))
        f.write("MOTION\nFrames: 1\nFrame Time: 0.033333\n" + " ".join(["0"] * (6 + 3 * depth)) + "\n")


def wide_bvh(joints):
    return lambda path: write_wide_bvh(path, joints)


def write_wide_bvh(path, joints):
    """A root with `joints` children (each with an end site): shallow, but many joints or effectors."""
    with open(path, "w") as f:
        f.write("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Xposition Yposition Zposition\n")
        for i in range(joints):
            f.write(f"  JOINT J{i}\n  {{\n    OFFSET {i % 7} 1 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
                    "    End Site\n    {\n      OFFSET 0 1 0\n    }\n  }\n")
        f.write("}\nMOTION\nFrames: 1\nFrame Time: 0.033333\n" + " ".join(["0"] * (3 + 3 * joints)) + "\n")


def many_frames_bvh(path):
    frames = 2000000
    with open(path, "w") as f:
        f.write("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Xposition Yposition Zposition\n"
                "  End Site\n  {\n    OFFSET 0 1 0\n  }\n}\n")
        f.write(f"MOTION\nFrames: {frames + 1}\nFrame Time: 0.033333\n")
        f.write("0 0 0\n" * frames)  # one frame short: the file ends before its last frame


def link_to(target):
    return lambda path: os.symlink(target, path)


GENERATORS = {
    "dev-zero.json": link_to("/dev/zero"),
    "dev-zero.bvh": link_to("/dev/zero"),
    "deep-nesting.json": deep_nesting,
    "million-byte-key.json": long_key,
    "huge-sparse.json": sparse(1 << 30),
    "directory.json": directory,
    "line\nbreak.json": lambda p: open(p, "w").write("{,}\n"),
    "huge-sparse.bvh": sparse(3 << 30),
    "directory.bvh": directory,
    "deep-hierarchy.bvh": deep_bvh,
    "wide-hierarchy.bvh": wide_bvh(20000),
    "three-hundred-leaves.bvh": wide_bvh(300),
    "truncated-two-million-frames.bvh": many_frames_bvh,
}


def main():
    manifest, corpus, bin_dir, work = (os.path.abspath(a) for a in sys.argv[1:5])
    prefix = sys.argv[5] if len(sys.argv) > 5 else ""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    rows = []
    with open(manifest, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            fields = line.split("\t")
            if len(fields) != 5:
                print(f"FAIL {manifest}:{number}: expected 5 tab-separated fields, got {len(fields)}")
                return 1
            if fields[0].startswith(prefix) or fields[0].startswith("gen:" + prefix):
                rows.append((number, *fields))
    failures, slowest = 0, (0.0, "")
    for number, name, lab, args, code, expected in rows:
        name = name.replace("\\n", "\n")  # a line break in a generated input's name
        if name.startswith("gen:"):
            base = name[4:].split("/", 1)[1]
            path = os.path.join(work, base)
            GENERATORS[base](path)
        else:
            base = os.path.basename(name)
            path = os.path.join(corpus, name)
            if not os.path.exists(path):
                print(f"FAIL line {number}: {name}: no such corpus file")
                failures += 1
                continue
        expected = expected.replace("{path}", path)
        argv = [os.path.join(bin_dir, "pba-" + lab)] + [a.replace("{input}", path) for a in args.split(" ")]
        label = f"line {number}: pba-{lab} {args.replace('{input}', name)}".replace("\n", "\\n")
        start = time.monotonic()
        try:
            run = subprocess.run(argv, capture_output=True, timeout=TIME_LIMIT_S, cwd=work)
        except subprocess.TimeoutExpired:
            print(f"FAIL {label}: still running after {TIME_LIMIT_S} s (a hang)")
            failures += 1
            continue
        elapsed = time.monotonic() - start
        slowest = max(slowest, (elapsed, name))
        err = run.stderr.decode("utf-8", "replace")
        lines = err.splitlines()
        problems = []
        if run.returncode < 0:
            problems.append(f"killed by signal {-run.returncode} (a crash)")
        elif run.returncode != int(code):
            problems.append(f"exit {run.returncode}, expected {code}")
        if run.stdout:
            problems.append(f"wrote to stdout: {run.stdout[:200]!r}")
        if len(lines) != 1 or not err.endswith("\n"):
            problems.append(f"{len(lines)} lines on stderr, expected one")
        first = lines[0] if lines else ""
        if not first.startswith(f"pba-{lab}: "):
            problems.append(f"the line does not start with 'pba-{lab}: '")
        shown = base.replace("\n", "\\n")[:40]
        if shown not in first:
            problems.append(f"the line does not name the file '{shown}'")
        if expected not in first:
            problems.append(f"the line does not contain '{expected}'")
        if problems:
            failures += 1
            print(f"FAIL {label}: {'; '.join(problems)}; stderr: {err[:600]!r}")
        else:
            print(f"ok   {label} ({elapsed:.2f} s)")
    print(f"{len(rows)} inputs, {failures} failures; slowest {slowest[1]} ({slowest[0]:.2f} s)")
    return 1 if failures or not rows else 0


if __name__ == "__main__":
    sys.exit(main())
