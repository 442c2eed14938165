#!/usr/bin/env python3
"""Benchmark (not a test): what the gap search costs and what it finds, on the
seed bar at M = 160 on FE_Q(10) x 40 (prm/seed.prm, plots and fields off).
Runs with the scene's `Fill gaps wider than` and with 0, interleaved; prints
min / median / max of the whole run's wall time for each, the ratio of the
medians, the main points each writes and the search's own Newton work from
the Result block. With a second binary (a baseline built from an earlier
commit), both binaries' rows, measured in the same sitting.

usage: gap_search_cost.py [--repeats N] [--harmonics M] NSM_BAR [BASELINE_NSM_BAR]
"""
import argparse
import os
import re
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(binary, harmonics, fill, directory):
    args = [binary, os.path.join(ROOT, "prm", "seed.prm"), "--output", directory,
            "--set", f"Harmonic balance/Harmonics={harmonics}",
            "--set", "Discretisation/Degree=10", "--set", "Discretisation/Cells=40",
            "--set", "Output/Plots=false", "--set", "Output/Fields at=",
            "--set", f"Continuation/Fill gaps wider than={fill}"]
    start = time.perf_counter()
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    wall = time.perf_counter() - start
    main = int(re.search(r"(\d+) main points", out).group(1))
    work = re.search(r"the gap search's work: (\d+) Newton solves, (\d+) of them not converged", out)
    return wall, main, (work.group(1), work.group(2)) if work else None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--harmonics", type=int, default=160)
    parser.add_argument("binaries", nargs="+")
    args = parser.parse_args()
    cases = [(b, fill) for b in args.binaries for fill in (0.02, 0)]
    times = {c: [] for c in cases}
    found = {}
    with tempfile.TemporaryDirectory() as scratch:
        for r in range(args.repeats):
            for i, (binary, fill) in enumerate(cases):
                wall, points, work = run(binary, args.harmonics, fill, os.path.join(scratch, f"{r}_{i}"))
                times[(binary, fill)].append(wall)
                found[(binary, fill)] = (points, work)
    print(f"seed bar, FE_Q(10) x 40, M = {args.harmonics}, {args.repeats} interleaved runs each, whole run [s]")
    print("| binary | Fill gaps wider than | min / median / max [s] | main points | search's Newton solves (not converged) |")
    print("|---|---|---|---|---|")
    for binary, fill in cases:
        t = times[(binary, fill)]
        points, work = found[(binary, fill)]
        solves = f"{work[0]} ({work[1]})" if work else "-"
        print(f"| {binary} | {fill} | {min(t):.2f} / {statistics.median(t):.2f} / {max(t):.2f} | {points} | {solves} |")
    for binary in args.binaries:
        ratio = statistics.median(times[(binary, 0.02)]) / statistics.median(times[(binary, 0)])
        share = found[(binary, 0.02)][0] / found[(binary, 0)][0]
        print(f"{binary}: with the search / without, ratio of medians {ratio:.2f}; main points {share:.3f} times")


if __name__ == "__main__":
    main()
