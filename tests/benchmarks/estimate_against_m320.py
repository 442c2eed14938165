#!/usr/bin/env python3
"""The error estimate and its check with 2M against M = 320 on one mesh.

usage: estimate_against_m320.py NSM_BAR [WORK_DIRECTORY]
For the seed bar (1.5 - x), exp(-x) and 2 - x on FE_Q(10) x 80 (automatic
range, prm/seed.prm otherwise), runs M = 320, 40, 80 and 160 and prints per
run the Result block's check with 2M (its median, how many of 15 found, the
estimate's median there, whether it warns) and the estimate against the
truth: each main point's energy against M = 320's main branch, read between
its main points less than 2e-3 apart (the ratio of the medians over the
points that have both). About 6 minutes. Not part of CTest
(doc/method.md, "The estimate's blind spot").
"""
import bisect
import csv
import os
import re
import subprocess
import sys

EXE = sys.argv[1]
WORK = sys.argv[2] if len(sys.argv) > 2 else "/tmp/nsm-estimate-m320"
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SPACING = 2e-3  # the largest Omega step across which the reference is read


def run(section, harmonics):
    name = re.sub(r"[^a-z0-9]+", "_", section) + f"_{harmonics}"
    out = os.path.join(WORK, name)
    if not os.path.exists(os.path.join(out, "backbone.csv")):
        result = subprocess.run([EXE, os.path.join(ROOT, "prm", "seed.prm"), "--output", out,
                                 "--set", f"Bar/Cross section={section}", "--set", "Discretisation/Degree=10",
                                 "--set", "Discretisation/Cells=80", "--set", f"Harmonic balance/Harmonics={harmonics}",
                                 "--set", "Continuation/Omega min=0", "--set", "Continuation/Omega max=0",
                                 "--set", "Output/Plots=false", "--set", "Output/Fields at="],
                                capture_output=True, text=True, check=True)
        with open(out + ".log", "w") as f:
            f.write(result.stdout)
    with open(os.path.join(out, "backbone.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    with open(out + ".log") as f:
        log = f.read()
    return rows, log


def main_curve(rows):
    return sorted((float(r["Omega"]), float(r["energy"])) for r in rows if r["branch"] == "main")


def read_at(curve, omega):
    xs = [p[0] for p in curve]
    i = bisect.bisect_left(xs, omega)
    if i == 0 or i == len(xs) or xs[i] - xs[i - 1] > SPACING:
        return None
    (x0, y0), (x1, y1) = curve[i - 1], curve[i]
    return y0 + (y1 - y0) * (omega - x0) / (x1 - x0)


def median(values):
    values = sorted(values)
    return values[len(values) // 2]


def check_line(log):
    match = re.search(r"\|E\(M\) / E\(2M\) - 1\| median (\S+) % over the (\d+) found again.*?"
                      r"the estimate reads a median (\S+) %", log)
    warns = "under-reads" in log
    return (f"{match.group(1)} % ({match.group(2)}), estimate {match.group(3)} %" if match else "none found") + \
        (", warns" if warns else "")


def main():
    os.makedirs(WORK, exist_ok=True)
    print("| bar | M | check with 2M: median (found of 15), estimate there | estimate / truth: medians (points) |")
    print("|---|---|---|---|")
    for section in ("1.5 - x", "exp(-x)", "2 - x"):
        reference = main_curve(run(section, 320)[0])
        for harmonics in (40, 80, 160):
            rows, log = run(section, harmonics)
            pairs = []
            for r in rows:
                if r["branch"] != "main" or r["energy_error_estimate"] == "":
                    continue
                truth = read_at(reference, float(r["Omega"]))
                if truth is not None:
                    pairs.append((abs(float(r["energy"]) / truth - 1), float(r["energy_error_estimate"])))
            ratio = f"{median([e for _, e in pairs]) / median([t for t, _ in pairs]):.2f} ({len(pairs)})" \
                if pairs else "no points"
            print(f"| {section} | {harmonics} | {check_line(log)} | {ratio} |", flush=True)


if __name__ == "__main__":
    main()
