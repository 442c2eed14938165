#!/usr/bin/env python3
"""Refine in time as a user sees it: backbone.csv's orbit columns agree with
each other and with the summary line.

usage: check_refinement.py NSM_BAR
A small seed scene (FE_Q(10) x 7, M = 20) with Refine every = 5. Every 5th main
point (counted along backbone.csv) has its orbit cells filled or empty
(shooting gave up); no other row has any. Where filled:
hb_energy_error = energy / orbit_energy - 1, stable = floquet_max <= 1 +
Stability margin, 0 < orbit_contact_fraction < 1 and isolation > 0. The
summary counts the same points shot and orbits found, the same median
|hb_energy_error| and the same orbits within 1 % with their share of the
points shot; the plots include orbits.png. Standard library only.
"""
import csv
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from failures import report  # noqa: E402
from small_scene import small_seed_scene  # noqa: E402

SCENE = small_seed_scene({"Directory": "refined", "Backbone": "true", "Refine in time": "true",
                          "Refine every": 5, "Stability margin": 1e-4, "Plots": "true"})
COLUMNS = ["orbit_energy", "hb_energy_error", "orbit_contact_fraction", "floquet_max", "stable", "isolation"]


def main():
    executable = sys.argv[1]
    shutil.rmtree("refined", ignore_errors=True)
    with open("scene.prm", "w") as f:
        f.write(SCENE)
    result = subprocess.run([executable, "scene.prm"], capture_output=True, text=True, timeout=900)
    failures = []
    if result.returncode != 0:
        print(result.stderr)
        return 1
    with open("refined/backbone.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    main_index, shot, errors = 0, 0, []
    for r in rows:
        due = r["branch"] == "main" and main_index % 5 == 0
        main_index += r["branch"] == "main"
        filled = [r[c] != "" for c in COLUMNS]
        if any(filled) and not (due and all(filled)):
            failures.append(f"Omega {r['Omega']}: orbit cells {filled} on a row not due or half filled")
        shot += due
        if not all(filled):
            continue
        energy, orbit = float(r["energy"]), float(r["orbit_energy"])
        error = float(r["hb_energy_error"])
        errors.append(abs(error))
        if abs(error - (energy / orbit - 1)) > 1e-12 * max(1.0, abs(error)):
            failures.append(f"Omega {r['Omega']}: hb_energy_error {error} != energy / orbit_energy - 1")
        if (r["stable"] == "true") != (float(r["floquet_max"]) <= 1 + 1e-4):
            failures.append(f"Omega {r['Omega']}: stable {r['stable']} with floquet_max {r['floquet_max']}")
        if not 0 < float(r["orbit_contact_fraction"]) < 1 or not float(r["isolation"]) > 0:
            failures.append(f"Omega {r['Omega']}: contact fraction or isolation out of range")
    errors.sort()
    line = [x for x in result.stdout.splitlines() if "refinement in time:" in x]
    expected = f"refinement in time: {shot} main points shot, {len(errors)} orbits found"
    if not line or expected not in line[0]:
        failures.append(f"summary {line} does not say {expected!r}")
    elif errors and f"median {errors[len(errors) // 2]:.3g}," not in line[0]:
        failures.append(f"summary {line[0]!r} lacks the median {errors[len(errors) // 2]:.3g}")
    within = sum(e <= 0.01 for e in errors)
    share = f"within 1 %: {within} of {len(errors)} ({int(100 * within / max(shot, 1) + 0.5)} % of the main points shot)"
    if errors and line and share not in line[0]:
        failures.append(f"summary {line[0]!r} does not say {share!r}")
    if not os.path.exists("refined/orbits.png"):
        failures.append("no orbits.png beside backbone.png")
    if not errors:
        failures.append("no orbit found: the scene no longer exercises the columns")
    return report(failures, f"{shot} points shot, {len(errors)} orbits found")


if __name__ == "__main__":
    sys.exit(main())
