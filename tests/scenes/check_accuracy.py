#!/usr/bin/env python3
"""A run states its own accuracy (doc/method.md, "The error estimate" and "The
band check").

usage: check_accuracy.py NSM_BAR SEED_PRM
On the paper's scene (FE_Q(1) x 4000, M = 40):
- backbone.csv's energy_error_estimate is finite on at least 80 % of the main
  points (230 of 243 measured) and the Result block's median and 90th percentile
  are the column's, to the digits printed;
- the band check's line is printed and does not warn: its judge (FE_Q(2) with
  every cell halved) moves the main points' energy by a median of 0.02 %
  against the estimate's 2.9 %.
On the same bar with 50 linear cells (28 modes in the band on 50 DoFs, 12 %
off), the band check warns, naming Discretisation/Cells. With
Output/Error estimate = false neither the column nor the lines appear, and the
stages do not run.
Standard library only.
"""
import csv
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from estimates import estimate_statement  # noqa: E402
from failures import report  # noqa: E402

EXE, SEED = sys.argv[1], sys.argv[2]
failures = []


def run(name, *sets):
    args = [EXE, SEED, "--output", name, "--set", "Output/Plots=false", "--set", "Output/Fields at="]
    for s in sets:
        args += ["--set", s]
    result = subprocess.run(args, capture_output=True, text=True, timeout=900)
    if result.returncode != 0:
        failures.append(f"{name}: exit {result.returncode}: {result.stderr[-300:]}")
    with open(os.path.join(name, "backbone.csv"), newline="") as f:
        return result.stdout, list(csv.DictReader(f))


def check_seed():
    stdout, rows = run("seed")
    main = [r for r in rows if r["branch"] == "main"]
    found = [float(r["energy_error_estimate"]) for r in main if r["energy_error_estimate"] != ""]
    if len(found) < 0.8 * len(main) or any(not (math.isfinite(e) and e >= 0) for e in found):
        failures.append(f"seed: an estimate on {len(found)} of {len(main)} main points")
        return
    expected = estimate_statement(found, len(main))
    line = [l for l in stdout.splitlines() if "estimated energy error of these M = 40 points" in l]
    if not line or expected not in line[0]:
        failures.append(f"seed: the Result block's estimate {line} is not the column's: {expected}")
    if "spatial error (FE_Q(1) x 4000 against FE_Q(2) with every cell halved (8000 cells))" not in stdout or "warning:" in stdout:
        failures.append(f"seed: the band check's line is missing or warns:\n{stdout[:1500]}")
    print(f"seed: estimate on {len(found)} of {len(main)} main points, {expected}")


def check_coarse():
    stdout, _ = run("coarse", "Discretisation/Cells=50")
    warning = [l for l in stdout.splitlines() if l.strip().startswith("warning: the mesh limits the accuracy")]
    if not warning or "Discretisation/Cells" not in warning[0] or "FE_Q(1) x 50" not in warning[0]:
        failures.append(f"coarse: no warning naming Discretisation/Cells:\n{stdout[:1500]}")
    else:
        print("coarse:", warning[0].strip())


def check_off():
    stdout, rows = run("off", "Output/Error estimate=false")
    if "energy_error_estimate" in rows[0] or "estimated energy error" in stdout or "spatial error" in stdout \
            or "band check" in stdout or "error estimate" in stdout:
        failures.append(f"off: the estimate ran or was written with Output/Error estimate = false:\n{stdout[:1500]}")


check_seed()
check_coarse()
check_off()
sys.exit(report(failures, "the run's statement of its accuracy"))
