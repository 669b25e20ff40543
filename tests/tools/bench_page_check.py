#!/usr/bin/env python3
"""ctest tools.bench-page: ./pba bench's record (tools/bench_run.py) and page (tools/bench_page.py) on
synthetic metrics reports and Google Benchmark JSON written here: every scene is in the table and the
budget verdict follows the median (heavy scenes exempt, exit 1 when one is over); a peer's row is paired
with ours of the same case and the ratio is ours ÷ peer in one unit; a comparison row gives its own ratio;
a filtered run keeps the other rows and names the run each comes from.
Usage: bench_page_check.py TOOLS_DIR WORK_DIR"""
import json
import os
import shutil
import subprocess
import sys
import unittest

TOOLS, WORK = sys.argv[1], sys.argv[2]


def write(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        json.dump(data, f)


def report(lab, scene, median, heavy=False):
    return {"lab": lab, "scene": scene, "frames": 600, "heavy": heavy,
            "step_ms": {"median": median, "p95": median * 1.5, "max": median * 3}}


def bench(name, time, unit="ms", **counters):
    return dict({"name": name, "run_name": name, "run_type": "iteration", "iterations": 1, "real_time": time,
                 "cpu_time": time * 2, "time_unit": unit, "label": ""}, **counters)


def tool(name, *args):
    return subprocess.run([sys.executable, os.path.join(TOOLS, name), *map(str, args)], capture_output=True, text=True)


class BenchPage(unittest.TestCase):
    def setUp(self):
        self.dir = os.path.join(WORK, self.id().rsplit(".", 1)[-1])
        shutil.rmtree(self.dir, ignore_errors=True)
        os.makedirs(self.dir)
        self.run_json = os.path.join(self.dir, "bench-run.json")
        self.page = os.path.join(self.dir, "performance.md")
        with open(os.path.join(self.dir, "CMakeCache.txt"), "w", encoding="utf-8") as f:
            f.write("CMAKE_BUILD_TYPE:STRING=RelWithDebInfo\nCMAKE_CXX_FLAGS_RELWITHDEBINFO:STRING=-O2 -g1\n")

    def record(self, name, scenes, kernels, filter_=""):
        sdir, kdir = os.path.join(self.dir, name, "scenes"), os.path.join(self.dir, name, "kernels")
        os.makedirs(sdir)
        os.makedirs(kdir)
        for order, r in scenes:
            write(os.path.join(sdir, f"{order:04d}.json"), r)
        for binary, rows in kernels.items():
            write(os.path.join(kdir, binary + ".json"), {"context": {}, "benchmarks": rows})
            with open(os.path.join(kdir, binary + ".seconds"), "w", encoding="utf-8") as f:
                f.write("17\n")
        done = tool("bench_run.py", "record", self.run_json, "--scenes", sdir, "--kernels", kdir, "--build", self.dir,
                    "--commit", name, "--preset", "release", "--date", "2026-12-05",
                    "--load-start", str((os.cpu_count() or 1) + 1.5), "--filter", filter_, "--seconds", "42", "--frames", "600")
        self.assertEqual(done.returncode, 0, done.stderr)

    def render(self):
        done = tool("bench_page.py", self.run_json, self.page, "--budget-ms", "2")
        with open(self.page, encoding="utf-8") as f:
            return done, f.read()

    def rows(self, text, first):
        return [line for line in text.splitlines() if line.startswith(f"| {first} |") and "| scene |" not in line]

    def test_budget_and_sections(self):
        self.record("a1", [(2, report("lab", "second", 0.5)), (1, report("lab", "first", 1.9)),
                           (3, report("lab", "pile", 30.0, heavy=True)), (4, report("other", "x", 0.01))],
                    {"pba_lab_bench": [bench("BM_Step/10", 3.0, "us", success=1.0)]})
        done, text = self.render()
        self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
        self.assertIn("all 3 scenes within 2 ms", done.stdout)
        self.assertIn("lab/first, 1.9 ms", done.stdout)  # the dearest scene held to the budget, not the heavy one
        lab = self.rows(text, "lab")
        self.assertEqual([r.split("|")[2].strip() for r in lab], ["first", "second", "pile"])  # the lab's order
        self.assertTrue(lab[2].endswith("| heavy |"), lab[2])
        for heading in ("## Run", "## Scenes", "## Peers", "## Kernels", "### pba_lab_bench"):
            self.assertIn(heading, text)
        self.assertIn("| a1 |", text)  # the commit
        self.assertIn("**Made under load**", text)  # a load average above the cores at the start
        # Not a manual-time benchmark: the CPU time (twice the real time here), with its counters.
        self.assertIn("| BM_Step/10 | 6 | us |  | success 1 |", text)
        self.assertIn("--benchmark_min_time=0.2` (17 s of the run)", text)

        self.record("a2", [(1, report("lab", "first", 2.5))], {}, filter_="lab/first")
        done, text = self.render()
        self.assertEqual(done.returncode, 1, done.stdout)
        self.assertIn("OVER BUDGET: 1 of 3 scenes over 2 ms per frame: lab/first 2.5 ms", done.stdout)
        first, second = self.rows(text, "lab")[:2]
        self.assertTrue(first.endswith("| **no** | 2 |"), first)  # measured by run 2, the filtered one
        self.assertTrue(second.endswith("| yes | 1 |"), second)  # kept from run 1
        self.assertIn("### pba_lab_bench (run 1)", text)
        self.assertIn("`--filter lab/first`", text)

    def test_peers(self):
        manual = "/manual_time"
        self.record("p", [(1, report("lab", "a", 0.1))], {"pba_ragdoll_bench": [
            bench("BM_Humans/constraint/136" + manual, 6.0), bench("BM_Humans/particle/136" + manual, 9.0),
            bench("BM_Bones/particle/136" + manual, 1.0),
            bench("BM_BulletHumans/136" + manual, 4.0),
            bench("BM_HumansAgainstBullet/136" + manual, 5.0, bullet_ms_per_step=6.25, ours_over_bullet=0.8)],
            "pba_ik_kdl_bench": [bench("BM_Ours_Fabrik/10/min_time:0.300", 10.0, "us"),
                                 bench("BM_Kdl_Lma/10/min_time:0.300", 0.1, "ms"),
                                 bench("BM_Kdl_Lma/100/min_time:0.300", 1.0, "ms")],
            "pba_cloth_softbody_bench": [
                bench("BM_SoftBodyCloth/peer:0/n:32/sweeps:10", 1.0, label="ours PBD; stretch"),
                bench("BM_SoftBodyCloth/peer:2/n:32/sweeps:10", 4.0, label="Bullet btSoftBody; stretch"),
                bench("BM_SoftBodyCloth/peer:0/n:64/sweeps:10", 3.0, label="ours PBD; stretch"),
                bench("BM_SoftBodyCloth/peer:2/n:64/sweeps:10", 5.0, label="Bullet btSoftBody; stretch")],
            "pba_rigid_bench": [bench("BM_Ours/boxes3000_soft_step/iterations:1" + manual, 15.0),
                                bench("BM_Ours/boxes3000x/iterations:1" + manual, 1.0),
                                bench("BM_Bullet/boxes3000/iterations:1" + manual, 20.0)]})
        done, text = self.render()
        self.assertEqual(done.returncode, 0, done.stderr)
        peers = text.split("## Peers")[1].split("## Kernels")[0]
        # Manual time: the real time. 6 / 4 and 9 / 4; BM_Bones shares the case but not the word "Humans".
        self.assertIn("| BM_BulletHumans/136/manual_time | 4 | BM_Humans/constraint/136/manual_time | 6 | 1.5 |", peers)
        self.assertIn("| BM_Humans/particle/136/manual_time | 9 | 2.25 |", peers)
        self.assertNotIn("BM_Bones", peers)
        # Ours in µs (CPU time 20 µs = 0.02 ms) against KDL in ms (CPU time 0.2 ms): 0.1.
        self.assertIn("| BM_Kdl_Lma/10/min_time:0.300 | 0.2 | BM_Ours_Fabrik/10/min_time:0.300 | 0.02 | 0.1 |", peers)
        self.assertIn("| BM_Kdl_Lma/100/min_time:0.300 | 2 | — (no case of ours) | — | — |", peers)
        self.assertIn("| BM_HumansAgainstBullet/136/manual_time | 5 | bullet | 6.25 | 0.8 |", peers)
        # A variant of ours of the peer's case (boxes3000_soft_step), not another case (boxes3000x): 15 / 20.
        self.assertIn("| BM_Ours/boxes3000_soft_step/iterations:1/manual_time | 15 | 0.75 |", peers)
        self.assertNotIn("boxes3000x", peers)
        # Ours and the peer as an argument: ours by its label, the case every other argument (n:32 with n:32).
        self.assertIn("| BM_SoftBodyCloth/peer:2/n:32/sweeps:10 | 8 | BM_SoftBodyCloth/peer:0/n:32/sweeps:10 | 2 | "
                      "0.25 |", peers)
        self.assertIn("| BM_SoftBodyCloth/peer:2/n:64/sweeps:10 | 10 | BM_SoftBodyCloth/peer:0/n:64/sweeps:10 | 6 | "
                      "0.6 |", peers)
        self.assertNotIn("| BM_SoftBodyCloth/peer:0/n:32/sweeps:10 | 2 | — (no case of ours)", peers)

    def test_bad_run_file(self):
        write(self.run_json, {"runs": []})
        done = tool("bench_page.py", self.run_json, self.page)
        self.assertEqual(done.returncode, 2)
        self.assertIn("field 'runs'", done.stderr)
        self.assertEqual(len(done.stderr.strip().splitlines()), 1)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
