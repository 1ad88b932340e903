#!/usr/bin/python3
"""The measurements of docs/accuracy.md, run by tools/accuracy.sh.

One run on this machine writes everything measured on the page: the machine (CPU model, cores,
date, commit, build type, load before and after), `frustum bench accuracy` (speed against error
of every numeric path and backend, the hard-case studies, both plots) and the cost of the
filtered predicates against the plain double sign (frustum_bench, Inside|Facing, CPU time per
batch over repetitions). The page's prose stays as written; only the text between the markers
`<!-- measured: begin -->` and `<!-- measured: end -->` is replaced.
"""
import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from performance import cpu_model, loadavg  # noqa: E402  (one definition of the machine's description)

BEGIN, END = "<!-- measured: begin -->", "<!-- measured: end -->"


def predicate_costs(bench, reps):
    """min / median / max CPU time (µs per 4096 cases) of each Inside|Facing benchmark."""
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([bench, "--benchmark_filter=Inside|Facing", f"--benchmark_repetitions={reps}",
                        f"--benchmark_out={out.name}", "--benchmark_out_format=json",
                        # repetitions of the plain and filtered runs interleaved, so drift in the
                        # machine's load does not favour whichever runs first
                        "--benchmark_enable_random_interleaving=true"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        data = json.load(open(out.name))
    runs, fallbacks = {}, {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "iteration":
            runs.setdefault(b["run_name"], []).append(b["cpu_time"])
            fallbacks[b["run_name"]] = b.get("fallbacks", 0)
    return {name: sorted(t) for name, t in runs.items()}, fallbacks


def cost_lines(costs, fallbacks, reps):
    def mmm(name):
        t = costs[name]
        return f"{t[0]:.1f}/{statistics.median(t):.1f}/{t[-1]:.1f} µs"

    def ratios(name, plain):
        # The filtered run's min, median and max over the plain run's (their repetitions interleaved).
        f, q = costs[name], costs[plain]
        return (f"{f[0] / q[0]:.2f}× / {statistics.median(f) / statistics.median(q):.2f}× / "
                f"{f[-1] / q[-1]:.2f}×")

    used = sum(int(fallbacks.get(n, 0)) for n in costs)
    return [
        f"Filter cost on ordinary input (bench/predicate_bench.cpp: 4096 cases of decimal coordinates in "
        f"[−10, 10]; CPU time per batch, {reps} repetitions interleaved at random, min/median/max). A sign "
        "the filter has proven is nonzero, so it takes one comparison where the plain sign takes two (the "
        "plain value may be 0): that is how a filtered test can cost less than the plain one.",
        "",
        "| predicate | plain double sign | filtered | filtered / plain: min / median / max |",
        "| --- | ---: | ---: | ---: |",
        f"| inside (three edge signs) | {mmm('BM_InsidePlain')} | {mmm('BM_InsideFiltered')} | "
        f"{ratios('BM_InsideFiltered', 'BM_InsidePlain')} |",
        f"| facing, bound computed per call | {mmm('BM_FacingPlain')} | {mmm('BM_FacingFiltered')} | "
        f"{ratios('BM_FacingFiltered', 'BM_FacingPlain')} |",
        f"| facing, bound prepared with the inputs (as `backface`'s numeric path runs it) | {mmm('BM_FacingPlain')} | "
        f"{mmm('BM_FacingFilteredPrepared')} | {ratios('BM_FacingFilteredPrepared', 'BM_FacingPlain')} |",
        "",
        f"The exact fallback ran in {used} of these cases (ordinary input: the bound proves every sign).",
        "",
    ]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--frustum", required=True)
    ap.add_argument("--bench", required=True)
    ap.add_argument("--repo", required=True)
    ap.add_argument("--reps", type=int, default=7)
    args = ap.parse_args()
    docs = os.path.join(args.repo, "docs")
    page = os.path.join(docs, "accuracy.md")
    text = open(page, encoding="utf-8").read()
    if BEGIN not in text or END not in text:
        sys.exit(f"{page}: the markers {BEGIN} and {END} are missing")

    load_before = loadavg()
    started = datetime.datetime.now(datetime.timezone.utc)
    commit = subprocess.run(["git", "-C", args.repo, "describe", "--always", "--dirty"], capture_output=True,
                            text=True).stdout.strip()
    cache = os.path.join(os.path.dirname(os.path.abspath(args.frustum)), "CMakeCache.txt")
    build_type = "?"
    if os.path.exists(cache):
        build_type = next((l.split("=", 1)[1].strip() for l in open(cache) if l.startswith("CMAKE_BUILD_TYPE:")), "?")

    print("frustum bench accuracy …", file=sys.stderr, flush=True)
    subprocess.run([args.frustum, "bench", "accuracy", "-o", docs, "--hard", os.path.join(args.repo, "problems/hard")],
                   stdout=subprocess.DEVNULL, check=True)
    results = open(os.path.join(docs, "accuracy_results.md"), encoding="utf-8").read()
    print("filtered predicates …", file=sys.stderr, flush=True)
    costs, fallbacks = predicate_costs(args.bench, args.reps)
    load_after = loadavg()

    lines = [
        BEGIN,
        f"Generated by `tools/accuracy.sh`: every figure from here to the end of the section is from one run; "
        "rerun it to reproduce them on your machine.",
        "",
        f"- date: {started:%Y-%m-%d %H:%M} UTC; commit {commit}; build type {build_type}",
        f"- CPU: {cpu_model()}; {os.cpu_count()} cores visible; {platform.system()} {platform.release()}",
        f"- load average (1, 5, 15 min): {load_before} before, {load_after} after (timings are CPU time; compare "
        "figures within this page, not across runs)",
        "",
    ]
    lines += cost_lines(costs, fallbacks, args.reps)
    # accuracy_results.md's sections become subsections here.
    lines += [("#" + l if l.startswith("#") else l) for l in results.rstrip("\n").split("\n")]
    lines.append(END)
    head, rest = text.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    with open(page, "w", encoding="utf-8") as f:
        f.write(head + "\n".join(lines) + tail)
    print(f"wrote {page}, {docs}/accuracy_results.md and the plots", file=sys.stderr)


if __name__ == "__main__":
    main()
