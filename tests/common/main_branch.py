"""A run's main branch read from backbone.csv, and its energy at an Omega
between main points on both sides (the forced response's checks)."""
import bisect
import csv
import os


def main_branch(directory):
    """(Omega, energy) of backbone.csv's main points, sorted by Omega."""
    with open(os.path.join(directory, "backbone.csv")) as f:
        return sorted((float(r["Omega"]), float(r["energy"])) for r in csv.DictReader(f) if r["branch"] == "main")


def main_energy_at(main, omega, spacing=0.02):
    """The main branch's energy at omega, linear between the main points on
    both sides; None where there is none on a side or they lie more than
    `spacing` apart."""
    xs = [w for w, _ in main]
    i = bisect.bisect_left(xs, omega)
    if i == 0 or i == len(xs) or xs[i] - xs[i - 1] > spacing:
        return None
    (w0, e0), (w1, e1) = main[i - 1], main[i]
    return e0 + (e1 - e0) * (omega - w0) / (w1 - w0)
