#!/usr/bin/env python3
"""Writes the whole of docs/performance.md from the results of `./pba bench` (tools/bench_run.py's RUN.json).

  bench_page.py RUN.json OUT.md [--budget-ms 2] [--min-time S] [--topics PAGE.md ...]

Sections: the runs the rows come from (date, commit, preset and flags, compiler, CPU and cores, load average
at the start and the end, duration, filter); every lab's every scene against the budget of physics time per
frame (median), scenes their lab marks heavy listed but not held to it; the peer comparisons (benchmarks
named after a peer library, or timing ours against one in one process) with ours ÷ peer where the bench gives
both; every benchmark binary's table. The last line printed is the budget's summary; the exit status is 1
when a scene that is not heavy is over the budget, else 0 (2 for a bad RUN.json).

Pairing of a peer's row with ours: in the same binary, the rows that are not a peer's and end in the same
case (the last part of the name: /136, /boxes3000, or a variant of ours of it: /boxes3000_soft_step); of
those, the ones of the same benchmark, else the ones that share a word of the peer's benchmark name
(BM_BulletHumans: BM_Humans/...), when any does. A benchmark that runs ours and the peer as an argument
(BM_SoftBodyCloth/peer:0/n:32/...) names ours by a label that starts with "ours"; its case is then every
part of the name but that argument. A row that times both in one process gives its own ratio as a counter ours_over_PEER (and the
peer's time as PEER_ms_per_step when it has it).
"""
import argparse
import json
import os
import re
import sys

PEERS = ("Bullet", "Kdl", "SoftBody", "Jolt")
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
# Google Benchmark's decorations of a name, which are not part of the case.
DECORATIONS = re.compile(r"^(min_time|min_warmup_time|iterations|repeats|threads):|^(manual_time|real_time)$")


def words(text):
    """The words of a benchmark's name: BM_BulletHumans → {Bullet, Humans}."""
    return set(re.findall(r"[A-Z]+(?![a-z])|[A-Z][a-z0-9]*|[a-z0-9]+", re.sub(r"^BM_", "", text)))


def base(name):
    return name.split("/", 1)[0]


def case(name):
    parts = [p for p in name.split("/")[1:] if not DECORATIONS.search(p)]
    if any(p.startswith("peer:") for p in parts):  # ours and the peer as an argument: the rest is the case
        return "/".join(p for p in parts if not p.startswith("peer:"))
    return parts[-1] if parts else ""


def same_case_of(ours, peer):
    """Ours runs the peer's case, maybe in a variant of its own: boxes3000_soft_step runs boxes3000."""
    return ours == peer or (peer != "" and ours.startswith(peer + "_"))


def peer_of(row):
    """The peer a benchmark row runs ('Bullet'), or None for ours; a comparison row (…Against…) is not a peer's,
    nor a row of a peer's benchmark labelled as ours."""
    b = base(row["name"])
    if "Against" in b or (row.get("label") or "").startswith("ours"):
        return None
    return next((p for p in PEERS if p in words(b) or p in b), None)


def ms(row):
    return None if row["time"] is None or row["error"] else row["time"] * TO_MS.get(row["unit"], float("nan"))


def num(x, digits=4):
    return "—" if x is None else f"{x:.{digits}g}"


def peer_rows(kernels):
    """(binary, peer row, [(ours row, ours ÷ peer)]) for every peer's row, and the comparison rows."""
    pairs, comparisons = [], []
    for binary, k in sorted(kernels.items()):
        rows = k["benchmarks"]
        together = []
        for r in rows:
            ratios = {c[len("ours_over_"):]: v for c, v in r["counters"].items() if c.startswith("ours_over_")}
            if "Against" in base(r["name"]) or ratios:
                comparisons.append((binary, r, ratios))
                together.append(r["name"])
        ours = [r for r in rows if peer_of(r) is None and r["name"] not in together]
        for r in rows:
            peer = peer_of(r)
            if peer is None:
                continue
            same_case = [o for o in ours if same_case_of(case(o["name"]), case(r["name"]))]
            same_bench = [o for o in same_case if base(o["name"]) == base(r["name"])]
            shared = words(base(r["name"])) - {peer} - set(PEERS)
            closer = [o for o in same_case if words(base(o["name"])) & shared]
            matched = same_bench or closer or same_case
            p = ms(r)
            pairs.append((binary, r, [(o, ms(o) / p if p and ms(o) is not None else None) for o in matched]))
    return pairs, comparisons


def runs_section(run, multiple):
    lines = ["## Runs" if multiple else "## Run", ""]
    if multiple:
        lines += ["Rows measured by an earlier run than the latest name it in their `run` column (a filtered run "
                  "keeps the other rows of the one before).", ""]
    lines += ["| run | date | commit | preset (flags) | compiler | machine | load average (start → end) | time "
              "| scope |",
              "|---|---|---|---|---|---|---|---:|---|"]
    for r in run["runs"]:
        machine = f"{r.get('cpu', '?')}, {r.get('cores', '?')} cores"
        load = f"{num(r.get('load_start'), 3)} → {num(r.get('load_end'), 3)}"
        seconds = "—" if r.get("seconds") is None else f"{r['seconds']:.0f} s"
        scope = "`--filter " + r["filter"].replace("|", "\\|") + "`" if r.get("filter") else "everything"
        lines.append(f"| {r['id']} | {r.get('date', '?')} | {r.get('commit', '?')} | {r.get('preset', '?')} "
                     f"({r.get('build_type', '?')} `{r.get('flags', '')}`) | {r.get('compiler', '?')} | {machine} | "
                     f"{load} | {seconds} | {scope} |")
    # The benchmarks run one thread, which alone holds the load average near 1: the run is quiet while the
    # load stays within the machine's cores (no other thread waited for one), under load beyond that.
    busy = [(x, r.get("cores") or 1) for r in run["runs"] for x in (r.get("load_start"), r.get("load_end"))
            if x is not None]
    if any(load > cores for load, cores in busy):
        top = max(load for load, _ in busy)
        lines += ["", f"**Made under load** (load average up to {top:.3g}, more than the machine's cores): compare "
                      "rows of one run only; these are not quiet-machine figures."]
    return lines + [""]


def scenes_section(run, budget, multiple):
    rows = sorted(run["scenes"].values(), key=lambda r: (r["lab"], r.get("order", 0), r["scene"]))
    held = [r for r in rows if not r["heavy"]]
    over = [r for r in held if r["median_ms"] > budget]
    frames = sorted({r["frames"] for r in rows})
    preset = run["runs"][-1].get("preset", "release")
    lines = [f"## Scenes (physics time per displayed frame, budget {budget:g} ms on one core)", "",
             f"Command: `build/{preset}/bin/pba-LAB --headless --scene SCENE --frames "
             f"{frames[0] if len(frames) == 1 else 'N'} --metrics -` (`step_ms` of the report). Every scene at "
             f"its defaults keeps a median within {budget:g} ms; a scene its lab marks heavy (a benchmark or "
             "stress scene, `Scene::heavy()`) is timed but not held to it.", ""]
    if not held:
        summary = "bench: no scene measured against the budget"
    elif over:
        names = ", ".join(f"{r['lab']}/{r['scene']} {r['median_ms']:.3g} ms" for r in over)
        summary = f"bench: OVER BUDGET: {len(over)} of {len(held)} scenes over {budget:g} ms per frame: {names}"
    else:
        top = max(held, key=lambda r: r["median_ms"])
        summary = (f"bench: all {len(held)} scenes within {budget:g} ms per frame (the dearest "
                   f"{top['lab']}/{top['scene']}, {top['median_ms']:.3g} ms)")
    if len(rows) > len(held):
        summary += f"; {len(rows) - len(held)} heavy, not held to it"
    lines += [f"**{summary[len('bench: '):]}**", ""]
    lines += ["| lab | scene | frames | median ms | p95 ms | max ms | within budget |" + (" run |" if multiple else ""),
              "|---|---|---:|---:|---:|---:|---|" + ("---:|" if multiple else "")]
    for r in rows:
        verdict = "heavy" if r["heavy"] else ("yes" if r["median_ms"] <= budget else "**no**")
        lines.append(f"| {r['lab']} | {r['scene']} | {r['frames']} | {r['median_ms']:.4f} | {r['p95_ms']:.4f} | "
                     f"{r['max_ms']:.4f} | {verdict} |" + (f" {r['run']} |" if multiple else ""))
    return lines + [""], summary, bool(over)


def peers_section(run):
    pairs, comparisons = peer_rows(run["kernels"])
    lines = ["## Peers", "",
             f"Benchmarks of another library ({', '.join(PEERS)}) beside ours on the same case, from the tables "
             "below; ours ÷ peer under 1 means ours is faster. Method and history: the per-topic pages.", ""]
    if not pairs and not comparisons:
        return lines + ["No peer was measured: the configure step names the package each peer needs (README.md, "
                        "optional packages).", ""]
    if pairs:
        lines += ["| binary | peer benchmark | peer ms | ours | ours ms | ours ÷ peer |",
                  "|---|---|---:|---|---:|---:|"]
        for binary, p, matched in pairs:
            for o, ratio in matched or [(None, None)]:
                ours = f"{o['name']} | {num(ms(o))}" if o else "— (no case of ours) | —"
                lines.append(f"| {binary} | {p['name']} | {num(ms(p))} | {ours} | {num(ratio, 3)} |")
        lines.append("")
    if comparisons:
        lines += ["Timed in one process, ours and the peer alternated:", "",
                  "| binary | benchmark | ours ms | peer | peer ms | ours ÷ peer |", "|---|---|---:|---|---:|---:|"]
        for binary, r, ratios in comparisons:
            for peer, ratio in sorted(ratios.items()) or [("?", None)]:
                lines.append(f"| {binary} | {r['name']} | {num(ms(r))} | {peer} | "
                             f"{num(r['counters'].get(f'{peer}_ms_per_step'))} | {num(ratio, 3)} |")
        lines.append("")
    return lines


def kernels_section(run, min_time, multiple):
    preset = run["runs"][-1].get("preset", "release")
    lines = ["## Kernels (Google Benchmark)", ""]
    for binary, k in sorted(run["kernels"].items()):
        took = "" if k.get("seconds") is None else f" ({k['seconds']:.0f} s of the run)"
        lines += [f"### {binary}" + (f" (run {k['run']})" if multiple else ""), "",
                  f"Command: `build/{preset}/bench/{binary} --benchmark_min_time={min_time:g}`{took}", "",
                  "| benchmark | time | unit | items/s | counters | label |", "|---|---:|---|---:|---|---|"]
        for b in k["benchmarks"]:
            counters = ", ".join(f"{c} {v:.4g}" for c, v in sorted(b["counters"].items()))
            items = "" if b["items_per_second"] is None else f"{b['items_per_second']:.3g}"
            label = b["error"] and f"error: {b['error']}" or b["label"]
            lines.append(f"| {b['name']} | {num(b['time'])} | {b['unit']} | {items} | {counters} | {label} |")
        lines.append("")
    return lines


def topics_lines(topics, out):
    links = []
    for path in sorted(topics):
        title = os.path.basename(path)
        try:
            with open(path, encoding="utf-8") as f:
                title = next((line[2:].strip() for line in f if line.startswith("# ")), title)
        except OSError:
            continue
        links.append(f"[{title}]({os.path.relpath(path, os.path.dirname(os.path.abspath(out)))})")
    return ["Method, current figures and limits of each topic, with the measurements made by hand: " +
            " · ".join(links) + ".", ""] if links else []


def page(run, out, budget, min_time, topics):
    multiple = len(run["runs"]) > 1
    scenes, summary, over = scenes_section(run, budget, multiple)
    lines = ["# Performance", "",
             "<!-- Written wholly by ./pba bench (tools/bench_page.py): change the generator, not this page. -->", "",
             "Every figure below comes from one run of `./pba bench` (or, where a row names another, an earlier "
             "one) on one thread; medians where the tool reports them. Regenerate with `./pba bench`; "
             "`./pba bench --filter REGEX` measures only what matches and keeps the other rows.", ""]
    lines += topics_lines(topics, out) + runs_section(run, multiple) + scenes + peers_section(run)
    lines += kernels_section(run, min_time, multiple)
    with open(out, "w", encoding="utf-8") as f:
        f.write("\n".join(lines).rstrip("\n") + "\n")
    return summary, over


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run")
    ap.add_argument("out")
    ap.add_argument("--budget-ms", type=float, default=2.0)
    ap.add_argument("--min-time", type=float, default=0.2)
    ap.add_argument("--topics", nargs="*", default=[])
    args = ap.parse_args()
    try:
        with open(args.run, encoding="utf-8") as f:
            run = json.load(f)
        if not run.get("runs"):
            raise ValueError("field 'runs': missing or empty")
        summary, over = page(run, args.out, args.budget_ms, args.min_time, args.topics)
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"pba bench: {args.run}: {e}", file=sys.stderr)
        return 2
    print(summary)
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
