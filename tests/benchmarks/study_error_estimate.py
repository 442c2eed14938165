#!/usr/bin/env python3
"""The error estimate (backbone.csv's energy_error_estimate) against the truth.

usage: study_error_estimate.py NSM_BAR [WORK_DIRECTORY]
- The uniform bar (prm/uniform.prm on FE_Q(10) x 40, which resolves the band
  up to M = 160, to Omega 2, Energy max 1e-4) at M = 20, 40, 80, 160, against
  the exact energy g0^2 / (2 (T - 3)^2) (3 < T < 4).
- The seed bar on the orbits' model (prm/seed-verify.prm, FE_Q(10) x 7,
  redistributed contact mass) at M = 20, 40, 80, against each main point's
  periodic orbit (hb_energy_error, Refine every 2 at M = 20 and 80, 1 at 40).
Prints one row per run: main points, those with an estimate (and an orbit),
the true error's and the estimate's median and 90th percentile, and the
ratio estimate / true error's 10th percentile, median and 90th percentile.
About 2 minutes. Not part of CTest (doc/accuracy-and-cost.md).
"""
import csv
import math
import os
import subprocess
import sys

EXE = sys.argv[1]
WORK = sys.argv[2] if len(sys.argv) > 2 else "/tmp/nsm-error-estimate"
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GAP = 1e-3  # prm/uniform.prm's Contact/Gap


def quantile(values, share):
    values = sorted(values)
    return values[min(len(values) - 1, int(share * len(values)))]


def run(scene, name, sets):
    out = os.path.join(WORK, name)
    args = [EXE, os.path.join(ROOT, "prm", scene), "--output", out, "--set", "Output/Plots=false",
            "--set", "Output/Fields at="]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True, capture_output=True)
    with open(os.path.join(out, "backbone.csv"), newline="") as f:
        return list(csv.DictReader(f))


def row(name, rows, true_error):
    main = [r for r in rows if r["branch"] == "main"]
    pairs = [(true_error(r), float(r["energy_error_estimate"])) for r in main if r["energy_error_estimate"] != ""]
    pairs = [(t, e) for t, e in pairs if t is not None and t > 0]
    truths, estimates = [t for t, _ in pairs], [e for _, e in pairs]
    ratios = [e / t for t, e in pairs]
    print(f"| {name} | {len(pairs)} of {len(main)} | {100 * quantile(truths, .5):.3g} / {100 * quantile(truths, .9):.3g} % "
          f"| {100 * quantile(estimates, .5):.3g} / {100 * quantile(estimates, .9):.3g} % "
          f"| {quantile(ratios, .1):.2f} / {quantile(ratios, .5):.2f} / {quantile(ratios, .9):.2f} |", flush=True)


def exact_error(r):
    period = 2 * math.pi / float(r["Omega"])
    if not 3 < period < 4:
        return None
    return abs(float(r["energy"]) / (GAP ** 2 / (2 * (period - 3) ** 2)) - 1)


def orbit_error(r):
    return abs(float(r["hb_energy_error"])) if r.get("hb_energy_error") else None


print("| run | points | true median / 90th | estimate median / 90th | estimate / true 10th / median / 90th |")
print("|---|---|---|---|---|")
for m in (20, 40, 80, 160):
    rows = run("uniform.prm", f"uniform_{m}", [f"Harmonic balance/Harmonics={m}", "Discretisation/Cells=40",
                                                "Continuation/Omega max=2.0", "Continuation/Energy max=1e-4"])
    row(f"uniform, M = {m}", rows, exact_error)
for m, every in ((20, 2), (40, 1), (80, 2)):
    rows = run("seed-verify.prm", f"seed_verify_{m}", [f"Harmonic balance/Harmonics={m}", f"Output/Refine every={every}"])
    row(f"seed orbits, M = {m}", rows, orbit_error)
