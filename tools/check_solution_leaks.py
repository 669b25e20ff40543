#!/usr/bin/env python3
"""The hand-out gives nothing away (docs/architecture.md §5): no solution's distinctive lines anywhere in the release.

Usage: check_solution_leaks.py SOURCE_ROOT RELEASE_ROOT [--window N]

Every "// BEGIN SOLUTION" ... "// END SOLUTION" block of SOURCE_ROOT is cut into windows of N
consecutive code tokens (comments dropped; identifiers, numbers and strings normalised, so that a copy
with other names or constants still matches; keywords and operators kept). Every text file of
RELEASE_ROOT (library, labs, tests, tools, docs, hints) is tokenised the same way, and any window of a
solution that occurs in a release file is reported with the block, the file and the line. Windows made
of boilerplate only (too few distinct tokens) are skipped. Exit status 1 when something leaks.

Fast paths (docs/architecture.md §5): a scalar exercise and its fast path are two blocks that may hold the
same computation. Both are gone from the release, so they never flag each other; a window of either that
reappears in code outside the blocks (a fast path escaping into shared code) is in the release and is
reported. The index therefore holds every block's windows and the scan reads only the release.
"""
import argparse
import os
import re
import sys

KEYWORDS = set("""alignas alignof and auto bool break case catch char class const constexpr const_cast continue
decltype default delete do double else enum explicit extern false float for friend goto if inline int long
mutable namespace new noexcept not nullptr operator or private protected public return short signed sizeof
static static_assert static_cast struct switch template this throw true try typedef typename union unsigned
using virtual void volatile while size_t""".split())
# A few names whose presence makes a window the same computation, whatever the variable names.
KEPT_NAMES = set("""sqrt cross dot length normalize atan2 acos asin sin cos tan clamp min max abs fabs exp log pow
angleAxis inverse transpose solveSpd""".split())
TOKEN = re.compile(r"""[A-Za-z_][A-Za-z0-9_]*|\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?|"(?:\\.|[^"\\])*"|'(?:\\.|[^'\\])*'|::|->|\+\+|--|[-+*/%=<>!&|^]=|&&|\|\||<<|>>|\S""")
TEXT_EXTENSIONS = (".cpp", ".h", ".hpp", ".inl", ".cc", ".md", ".tsv", ".py", ".sh", ".cmake", ".txt", ".json")


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def tokens(text):
    """(normalised token, line number) pairs of C++-like text."""
    out = []
    for line_no, line in enumerate(strip_comments(text).split("\n"), start=1):
        for tok in TOKEN.findall(line):
            if tok[0].isalpha() or tok[0] == "_":
                tok = tok if tok in KEYWORDS or tok in KEPT_NAMES else "I"
            elif tok[0].isdigit() or (tok[0] == "." and len(tok) > 1):
                tok = "N"
            elif tok[0] in "\"'":
                tok = "S"
            out.append((tok, line_no))
    return out


def solution_blocks(root):
    blocks = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in (".git", "build")]
        for name in filenames:
            if not name.endswith((".cpp", ".h")):
                continue
            path = os.path.join(dirpath, name)
            with open(path, encoding="utf-8", errors="replace") as f:
                lines = f.read().split("\n")
            start = None
            for i, line in enumerate(lines):
                if "// BEGIN SOLUTION" in line:
                    start = i + 1
                elif "// END SOLUTION" in line and start is not None:
                    stub = next((l for l in lines[i + 1:i + 4] if "STUB:" in l or "FAST PATH:" in l), "")
                    tag = re.search(r'"([A-Z]+-[0-9]+)"|FAST PATH: ([A-Z]+-[0-9]+)', stub)
                    blocks.append((os.path.relpath(path, root), start + 1, (tag.group(1) or tag.group(2)) if tag else "?",
                                   "\n".join(lines[start:i])))
                    start = None
    return blocks


def windows(toks, n, min_distinct):
    for i in range(len(toks) - n + 1):
        w = tuple(t for t, _ in toks[i:i + n])
        if len(set(w)) >= min_distinct:
            yield w, toks[i][1]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("source")
    ap.add_argument("release")
    ap.add_argument("--window", type=int, default=34, help="tokens per window (default 34)")
    ap.add_argument("--min-distinct", type=int, default=10, help="distinct tokens a window needs (default 10)")
    args = ap.parse_args()
    index = {}
    blocks = solution_blocks(args.source)
    if not blocks:
        print(f"leaks: no solution blocks under {args.source}", file=sys.stderr)
        return 2
    for path, line, tag, body in blocks:
        for w, l in windows(tokens(body), args.window, args.min_distinct):
            index.setdefault(w, (tag, path, line + l - 1))
    leaks = {}
    for dirpath, dirnames, filenames in os.walk(args.release):
        dirnames[:] = [d for d in dirnames if d not in (".git", "build")]
        for name in filenames:
            if not name.endswith(TEXT_EXTENSIONS):
                continue
            path = os.path.join(dirpath, name)
            with open(path, encoding="utf-8", errors="replace") as f:
                text = f.read()
            rel = os.path.relpath(path, args.release)
            for w, l in windows(tokens(text), args.window, args.min_distinct):
                if w in index:
                    tag, src, src_line = index[w]
                    leaks.setdefault((tag, rel), (l, src, src_line))
    for (tag, rel), (l, src, src_line) in sorted(leaks.items()):
        print(f"leak: {rel}:{l} repeats {tag}'s solution ({src}:{src_line})")
    if leaks:
        print(f"leaks: {len(leaks)} place(s) in the release repeat a solution; make one piece of code serve, "
              "or reach the value by another route")
        return 1
    print(f"leaks: none ({len(blocks)} solution blocks, windows of {args.window} tokens)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
