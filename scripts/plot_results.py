#!/usr/bin/python3
"""Plots of an nsm-bar output directory (run by nsm-bar when Output/Plots = true).

usage: plot_results.py DIRECTORY [--gap G0] [--wall rigid|compliant]
--gap and --wall default to the run's own record, DIRECTORY/parameters.prm
(Contact/Gap and Contact/Wall), as nsm-bar wrote it.
Writes backbone.png (from backbone.csv, tongues.csv, resonances.csv, fields.csv), frc.png
(from frc.csv, over backbone.csv's main branch), per
field k, field_k_spacetime.png and field_k_tip.png, and for a study study.png (from
study.csv); prints "wrote PATH" per file, and "plots done" last. A folder
with none of these files is an error (exit 2): there is nothing to plot.

Every input is read and checked before any plot is drawn: bad input (a file
that is not UTF-8 CSV with one named column per field of every row, a number
that is not a finite decimal, an energy <= 0, a missing column, too few rows,
a bad option) is one line on stderr naming the file, line and column, or the
option, and exit code 2, with no plot written. A leading UTF-8 byte order
mark is skipped. Of each file's columns, those doc/output.md describes are
checked where present; empty cells only where a run leaves them empty.
"""
import argparse
import glob
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from csv_input import BACKBONE, BRANCHES, FRC, BadInput, Column, checked, decimal, read_table  # noqa: E402
import csv_input  # noqa: E402

try:
    import matplotlib
except ImportError as missing:  # a python3 without Debian's python3-matplotlib (a virtualenv's, pyenv's)
    sys.exit(f"plot_results.py: error: {missing} in {sys.executable}; run it with /usr/bin/python3, "
             "which ./run.sh provides with matplotlib")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import ticker  # noqa: E402


PROG = "plot_results.py"


def fail(message, code=2):
    csv_input.fail(PROG, message, code)


# The energy error the run summary counts as close: summary_energy_error in
# source/verification/orbit_refinement.cc, which the summary line prints.
CLOSE_ENERGY_ERROR = 0.01


def required(*names, **rule):
    return {name: Column(required=True, **rule) for name in names}


GRAZING = {**required("mode", whole=True, positive=True), **required("omega", "energy", positive=True),
           "accumulation_omega": Column(positive=True)}
TONGUES = {**required("mode", "harmonic", whole=True), **required("omega_resonance", "foot_omega_begin",
                                                                  "foot_omega_end"),
           **required("max_energy", positive=True), "points": Column(whole=True),
           "kind": Column(words=("internal", "unnamed", "accumulation"))}
RESONANCES = {**required("omega"), **required("mode", "harmonic", whole=True)}
FIELDS = {**required("index", whole=True), **required("Omega"), **required("energy", positive=True),
          "branch": Column(words=BRANCHES),
          **{name: Column(whole=True) for name in ("segment", "resonance_mode", "resonance_harmonic")}}
TIP = {**required("t", "contact_displacement", "contact_force"), "contact_velocity": Column()}
SPACETIME = required("t", "x", "displacement")


class Table(dict):
    """A CSV file's columns as lists of values (nan in an empty optional
    cell), with its path and each row's line number for messages."""

    def __init__(self, path, header, rows, columns):
        super().__init__({name: [row[name] for _, row in rows] for name in header if name in columns})
        self.path, self.lines = path, [line for line, _ in rows]

    def bad(self, i, column, what):
        return BadInput(f"{self.path}: line {self.lines[i]}, column {column}: {what}")


def one_period(tip):
    """A tip file's t: one period's samples, from t >= 0 up."""
    for i, t in enumerate(tip["t"]):
        if t < 0 or (i and t <= tip["t"][i - 1]):
            raise tip.bad(i, "t", f"{t!r} is " + ("< 0" if t < 0 else "not above the row before's"))


def grid(table):
    """A space-time file's t (from 0 up) and x: each two values or more."""
    for i, t in enumerate(table["t"]):
        if t < 0:
            raise table.bad(i, "t", f"{t!r} is < 0")
    for name in ("t", "x"):
        if len(set(table[name])) < 2:
            raise BadInput(f"{table.path}: column {name}: fewer than 2 distinct values")


# Each input by its name: its columns, its fewest and most rows, a check of the whole.
RULES = ((r"backbone\.csv", BACKBONE, 0, None, None), (r"frc\.csv", FRC, 0, None, None),
         (r"force_response\.csv", FRC, 0, None, None), (r"grazing\.csv", GRAZING, 1, 1, None),
         (r"tongues\.csv", TONGUES, 0, None, None), (r"resonances\.csv", RESONANCES, 0, None, None),
         (r"fields\.csv", FIELDS, 0, None, None), (r"field_\d+_tip\.csv", TIP, 2, None, one_period),
         (r"field_\d+_spacetime\.csv", SPACETIME, 4, None, grid))
TABLES = {}  # path: its Table, read and checked once


def read(path):
    """The Table of an input named in RULES, checked by its rules."""
    if path not in TABLES:
        columns, fewest, most, check = next(rule[1:] for rule in RULES
                                            if re.fullmatch(rule[0], os.path.basename(path)))
        header, rows = read_table(path, columns)
        if len(rows) < fewest or (most is not None and len(rows) > most):
            needed = f"exactly {fewest}" if fewest == most else f"at least {fewest}"
            raise BadInput(f"{path}: {len(rows)} data row{'s' * (len(rows) != 1)}, {needed} needed")
        table = Table(path, header, rows, columns)
        if check:
            check(table)
        TABLES[path] = table
    return TABLES[path]


def save(figure, path):
    """Writes PATH.partial and renames it into place: a plot stopped half-way
    (a kill, a full disk) never leaves a truncated PATH behind."""
    partial = path + ".partial"
    try:
        figure.savefig(partial, dpi=130, bbox_inches="tight", format=os.path.splitext(path)[1][1:])
        os.replace(partial, path)
    except OSError as error:  # a full disk, a file limit, no write permission
        if os.path.lexists(partial):
            os.remove(partial)
        fail(f"{path}: cannot be written: {error.strerror}", code=1)
    plt.close(figure)
    print("wrote " + path, flush=True)


# What run drew the plots (--caption): the scene, its mesh and M.
CAPTION = ""
GAP = 1.0  # --gap
# The last line of a complete run of this script (source/output/plots.cc).
DONE = "plots done"
# The files a plot is drawn from (besides each field's field_k_tip.csv).
PLOTTED = ("backbone.csv", "frc.csv", "force_response.csv", "study.csv")


def label_between_decades(axes, which="y"):
    """A log axis ("x", "y" or both) spanning few decades gets labels at 2 and
    5 times each power of ten too, so that values can be read off it."""
    for name in which:
        axis = axes.xaxis if name == "x" else axes.yaxis
        low, high = axes.get_xlim() if name == "x" else axes.get_ylim()
        if axis.get_scale() == "log" and low > 0 and high / low < 1e4:
            axis.set_major_locator(ticker.LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
            axis.set_major_formatter(ticker.FuncFormatter(lambda value, _: f"{value:g}"))
            axis.set_minor_formatter(ticker.NullFormatter())


def grazing_scale(directory):
    """(mode, w_j, E_g) from grazing.csv: the traced mode's linear energy with
    u(L) = g0, the energy scale; (None, None, 1.0) without it."""
    path = os.path.join(directory, "grazing.csv")
    if not os.path.exists(path):
        return None, None, 1.0
    g = read(path)
    return int(g["mode"][0]), g["omega"][0], g["energy"][0]


def place_labels(axes, labels, min_gap=0.045):
    """Annotates (x, y, text) points, largest first, skipping any whose spot
    (in axes fractions) lies within min_gap of one already placed."""
    placed, seen = [], set()
    to_axes = axes.transAxes.inverted()
    for x, y, text in labels:
        if text in seen:
            continue  # one resonance, two tongues (its two flanks): one label
        seen.add(text)
        fx, fy = to_axes.transform(axes.transData.transform((x, y)))
        if not (0 <= fx <= 1 and 0 <= fy <= 0.93):
            continue  # off the axes, or under the title's edge
        if all(abs(fx - px) > min_gap or abs(fy - py) > min_gap for px, py in placed):
            axes.annotate(text, (x, y), fontsize=7, color="C3", ha="center", va="bottom")
            placed.append((fx, fy))


def tongue_top(points, tongues, i):
    """(Omega, energy) of tongue i's highest point: its tongue points between
    its feet (tongues.csv); the resonance's own Omega if none is found."""
    begin, end = tongues["foot_omega_begin"][i], tongues["foot_omega_end"][i]
    low, high = min(begin, end), max(begin, end)
    on = [(e, w) for w, e, b in zip(points["Omega"], points["energy"], points["branch"])
          if b == "tongue" and low <= w <= high]
    if tongues.get("kind") and tongues["kind"][i] == "accumulation":
        # Its feet span other tongues too: its own highest point.
        top = tongues["max_energy"][i]
        on = [(e, w) for e, w in on if abs(e - top) <= 1e-12 * top]
    if not on:
        return tongues["omega_resonance"][i], tongues["max_energy"][i]
    energy, omega = max(on)
    return omega, energy


def backbone_plot(directory):
    points = read(os.path.join(directory, "backbone.csv"))
    mode, w_mode, e_g = grazing_scale(directory)
    energy = [e / e_g for e in points["energy"]]
    figure, axes = plt.subplots(figsize=(8, 5))
    # The main branch: a line through consecutive main points of one segment.
    runs, run = [], []
    for w, e, g, b in zip(points["Omega"], energy, points["segment"], points["branch"]):
        if run and (b != "main" or g != run[-1][2]):
            runs.append(run)
            run = []
        if b == "main":
            run.append((w, e, g))
    runs.append(run)
    for n, r in enumerate(x for x in runs if x):
        axes.semilogy([p[0] for p in r], [p[1] for p in r], "-", marker=".", markersize=3,
                      linewidth=1.2, color="C0", label="main branch" if n == 0 else None, zorder=3)
    tongue = [(w, e) for w, e, b in zip(points["Omega"], energy, points["branch"]) if b == "tongue"]
    if tongue:
        axes.semilogy([w for w, _ in tongue], [e for _, e in tongue], "x", markersize=3,
                      color="C3", alpha=0.6, label="resonance tongues", zorder=2)
    # Other families a leap landed on: less contact than the mode before them.
    other = [(w, e) for w, e, b in zip(points["Omega"], energy, points["branch"]) if b == "other"]
    if other:
        axes.semilogy([w for w, _ in other], [e for _, e in other], "+", markersize=3,
                      color="0.55", alpha=0.6, label="other families", zorder=1)
    # Points whose time integration does not come back after one period:
    # small rings behind the branch, so that they do not hide it.
    failed = [(w, e) for w, e, v in zip(points["Omega"], energy, points.get("verified", [])) if v == "false"]
    if failed:
        axes.semilogy([w for w, _ in failed], [e for _, e in failed], "o", markersize=7, markerfacecolor="none",
                      markeredgewidth=0.6, color="C1", alpha=0.7, label="not periodic in time", zorder=1)
    # Points refined in time: the orbit's energy, stable and unstable apart.
    for flag, marker, label in (("true", "s", "orbit in time, stable"), ("false", "D", "orbit in time, unstable")):
        orbit = [(w, e / e_g) for w, e, s in zip(points["Omega"], points.get("orbit_energy", []),
                                                 points.get("stable", [])) if s == flag]
        if orbit:
            axes.semilogy([w for w, _ in orbit], [e for _, e in orbit], marker, markersize=5,
                          markerfacecolor="none", color="C2" if flag == "true" else "C4", label=label, zorder=4)
    segments = sorted(set(points["segment"]))
    low, high = min(points["Omega"]), max(points["Omega"])
    margin = 0.02 * (high - low or 1)
    axes.set_xlim(low - margin, high + margin)
    # Internal resonances: only those whose tongue the run found, faint.
    tongues_path = os.path.join(directory, "tongues.csv")
    t = read(tongues_path) if os.path.exists(tongues_path) else {}
    # An unnamed tongue (mode 0: no w_j / k near it) has no line and no label.
    named = [i for i, j in enumerate(t.get("mode", [])) if int(j) > 0]
    for n, omega in enumerate(t["omega_resonance"][i] for i in named):
        axes.axvline(omega, color="grey", linewidth=0.5, linestyle=":", zorder=0,
                     label="internal resonance $\\omega_j / k$ of a tongue found" if n == 0 else None)
    resonances = os.path.join(directory, "resonances.csv")
    if os.path.exists(resonances):
        r = read(resonances)
        first = True
        for omega, m, harmonic in zip(r.get("omega", []), r.get("mode", []), r.get("harmonic", [])):
            # Only inside the axes: a label beyond them would stretch the
            # figure's tight bounding box (Omega min = 0 lists w_1 / 1).
            if harmonic == 1 and low - margin <= omega <= high + margin:
                axes.axvline(omega, color="black", linewidth=1.2, label="linear frequency $\\omega_j$" if first else None)
                right = omega > low + 0.9 * (high - low)  # near the right edge: label on the left
                axes.annotate(f"$\\omega_{{{int(m)}}}$ " if right else f" $\\omega_{{{int(m)}}}$", (omega, 0.98),
                              xycoords=("data", "axes fraction"), ha="right" if right else "left", va="top")
                first = False
    # The accumulation point of the internal resonances, where the branch crosses it.
    grazing = os.path.join(directory, "grazing.csv")
    for w_acc in (read(grazing).get("accumulation_omega", []) if os.path.exists(grazing) else []):
        if low - margin <= w_acc <= high + margin:
            axes.axvline(w_acc, color="tab:purple", linewidth=1.2, linestyle="--", zorder=0,
                         label=f"accumulation point $W_{{acc}}$ = {w_acc:.6g} of $\\omega_j / (2j - 1)$")
    fields = os.path.join(directory, "fields.csv")
    if os.path.exists(fields):
        f = read(fields)
        axes.plot(f["Omega"], [e / e_g for e in f["energy"]], "r*", markersize=12, label="fields", zorder=5)
    axes.set_xlabel("$\\Omega$ (the scene's units: rad/s if its inputs are SI)")
    axes.set_ylabel(f"energy / $E_g$ ($E_g$ = {e_g:.3g}: mode {mode} linear, $u(L) = g_0$)" if mode
                    else "energy (period mean)")
    if w_mode:
        top = axes.secondary_xaxis("top", functions=(lambda x: x / w_mode, lambda x: x * w_mode))
        top.set_xlabel(f"$\\Omega / \\omega_{mode}$", fontsize=8)
        top.tick_params(labelsize=7)
    # Tongue labels w_j/k at each tongue's highest point, the highest tongues
    # first, none overlapping; the axis is raised so that the top ones fit.
    tops = {i: tongue_top(points, t, i) for i in named}
    # The climb's truncated top into the accumulation point: a tongue of W_acc.
    climb = [i for i, kind in enumerate(t.get("kind", [])) if kind == "accumulation"]
    tops.update({i: tongue_top(points, t, i) for i in climb})
    if tops:
        low_e, high_e = axes.get_ylim()
        axes.set_ylim(low_e, max(high_e, 3 * max(e for _, e in tops.values()) / e_g))
    order = sorted(tops, key=lambda i: -tops[i][1])
    place_labels(axes, [(tops[i][0], tops[i][1] / e_g, "tongue of $W_{acc}$" if i in climb else
                         f"$\\omega_{{{int(t['mode'][i])}}}/{int(t['harmonic'][i])}$") for i in order])
    label_between_decades(axes)
    main = points["branch"].count("main")
    others = points["branch"].count("other")
    title = (f"Backbone: {main} main points, {len(points['Omega']) - main - others} on tongues, "
             f"{others} on other families, {len(segments)} segments")
    if CAPTION:
        title = CAPTION + "\n" + title
    if "verified" in points:
        checked = sum(v in ("true", "false") for v in points["verified"])
        title += f"\n{checked} verified in time, {len(failed)} not periodic"
    if "stable" in points:
        found = sum(s in ("true", "false") for s in points["stable"])
        title += f"\n{found} orbits found in time, {points['stable'].count('false')} unstable"
    axes.set_title(title, fontsize=10, pad=22 if w_mode else 6)
    # A branch that rises in Omega (the physical sign) climbs away from
    # grazing: the corner below its far end is free of points and of tongue
    # labels (they sit at the tongues' tops). The eq. (5) branch runs flat.
    rising = points["Omega"][-1] >= points["Omega"][0]
    axes.legend(loc="lower right" if rising else "best", fontsize=7, framealpha=0.9)
    save(figure, os.path.join(directory, "backbone.png"))


def drive_per_length(directory):
    """Whether the run's drive acts per unit length (Forcing/Shape = uniform
    in its parameters.prm); at the contact end where the file or the entry is
    missing."""
    section = None
    try:
        with open(os.path.join(directory, "parameters.prm")) as f:
            for line in f:
                words = line.split()
                if words[:1] == ["subsection"]:
                    section = " ".join(words[1:])
                elif words[:1] == ["end"]:
                    section = None
                elif section == "Forcing" and words[:4] == ["set", "Shape", "=", "uniform"]:
                    return True
    except (OSError, UnicodeDecodeError):
        pass
    return False


def frc_plot(directory):
    """frc.png: the forced curves over the backbone's main branch (energy over
    the grazing energy against Omega), and the contact end's amplitude over g0."""
    _, _, e_g = grazing_scale(directory)
    backbone_path = os.path.join(directory, "backbone.csv")
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    if os.path.exists(backbone_path):
        points = read(backbone_path)
        main = [(w, e / e_g) for w, e, b in zip(points["Omega"], points["energy"], points["branch"]) if b == "main"]
        top.semilogy([w for w, _ in main], [e for _, e in main], ".", markersize=3, color="0.3",
                     label="backbone, main branch", zorder=3)
    per_length = drive_per_length(directory)
    curve_plot(directory, figure, top, bottom, "frc", fixed="forcing", along="Omega",
               label="F per length" if per_length else "F", xlabel="Omega (rad/s)",
               title="Forced response: frequency-response curves" +
               (" over the backbone" if os.path.exists(backbone_path) else " (no backbone.csv in this folder)") +
               (" (drive per unit length along the bar)" if per_length else ""))


def stability_runs(rows, values, stable):
    """The rows' indices (one curve's, in order) cut into runs of one segment
    and one verdict; a change of verdict joins the two at its last point."""
    runs, run = [], []
    for i in rows:
        if run and values["segment"][i] != values["segment"][run[-1]]:
            runs.append(run)
            run = []
        elif run and stable[i] != stable[run[-1]]:
            runs.append(run)
            run = [run[-1]]
        run.append(i)
    runs.append(run)
    return runs


def curve_plot(directory, figure, top, bottom, name, fixed, along, label, xlabel, title):
    """NAME.png from NAME.csv: one colour per value of the column `fixed`,
    energy over the grazing energy (log) above and the contact end's amplitude
    over g0 below, against the column `along`; a line through consecutive
    points of one segment (a leap starts a new one), solid where the fold
    test finds them stable and dashed where not."""
    table = read(os.path.join(directory, name + ".csv"))
    mode, _, e_g = grazing_scale(directory)
    stable = table.get("stable") or [1] * len(table[along])
    for n, value in enumerate(sorted(set(table[fixed]))):
        rows = [i for i, v in enumerate(table[fixed]) if v == value]
        for k, r in enumerate(stability_runs(rows, table, stable)):
            legend = f"{label} = {value:g}" if k == 0 else None
            style = "-" if stable[r[-1]] == 1 else "--"
            top.semilogy([table[along][i] for i in r], [table["energy"][i] / e_g for i in r], style,
                         linewidth=1, color=f"C{n % 10}", label=legend)
            bottom.plot([table[along][i] for i in r], [table["tip_amplitude"][i] / GAP for i in r], style,
                        linewidth=1, color=f"C{n % 10}", label=legend)
    if any(s == 0 for s in stable):
        bottom.plot([], [], "--", linewidth=1, color="0.3", label="unstable (fold test)")
    floquet_markers(table, along, bottom)
    top.set_ylabel(f"energy / E_g (E_g of mode {mode}, grazing.csv)" if mode else "energy")
    bottom.set_ylabel("max |u(L, t)| / g0")
    bottom.axhline(1, color="0.6", linewidth=0.6, linestyle=":")
    bottom.set_xlabel(xlabel)
    top.set_title((CAPTION + "\n" + title) if CAPTION else title, fontsize=10)
    top.legend(fontsize=7, loc="best")
    bottom.legend(fontsize=7, loc="best")
    save(figure, os.path.join(directory, name + ".png"))


def floquet_markers(table, along, axes):
    """Marks the points whose largest Floquet multiplier (Forcing/Floquet)
    lies outside the unit circle by a complex pair (Neimark-Sacker) or beyond
    -1 (a period doubling): the instabilities the fold test cannot see."""
    largest = table.get("floquet_largest")
    if not largest:
        return
    for marker, label, chosen in (("x", "Neimark-Sacker (Floquet)", lambda i: table["floquet_imag"][i] != 0),
                                  ("+", "period doubling (Floquet)", lambda i: table["floquet_imag"][i] == 0 and
                                   table["floquet_real"][i] < -1)):
        rows = [i for i, m in enumerate(largest) if m == m and m > 1 and chosen(i)]
        if rows:
            axes.plot([table[along][i] for i in rows], [table["tip_amplitude"][i] / GAP for i in rows], marker,
                      color="black", markersize=6, label=label, zorder=4)


def force_response_plot(directory):
    """force_response.png: each curve in F at its fixed W, energy over the
    grazing energy and the contact end's amplitude over g0 against F."""
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    curve_plot(directory, figure, top, bottom, "force_response", fixed="Omega", along="forcing", label="Omega",
               xlabel="F, the drive's amplitude" + (" per unit length" if drive_per_length(directory) else ""),
               title="Forced response in F at fixed Omega: a sweep in force jumps at the folds")


def orbit_error_plot(directory):
    """orbits.png: the harmonic balance's energy error against the periodic
    orbit in time of each refined point, |error| on a log scale, with 1 %."""
    points = read(os.path.join(directory, "backbone.csv"))
    stable = points.get("stable", [])
    found = [(w, err, s) for w, err, s in zip(points["Omega"], points.get("hb_energy_error", []), stable)
             if s in ("true", "false")]
    if not found:
        return
    figure, axes = plt.subplots(figsize=(8, 4))
    for sign, marker, label in ((1, "^", "HB above the orbit"), (-1, "v", "HB below the orbit")):
        side = [(w, abs(err)) for w, err, _ in found if err * sign > 0 or (sign > 0 and err == 0)]
        if side:
            axes.semilogy([w for w, _ in side], [max(e, 1e-12) for _, e in side], marker, markersize=4,
                          color="C0" if sign > 0 else "C3", label=label)
    axes.axhline(CLOSE_ENERGY_ERROR, color="black", linestyle="--", linewidth=1,
                 label=f"{100 * CLOSE_ENERGY_ERROR:g} %")
    axes.set_xlabel("$\\Omega$ (the scene's units: rad/s if its inputs are SI)")
    axes.set_ylabel("|HB energy / orbit energy - 1|")
    within = sum(abs(err) <= CLOSE_ENERGY_ERROR for _, err, _ in found)
    axes.set_title(f"Harmonic balance against the orbit in time: {len(found)} orbits found, "
                   f"{within} within {100 * CLOSE_ENERGY_ERROR:g} %, {stable.count('true')} stable", fontsize=10)
    axes.legend(loc="best", fontsize=7, framealpha=0.9)
    save(figure, os.path.join(directory, "orbits.png"))


def explain_ringing(top, bottom, tip, gap, peak, rigid):
    """Says on the plot where the truncated series leaves the contact law's
    bounds: a negative contact force, or the end beyond a rigid wall. Both are
    Gibbs ringing of M harmonics around the impact's jumps (the harmonic
    balance enforces the law on the Fourier coefficients, so the truncated
    series need not satisfy it pointwise). Beyond a compliant wall's face the
    end is where its spring is compressed: no note."""
    n = len(tip["contact_force"])
    negative = sum(v < -1e-9 * peak for v in tip["contact_force"])
    beyond = rigid and sum(u > gap * (1 + 1e-9) for u in tip["contact_displacement"])
    # In the free flight's free space: mid-height of the force (zero there),
    # the bottom left of the displacement (which starts at the wall).
    note = dict(fontsize=7, color="0.25", bbox=dict(boxstyle="round", fc="white", ec="0.7", alpha=0.9))
    if negative:
        where = "at the impact's jumps" if rigid else "where contact begins and ends"
        bottom.text(0.5, 0.5, f"$\\lambda < 0$ at {negative} of {n} samples: Gibbs ringing of the truncated\n"
                    f"series {where}, not a pull of the wall", ha="center", va="center",
                    transform=bottom.transAxes, **note)
    if beyond:
        top.text(0.02, 0.04, f"$u(L) > g_0$ at {beyond} of {n} samples (largest "
                 f"{max(tip['contact_displacement']) / gap:.4g} $g_0$):\nthe truncated series overshoots the wall",
                 ha="left", va="bottom", transform=top.transAxes, **note)


def field_tips(directory):
    """(k, path) of each field_k_tip.csv (a name with no number in it is none)."""
    paths = glob.glob(os.path.join(glob.escape(directory), "field_*_tip.csv"))
    names = [re.fullmatch(r"field_(\d+)_tip\.csv", os.path.basename(path)) for path in paths]
    return sorted((int(name.group(1)), path) for name, path in zip(names, paths) if name)


def field_plots(directory, gap, rigid):
    omegas = {}
    if os.path.exists(os.path.join(directory, "fields.csv")):
        f = read(os.path.join(directory, "fields.csv"))
        omegas = {int(i): w for i, w in zip(f["index"], f["Omega"])}
    for index, path in field_tips(directory):
        title = f"$\\Omega$ = {omegas[index]:.6g}" if index in omegas else f"field {index}"
        tip = read(path)
        period = tip["t"][-1] * len(tip["t"]) / (len(tip["t"]) - 1)
        phase = [t / period for t in tip["t"]]
        figure, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
        top.plot(phase, [u / gap for u in tip["contact_displacement"]], "b-")
        top.axhline(1.0, color="black", linestyle="--", linewidth=1,
                    label="wall ($u = g_0$)" if rigid else "compliant wall's face ($u = g_0$)")
        top.set_ylabel("$u(L, t) / g_0$")
        top.legend(loc="lower right", fontsize=8)
        top.set_title("Contact end over one period, " + title)
        peak = max(abs(v) for v in tip["contact_force"]) or 1.0
        bottom.plot(phase, [v / peak for v in tip["contact_force"]], "r-")
        bottom.axhline(0.0, color="black", linewidth=0.5)
        bottom.set_ylabel(f"$\\lambda(t) / \\max|\\lambda|$ (max = {peak:.3g})")
        bottom.set_xlabel("$t / T$")
        explain_ringing(top, bottom, tip, gap, peak, rigid)
        if CAPTION:
            figure.text(0.5, 0.005, CAPTION, ha="center", va="bottom", fontsize=7, color="0.3")
        save(figure, path.replace("_tip.csv", "_tip.png"))

        grid_path = path.replace("_tip.csv", "_spacetime.csv")
        if os.path.exists(grid_path):
            grid = read(grid_path)
            xs = sorted(set(grid["x"]))
            ts = sorted(set(grid["t"]))
            column = {x: i for i, x in enumerate(xs)}
            row = {t: i for i, t in enumerate(ts)}
            values = [[0.0] * len(xs) for _ in ts]
            for t, x, u in zip(grid["t"], grid["x"], grid["displacement"]):
                values[row[t]][column[x]] = u / gap
            figure, axes = plt.subplots(figsize=(7, 5))
            mesh = axes.pcolormesh(xs, [t / ts[-1] for t in ts], values, shading="auto", cmap="RdBu_r")
            figure.colorbar(mesh, ax=axes, label="$u(x, t) / g_0$")
            axes.set_xlabel("$x$")
            axes.set_ylabel("$t / T$")
            axes.set_title("Displacement field over one period, " + title)
            if CAPTION:
                figure.text(0.5, 0.005, CAPTION, ha="center", va="bottom", fontsize=7, color="0.3")
            save(figure, grid_path.replace(".csv", ".png"))


STUDY_ERRORS = (("spectrum_error", "eigenfrequencies"), ("receptance_error", "receptance"),
                ("energy_error_max", "main-branch energy (max)"),
                ("energy_error_median", "main-branch energy (median)"),
                ("main_energy_error_median", "energy of the main points (median)"),
                ("main_time_defect_median", "one-period defect in time / g0 (median)"))


def natural(key):
    """Sort key: numbers as numbers, then text (such as "-", a value not used)."""
    def part(value):
        try:
            return (0, float(value), "")
        except ValueError:
            return (1, 0.0, value)
    return [part(v) for v in key]


def pareto(times, errors):
    """The points no other point beats in both time and error, by time."""
    front, best = [], float("inf")
    for t, e in sorted(zip(times, errors)):
        if e < best:
            front.append((t, e))
            best = e
    return front


def measured(column, rows):
    """The column a study's error is drawn from: the main-branch energy
    errors over the Backbone omegas every row shares with the reference
    (COLUMN_shared), where study.csv has them; else COLUMN."""
    shared = column + "_shared"
    return shared if column.startswith("energy_error") and shared in rows[0] else column


def energy_partial(row, column, rows):
    """A row left out of an energy error's front: it has an error of its own
    but none over the shared Omegas (study.csv's rule: its continuation ended
    inside the Backbone omegas, or none is shared)."""
    return column.startswith("energy_error") and not row.get(measured(column, rows), "x")


# study.csv: the columns the plot needs; the numbers of its rows whose status is ok.
STUDY = required("status", "reference", "cells", "harmonics", "dofs", "wall_total_median",
                 *(column for column, _ in STUDY_ERRORS), text=True)
STUDY_OK = {**{name: Column(whole=True) for name in ("cells", "harmonics", "dofs")}, "wall_total_median": Column(),
            "energy_points": Column(empty=True, whole=True), "shared_omegas": Column(empty=True, whole=True),
            "energy_error_partial": Column(empty=True, words=("yes", "no")),
            **{column: Column(empty=True) for column, _ in STUDY_ERRORS},
            **{column + "_shared": Column(empty=True) for column in ("energy_error_max", "energy_error_median")}}


def study_rows(path):
    """study.csv's rows whose status is ok, as text, their numbers checked."""
    if path not in TABLES:
        rows = read_table(path, STUDY)[1]
        for line, row in rows:
            if row["status"] == "ok":
                checked(path, line, dict(row), STUDY_OK)
        TABLES[path] = [row for _, row in rows if row["status"] == "ok"]
    return TABLES[path]


def forced_study_plot(directory):
    """study_forced.png (Study/Forced peaks): per row, the largest distance of
    a forced curve's peak from the main branch, and the peaks' phase lags
    (pi / 2 at phase resonance), against the modal damping ratio."""
    rows = [r for r in study_rows(os.path.join(directory, "study.csv")) if r.get("forced_peak_distance_max")]
    if not rows or not all(r.get("modal_ratio", "-") not in ("", "-") for r in rows):
        return
    rows.sort(key=lambda r: float(r["modal_ratio"]))
    ratio = [float(r["modal_ratio"]) for r in rows]
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    top.semilogx(ratio, [100 * float(r["forced_peak_distance_max"]) for r in rows], "o-", color="C0")
    # A row whose curves were not all traced whole compares fewer peaks.
    for x, r in zip(ratio, rows):
        if r.get("forced_curves_whole") not in (None, "", r["forced_curves"]):
            whole = r["forced_curves_whole"]
            top.annotate(f"{r['forced_peaks_compared']} of {r['forced_curves']} peaks\n({whole} "
                         f"curve{'' if whole == '1' else 's'} traced whole)", (x, 100 * float(r["forced_peak_distance_max"])),
                         textcoords="offset points", xytext=(8, 4), fontsize=7)
    top.set_ylabel("largest |E_peak / E_main - 1| (%)")
    top.set_title((CAPTION + "\n" if CAPTION else "") + "Forced curves' peaks against the backbone's main branch",
                  fontsize=10)
    bottom.semilogx(ratio, [float(r["forced_peak_phase_min"]) for r in rows], "v-", color="C1", label="smallest")
    bottom.semilogx(ratio, [float(r["forced_peak_phase_max"]) for r in rows], "^-", color="C2", label="largest")
    bottom.axhline(math.pi / 2, color="0.5", linestyle="--", linewidth=1, label="pi / 2 (phase resonance)")
    bottom.set_ylabel("phase lag at the peaks")
    bottom.set_xlabel("Damping/Modal ratio")
    bottom.legend(fontsize=8)
    label_between_decades(bottom, "x")
    save(figure, os.path.join(directory, "study_forced.png"))


def study_plot(directory):
    rows = study_rows(os.path.join(directory, "study.csv"))
    if not rows:
        return
    swept = list(rows[0])[:list(rows[0]).index("status")]
    # The size along a line: the mesh, or the harmonics in a study of M alone.
    size, size_column, size_name = "cells", "dofs", "DoFs"
    if len({r["cells"] for r in rows}) == 1 and len({r["harmonics"] for r in rows}) > 1:
        size, size_column, size_name = "harmonics", "harmonics", "harmonics M"
    # One line per combination of the varying parameters but the size.
    # "-" marks a value a row's run does not use: it names nothing.
    varying = [c for c in swept if c != size and len({r[c] for r in rows} - {"-"}) > 1]
    measures = [(c, name) for c, name in STUDY_ERRORS if any(r[measured(c, rows)] for r in rows)]
    if not measures:
        return
    figure, axes = plt.subplots(len(measures), 2, figsize=(12, 4.2 * len(measures)), squeeze=False)
    for axes_row, ((plain, name), (by_dofs, by_time)) in enumerate(zip(measures, axes)):
        column = measured(plain, rows)
        partial = [r for r in rows if r[plain] and energy_partial(r, plain, rows)]
        valid = [r for r in rows if r[column] and float(r[column]) > 0]
        over = ""
        if column != plain:
            shared = {r["shared_omegas"] for r in valid} - {""}
            over = f", over the {shared.pop() if shared else 0} Omegas all rows share"
        groups = {}
        for r in valid:
            groups.setdefault(tuple(r[c] for c in varying), []).append(r)
        # Up to 10 series in colours told apart (tab10); more along viridis.
        colours = (plt.cm.tab10(range(len(groups))) if len(groups) <= 10 else
                   plt.cm.viridis([i / max(1, len(groups) - 1) for i in range(len(groups))]))
        styles = {}
        for (key, group), colour in zip(sorted(groups.items(), key=lambda g: natural(g[0])), colours):
            group.sort(key=lambda r: int(r[size_column]))
            label = ", ".join(f"{c} {v}" for c, v in zip(varying, key) if v != "-") or "study"
            # The parameters after the first (e.g. the refinement) set marker and line style.
            index = styles.setdefault(key[1:], len(styles))
            marker, dashes = "os^vdp"[index % 6], ["-", "--", ":", "-."][index % 4]
            errors = [float(r[column]) for r in group]
            by_dofs.loglog([int(r[size_column]) for r in group], errors, marker, ls=dashes, ms=3, color=colour,
                           label=label)
            by_time.loglog([float(r["wall_total_median"]) for r in group], errors, marker, ms=3,
                           color=colour)
        # study.csv says which rows ended inside the Backbone omegas: their own
        # error (over part of them) is ringed grey, off the front.
        partial = [r for r in partial if float(r[plain]) > 0]
        if partial:
            errors = [float(r[plain]) for r in partial]
            by_dofs.loglog([int(r[size_column]) for r in partial], errors, "o", ms=9, mfc="none", color="0.5")
            by_time.loglog([float(r["wall_total_median"]) for r in partial], errors, "o", ms=9, mfc="none",
                           color="0.5", label="ended inside the Backbone omegas (own error, not on the front)")
        on_front = [r for r in valid if r not in partial]
        front = pareto([float(r["wall_total_median"]) for r in on_front], [float(r[column]) for r in on_front])
        by_time.step([t for t, _ in front], [e for _, e in front], "k-", where="post", lw=1,
                     label="Pareto front")
        by_time.plot([t for t, _ in front], [e for _, e in front], "ks", mfc="none", ms=7)
        by_dofs.set_xlabel(size_name)
        if size == "harmonics":  # M itself on the axis: 5, 10, 20, not 2 x 10^1
            by_dofs.xaxis.set_major_formatter(ticker.FuncFormatter(lambda value, _: f"{value:g}"))
            by_dofs.xaxis.set_minor_formatter(ticker.FuncFormatter(lambda value, _: f"{value:g}"))
        by_time.set_xlabel("wall time per run [s] (median)")
        by_dofs.set_ylabel("relative error:\n" + name)
        by_time.set_title("relative error: " + name + over + ", against time", fontsize=9)
        for a in (by_dofs, by_time):
            a.grid(True, which="both", alpha=0.3)
        if size != "harmonics":
            label_between_decades(by_dofs, "xy")
        label_between_decades(by_time, "xy")
        by_time.legend(fontsize=7)
        if axes_row == 0:  # the series' legend once, right of the first row
            by_dofs.legend(fontsize=8, ncol=1 + len(groups) // 12, loc="upper left", bbox_to_anchor=(2.25, 1))
    figure.suptitle("Accuracy against cost, " + ", ".join(sorted({r["reference"] for r in rows})) +
                    " reference" + ("\n" + CAPTION if CAPTION else ""))
    figure.subplots_adjust(wspace=0.3, hspace=0.35)
    save(figure, os.path.join(directory, "study.png"))


def gap_value(text):
    """--gap: a finite decimal number > 0."""
    value = decimal(text)
    if value is None or value <= 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not a finite decimal number > 0")
    return value


class Parser(argparse.ArgumentParser):
    """Errors in one line (no usage block), exit 2."""

    def error(self, message):
        fail(message)


def read_inputs(directory):
    """Reads and checks every file the plots draw, before any is drawn."""
    if not os.path.isdir(directory):
        raise BadInput(f"{directory}: not a folder")
    for name in ("backbone.csv", "frc.csv", "force_response.csv", "grazing.csv", "tongues.csv", "resonances.csv",
                 "fields.csv"):
        if os.path.exists(os.path.join(directory, name)):
            read(os.path.join(directory, name))
    for _, path in field_tips(directory):
        read(path)
        if os.path.exists(path.replace("_tip.csv", "_spacetime.csv")):
            read(path.replace("_tip.csv", "_spacetime.csv"))
    if os.path.exists(os.path.join(directory, "study.csv")):
        study_rows(os.path.join(directory, "study.csv"))


def recorded_contact(directory):
    """Contact/Gap and Contact/Wall as the run's record (parameters.prm)
    holds them, each None where it does not (no record, or no such entry)."""
    path = os.path.join(directory, "parameters.prm")
    values = {}
    if not os.path.isfile(path):
        return None, None
    sections = []
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            words = line.split("#")[0].split()
            if words[:1] == ["subsection"]:
                sections.append(" ".join(words[1:]))
            elif words == ["end"] and sections:
                sections.pop()
            elif words[:1] == ["set"] and sections == ["Contact"] and "=" in " ".join(words):
                name, value = " ".join(words[1:]).split("=", 1)
                values[" ".join(name.split())] = value.strip()
    return values.get("Gap"), values.get("Wall")


def main():
    parser = Parser(prog=PROG)
    parser.add_argument("directory")
    parser.add_argument("--gap", type=gap_value, help="the gap g0: a number > 0 (default: the run's Contact/Gap)")
    parser.add_argument("--wall", choices=("rigid", "compliant"),
                        help="compliant: u(L) > g0 is the spring's compression, not an overshoot "
                             "(default: the run's Contact/Wall, else rigid)")
    parser.add_argument("--caption", default="", help="what run drew the plots: its scene, mesh and M")
    arguments = parser.parse_args()
    if not os.path.isdir(arguments.directory):
        fail(f"{arguments.directory}: not a directory (a run's or a study's output folder)")
    if not any(os.path.exists(os.path.join(arguments.directory, name)) for name in PLOTTED) and \
            not field_tips(arguments.directory):
        fail(f"{arguments.directory}: nothing to plot (none of {', '.join(PLOTTED)} or field_k_tip.csv)")
    recorded_gap, recorded_wall = recorded_contact(arguments.directory)
    # The gap scales the forced curves' amplitudes and the fields; a folder
    # without them (a study's) draws nothing in units of g0.
    in_gaps = any(os.path.exists(os.path.join(arguments.directory, name))
                  for name in ("frc.csv", "force_response.csv")) or bool(field_tips(arguments.directory))
    if arguments.gap is None and recorded_gap is not None:
        try:
            arguments.gap = gap_value(recorded_gap)
        except argparse.ArgumentTypeError as error:
            fail(f"{os.path.join(arguments.directory, 'parameters.prm')}: Contact/Gap: {error}")
    if arguments.gap is None and in_gaps:
        fail(f"--gap: needed, since {os.path.join(arguments.directory, 'parameters.prm')} does not give "
             "Contact/Gap (a number > 0)")
    if arguments.gap is None:
        arguments.gap = 1.0
    if arguments.wall is None:
        arguments.wall = recorded_wall if recorded_wall in ("rigid", "compliant") else "rigid"
    global CAPTION, GAP
    CAPTION = arguments.caption
    GAP = arguments.gap
    try:
        read_inputs(arguments.directory)
    except BadInput as error:
        fail(str(error))
    backbone = os.path.join(arguments.directory, "backbone.csv")
    if os.path.exists(backbone) and not read(backbone)["Omega"]:
        # A run stopped before its first point in the range writes the header alone.
        print(f"{backbone} holds no point: backbone.png not drawn", flush=True)
    elif os.path.exists(backbone):
        backbone_plot(arguments.directory)
        orbit_error_plot(arguments.directory)
    frc = os.path.join(arguments.directory, "frc.csv")
    if os.path.exists(frc) and read(frc)["Omega"]:
        frc_plot(arguments.directory)
    force = os.path.join(arguments.directory, "force_response.csv")
    if os.path.exists(force) and read(force)["Omega"]:
        force_response_plot(arguments.directory)
    field_plots(arguments.directory, arguments.gap, arguments.wall == "rigid")
    if os.path.exists(os.path.join(arguments.directory, "study.csv")):
        study_plot(arguments.directory)
        forced_study_plot(arguments.directory)
    # The run takes the plots as drawn only after this line (a script that
    # ended early with status 0 drew some of them at most).
    print(DONE, flush=True)


if __name__ == "__main__":
    main()
