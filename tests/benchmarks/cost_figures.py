#!/usr/bin/env python3
"""Recomputes the cost figures the docs quote, with the command behind each.

usage: cost_figures.py NSM_BAR [WORK_DIRECTORY] [--only NAME]
Prints, per figure, the lines to compare with the docs (times in seconds or
milliseconds on this machine, and the ratios the docs state):
  study-seed   the table of doc/accuracy-and-cost.md, "The seed bar: the
               paper's discretisation against cheaper ones" (prm/study-seed.prm,
               3 repeats), and its ratios to FE_Q(1) x 4000;
  backbone     the seed scene on FE_Q(10) x 20 at M = 80 and 160, with the gap
               search and without (Fill gaps wider than = 0): whole runs, and
               the error estimate's stage against the harmonic balance's;
  seed-verify  prm/seed-verify.prm: main points, orbits found, the HB energy
               error against the orbits, and the run's time (doc/reproduction.md);
  study-harmonics  the table of doc/accuracy-and-cost.md, "Harmonics and
               integration" (prm/study-harmonics.prm with that page's labels:
               Main contact drop = 1, Fill gaps wider than = 0; 90 s);
  orbit-hp     the table of "The orbit's energy in h and p" (study_truncation,
               built beside nsm-bar in tests/, on each model; 30 s).
Each run is made once (a benchmark repeats with tests/benchmarks/repeat_benchmark.py).
About 7 minutes in all. Not part of CTest.
"""
import csv
import os
import re
import subprocess
import sys
import time

args = [a for a in sys.argv[1:] if not a.startswith("--only")]
ONLY = next((sys.argv[i + 1] for i, a in enumerate(sys.argv) if a == "--only"), None)
EXE = os.path.abspath(args[0])
WORK = args[1] if len(args) > 1 and args[1] != ONLY else "/tmp/nsm-cost-figures"
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def nsm(scene, out, *sets):
    command = [EXE, os.path.join(ROOT, "prm", scene), "--output", out]
    for s in sets:
        command += ["--set", s]
    start = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True, check=True)
    return result.stdout, time.monotonic() - start


def stage(summary, name):
    match = re.search(rf"^\s+{re.escape(name)}\s+([0-9.]+)", summary, re.MULTILINE)
    return float(match.group(1)) if match else 0.0


def study_seed():
    out = os.path.join(WORK, "study-seed")
    _, seconds = nsm("study-seed.prm", out, "Output/Plots=false")
    with open(os.path.join(out, "study.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    print(f"study-seed: ./build/nsm-bar prm/study-seed.prm ({seconds:.1f} s in all)")
    print("| row | DoFs | eigenfrequency error | gamma error | time min / median / max [ms] | receptance set-up [ms] |")
    print("|---|---|---|---|---|---|")
    median = {}
    for r in rows:
        ms = [1e3 * float(r[c]) for c in ("wall_total_min", "wall_total_median", "wall_total_max")]
        median[(r["degree"], r["cells"])] = ms[1]
        print(f"| p = {r['degree']}, {r['cells']} cells | {r['dofs']} | {float(r['spectrum_error']):.2e} | "
              f"{float(r['receptance_error']):.2e} | {ms[0]:.3g} / {ms[1]:.3g} / {ms[2]:.3g} | "
              f"{1e3 * float(r['wall_receptance_set_up']):.3g} |")
    print(targets(rows))
    paper = median[("1", "4000")]
    for key in (("10", "7"), ("6", "28"), ("10", "28")):
        print(f"FE_Q({key[0]}) x {key[1]}: {median[key]:.3g} ms, {paper / median[key]:.1f} times faster than "
              f"FE_Q(1) x 4000 ({paper:.3g} ms)")


def targets(rows):
    """The cheapest row (by median time) that reaches each target."""
    lines = ["| target | eigenfrequencies (10 modes) | `gamma` over the band |", "|---|---|---|"]
    for target in (1e-2, 1e-3, 1e-4, 1e-6, 1e-8):
        cells = []
        for column in ("spectrum_error", "receptance_error"):
            reaching = [r for r in rows if float(r[column]) <= target]
            best = min(reaching, key=lambda r: float(r["wall_total_median"]))
            cells.append(f"p = {best['degree']}, {best['cells']} cells: {float(best[column]):.2g}, "
                         f"{1e3 * float(best['wall_total_median']):.2g} ms")
        lines.append(f"| {target:.0e} | {cells[0]} | {cells[1]} |".replace("e-0", "e-"))
    return "\n".join(lines)


def backbone():
    print("backbone: prm/seed.prm on FE_Q(10) x 20, Omega max 2.2 (the scene's)")
    for harmonics in (80, 160):
        times = {}
        for fill, label in (("0.02", "with the gap search"), ("0", "without it")):
            out = os.path.join(WORK, f"seed_{harmonics}_{fill}")
            summary, seconds = nsm("seed.prm", out, "Discretisation/Degree=10", "Discretisation/Cells=20",
                                   f"Harmonic balance/Harmonics={harmonics}", "Output/Plots=false",
                                   "Output/Fields at=", f"Continuation/Fill gaps wider than={fill}")
            hb, estimate = stage(summary, "harmonic balance"), stage(summary, "error estimate")
            times[fill] = seconds
            print(f"  M = {harmonics}, {label}: {seconds:.2f} s the run, harmonic balance {hb:.2f} s, "
                  f"error estimate {estimate:.3f} s ({hb / max(estimate, 1e-9):.0f} times less)")
        print(f"  M = {harmonics}: the gap search makes the run {times['0.02'] / times['0']:.2f} times as long")


def seed_verify():
    out = os.path.join(WORK, "seed-verify")
    summary, seconds = nsm("seed-verify.prm", out, "Output/Plots=false")
    line = next((l.strip() for l in summary.splitlines() if "refinement in time" in l), "no refinement line")
    print(f"seed-verify: ./build/nsm-bar prm/seed-verify.prm: {seconds:.0f} s")
    print(f"  {line}")


def study_harmonics():
    out = os.path.join(WORK, "study-harmonics")
    _, seconds = nsm("study-harmonics.prm", out, "Continuation/Main contact drop=1",
                     "Continuation/Fill gaps wider than=0", "Output/Plots=false")
    with open(os.path.join(out, "study.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    number = lambda x: f"{float(x):.3g}" if x else "-"
    print(f"study-harmonics: {seconds:.0f} s in all")
    for r in rows:
        found = sum(1 for k in r if k.startswith("energy_at_") and r[k])
        print(f"| {r['harmonics']} | {r['integration']} | {r['hb_unknowns']} | {r['main_points']} | "
              f"{number(r['main_energy_error_median'])} / {number(r['main_energy_error_q90'])} | {found} | "
              + (f"{number(r['energy_error_median'])} / {number(r['energy_error_max'])}" if found else "-")
              + f" | {r['failed_solves']} | {number(r['wall_total_min'])} / {number(r['wall_total_median'])} / "
              f"{number(r['wall_total_max'])} |")


def orbit_hp():
    program = os.path.join(os.path.dirname(EXE), "tests", "study_truncation")
    print("orbit-hp: study_truncation MODEL 1.9628,2.1302,2.1581 exact redistributed 20 40 80 160")
    for model in ("1x8", "1x16", "1x32", "1x64", "2x2", "4x2", "6x2", "8x2", "10x2", "10x4", "10x5", "10x6",
                  "10x7", "10x8", "10x20", "10x28"):
        result = subprocess.run([program, model, "1.9628,2.1302,2.1581", "exact", "redistributed", "20", "40", "80",
                                 "160"], capture_output=True, text=True, check=True)
        rows = list(csv.DictReader(l for l in result.stdout.splitlines() if not l.startswith("#")))
        cells = []
        for omega in ("1.962800", "2.130200", "2.158100"):
            shot = [r for r in rows if r["omega"] == omega and r["orbit_found"] == "1"]
            if not shot:
                cells.append("none")
                continue
            top = max(shot, key=lambda r: int(r["M"]))
            energy = 1e6 * float(top["orbit_energy"])
            cells.append(f"{energy:.4f}, {float(top['error_against_reference']):+.0e}" if top["M"] == "160"
                         else f"{energy:.4f} (M = {top['M']})")
        print(f"| {model} | " + " | ".join(cells) + " |", flush=True)


def main():
    os.makedirs(WORK, exist_ok=True)
    for name, figure in (("study-seed", study_seed), ("backbone", backbone), ("seed-verify", seed_verify),
                         ("study-harmonics", study_harmonics), ("orbit-hp", orbit_hp)):
        if ONLY in (None, name):
            figure()
            sys.stdout.flush()


if __name__ == "__main__":
    main()
