#!/usr/bin/env python3
"""Do two runs find the same main branch? Compares the backbone.csv of run A
with that of run B (for example steps of 1e-3 against 1e-4, or sequential
against arclength) at A's main points: B's energy there is interpolated
linearly between two consecutive main points of one of B's segments that
bracket it (the closest of several such pieces is taken). A's points outside
every such piece of B are not compared.

usage: compare_backbones.py A/backbone.csv B/backbone.csv [tolerance] [--sampled-from FINE/backbone.csv]

Prints how many of A's main points were compared, how many agree within the
tolerance (relative energy, default 1e-3), the median and 90th percentile of
the differences, and the points that differ by more.

With --sampled-from, B's points are replaced by the points of the run FINE
(steps much smaller than B's) nearest in Omega to B's main points: FINE's
branch sampled where B sampled its own. Comparing A with that tells what the
linear interpolation between B's points costs by itself, whatever branch B
followed.
"""
import csv
import statistics
import sys


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main_pieces(rows):
    """(W0, E0, W1, E1) for consecutive main points of one segment."""
    return [(float(a["Omega"]), float(a["energy"]), float(b["Omega"]), float(b["energy"]))
            for a, b in zip(rows, rows[1:])
            if a["segment"] == b["segment"] and a["branch"] == b["branch"] == "main"]


def energies_at(pieces, omega):
    return [e0 + (e1 - e0) * (omega - w0) / (w1 - w0)
            for w0, e0, w1, e1 in pieces if min(w0, w1) <= omega <= max(w0, w1) and w0 != w1]


def sampled_like(fine, coarse):
    """FINE's points nearest in Omega to COARSE's main points, in FINE's order."""
    omegas = [float(r["Omega"]) for r in fine]
    nearest = {min(range(len(fine)), key=lambda i: abs(omegas[i] - float(r["Omega"])))
               for r in coarse if r["branch"] == "main"}
    return [fine[i] for i in sorted(nearest)]


def main():
    args = sys.argv[1:]
    fine = None
    if "--sampled-from" in args:
        at = args.index("--sampled-from")
        fine = read(args[at + 1])
        del args[at:at + 2]
    a, b = read(args[0]), read(args[1])
    if fine is not None:
        b = sampled_like(fine, b)
    tolerance = float(args[2]) if len(args) > 2 else 1e-3
    pieces = main_pieces(b)
    compared = []
    for row in a:
        if row["branch"] != "main":
            continue
        omega, energy = float(row["Omega"]), float(row["energy"])
        others = energies_at(pieces, omega)
        if others:
            compared.append((min(abs(energy / e - 1) for e in others), omega, energy, others))
    main_a = sum(r["branch"] == "main" for r in a)
    print(f"{len(compared)} of A's {main_a} main points lie inside a main piece of B")
    if not compared:
        return
    differences = sorted(d for d, *_ in compared)
    agree = sum(d <= tolerance for d in differences)
    print(f"{agree} ({100 * agree / len(compared):.0f} %) agree within {tolerance:g}; median "
          f"{statistics.median(differences):.2e}, 90th percentile "
          f"{differences[int(0.9 * (len(differences) - 1))]:.2e}, largest {differences[-1]:.2e}")
    for d, omega, energy, others in compared:
        if d > tolerance:
            print(f"  Omega {omega:.6f}: A {energy:.6e}, B {' or '.join(f'{e:.6e}' for e in others)} ({d:.2e})")


if __name__ == "__main__":
    main()
