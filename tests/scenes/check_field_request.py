#!/usr/bin/env python3
"""A field request that misses the computed branch keeps the run.

usage: check_field_request.py NSM_BAR SEED_PRM
The seed scene at Harmonics = 80 has no converged solution at its Fields at
(1.96), which falls between two main segments. The run must still write its
backbone, put the field at the main point of backbone.csv nearest 1.96
(within Continuation/Search reach), say so naming Output/Fields at and both
Omega, and exit 0. With Max steps = 50 the branch ends near 1.93, and a field
at 2.1 has no main point within reach: the run must write everything else,
then exit 3 with one line naming Output/Fields at and the nearest main Omega
below (the last main point of backbone.csv). Standard library only.
"""
import csv
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from failures import report  # noqa: E402


def main():
    executable, seed = sys.argv[1], sys.argv[2]
    shutil.rmtree("h80", ignore_errors=True)
    result = subprocess.run([executable, seed, "--set", "Harmonic balance/Harmonics=80", "--set", "Output/Plots=false",
                             "--output", "h80"], capture_output=True, text=True, timeout=600)
    failures = []
    if result.returncode != 0:
        failures.append(f"exit {result.returncode}: {result.stderr.strip()}")
    else:
        with open("h80/backbone.csv", newline="") as f:
            main_omegas = [float(r["Omega"]) for r in csv.DictReader(f) if r["branch"] == "main"]
        nearest = min(main_omegas, key=lambda w: abs(w - 1.96))
        with open("h80/fields.csv", newline="") as f:
            fields = [float(r["Omega"]) for r in csv.DictReader(f)]
        if len(fields) != 1 or abs(fields[0] - nearest) > 1e-12 * nearest:
            failures.append(f"field at {fields}, nearest main point {nearest}")
        if abs(nearest - 1.96) < 1e-6:
            failures.append("1.96 is itself a main point: the scene no longer exercises a miss")
        note = [line for line in result.stdout.splitlines() if "moved to the nearest main point" in line]
        if not note or "Output/Fields at" not in note[0] or f"{nearest:.8g}" not in note[0]:
            failures.append(f"no note naming Output/Fields at and {nearest:.8g}: {note}")
    shutil.rmtree("short", ignore_errors=True)
    short = subprocess.run([executable, seed, "--set", "Continuation/Max steps=50", "--set", "Output/Fields at=2.1",
                            "--set", "Output/Plots=false", "--output", "short"], capture_output=True, text=True,
                           timeout=600)
    lines = short.stderr.strip().splitlines()
    if short.returncode != 3 or len(lines) != 1:
        failures.append(f"short branch: exit {short.returncode}, stderr {short.stderr!r}")
    else:
        with open("short/backbone.csv", newline="") as f:
            last_main = max(float(r["Omega"]) for r in csv.DictReader(f) if r["branch"] == "main")
        needles = ["'Output/Fields at' = 2.1", "no main point within Continuation/Search reach",
                   f"nearest main points: {last_main:f} below, none above"]
        if not all(n in lines[0] for n in needles):
            failures.append(f"short branch: {lines[0]!r} lacks one of {needles}")
        if sorted(os.listdir("short")) != ["backbone.csv", "continuation.log", "grazing.csv", "nsm-bar.manifest",
                                           "parameters.prm", "resonances.csv", "spectrum.csv", "summary.txt",
                                           "tongues.csv"]:
            failures.append(f"short branch wrote {sorted(os.listdir('short'))}")
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
