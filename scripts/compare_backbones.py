#!/usr/bin/python3
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

Prints a summary first: how many of A's main points were compared, how many
agree within the tolerance (relative energy), the median, 90th percentile and
largest difference, then the ten points that differ most beyond the
tolerance, in Omega order (--all: every point beyond it).

With --sampled-from, B's points are replaced by the points of the run FINE
(steps much smaller than B's) nearest in Omega to B's main points: FINE's
branch sampled where B sampled its own. Comparing A with that tells what the
linear interpolation between B's points costs by itself, whatever branch B
followed.

Bad input (a file that is not UTF-8 CSV with one named column per field of
every row, a number that is not a finite decimal, an energy <= 0, a branch
not main, tongue or other, a bad option, nothing to compare) is one line on
stderr naming the file and line, or the option, and exit code 2. A leading
UTF-8 byte order mark is skipped.
"""
import argparse
import os
import signal
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from csv_input import BACKBONE, BadInput, decimal, read_table  # noqa: E402
import csv_input  # noqa: E402

PROG = "compare_backbones.py"
WORST = 10  # points listed without --all


def fail(message, code=2):
    csv_input.fail(PROG, message, code)


def backbone_path(path):
    """A backbone.csv, or the output folder that holds one."""
    if os.path.isdir(path):
        path = os.path.join(path, "backbone.csv")
    if not os.path.isfile(path):
        raise BadInput(f"{path} is not a backbone.csv or a folder holding one")
    return path


def read(path):
    """(the file, its rows) of a backbone.csv or of the folder holding one."""
    path = backbone_path(path)
    return path, [row for _, row in read_table(path, BACKBONE)[1]]


def main_pieces(rows, same_segment, max_gap):
    """(W0, E0, W1, E1): consecutive main points of one segment
    (same_segment), or else neighbours in Omega of the main branch at most
    max_gap apart."""
    if same_segment:
        return [(a["Omega"], a["energy"], b["Omega"], b["energy"]) for a, b in zip(rows, rows[1:])
                if a["segment"] == b["segment"] and a["branch"] == b["branch"] == "main"]
    main = sorted((r["Omega"], r["energy"]) for r in rows if r["branch"] == "main")
    return [(w0, e0, w1, e1) for (w0, e0), (w1, e1) in zip(main, main[1:]) if 0 < w1 - w0 <= max_gap]


def energies_at(pieces, omega):
    return [e0 + (e1 - e0) * (omega - w0) / (w1 - w0)
            for w0, e0, w1, e1 in pieces if min(w0, w1) <= omega <= max(w0, w1) and w0 != w1]


def sampled_like(fine, coarse):
    """FINE's points nearest in Omega to COARSE's main points, in FINE's order."""
    nearest = {min(range(len(fine)), key=lambda i: abs(fine[i]["Omega"] - r["Omega"]))
               for r in coarse if r["branch"] == "main"}
    return [fine[i] for i in sorted(nearest)]


def compare(a, pieces):
    """(difference, Omega, A's energy, B's energies) at each of A's main
    points inside a piece of B, the difference relative to B's energy
    (> 0: B's main points have energies > 0)."""
    compared = []
    for row in a:
        others = energies_at(pieces, row["Omega"]) if row["branch"] == "main" else []
        if others:
            compared.append((min(abs(row["energy"] / e - 1) for e in others), row["Omega"], row["energy"], others))
    return compared


def summary(compared, main_a, tolerance, every):
    """The counts and the differences' quantiles, then the points beyond the
    tolerance in Omega order: the WORST largest, or every one."""
    print(f"{len(compared)} of A's {main_a} main points lie inside a main piece of B")
    differences = sorted(d for d, *_ in compared)
    agree = sum(d <= tolerance for d in differences)
    print(f"{agree} ({100 * agree / len(compared):.0f} %) agree within {tolerance:g}; median "
          f"{statistics.median(differences):.2e}, 90th percentile "
          f"{differences[int(0.9 * (len(differences) - 1))]:.2e}, largest {differences[-1]:.2e}")
    beyond = sorted((p for p in compared if p[0] > tolerance), key=lambda p: -p[0])
    if not beyond:
        return
    points = f"{len(beyond)} point{'s' * (len(beyond) > 1)} beyond {tolerance:g}"
    if every or len(beyond) <= WORST:
        print(f"the {points}, in Omega order:")
    else:
        print(f"the {WORST} largest differences of the {points}, in Omega order (--all: every one):")
        beyond = beyond[:WORST]
    for d, omega, energy, others in sorted(beyond, key=lambda p: p[1]):
        print(f"  Omega {omega:.6f}: A {energy:.6e}, B {' or '.join(f'{e:.6e}' for e in others)} ({d:.2e})")


def overlay(runs, path):
    """Both runs' main branches (lines joining the main points of a segment),
    tongue points (x) and other families' (+), energy on a log scale against
    Omega, as backbone.png draws them. Written as PATH.partial, then renamed."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(8, 5))
    for (label, rows), colour in zip(runs, ("tab:blue", "tab:orange")):
        segments = {}
        for r in rows:
            if r["branch"] == "main":
                segments.setdefault(r["segment"], []).append((r["Omega"], r["energy"]))
        for i, points in enumerate(segments.values()):
            axes.plot(*zip(*points), color=colour, lw=1.2, label=f"{label}: main" if i == 0 else None)
        for branch, marker in (("tongue", "x"), ("other", "+")):
            points = [(r["Omega"], r["energy"]) for r in rows if r["branch"] == branch]
            if points:
                axes.plot(*zip(*points), marker, color=colour, ms=3, alpha=0.6, ls="none",
                          label=f"{label}: {branch}")
    axes.set_yscale("log")
    axes.set_xlabel("Omega")
    axes.set_ylabel("energy")
    axes.set_title("backbones compared: " + " against ".join(label for label, _ in runs), fontsize=10)
    axes.legend(fontsize=8)
    partial = path + ".partial"
    try:
        figure.savefig(partial, dpi=130, bbox_inches="tight", format=plot_format(path))
        os.replace(partial, path)
    except Exception as error:  # a full disk, no write permission, a format's missing tool
        if os.path.lexists(partial):
            os.remove(partial)
        fail(f"{path}: cannot be written: {getattr(error, 'strerror', None) or error}", code=1)
    print(f"wrote {path}")


def plot_format(path):
    return os.path.splitext(path)[1][1:].lower()


def plot_path(path):
    """--plot's value: a file name with an extension matplotlib writes, in a folder that exists."""
    try:
        from matplotlib.backend_bases import FigureCanvasBase
    except ImportError:
        raise argparse.ArgumentTypeError(f"{sys.executable} has no matplotlib to draw with")
    formats = FigureCanvasBase.get_supported_filetypes()
    if plot_format(path) not in formats:
        raise argparse.ArgumentTypeError(f"{path!r} does not end in .png or another extension matplotlib "
                                         f"writes ({', '.join(sorted(formats))})")
    folder = os.path.dirname(path) or "."
    if not os.path.isdir(folder):
        raise argparse.ArgumentTypeError(f"{path!r}: no folder {folder!r}")
    if os.path.isdir(path):
        raise argparse.ArgumentTypeError(f"{path!r} is a folder")
    return path


def bounded(least, above):
    """An option's type: a finite decimal number >= LEAST (> it if ABOVE)."""
    def number(text):
        value = decimal(text)
        if value is None or value < least or (above and value == least):
            raise argparse.ArgumentTypeError(f"{text!r} is not a finite decimal number {'>' if above else '>='} "
                                             f"{least:g}")
        return value
    return number


class Parser(argparse.ArgumentParser):
    """Errors in one line (no usage block), exit 2."""

    def error(self, message):
        fail(message)


def arguments():
    parser = Parser(prog=PROG,
                    description="Compare two runs' main branches at A's main points; optionally draw both.")
    parser.add_argument("a", help="run A: its backbone.csv or its output folder")
    parser.add_argument("b", help="run B: its backbone.csv or its output folder")
    parser.add_argument("tolerance", nargs="?", type=bounded(0, False), default=1e-3,
                        help="relative energy difference counted as agreement (default 1e-3)")
    parser.add_argument("--max-gap", type=bounded(0, True), default=0.01,
                        help="largest Omega spacing of B's main points interpolated across (default 0.01)")
    parser.add_argument("--same-segment", action="store_true",
                        help="interpolate only between consecutive main points of one of B's segments")
    parser.add_argument("--sampled-from", metavar="FINE",
                        help="replace B's points by FINE's nearest to B's main points")
    parser.add_argument("--all", action="store_true",
                        help=f"list every point beyond the tolerance (default: the {WORST} largest)")
    parser.add_argument("--plot", metavar="PNG", type=plot_path,
                        help="draw both runs' main branches, tongues and other families into PNG")
    return parser.parse_args()


def run(args):
    (a_path, a), (b_path, b) = read(args.a), read(args.b)
    for path, rows in ((a_path, a), (b_path, b)):
        if not any(r["branch"] == "main" for r in rows):
            raise BadInput(f"{path}: no main point to compare")
    if args.sampled_from:
        fine_path, fine = read(args.sampled_from)
        if not fine:
            raise BadInput(f"{fine_path}: no rows to sample B from")
        b_path, b = fine_path, sampled_like(fine, b)
        if not any(r["branch"] == "main" for r in b):
            raise BadInput(f"{fine_path}: none of the points nearest to B's main points is a main point")
    main_a = sum(r["branch"] == "main" for r in a)
    compared = compare(a, main_pieces(b, args.same_segment, args.max_gap))
    if not compared:
        pieces = "consecutive main points of one segment" if args.same_segment else \
            f"main points at most --max-gap {args.max_gap:g} apart"
        raise BadInput(f"{a_path}: none of A's {main_a} main points lies between two {pieces} of {b_path}")
    summary(compared, main_a, args.tolerance, args.all)
    if args.plot:
        overlay([(f"A ({args.a})", a), (f"B ({args.b})", b)], args.plot)


def main():
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # piped into head: end quietly
    args = arguments()
    try:
        run(args)
    except BadInput as error:
        fail(str(error))


if __name__ == "__main__":
    main()
