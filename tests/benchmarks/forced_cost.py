#!/usr/bin/env python3
"""What a forced-response point costs against a backbone point at the same M.

usage: forced_cost.py NSM_BAR [REPEATS] [WORK_DIRECTORY]
Runs prm/forced.prm (the seed bar, FE_Q(10) x 20, M = 40, its three curves
and its backbone in one run) REPEATS times (default 5), plots and the
verification in time and the curves in F off, and prints
per run the harmonic balance's and the forced response's wall seconds from the
run summary, over the points each wrote (backbone.csv, frc.csv), and their
ratio; then min / median / max of the ratio. The forced stage's time includes
its restarts and leaps, whose probes write no point. Not part of CTest.
"""
import csv
import os
import re
import statistics
import subprocess
import sys

EXE = sys.argv[1]
REPEATS = int(sys.argv[2]) if len(sys.argv) > 2 else 5
WORK = sys.argv[3] if len(sys.argv) > 3 else "/tmp/nsm-forced-cost"
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def stage(summary, name):
    return float(re.search(rf"^  {name} +([0-9.]+) +[0-9.]+$", summary, re.M).group(1))


def count(path):
    with open(path) as f:
        return sum(1 for _ in csv.DictReader(f))


def main():
    ratios = []
    print("| run | backbone: s / points = ms per point | forced: s / points = ms per point | ratio |")
    print("|---|---|---|---|")
    for r in range(REPEATS):
        out = os.path.join(WORK, str(r))
        summary = subprocess.run([EXE, os.path.join(ROOT, "prm", "forced.prm"), "--output", out,
                                  "--set", "Output/Plots=false", "--set", "Forcing/Verify every=0",
                                  "--set", "Forcing/Omegas="], check=True, capture_output=True, text=True).stdout
        hb, forced = stage(summary, "harmonic balance"), stage(summary, "forced response")
        n_hb, n_forced = count(os.path.join(out, "backbone.csv")), count(os.path.join(out, "frc.csv"))
        ratio = (forced / n_forced) / (hb / n_hb)
        ratios.append(ratio)
        print(f"| {r} | {hb:.3f} / {n_hb} = {1e3 * hb / n_hb:.3f} | {forced:.3f} / {n_forced} = "
              f"{1e3 * forced / n_forced:.3f} | {ratio:.2f} |", flush=True)
    print(f"ratio min / median / max: {min(ratios):.2f} / {statistics.median(ratios):.2f} / {max(ratios):.2f}")


if __name__ == "__main__":
    main()
