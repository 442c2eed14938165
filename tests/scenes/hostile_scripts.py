#!/usr/bin/env python3
"""Hostile and valid inputs for scripts/compare_backbones.py and
scripts/plot_results.py, one table row each.

usage: python3 hostile_scripts.py SCRIPTS_DIR [NAME_REGEX]
Each row builds a small folder of CSV files in a temporary directory, runs one
script there (with Debian's /usr/bin/python3, which has matplotlib, as nsm-bar
runs plot_results.py) and checks:
- bad input: exit code 2, exactly one line on stderr that names the file
  (and the line and column where the row gives them) or the option, no
  'Traceback' anywhere, no PNG (or other plot) and no .partial file left;
- valid input: exit code 0, no 'Traceback', the summary (compare) or
  backbone.png and 'plots done' as the last line (plot), and the row's own
  check.
Prints one line per row, the counts per class, and 'N passed, M failed' last;
exits 0 when every row passed. Standard library only.
"""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

PYTHON = "/usr/bin/python3" if os.access("/usr/bin/python3", os.X_OK) else sys.executable
GAP = 0.01
BOM = b"\xef\xbb\xbf"


# ---------------------------------------------------------------- valid data
def table(header, rows):
    return ",".join(header) + "\n" + "".join(",".join(str(v) for v in row) + "\n" for row in rows)


BACKBONE_HEADER = ("segment,Omega,energy,energy_spread,max_contact_force,max_contact_displacement,"
                   "contact_fraction,newton_iterations,residual,branch,resonance_mode,resonance_harmonic,"
                   "leading_harmonic,energy_error_estimate,verified,periodicity_defect,periodicity_defect_end,"
                   "energy_drift,impulse_ratio,verified_contact_fraction,verified_energy,orbit_energy,hb_energy_error,"
                   "orbit_contact_fraction,floquet_max,stable,isolation").split(",")
TONGUE_ROWS, OTHER_ROW, SECOND_SEGMENT = (10, 11), 30, 20


def omega(i, shift=0.0):
    return 1.92 + shift + 0.005 * i


def backbone(n=40, wobble=0.0, branch=None, segment=None, shift=0.0):
    """A backbone.csv: main points but tongue points at rows 10 and 11 and
    another family's at row 30, two segments; empty estimate, verification
    and orbit cells on some rows as a run leaves them. Row i is on line i + 2."""
    rows = []
    for i in range(n):
        w = omega(i, shift)
        e = 1.0 + 10 * (w - 1.92) ** 2 * (1 + wobble * math.sin(40 * w))
        b = branch(i) if branch else ("tongue" if i in TONGUE_ROWS else "other" if i == OTHER_ROW else "main")
        seg = segment(i) if segment else int(i >= SECOND_SEGMENT)
        tongue = b == "tongue"
        verify = ["true" if i % 4 else "false", 1e-4, 2e-4, -1e-6, 1.01, 0.2, e] if i % 3 == 0 else [""] * 7
        orbit = [e * 1.001, -0.001, 0.21, 1.5, "true" if i % 2 else "false", 1e-3] if i % 5 == 0 else [""] * 6
        rows.append([seg, repr(w), repr(e), 0.1, 1.5, 0.0101, 0.2, 3, 1e-12, b, 2 if tongue else 0,
                     3 if tongue else 0, 3 if tongue else 1, "" if i % 7 == 0 else 1e-4, *verify, *orbit])
    return table(BACKBONE_HEADER, rows)


def field_tip(n=16, w=2.0):
    period = 2 * math.pi / w
    rows = []
    for j in range(n):
        t = period * j / n
        phase = 2 * math.pi * j / n
        rows.append([repr(t), repr(GAP * math.cos(phase)), repr(-GAP * w * math.sin(phase)),
                     repr(max(0.0, math.cos(phase)) * 3.0 - 0.01)])
    return table(["t", "contact_displacement", "contact_velocity", "contact_force"], rows)


def field_spacetime(n=8, w=2.0):
    period = 2 * math.pi / w
    rows = [[repr(period * j / n), repr(x / 4), repr(GAP * x / 4 * math.cos(2 * math.pi * j / n))]
            for j in range(n + 1) for x in range(5)]
    return table(["t", "x", "displacement"], rows)


STUDY_HEADER = ("degree,cells,harmonics,status,reference,dofs,spectrum_error,receptance_error,energy_error_max,"
                "energy_error_median,main_energy_error_median,main_time_defect_median,energy_points,"
                "energy_error_partial,wall_total_median").split(",")


def study():
    """A study.csv: three rows ok, one failed (its measures empty)."""
    ok = [[4, c, 20, "ok", "uniform (tan)", 4 * c + 1, 1e-3 / c, "", 1e-2 / c, 5e-3 / c, 4e-3 / c, "", 5, "no",
           0.1 * c] for c in (2, 4, 8)]
    return table(STUDY_HEADER, ok + [[4, 16, 20, "failed: no convergence", "uniform (tan)", 0] + [""] * 6
                                     + [0, "", 3.0]])


def run_folder():
    """A run's output folder as plot_results.py reads it."""
    return {"out/backbone.csv": backbone(),
            "out/grazing.csv": "mode,omega,energy\n1,1.9191370000000001,0.25\n",
            "out/tongues.csv": table("mode,harmonic,omega_resonance,foot_omega_begin,foot_omega_end,max_energy,"
                                     "points,kind".split(","),
                                     [[2, 3, 1.972, repr(omega(9)), repr(omega(12)), 1.03, 2, "internal"]]),
            "out/resonances.csv": table(["omega", "mode", "harmonic"], [[1.919137, 1, 1], [5.76, 2, 1]]),
            "out/fields.csv": table("index,Omega,segment,energy,branch,resonance_mode,resonance_harmonic".split(","),
                                    [[0, 2.0, 0, 1.064, "main", 0, 0]]),
            "out/field_0_tip.csv": field_tip(),
            "out/field_0_spacetime.csv": field_spacetime()}


def two_runs():
    return {"a/backbone.csv": backbone(), "b/backbone.csv": backbone(wobble=0.02)}


# ------------------------------------------------------------ text mutations
def set_cell(text, line, column, value):
    """TEXT with the cell of COLUMN on LINE (1-based) set to VALUE."""
    lines = text.split("\n")
    c = lines[0].split(",").index(column)
    fields = lines[line - 1].split(",")
    fields[c] = value
    lines[line - 1] = ",".join(fields)
    return "\n".join(lines)


def set_column(text, column, value):
    for line in range(2, text.count("\n") + 1):
        text = set_cell(text, line, column, value)
    return text


def edit_line(text, line, change):
    lines = text.split("\n")
    lines[line - 1] = change(lines[line - 1])
    return "\n".join(lines)


def header_only(text):
    return text.split("\n")[0] + "\n"


def with_bytes(text, line, column, raw):
    """TEXT as bytes with the cell of COLUMN on LINE holding the bytes RAW."""
    before, after = set_cell(text, line, column, "\0").encode().split(b"\0")
    return before + raw + after


# --------------------------------------------------------------------- rows
class Case:
    def __init__(self, name, klass, script, files, args, names=None, line=None, column=None, ok=False,
                 check=None):
        self.name, self.klass, self.script, self.files, self.args = name, klass, script, files, args
        self.names, self.line, self.column, self.ok, self.check = names, line, column, ok, check


PLOT_ARGS = ["--gap", str(GAP), "--wall", "rigid", "--caption=hostile table", "--", "out"]
COMPARE_ARGS = ["a", "b", "--plot", "out.png"]


def compare_case(name, klass, changes=None, args=None, **expect):
    files = two_runs()
    files.update(changes or {})
    return Case(name, klass, "compare_backbones.py", files, COMPARE_ARGS if args is None else args, **expect)


def plot_case(name, klass, changes=None, args=None, **expect):
    files = run_folder()
    files.update(changes or {})
    return Case(name, klass, "plot_results.py", files, PLOT_ARGS if args is None else args, **expect)


def in_a(column, value, line=7):
    return {"a/backbone.csv": set_cell(backbone(), line, column, value)}


def in_b(column, value, line=7):
    return {"b/backbone.csv": set_cell(backbone(wobble=0.02), line, column, value)}


def in_out(name, text):
    return {f"out/{name}": text}


A, B, OUT_B = "a/backbone.csv", "b/backbone.csv", "out/backbone.csv"


def compare_summary(result, _):
    lines = result.stdout.splitlines()
    if not re.fullmatch(r"37 of A's 37 main points lie inside a main piece of B", lines[0]):
        return f"first line {lines[0]!r}"
    if not re.match(r"\d+ \(\d+ %\) agree within 0\.001; median \S+, 90th percentile \S+, largest \S+$", lines[1]):
        return f"second line {lines[1]!r}"
    listed = [line for line in lines if line.startswith("  Omega ")]
    omegas = [float(line.split()[1].rstrip(":")) for line in listed]
    worst = "the 10 largest differences of the 20 points beyond 0.001, in Omega order"
    if len(listed) != 10 or omegas != sorted(omegas) or worst not in result.stdout:
        return f"{len(listed)} points listed, in Omega order: {omegas == sorted(omegas)} (the worst 10 expected)"
    return None


def compare_all(result, _):
    listed = [line for line in result.stdout.splitlines() if line.startswith("  Omega ")]
    omegas = [float(line.split()[1].rstrip(":")) for line in listed]
    return None if len(listed) == 20 and omegas == sorted(omegas) else f"--all listed {len(listed)} (20 expected)"


def is_png(path):
    if not os.path.isfile(path):
        return False
    with open(path, "rb") as f:
        return f.read(8) == b"\x89PNG\r\n\x1a\n"


def compare_png(result, folder):
    return compare_summary(result, folder) or (None if is_png(os.path.join(folder, "out.png")) else "no out.png")


def legend(result, folder):
    with open(os.path.join(folder, "out.svg"), encoding="utf-8") as f:
        svg = f.read()
    wanted = ["A (a): main", "A (a): tongue", "A (a): other", "B (b): main", "B (b): tongue", "B (b): other"]
    missing = [w for w in wanted if f"<!-- {w} -->" not in svg]
    return f"legend lacks {missing}" if missing or "tongue points" in svg else None


def plots(*names, out="out"):
    def check(result, folder):
        if result.stdout.splitlines()[-1:] != ["plots done"]:
            return f"last line {result.stdout.splitlines()[-1:]}"
        bad = [n for n in names if not is_png(os.path.join(folder, out, n))]
        return f"not drawn: {bad}" if bad else None
    return check


def no_backbone_plot(result, folder):
    if result.stdout.splitlines()[-1:] != ["plots done"] or "holds no point" not in result.stdout:
        return f"output {result.stdout!r}"
    return "backbone.png drawn" if os.path.exists(os.path.join(folder, "out", "backbone.png")) else None


def shebang(_, __):
    with open(os.path.join(SCRIPTS, "compare_backbones.py")) as f:
        first = f.readline().rstrip("\n")
    return None if first == "#!/usr/bin/python3" else f"shebang {first!r}"


def compare_cases():
    c = compare_case
    bad_bytes = {B: with_bytes(backbone(wobble=0.02), 7, "energy", b"1.0\xff")}
    return [
        c("valid: summary, worst ten in Omega order, PNG", "valid", ok=True, check=compare_png),
        c("valid: --all lists every point beyond", "valid", args=["a", "b", "--all"], ok=True,
          check=compare_all),
        c("valid: legend main, tongue, other per run", "valid", args=["a", "b", "--plot", "out.svg"], ok=True,
          check=legend),
        c("valid: A with a BOM (accepted)", "BOM", {A: (BOM + backbone().encode())}, ok=True, check=compare_summary),
        c("valid: shebang is /usr/bin/python3", "shebang", args=["--help"], ok=True, check=shebang),
        c("energy 0 in B", "division by 0", in_b("energy", "0"), names=B, line=7, column="energy"),
        c("energy 0.0 in A", "division by 0", in_a("energy", "0.0"), names=A, line=7, column="energy"),
        c("energy < 0 in B", "division by 0", in_b("energy", "-1.5"), names=B, line=7, column="energy"),
        c("energy underflows to 0 in B", "division by 0", in_b("energy", "1e-400"), names=B, line=7, column="energy"),
        c("empty energy cell in B", "number format", in_b("energy", ""), names=B, line=7, column="energy"),
        c("text in Omega of A", "number format", in_a("Omega", "abc"), names=A, line=7, column="Omega"),
        c("hex float energy in B", "number format", in_b("energy", "0x1p-3"), names=B, line=7, column="energy"),
        c("nan energy in A", "non-finite", in_a("energy", "nan"), names=A, line=7, column="energy"),
        c("NaN energy in B (main row 3)", "non-finite", in_b("energy", "NaN", line=3), names=B, line=3,
          column="energy"),
        c("inf energy in B", "non-finite", in_b("energy", "inf"), names=B, line=7, column="energy"),
        c("-Infinity Omega in A", "non-finite", in_a("Omega", "-Infinity"), names=A, line=7, column="Omega"),
        c("energy overflows (1e999) in B", "non-finite", in_b("energy", "1e999"), names=B, line=7, column="energy"),
        c("underscore number in Omega", "number format", in_a("Omega", "1_9"), names=A, line=7, column="Omega"),
        c("space before a number", "number format", in_b("Omega", " 1.95"), names=B, line=7, column="Omega"),
        c("segment 0.5 (not whole)", "value rules", in_b("segment", "0.5"), names=B, line=7, column="segment"),
        c("non-UTF-8 byte in B", "encoding", bad_bytes, names=B, line=7),
        c("Latin-1 header in A", "encoding", {A: backbone().replace("residual", "r\u00e9sidu").encode("latin-1")},
          names=A, line=1),
        c("NUL byte in a cell of A", "number format", {A: with_bytes(backbone(), 9, "Omega", b"1.9\x00")},
          names=A, line=9),
        c("truncated row (fewer fields) in B", "row length",
          {B: edit_line(backbone(wobble=0.02), 12, lambda s: s.rsplit(",", 3)[0])}, names=B, line=12),
        c("row cut after energy in A", "row length",
          {A: edit_line(backbone(), 20, lambda s: ",".join(s.split(",")[:3]))}, names=A, line=20),
        c("extra field in a row of B", "row length", {B: edit_line(backbone(wobble=0.02), 9, lambda s: s + ",7")},
          names=B, line=9),
        c("duplicated column energy in A", "header",
          {A: edit_line(backbone(), 1, lambda s: s.replace("energy_spread", "energy"))}, names=A, line=1,
          column="energy"),
        c("missing column segment in B", "header",
          {B: edit_line(backbone(wobble=0.02), 1, lambda s: s.replace("segment", "seg"))}, names=B, column="segment"),
        c("empty header name in A", "header", {A: edit_line(backbone(), 1, lambda s: s.replace("residual", ""))},
          names=A, line=1),
        c("unterminated quote in B", "header", {B: backbone(wobble=0.02) + '0,"2.2\n'}, names=B),
        c("empty file A (0 bytes)", "empty", {A: ""}, names=A),
        c("B header only", "empty", {B: header_only(backbone())}, names=B),
        c("B with no main point", "empty", {B: backbone(branch=lambda i: "tongue")}, names=B),
        c("A with no main point", "empty", {A: backbone(branch=lambda i: "other")}, names=A),
        c("B's Omega range misses A's", "empty",
          {B: backbone(shift=1.0)}, names=A),
        c("--max-gap smaller than B's spacing", "empty", args=["a", "b", "--max-gap", "1e-6"], names=A),
        c("--same-segment, every main point its own segment", "empty",
          {B: backbone(segment=lambda i: i)}, args=["a", "b", "--same-segment", "--plot", "out.png"], names=A),
        c("unknown branch word Main in B", "labels", in_b("branch", "Main"), names=B, line=7, column="branch"),
        c("tolerance -1", "options", args=["a", "b", "-1", "--plot", "out.png"], names="tolerance"),
        c("tolerance nan", "options", args=["a", "b", "nan", "--plot", "out.png"], names="tolerance"),
        c("tolerance inf", "options", args=["a", "b", "inf"], names="tolerance"),
        c("tolerance hex 0x1p-3", "options", args=["a", "b", "0x1p-3"], names="tolerance"),
        c("--max-gap 0", "options", args=["a", "b", "--max-gap", "0", "--plot", "out.png"], names="--max-gap"),
        c("--max-gap -0.1", "options", args=["a", "b", "--max-gap=-0.1"], names="--max-gap"),
        c("--max-gap nan", "options", args=["a", "b", "--max-gap", "nan"], names="--max-gap"),
        c("--plot x.foo", "options", args=["a", "b", "--plot", "x.foo"], names="--plot"),
        c("--plot without extension", "options", args=["a", "b", "--plot", "overlay"], names="--plot"),
        c("--plot into a missing folder", "options", args=["a", "b", "--plot", "missing/x.png"], names="--plot"),
        c("--sampled-from an empty file", "empty", {"fine.csv": ""},
          args=["a", "b", "--sampled-from", "fine.csv", "--plot", "out.png"], names="fine.csv"),
        c("--sampled-from header only", "empty", {"fine.csv": header_only(backbone())},
          args=["a", "b", "--sampled-from", "fine.csv"], names="fine.csv"),
        c("--sampled-from non-UTF-8", "encoding", {"fine.csv": with_bytes(backbone(), 4, "branch", b"m\xe4in")},
          args=["a", "b", "--sampled-from", "fine.csv"], names="fine.csv", line=4),
        c("A is nowhere", "files", args=["nowhere", "b"], names="nowhere"),
    ]


def plot_cases():
    p = plot_case
    base = backbone()
    return [
        p("valid: every plot, 'plots done' last", "valid", ok=True,
          check=plots("backbone.png", "orbits.png", "field_0_tip.png", "field_0_spacetime.png")),
        p("valid: empty optional cells, no tongue, no resonance", "valid",
          {OUT_B: set_column(base, "energy_error_estimate", ""),
           "out/tongues.csv": header_only(run_folder()["out/tongues.csv"]),
           "out/resonances.csv": "omega,mode,harmonic\n"}, ok=True, check=plots("backbone.png")),
        p("valid: a study folder", "valid", {**{k: None for k in run_folder()}, "out/study.csv": study()}, ok=True,
          check=plots("study.png")),
        p("valid: a stray field_x_tip.csv is no field", "valid", {"out/field_x_tip.csv": "t\n"}, ok=True,
          check=plots("backbone.png", "field_0_tip.png")),
        Case("valid: a folder named out[1] (glob characters)", "valid", "plot_results.py",
             {name.replace("out/", "out[1]/"): text for name, text in run_folder().items()},
             PLOT_ARGS[:-1] + ["out[1]"], ok=True, check=plots("backbone.png", "field_0_tip.png", out="out[1]")),
        p("valid: backbone.csv with a BOM (accepted)", "BOM", {OUT_B: BOM + base.encode()}, ok=True,
          check=plots("backbone.png")),
        p("valid: grazing.csv with a BOM (accepted)", "BOM",
          {"out/grazing.csv": BOM + run_folder()["out/grazing.csv"].encode()}, ok=True, check=plots("backbone.png")),
        p("valid: tongues.csv with a BOM (accepted)", "BOM",
          {"out/tongues.csv": BOM + run_folder()["out/tongues.csv"].encode()}, ok=True, check=plots("backbone.png")),
        p("empty backbone.csv (0 bytes)", "empty", {OUT_B: ""}, names=OUT_B),
        p("valid: header-only backbone.csv (a run stopped before its first point): no backbone.png", "valid",
          {OUT_B: header_only(base)}, ok=True, check=no_backbone_plot),
        p("header-only grazing.csv", "empty", {"out/grazing.csv": "mode,omega,energy\n"}, names="out/grazing.csv"),
        p("grazing.csv with two rows", "row length",
          {"out/grazing.csv": "mode,omega,energy\n1,1.9,0.25\n2,5.7,3\n"}, names="out/grazing.csv"),
        p("grazing energy 0", "division by 0", {"out/grazing.csv": "mode,omega,energy\n1,1.9191,0\n"},
          names="out/grazing.csv", line=2, column="energy"),
        p("grazing omega 0", "division by 0", {"out/grazing.csv": "mode,omega,energy\n1,0.0,0.25\n"},
          names="out/grazing.csv", line=2, column="omega"),
        p("grazing mode 1.5", "value rules", {"out/grazing.csv": "mode,omega,energy\n1.5,1.9,0.25\n"},
          names="out/grazing.csv", line=2, column="mode"),
        p("--gap 0", "options", args=["--gap", "0", "--", "out"], names="--gap"),
        p("--gap -0.01", "options", args=["--gap=-0.01", "--", "out"], names="--gap"),
        p("--gap nan", "options", args=["--gap", "nan", "--", "out"], names="--gap"),
        p("--gap inf", "options", args=["--gap", "inf", "--", "out"], names="--gap"),
        p("--gap 0x1p-3", "options", args=["--gap", "0x1p-3", "--", "out"], names="--gap"),
        p("--gap empty", "options", args=["--gap", "", "--", "out"], names="--gap"),
        p("--wall bogus", "options", args=["--gap", "0.01", "--wall", "bogus", "--", "out"], names="--wall"),
        p("valid: no --gap, the run's record gives Contact/Gap (accepted)", "options",
          {"out/parameters.prm": f"subsection Bar\n  set Length = 1\nend\nsubsection Contact\n  set Gap = {GAP}\n"
                                 "  set Wall = rigid\nend\n"},
          args=["--", "out"], ok=True, check=plots("backbone.png", "field_0_tip.png")),
        p("no --gap and no record to read it from", "options", args=["--", "out"], names="--gap"),
        p("no --gap, a record without Contact/Gap", "options",
          {"out/parameters.prm": "subsection Bar\n  set Gap = 0.5\nend\n"}, args=["--", "out"], names="--gap"),
        p("Omega all nan (NaN axis limits)", "non-finite", {OUT_B: set_column(base, "Omega", "nan")},
          names=OUT_B, line=2, column="Omega"),
        p("energy all nan", "non-finite", {OUT_B: set_column(base, "energy", "nan")}, names=OUT_B, line=2,
          column="energy"),
        p("energy inf in one row", "non-finite", {OUT_B: set_cell(base, 15, "energy", "inf")}, names=OUT_B,
          line=15, column="energy"),
        p("hex float Omega", "number format", {OUT_B: set_cell(base, 5, "Omega", "0x1.fp+0")}, names=OUT_B,
          line=5, column="Omega"),
        p("empty Omega cell", "number format", {OUT_B: set_cell(base, 5, "Omega", "")}, names=OUT_B, line=5,
          column="Omega"),
        p("text in energy_error_estimate", "number format", {OUT_B: set_cell(base, 6, "energy_error_estimate", "n/a")},
          names=OUT_B, line=6, column="energy_error_estimate"),
        p("verified = yes", "labels", {OUT_B: set_cell(base, 5, "verified", "yes")}, names=OUT_B, line=5,
          column="verified"),
        p("unknown branch word in backbone.csv", "labels", {OUT_B: set_cell(base, 8, "branch", "tongues")},
          names=OUT_B, line=8, column="branch"),
        p("extra field in backbone.csv", "row length", {OUT_B: edit_line(base, 4, lambda s: s + ",1")},
          names=OUT_B, line=4),
        p("extra field in tongues.csv", "row length",
          {"out/tongues.csv": edit_line(run_folder()["out/tongues.csv"], 2, lambda s: s + ",9")},
          names="out/tongues.csv", line=2),
        p("truncated row in field_0_tip.csv", "row length",
          {"out/field_0_tip.csv": edit_line(field_tip(), 6, lambda s: s.rsplit(",", 1)[0])},
          names="out/field_0_tip.csv", line=6),
        p("non-UTF-8 in tongues.csv", "encoding",
          {"out/tongues.csv": with_bytes(run_folder()["out/tongues.csv"], 2, "max_energy", b"\xc3(")},
          names="out/tongues.csv", line=2),
        p("non-UTF-8 in backbone.csv", "encoding", {OUT_B: with_bytes(base, 30, "branch", b"\x80main")},
          names=OUT_B, line=30),
        p("UTF-16 backbone.csv", "encoding", {OUT_B: base.encode("utf-16")}, names=OUT_B, line=1),
        p("duplicated column Omega", "header", {OUT_B: edit_line(base, 1, lambda s: s.replace("residual", "Omega"))},
          names=OUT_B, line=1, column="Omega"),
        p("missing column energy", "header", {OUT_B: edit_line(base, 1, lambda s: s.replace(",energy,", ",E,"))},
          names=OUT_B, column="energy"),
        p("tongues.csv without max_energy", "header",
          {"out/tongues.csv": run_folder()["out/tongues.csv"].replace("max_energy", "top")},
          names="out/tongues.csv", column="max_energy"),
        p("tip t all 0 (period 0)", "division by 0", {"out/field_0_tip.csv": set_column(field_tip(), "t", "0")},
          names="out/field_0_tip.csv", line=3, column="t"),
        p("tip with one row", "empty", {"out/field_0_tip.csv": "\n".join(field_tip().split("\n")[:2]) + "\n"},
          names="out/field_0_tip.csv"),
        p("tip t going back", "value rules", {"out/field_0_tip.csv": set_cell(field_tip(), 9, "t", "0.1")},
          names="out/field_0_tip.csv", line=9, column="t"),
        p("spacetime t all 0 (period 0)", "division by 0",
          {"out/field_0_spacetime.csv": set_column(field_spacetime(), "t", "0")},
          names="out/field_0_spacetime.csv", column="t"),
        p("text in tip contact_force", "number format",
          {"out/field_0_tip.csv": set_cell(field_tip(), 4, "contact_force", "high")},
          names="out/field_0_tip.csv", line=4, column="contact_force"),
        p("hex float fields.csv energy", "number format",
          {"out/fields.csv": set_cell(run_folder()["out/fields.csv"], 2, "energy", "0x1p-1")},
          names="out/fields.csv", line=2, column="energy"),
        p("resonances harmonic 1.5", "value rules",
          {"out/resonances.csv": "omega,mode,harmonic\n1.919137,1,1.5\n"}, names="out/resonances.csv", line=2,
          column="harmonic"),
        p("study.csv: text in dofs of an ok row", "number format",
          {"out/study.csv": set_cell(study(), 3, "dofs", "many")}, names="out/study.csv", line=3, column="dofs"),
        p("study.csv: extra field", "row length", {"out/study.csv": edit_line(study(), 4, lambda s: s + ",x")},
          names="out/study.csv", line=4),
        p("study.csv without receptance_error", "header",
          {"out/study.csv": study().replace("receptance_error", "receptance")}, names="out/study.csv",
          column="receptance_error"),
        p("folder that does not exist", "files", args=["--gap", "0.01", "--", "nowhere"], names="nowhere"),
        p("a folder with nothing to plot (its summary alone)", "files",
          {**{k: None for k in run_folder()}, "out/summary.txt": "Result\n"}, names="nothing to plot"),
    ]


# --------------------------------------------------------------------- runner
def lay_out(folder, files):
    for name, content in files.items():
        if content is None:
            continue
        path = os.path.join(folder, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(content if isinstance(content, bytes) else content.encode())


def left_behind(folder):
    plots = (".png", ".svg", ".partial", ".foo", ".pdf")
    return sorted(os.path.relpath(os.path.join(base, n), folder) for base, _, names in os.walk(folder)
                  for n in names if n.endswith(plots) or n in ("overlay", "x"))


def verdict(case, result, folder):
    """None if the case passed, else what went wrong."""
    everything = result.stdout + result.stderr
    if "Traceback" in everything:
        return "Traceback: " + result.stderr.strip().splitlines()[-1][:150]
    if case.ok:
        return (f"exit {result.returncode}: {result.stderr.strip()[-150:]}" if result.returncode
                else case.check(result, folder) if case.check else None)
    lines = result.stderr.strip("\n").split("\n") if result.stderr.strip() else []
    wanted = [case.names] + ([f"line {case.line}"] if case.line else []) + ([case.column] if case.column else [])
    problems = ([f"exit {result.returncode}, 2 expected"] if result.returncode != 2 else []) + \
        ([f"{len(lines)} stderr lines"] if len(lines) != 1 else []) + \
        [f"stderr does not name {w!r}" for w in wanted if w not in result.stderr] + \
        [f"left {n}" for n in left_behind(folder)]
    return "; ".join(problems) + (f" [{result.stderr.strip()[:160]!r}]" if problems else "") or None


def run_case(case, root):
    folder = tempfile.mkdtemp(dir=root)
    lay_out(folder, case.files)
    command = [PYTHON, os.path.join(SCRIPTS, case.script)] + case.args
    try:
        result = subprocess.run(command, cwd=folder, capture_output=True, text=True, errors="replace", timeout=120)
    except subprocess.TimeoutExpired:
        return "timed out"
    try:
        return verdict(case, result, folder)
    except Exception as error:  # the table's own check failed: a failure of the row, not of the table
        return f"check raised {type(error).__name__}: {error}"


def main():
    global SCRIPTS
    if len(sys.argv) < 2:
        sys.exit("usage: hostile_scripts.py SCRIPTS_DIR [NAME_REGEX]")
    SCRIPTS = os.path.abspath(sys.argv[1])
    pattern = re.compile(sys.argv[2] if len(sys.argv) > 2 else "")
    cases = [c for c in compare_cases() + plot_cases() if pattern.search(c.name)]
    counts = {}
    root = tempfile.mkdtemp(prefix="hostile-scripts-")
    try:
        for case in cases:
            problem = run_case(case, root)
            counts.setdefault(case.klass, [0, 0])[problem is not None] += 1
            print(f"{'FAIL' if problem else 'ok  '} {case.script[:-3]}: {case.name}"
                  + (f": {problem}" if problem else ""), flush=True)
    finally:
        shutil.rmtree(root, ignore_errors=True)
    print("per class:")
    for klass, (good, bad) in sorted(counts.items()):
        print(f"  {klass}: {good} passed, {bad} failed")
    passed = sum(good for good, _ in counts.values())
    failed = sum(bad for _, bad in counts.values())
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


SCRIPTS = None

if __name__ == "__main__":
    main()
