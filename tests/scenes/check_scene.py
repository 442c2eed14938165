#!/usr/bin/env python3
"""Runs nsm-bar on tests/scenes/NAME.prm and checks what it wrote.

usage: check_scene.py NSM_BAR SCENE_DIRECTORY NAME
References are exact or independent (method.md); tolerances are stated at
each check. Uses the standard library only.
"""
import csv
import math
import os
import shutil
import subprocess
import sys

W1 = 1.919137          # method.md: first clamped-free frequency, 6 digits
W1_CC = 3.096918       # method.md: first clamped-clamped frequency
TOLERANCE = 1e-10      # the scenes' Newton tolerance (default)


def run(executable, scene_directory, name):
    shutil.rmtree(name, ignore_errors=True)
    result = subprocess.run([executable, os.path.join(scene_directory, name + ".prm")],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"nsm-bar failed ({result.returncode}):\n{result.stdout}\n{result.stderr}")
    return result.stdout


def table(path, header):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == header, f"{path}: header {rows[0]} != {header}"
    values = [[float(v) for v in row] for row in rows[1:]]
    for row in values:
        assert all(math.isfinite(v) for v in row), f"{path}: non-finite value in {row}"
    return values


def check_full_precision(path):
    """CSV values carry 17 significant digits (full double precision)."""
    with open(path) as f:
        f.readline()
        longest = max(len(v.replace("-", "").replace(".", "").split("e")[0])
                      for line in f for v in line.strip().split(","))
    assert longest >= 15, f"{path}: values are not written with full precision"


def check_spectrum_receptance(name, summary):
    spectrum = table(f"{name}/spectrum.csv", ["j", "omega_clamped_free", "omega_clamped_clamped"])
    assert len(spectrum) == 10
    # FE_Q(8) on 40 cells: frequencies exact far below the 6 digits given.
    assert abs(spectrum[0][1] - W1) < 1e-6, spectrum[0]
    assert abs(spectrum[0][2] - W1_CC) < 1e-6, spectrum[0]
    for j, (index, free, clamped) in enumerate(spectrum):
        assert index == j + 1
        assert free < clamped, "clamped-free below clamped-clamped"
        if j + 1 < len(spectrum):
            assert clamped < spectrum[j + 1][1], "interlacing"
    receptance = table(f"{name}/receptance.csv", ["omega", "gamma", "dgamma_domega2"])
    assert [r[0] for r in receptance] == [0, 0.5, 2.5, 2.75, 3.0, 3.25, 3.5]
    assert abs(receptance[0][1] - math.log(3)) < 1e-12, "gamma(0) = ln 3"
    assert all(r[2] > 0 for r in receptance), "d gamma / d w^2 = h^T M h > 0"
    # gamma changes sign at the clamped-clamped frequency 3.0969 (a zero)
    assert receptance[4][1] < 0 < receptance[5][1]
    check_full_precision(f"{name}/receptance.csv")
    assert "harmonic balance" not in summary, "no backbone was requested"
    assert not os.path.exists(f"{name}/backbone.csv")


def check_backbone(name, below_w1):
    points = table(f"{name}/backbone.csv",
                   ["segment", "Omega", "energy", "energy_spread", "max_contact_force",
                    "contact_fraction", "newton_iterations", "residual"])
    assert len(points) > 20, len(points)
    segments = [p[0] for p in points]
    assert segments == sorted(segments), "segments are numbered along the branch"
    for segment, omega, energy, spread, force, fraction, iterations, residual in points:
        assert (omega < W1) if below_w1 else (omega > W1), omega
        assert energy > 0 and force > 0 and 0 < fraction < 1
        assert residual <= TOLERANCE, residual
        assert iterations >= 0
        assert spread < 0.2, "energy varies over the period by the truncation only"
    check_full_precision(f"{name}/backbone.csv")
    return points


def check_backbone_physical(name, summary):
    points = check_backbone(name, below_w1=False)
    # Hardening from the linear grazing value.
    assert points[-1][2] > 2 * points[0][2]
    spectrum = table(f"{name}/spectrum.csv", ["j", "omega_clamped_free", "omega_clamped_clamped"])
    resonances = table(f"{name}/resonances.csv", ["omega", "mode", "harmonic"])
    assert resonances, "resonances in [1.5, 2]"
    omegas = [r[0] for r in resonances]
    assert omegas == sorted(omegas)
    for omega, mode, harmonic in resonances:
        assert 1.5 <= omega <= 2.0 and 1 <= harmonic <= 40
        if mode <= len(spectrum):
            # the same FE eigenfrequency, written by two stages
            assert abs(omega * harmonic / spectrum[int(mode) - 1][1] - 1) < 1e-12
    assert "backbone:" in summary and "start at grazing" in summary


def check_backbone_eq5(name, summary):
    points = check_backbone(name, below_w1=True)
    assert min(p[1] for p in points) < 1.907 < max(p[1] for p in points), \
        "the branch passes the paper's Omega = 1.907"


def check_nothing_requested(name, summary):
    assert "nothing to do" in summary
    assert not os.path.exists(name), "no output directory without a requested output"
    assert "mesh and assembly" not in summary


def main():
    executable, scene_directory, name = sys.argv[1:4]
    summary = run(executable, scene_directory, name)
    globals()["check_" + name](name, summary)
    print(f"{name}: all checks passed")


if __name__ == "__main__":
    main()
