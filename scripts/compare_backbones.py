#!/usr/bin/env python3
"""Do two runs find the same main branch? Compares run A's backbone with run
B's at A's main points, and draws both (--plot).

A and B are backbone.csv files or the output folders that hold them. B's
energy at A's main point is interpolated linearly along B's main branch:
between B's main points just below and just above A's Omega, of any segment,
when they lie within --max-gap of each other (so that the comparison follows
the branch where the two runs' Omega grids differ, and across B's leaps,
but not across a gap where B found no main point). With --same-segment the
two must be consecutive main points of one of B's segments (the closest of
several such pieces is taken). A's points outside every piece are not
compared.

Prints how many of A's main points were compared, how many agree within the
tolerance (relative energy), the median and 90th percentile of the
differences, and the points that differ by more.

With --sampled-from, B's points are replaced by the points of the run FINE
(steps much smaller than B's) nearest in Omega to B's main points: FINE's
branch sampled where B sampled its own. Comparing A with that tells what the
linear interpolation between B's points costs by itself, whatever branch B
followed.
"""
import argparse
import csv
import os
import signal
import statistics
import sys


def backbone_path(path):
    """A backbone.csv, or the output folder that holds one."""
    if os.path.isdir(path):
        path = os.path.join(path, "backbone.csv")
    if not os.path.isfile(path):
        sys.exit(f"compare_backbones.py: error: {path} is not a backbone.csv or a folder holding one")
    return path


def read(path):
    with open(backbone_path(path), newline="") as f:
        rows = list(csv.DictReader(f))
    if rows and not {"Omega", "energy", "branch", "segment"} <= set(rows[0]):
        sys.exit(f"compare_backbones.py: error: {path} has no Omega, energy, branch and segment columns")
    return rows


def main_pieces(rows, same_segment, max_gap):
    """(W0, E0, W1, E1): consecutive main points of one segment
    (same_segment), or else neighbours in Omega of the main branch at most
    max_gap apart."""
    if same_segment:
        return [(float(a["Omega"]), float(a["energy"]), float(b["Omega"]), float(b["energy"]))
                for a, b in zip(rows, rows[1:])
                if a["segment"] == b["segment"] and a["branch"] == b["branch"] == "main"]
    main = sorted((float(r["Omega"]), float(r["energy"])) for r in rows if r["branch"] == "main")
    return [(w0, e0, w1, e1) for (w0, e0), (w1, e1) in zip(main, main[1:]) if 0 < w1 - w0 <= max_gap]


def energies_at(pieces, omega):
    return [e0 + (e1 - e0) * (omega - w0) / (w1 - w0)
            for w0, e0, w1, e1 in pieces if min(w0, w1) <= omega <= max(w0, w1) and w0 != w1]


def sampled_like(fine, coarse):
    """FINE's points nearest in Omega to COARSE's main points, in FINE's order."""
    omegas = [float(r["Omega"]) for r in fine]
    nearest = {min(range(len(fine)), key=lambda i: abs(omegas[i] - float(r["Omega"])))
               for r in coarse if r["branch"] == "main"}
    return [fine[i] for i in sorted(nearest)]


def compare(a, b, tolerance, pieces):
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


def overlay(runs, path):
    """Both runs' main branches (lines joining the main points of a segment)
    and tongue points, energy on a log scale against Omega."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(8, 5))
    for (label, rows), colour, marker in zip(runs, ("tab:blue", "tab:orange"), ("x", "+")):
        segments = {}
        for r in rows:
            if r["branch"] == "main":
                segments.setdefault(r["segment"], []).append((float(r["Omega"]), float(r["energy"])))
        for i, points in enumerate(segments.values()):
            axes.plot(*zip(*points), color=colour, lw=1.2, label=f"{label}: main branch" if i == 0 else None)
        tongue = [(float(r["Omega"]), float(r["energy"])) for r in rows if r["branch"] != "main"]
        if tongue:
            axes.plot(*zip(*tongue), marker, color=colour, ms=3, alpha=0.6, ls="none",
                      label=f"{label}: tongue points")
    axes.set_yscale("log")
    axes.set_xlabel("Omega")
    axes.set_ylabel("energy")
    axes.set_title("backbones compared: " + " against ".join(label for label, _ in runs), fontsize=10)
    axes.legend(fontsize=8)
    figure.savefig(path, dpi=130, bbox_inches="tight")
    print(f"wrote {path}")


def main():
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # piped into head: end quietly
    parser = argparse.ArgumentParser(
        description="Compare two runs' main branches at A's main points; optionally draw both.")
    parser.add_argument("a", help="run A: its backbone.csv or its output folder")
    parser.add_argument("b", help="run B: its backbone.csv or its output folder")
    parser.add_argument("tolerance", nargs="?", type=float, default=1e-3,
                        help="relative energy difference counted as agreement (default 1e-3)")
    parser.add_argument("--max-gap", type=float, default=0.01,
                        help="largest Omega spacing of B's main points interpolated across (default 0.01)")
    parser.add_argument("--same-segment", action="store_true",
                        help="interpolate only between consecutive main points of one of B's segments")
    parser.add_argument("--sampled-from", metavar="FINE",
                        help="replace B's points by FINE's nearest to B's main points")
    parser.add_argument("--plot", metavar="PNG", help="draw both runs' main branches and tongues into PNG")
    args = parser.parse_args()
    a, b = read(args.a), read(args.b)
    if args.sampled_from:
        b = sampled_like(read(args.sampled_from), b)
    compare(a, b, args.tolerance, main_pieces(b, args.same_segment, args.max_gap))
    if args.plot:
        overlay([(f"A ({args.a})", a), (f"B ({args.b})", b)], args.plot)


if __name__ == "__main__":
    main()
