#!/usr/bin/env python3
"""A scene that names only its bar gets the first nonsmooth mode from grazing
to an Omega max read off its spectrum, under an energy ceiling relative to
its grazing energy.

usage: check_defaults.py NSM_BAR
- The uniform bar, against closed forms: w1 = pi / 2 (clamped-free),
  pi (clamped-clamped), the bilinear limit 2 pi / 3, so the automatic
  Omega max is pi / 2 + 0.8 (2 pi / 3 - pi / 2); E_g = w1^2 g0^2 / 4
  (phi_1(L)^2 = 2 for the mass-normalised sin(pi x / 2)), and the automatic
  Energy max is 1000 E_g. The run must end exactly at that Omega max,
  covering the range, with no point above the ceiling. The tolerance 1e-6
  is the FE frequency error of 4000 linear cells, (pi h / 2)^2 / 12 ~ 1e-8,
  with margin; a wrong share, limit or factor moves the values by > 1 %.
- A bar of its own, A = 1 + x, in a 10-line scene: its automatic Omega max
  lies between w1 and the bilinear limit from its own spectrum.csv, at the
  share 0.8; the run ends there (range) with main points written.
- A study leaving Omega max automatic, and Omega min above the automatic
  Omega max, exit 2 naming the parameter, and write nothing.
Standard library only.
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from failures import report  # noqa: E402

GAP = 1e-3
SHARE = 0.8


def run(executable, name, text, *extra):
    shutil.rmtree(name, ignore_errors=True)
    with open(f"{name}.prm", "w") as f:
        f.write(text)
    return subprocess.run([executable, f"{name}.prm", "--output", name] + list(extra), capture_output=True,
                          text=True, timeout=600)


def automatic(stdout, entry):
    match = re.search(rf"Continuation/{entry} = 0: (\S+?),? ", stdout)
    return float(match.group(1)) if match else None


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def close(a, b, tolerance):
    return a is not None and abs(a - b) <= tolerance * abs(b)


def uniform(executable, failures):
    r = run(executable, "uniform", "subsection Bar\n  set Cross section = 1\nend\n"
            "subsection Output\n  set Backbone = true\nend\n")
    if r.returncode != 0:
        return failures.append(f"uniform bar: exit {r.returncode}: {r.stderr[-300:]}")
    w1, wcc = math.pi / 2, math.pi
    omega_max = w1 + SHARE * (2 * w1 * wcc / (w1 + wcc) - w1)
    grazing = w1 ** 2 * GAP ** 2 / 4
    got_omega, got_energy = automatic(r.stdout, "Omega max"), automatic(r.stdout, "Energy max")
    if not close(got_omega, omega_max, 1e-6):
        failures.append(f"uniform bar: automatic Omega max {got_omega}, exact {omega_max}")
    if not close(got_energy, 1000 * grazing, 1e-6):
        failures.append(f"uniform bar: automatic Energy max {got_energy}, exact {1000 * grazing}")
    points = rows("uniform/backbone.csv")
    last = float(points[-1]["Omega"])
    if "ended: range" not in r.stdout or not close(last, omega_max, 1e-6):
        failures.append(f"uniform bar: the backbone ends at {last}, not at the automatic Omega max {omega_max}")
    if not close(float(rows("uniform/grazing.csv")[0]["energy"]), grazing, 1e-6):
        failures.append("uniform bar: grazing.csv's E_g is not w1^2 g0^2 / 4")
    if max(float(p["energy"]) for p in points) > 1000 * grazing:
        failures.append("uniform bar: a point lies above the automatic Energy max")


def own_bar(executable, failures):
    scene = ("# A bar of its own: only what differs from the defaults.\n"
             "subsection Bar\n  set Cross section = 1 + x\nend\n"
             "subsection Output\n  set Backbone       = true\n  set Spectrum modes = 1\n  set Plots          = true\n"
             "end\n")
    assert len(scene.splitlines()) <= 10
    r = run(executable, "own", scene)
    if r.returncode != 0:
        return failures.append(f"A = 1 + x: exit {r.returncode}: {r.stderr[-300:]}")
    spectrum = rows("own/spectrum.csv")[0]
    w1, wcc = float(spectrum["omega_clamped_free"]), float(spectrum["omega_clamped_clamped"])
    expected = w1 + SHARE * (2 * w1 * wcc / (w1 + wcc) - w1)
    got = automatic(r.stdout, "Omega max")
    if not close(got, expected, 1e-9):
        failures.append(f"A = 1 + x: automatic Omega max {got}, from its spectrum {expected}")
    points = rows("own/backbone.csv")
    main = sum(p["branch"] == "main" for p in points)
    reached = max(float(p["Omega"]) for p in points)  # the gap search writes its segments last
    if "ended: range" not in r.stdout or not close(reached, expected, 1e-9) or main == 0:
        failures.append(f"A = 1 + x: the backbone does not cover its automatic range ({r.stdout[:400]})")
    return f"A = 1 + x: Omega max {got:.6f}, {main} main points of {len(points)}"


def refusals(executable, failures):
    study = ("subsection Study\n  set Degrees = 1, 2\n  set Backbone omegas = 1.6\nend\n"
             "subsection Continuation\n  set Omega min = 1.5\nend\n")
    high = "subsection Continuation\n  set Omega min = 2.5\nend\nsubsection Output\n  set Backbone = true\nend\n"
    for name, text, entry in (("study", study, "Continuation/Omega max"), ("high", high, "Continuation/Omega min")):
        r = run(executable, name, text)
        message = r.stderr.strip().splitlines()
        if r.returncode != 2 or len(message) != 1 or entry not in message[0]:
            failures.append(f"{name}: exit {r.returncode}, not 2 naming {entry}: {r.stderr[-300:]!r}")
        if os.path.exists(name) and os.listdir(name):
            failures.append(f"{name}: a refused scene wrote {os.listdir(name)}")


def main():
    executable = sys.argv[1]
    failures = []
    uniform(executable, failures)
    said = own_bar(executable, failures)
    refusals(executable, failures)
    return report(failures, said or "")


if __name__ == "__main__":
    sys.exit(main())
