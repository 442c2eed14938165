#!/usr/bin/env python3
"""Output/Bar amplitude and Output/Harmonics table on the uniform bar
(FE_Q(10) x 10, M = 40, from grazing to Omega = 1.85).

usage: check_amplitudes.py NSM_BAR
- harmonics.csv holds every backbone point's harmonics k = 0 .. M, in order.
- max_displacement, the largest |u| over the bar, is bounded on both sides
  by physics: below by the contact end's |u(L, t)|, summed here from
  harmonics.csv at the same Field time samples (the bar includes x = L), and
  above by the energy: |u(x)| = |int_0^x u'| <= sqrt(2 L E_strain / (E A_min))
  with E_strain <= the point's energy (its period mean times 1 + its
  energy_spread, the largest the HB energy reaches).
- At the first point, a hair above grazing, the motion is the linear mode
  sin(pi x / 2) with u(L) = g0, whose largest |u| is g0 (at L); the HB
  truncation at M = 40 moves it by 0.2 %, within the 1 % allowed.
A wrong field (a factor, a sign of a harmonic), a wrong column or a table
that misses harmonics fails one of them. Standard library only.
"""
import collections
import csv
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from failures import report  # noqa: E402

M = 40
GAP = 1e-3
SAMPLES = 2 * (2 * M + 1)  # Field time samples' default
SCENE = f"""subsection Bar
  set Cross section = 1
end
subsection Discretisation
  set Degree = 10
  set Cells  = 10
end
subsection Harmonic balance
  set Harmonics = {M}
end
subsection Continuation
  set Omega max = 1.85
end
subsection Output
  set Directory       = out
  set Backbone        = true
  set Bar amplitude   = true
  set Harmonics table = true
end
"""


def contact_end_amplitude(rows):
    """max over the field samples of |u(L, t)| from the cosine series."""
    return max(abs(sum(float(r["displacement"]) * math.cos(int(r["k"]) * 2 * math.pi * s / SAMPLES) for r in rows))
               for s in range(SAMPLES))


def main():
    executable = sys.argv[1]
    shutil.rmtree("out", ignore_errors=True)
    with open("scene.prm", "w") as f:
        f.write(SCENE)
    r = subprocess.run([executable, "scene.prm"], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    with open("out/backbone.csv") as f:
        points = list(csv.DictReader(f))
    harmonics = collections.defaultdict(list)
    with open("out/harmonics.csv") as f:
        for row in csv.DictReader(f):
            harmonics[int(row["point"])].append(row)
    failures = []
    if sorted(harmonics) != list(range(len(points))):
        failures.append(f"harmonics.csv covers points {sorted(harmonics)[:5]}..., not the {len(points)} of backbone.csv")
    for i, p in enumerate(points):
        rows = harmonics.get(i, [])
        if [int(r["k"]) for r in rows] != list(range(M + 1)) or any(float(r["Omega"]) != float(p["Omega"])
                                                                   for r in rows):
            failures.append(f"point {i}: harmonics.csv's rows are not k = 0 .. {M} at its Omega")
            continue
        amplitude = float(p["max_displacement"])
        below = contact_end_amplitude(rows)
        above = math.sqrt(2 * float(p["energy"]) * (1 + float(p["energy_spread"])))  # L = E = A_min = 1
        if not below * (1 - 1e-9) <= amplitude <= above:
            failures.append(f"point {i} (Omega {p['Omega']}): max_displacement {amplitude:.6g} outside "
                            f"[{below:.6g}, {above:.6g}]")
    first = float(points[0]["max_displacement"]) / GAP
    if abs(first - 1) > 0.01:
        failures.append(f"at grazing, max_displacement / g0 = {first:.5f}, not 1 (the linear mode's)")
    return report(failures, f"{len(points)} points; at grazing max |u| / g0 = {first:.5f}")


if __name__ == "__main__":
    sys.exit(main())
