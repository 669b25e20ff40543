#!/usr/bin/env python3
"""Checks a --pose-json file of the IK lab from outside (tests/labs/ik_cli_tests.cmake).

Usage: check_pose_json.py REST.json POSE.json METRICS.json

REST.json is the pose after one frame, POSE.json after the run, METRICS.json the run's --metrics. The
distance of each goal's joint to its goal is computed here from the file's coordinates; the largest
must equal the solver's own residual (metric "residual", 1e-9 m: the same numbers printed to 17
digits), and lie within 1 mm when the solve succeeded. Every goal has its joint, the joints are the
same in both files, and every coordinate is finite.
"""
import json
import math
import sys


def main():
    rest, pose, metrics = (json.load(open(p)) for p in sys.argv[1:4])
    ik = metrics[metrics["lab"]]
    joints, goals = pose["joints"], pose.get("goals", {})
    if not goals:
        sys.exit(f"{sys.argv[2]}: no goals")
    if set(joints) != set(rest["joints"]):
        sys.exit("the joints changed between the two runs")
    for name, p in joints.items():
        if len(p) != 3 or not all(math.isfinite(v) for v in p):
            sys.exit(f"joint {name}: {p}")
    worst = 0.0
    for name, g in goals.items():
        if name not in joints:
            sys.exit(f"goal {name} has no joint")
        worst = max(worst, math.dist(joints[name], g))
    print(f"{pose['scene']}: {len(joints)} joints, {len(goals)} goals, largest goal distance {worst:.3e} m, "
          f"residual {ik['residual']:.3e} m, status {ik['status']}")
    if abs(worst - ik["residual"]) > 1e-9:
        sys.exit("the file's goal distance disagrees with the solver's residual")
    if ik["status"] == "success" and worst > 1e-3:
        sys.exit("a successful solve leaves a goal more than 1 mm away")


main()
