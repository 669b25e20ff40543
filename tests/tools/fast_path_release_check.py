#!/usr/bin/env python3
"""ctest tools.fast-path-release: the hand-out machinery on a fast path (docs/architecture.md §5, "Fast paths").

A tiny source tree holds a scalar exercise DEMO-1 and its fast path (a block whose stub calls the scalar
exercise, named by a "// FAST PATH: DEMO-1" line). Checked from outside:
  1. the student release turns the fast path into a call of the scalar exercise, keeps the FAST PATH line
     as a comment and drops both solutions; the leak check finds nothing (the two blocks, which hold the
     same computation, do not flag each other);
  2. the switchable tree gives the fast path the switch of DEMO-1, so it switches with its exercise;
  3. a copy of the fast path's body in shared code (outside any block) is reported as a leak of DEMO-1.
The trees are written to a temporary folder outside any git checkout: inside one (the build folder),
student_release.sh would hand out what that checkout's git tracks. Usage: fast_path_release_check.py TOOLS_DIR"""
import os
import shutil
import subprocess
import sys
import tempfile

tools = sys.argv[1]
work = tempfile.mkdtemp(prefix="pba-fast-path-")
failures = []


def expect(ok, what):
    if not ok:
        failures.append(what)


FAST_BODY = """  for (std::size_t k = 0; k + 1 < n; k += 2) {
    const double a0 = x[k] * scale + offset[k], a1 = x[k + 1] * scale + offset[k + 1];
    y[k] = a0 > limit ? limit : a0 / (1.0 + weight[k] * a0);
    y[k + 1] = a1 > limit ? limit : a1 / (1.0 + weight[k + 1] * a1);
  }
  if (n % 2 == 1) y[n - 1] = demoScalar(x[n - 1], scale, offset[n - 1], weight[n - 1], limit);
"""
SOURCE = """#include <cstddef>
#include "not_implemented.h"

double demoScalar(double x, double scale, double offset, double weight, double limit) {
  // BEGIN SOLUTION
  const double a = x * scale + offset;
  return a > limit ? limit : a / (1.0 + weight * a);
  // END SOLUTION
  // STUB: return exercises::notImplemented("DEMO-1", 0.0, x, scale, offset, weight, limit);
}

void demoFast(const double* x, const double* offset, const double* weight, double scale, double limit,
              std::size_t n, double* y) {
  // BEGIN SOLUTION
""" + FAST_BODY + """  // END SOLUTION
  // FAST PATH: DEMO-1 (the hand-out runs the scalar exercise)
  // STUB: for (std::size_t k = 0; k < n; ++k) y[k] = demoScalar(x[k], scale, offset[k], weight[k], limit);
}
"""


def tree(name, files):
    root = os.path.join(work, name)
    for rel, text in files.items():
        path = os.path.join(root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
    return root


def run(*args):
    done = subprocess.run(list(args), capture_output=True, text=True)
    print(" ".join(args), "->", done.returncode)
    print(done.stdout[-3000:], done.stderr[-3000:])
    return done


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


release_sh = os.path.join(tools, "student_release.sh")
leaks_py = os.path.join(tools, "check_solution_leaks.py")

# 1. The release, and the leak check on it.
src = tree("src", {"lib/demo.cpp": SOURCE})
out = os.path.join(work, "release")
expect(run("bash", release_sh, src, out).returncode == 0, "student_release.sh failed on the fast path")
handout = read(os.path.join(out, "lib/demo.cpp"))
expect("  for (std::size_t k = 0; k < n; ++k) y[k] = demoScalar(" in handout,
       "the hand-out's fast path does not call the scalar exercise")
expect("// FAST PATH: DEMO-1" in handout, "the FAST PATH line is not kept as a comment")
expect("a0" not in handout and "a / (1.0" not in handout, "a solution is left in the hand-out")
done = run(sys.executable, leaks_py, src, out)
expect(done.returncode == 0 and "2 solution blocks" in done.stdout,
       "the leak check flags the scalar exercise and its fast path against each other")

# 2. The switchable tree: the fast path switches with DEMO-1.
switchable = os.path.join(work, "switchable")
expect(run("bash", release_sh, "--switchable", src, switchable).returncode == 0, "--switchable failed")
text = read(os.path.join(switchable, "lib/demo.cpp"))
expect(text.count('pbaExerciseSwitch("DEMO-1")') == 2, "the fast path does not switch with DEMO-1's tag")
expect("a0 > limit" in text, "the switchable tree lost the fast path's solution")

# 3. The fast path escaping into shared code is caught.
escaped = tree("escaped", {"lib/demo.cpp": SOURCE,
                           "lib/shared.cpp": "void sharedHelper(const double* x, const double* offset, "
                                             "const double* weight, double scale, double limit, std::size_t n, "
                                             "double* y) {\n" + FAST_BODY + "}\n"})
out = os.path.join(work, "escaped-release")
expect(run("bash", release_sh, escaped, out).returncode == 0, "student_release.sh failed on the escaped tree")
done = run(sys.executable, leaks_py, escaped, out)
expect(done.returncode == 1 and "lib/shared.cpp" in done.stdout and "DEMO-1" in done.stdout,
       "a fast path copied into shared code is not reported as DEMO-1's leak")

shutil.rmtree(work, ignore_errors=True)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
