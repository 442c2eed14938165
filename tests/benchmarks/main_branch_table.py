#!/usr/bin/env python3
"""Recomputes doc/method.md's table "On other bars": per bar, the coverage of the
main branch, the largest contact drop between consecutive main points (on one
side of the accumulation point) and the whole run's time, for the labels of
the energy envelope alone (Main contact drop = 1, Fill gaps wider than = 0) and
for the defaults. Coverage and drop are tests/common/branch_measures.py's, as
scene.main_branch measures them; the times are medians of 3 alternating runs
of the whole process.

usage: main_branch_table.py NSM_BAR [--repeats N]
Not part of CTest (about 2 minutes).
"""
import csv
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from branch_measures import measures  # noqa: E402

BARS = [
    ("seed `1.5 - x`", []),
    ("`exp(-x)`", ["Bar/Cross section=exp(-x)"]),
    ("`1 + x^2`", ["Bar/Cross section=1 + x^2"]),
    ("stepped `x < 0.5 ? 2 : 1`", ["Bar/Cross section=x < 0.5 ? 2 : 1"]),
    ("`1.5 + 0.5 sin(2 pi x)`", ["Bar/Cross section=1.5 + 0.5*sin(2*pi*x)"]),
    ("seed, `Mode = 2`", ["Continuation/Mode=2"]),
    ("seed, M = 80", ["Harmonic balance/Harmonics=80"]),
    ("uniform (g0 0.5, alpha 4, to 2)", ["Bar/Cross section=1", "Contact/Gap=0.5", "Contact/Alpha=4",
                                          "Continuation/Omega max=2"]),
]
ENVELOPE = ["Continuation/Main contact drop=1", "Continuation/Fill gaps wider than=0"]


def run(exe, sets, directory):
    with open(os.path.join(directory, "backbone.prm"), "w") as f:
        f.write("subsection Output\n  set Backbone = true\n  set Plots = false\nend\n")
    args = [exe, "backbone.prm", "--output", "out"]
    for s in sets:
        args += ["--set", s]
    start = time.perf_counter()
    subprocess.run(args, capture_output=True, text=True, check=True, cwd=directory)
    wall = time.perf_counter() - start
    with open(os.path.join(directory, "out", "backbone.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return wall, rows




def main():
    exe = os.path.abspath(sys.argv[1])
    repeats = int(sys.argv[sys.argv.index("--repeats") + 1]) if "--repeats" in sys.argv else 3
    print("| bar | coverage: envelope, now | largest contact drop between main points: envelope, now "
          "| run [s], median of 3: envelope, now |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as scratch:
        for name, sets in BARS:
            mode = int(next((s.split("=")[1] for s in sets if s.startswith("Continuation/Mode=")), 1))
            cases = {"envelope": sets + ENVELOPE, "now": sets}
            times = {k: [] for k in cases}
            found = {}
            for _ in range(repeats):
                for key, case in cases.items():
                    directory = tempfile.mkdtemp(dir=scratch)
                    wall, rows = run(exe, case, directory)
                    times[key].append(wall)
                    _, drop, coverage, _, _ = measures(rows, (2 * mode - 1) * math.pi / 2)
                    found[key] = coverage, drop
            e, n = found["envelope"], found["now"]
            print(f"| {name} | {e[0]:.2f}, {n[0]:.2f} | {e[1]:.3f}, {n[1]:.3f} | "
                  f"{statistics.median(times['envelope']):.2f}, {statistics.median(times['now']):.2f} |", flush=True)


if __name__ == "__main__":
    main()
