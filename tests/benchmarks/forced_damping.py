#!/usr/bin/env python3
"""The forced response's peaks against the backbone at decreasing damping.

usage: forced_damping.py NSM_BAR [WORK_DIRECTORY]
Runs prm/forced.prm (the seed bar, FE_Q(10) x 20, M = 40) at modal damping
0.01, 0.004, 0.002 and 0.001 with F = zeta x (5e-3, 1e-2, 2e-2), so that the
peaks reach about the same energies, and prints the table of doc/method.md,
"The forced response": per curve the Omegas its traces reached (from Omega
min, and from Omega max where that one stopped), its peak (most energy) and where its phase
lag crosses pi/2, each against the backbone's main branch (the peak also in
Omega at its own energy), read from frc.csv
and backbone.csv (main points on both sides at most 0.02 apart). About 15 s.
Not part of CTest (scene.forced_response checks the 0.002 row).
"""
import csv
import math
import os
import subprocess
import sys

EXE = sys.argv[1]
WORK = sys.argv[2] if len(sys.argv) > 2 else "/tmp/nsm-forced-damping"
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "common"))
from main_branch import main_branch, main_energy_at  # noqa: E402


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def against(main, omega, energy):
    reference = main_energy_at(main, omega)
    return f"{100 * (energy / reference - 1):+.1f} %" if reference else "-"


def at_same_energy(main, omega, energy):
    """The peak's Omega against the main branch's where it has the peak's
    energy (between consecutive main points at most 0.02 apart, the nearest
    such crossing): the backbone is steep, d ln E / d ln W about 20 to 30 on
    the seed bar, so a distance in energy at a fixed Omega reads 20 to 30
    times one in Omega at a fixed energy."""
    found = [w0 + (energy - e0) / (e1 - e0) * (w1 - w0) for (w0, e0), (w1, e1) in zip(main, main[1:])
             if w1 - w0 <= 0.02 and e0 != e1 and (e0 - energy) * (e1 - energy) <= 0]
    if not found:
        return "-"
    near = min(found, key=lambda w: abs(w - omega))
    return f"{near:.4f}, {100 * (omega / near - 1):+.2f} %"


def quadratures(curve):
    found = []
    for p, q in zip(curve, curve[1:]):
        a, b = float(p["phase"]) - math.pi / 2, float(q["phase"]) - math.pi / 2
        # A lag wrapping from pi to -pi changes sign about pi/2 without crossing it.
        if p["segment"] == q["segment"] and a * b <= 0 and a != b and abs(b - a) <= math.pi:
            t = a / (a - b)
            found.append((float(p["Omega"]) + t * (float(q["Omega"]) - float(p["Omega"])),
                          float(p["energy"]) + t * (float(q["energy"]) - float(p["energy"]))))
    return found


def main():
    os.makedirs(WORK, exist_ok=True)
    print("| zeta | F | Omega reached | peak's Omega | peak / main - 1 | main at the peak's energy: Omega, peak's / it - 1 "
          "| phase lag there | phase lag pi/2: Omega, E / main - 1 |")
    print("|---|---|---|---|---|---|---|---|")
    for zeta in (0.01, 0.004, 0.002, 0.001):
        out = os.path.join(WORK, f"zeta_{zeta}")
        forces = [zeta * k for k in (5e-3, 1e-2, 2e-2)]
        subprocess.run([EXE, os.path.join(ROOT, "prm", "forced.prm"), "--output", out,
                        "--set", f"Damping/Modal ratio={zeta}",
                        "--set", "Forcing/Amplitudes=" + ", ".join(f"{f:g}" for f in forces),
                        "--set", "Output/Plots=false"], check=True, capture_output=True)
        main = main_branch(out)
        frc = rows(os.path.join(out, "frc.csv"))
        for force in forces:
            curve = [r for r in frc if math.isclose(float(r["forcing"]), force, rel_tol=1e-12)]
            omegas = [float(r["Omega"]) for r in curve]
            # A curve traced again from Omega max (its trace from Omega min
            # stopped): that trace's start and where it stopped.
            far = next((i for i, r in enumerate(curve) if i > 0 and float(r["Omega"]) == max(omegas)
                        and r["segment"] != curve[i - 1]["segment"] and max(omegas[:i]) < max(omegas)), None)
            reached = (f"{min(omegas):.3f} to {max(omegas):.4f}" if far is None else
                       f"{min(omegas[:far]):.3f} to {max(omegas[:far]):.4f}; from {max(omegas):.4f} to "
                       f"{omegas[-1]:.4f}")
            peak = max(curve, key=lambda r: float(r["energy"]))
            w, e = float(peak["Omega"]), float(peak["energy"])
            if w in (min(omegas), max(omegas)):
                # Still climbing at the range's end: no peak inside it.
                print(f"| {zeta} | {force:g} | {reached} | {w:.4f} (the range's end) | - | - | "
                      f"{float(peak['phase']):.2f} | none |", flush=True)
                continue
            crossings = "; ".join(f"{q:.4f}, {against(main, q, qe)}" for q, qe in quadratures(curve)) or "none"
            print(f"| {zeta} | {force:g} | {reached} | {w:.4f} | {against(main, w, e)} | "
                  f"{at_same_energy(main, w, e)} | {float(peak['phase']):.2f} | {crossings} |", flush=True)


if __name__ == "__main__":
    main()
