#!/usr/bin/env python3
"""The fourth table of hostile cases, one class of defect per block: values
the record would not read back, default folders two scene files share, a
record rerun into its own folder, two runs into one folder at once, memory
that grows with the points and the receptance frequencies, a range the
branch never reaches, the search for the band's cells (hangs, exit 3, stop
signals), degenerate lengths and walls, and messages.

usage: hostile_round_four.py NSM_BAR [NAME_REGEX ...]
Rows run as hostile_inputs.py's do (its run_row: exit code, one line on
stderr naming the parameter, nothing left behind but `leaves`, refusals
before any work); a row with `runner` is run by that function instead. It
prints the number of cases per class at the end.
"""
import os
import re
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hostile_inputs import SMALL, output, row_directory, run_row, section  # noqa: E402
from hostile_round_three import complete, run_table, wait_for  # noqa: E402
from hostile_round_two import read, write  # noqa: E402

SPECTRUM = SMALL + output(Spectrum_modes=2)
BACKBONE = SMALL + section("Continuation", Omega_max=2.0, Energy_max=1e-3) + output(Backbone="true")
# A continuation that announces each point (Progress every tiny), so that a
# row can act once it runs.
ANNOUNCED = SMALL + section("Continuation", Omega_max=2.0, Energy_max=1e-3) + \
    output(Backbone="true", Progress_every=1e-9)


def run(executable, scene_file, *args):
    return subprocess.run([executable, scene_file, *args], capture_output=True, text=True, errors="replace")


def first_output(executable, scene_file, scene=SPECTRUM, *args):
    """A setup: a complete run of `scene` from `scene_file` (folders made)."""
    def setup(_):
        os.makedirs(os.path.dirname(scene_file) or ".", exist_ok=True)
        write(scene_file, scene)
        result = run(executable, scene_file, *args)
        assert result.returncode == 0, result.stderr
    return setup


def untouched(directory, scene_file):
    """A check: `directory` still holds the whole output the setup wrote from
    `scene_file` (its manifest names that file's default folder)."""
    def check(_):
        assert complete(directory), f"{directory} is not a whole output"
        manifest = read(os.path.join(directory, "nsm-bar.manifest"))
        assert os.path.abspath(scene_file) in manifest, f"{directory} was replaced:\n{manifest}"
    return check


def reads_back(row):
    """A check: the record of a run reads back the directory it wrote."""
    record = read("out/parameters.prm")
    assert re.search(r"set Directory\s+= out\n", record), record


# ---- 4. two runs into one folder at once -------------------------------------

def overlapping_runs(row, executable):
    """Run A stops (SIGSTOP) once its continuation runs, run B into the same
    folder runs whole meanwhile, then A goes on: B's output is kept, and A
    fails (exit 5) without replacing it. With `existing`, the folder holds an
    earlier output before either starts."""
    write("a.prm", ANNOUNCED + output(Directory="same"))
    write("b.prm", row["scene"])
    if row.get("existing"):
        first = run(executable, "b.prm")
        assert first.returncode == 0, first.stderr
    a = subprocess.Popen([executable, "a.prm"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    line = a.stderr.readline()
    assert "nsm-bar:" in line, f"run A said no progress line: {line!r}"
    a.send_signal(signal.SIGSTOP)
    b = run(executable, "b.prm")
    a.send_signal(signal.SIGCONT)
    rest = a.communicate()[1]
    assert b.returncode == 0, f"run B: exit {b.returncode}: {b.stderr}"
    assert a.returncode == 5, f"run A: exit {a.returncode}, expected 5: {rest}"
    assert "another run" in rest and "Output/Directory" in rest, rest
    assert complete("same"), "same is not a whole output"
    assert "b.prm" in read("same/summary.txt").splitlines()[0], "B's output was replaced"
    leftovers = [n for n in os.listdir(".") if n.startswith(".nsm-bar-")]
    assert not leftovers, f"staging folders left: {leftovers}"


def resume_keeps_the_default_folder(row, executable):
    """x.prm into its default folder, stopped (SIGINT at its first progress
    line) and resumed through the folder (nsm-bar output/x --resume): the
    folder still belongs to x.prm, which reruns into it, and b/x.prm is
    still refused it."""
    write("x.prm", ANNOUNCED)
    process = subprocess.Popen([executable, "x.prm"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wait_for(lambda: "continuation" in process.stderr.readline(), "a progress line", process)
    process.send_signal(signal.SIGINT)
    process.communicate()
    assert process.returncode == 130, process.returncode
    resumed = run(executable, "output/x", "--resume")
    assert resumed.returncode == 0 and "resumed from continuation.resume" in resumed.stdout, resumed.stderr
    assert os.path.abspath("x.prm") in read("output/x/nsm-bar.manifest"), read("output/x/nsm-bar.manifest")
    again = run(executable, "x.prm")
    assert again.returncode == 0, again.stderr
    os.makedirs("b")
    write("b/x.prm", ANNOUNCED)
    other = run(executable, "b/x.prm")
    assert other.returncode == 2 and "x.prm" in other.stderr, (other.returncode, other.stderr)


# ---- 7. a stop while the band's cells are sought ------------------------------

def stop_during_cells_search(row, executable):
    """SIGTERM at the search's first progress line ends the run within
    seconds (exit 143), with no output and no staging folder."""
    write("scene.prm", row["scene"])
    process = subprocess.Popen([executable, "scene.prm"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               text=True)
    wait_for(lambda: "cells for the band" in process.stderr.readline(), "a line of the search", process)
    process.send_signal(signal.SIGTERM)
    asked = time.time()
    try:
        stderr = process.communicate(timeout=60)[1]
    except subprocess.TimeoutExpired:
        process.kill()
        raise AssertionError("no exit within 60 s of SIGTERM")
    waited = time.time() - asked
    assert process.returncode == 143, f"exit {process.returncode}: {stderr}"
    assert "stopped by SIGTERM" in stderr and "no output written" in stderr, stderr
    assert not os.path.exists("out"), "an output was written"
    leftovers = [n for n in os.listdir(".") if n.startswith(".nsm-bar-")]
    assert not leftovers, f"staging folders left: {leftovers}"
    print(f"     answered SIGTERM in {waited:.1f} s")


# ---- 9. messages -------------------------------------------------------------

def earlier_output_with_record(executable):
    """A setup: out holds a complete run (and its record, out/parameters.prm)."""
    def setup(row):
        first_output(executable, "first.prm", SPECTRUM + output(Directory="out"))(row)
    return setup


def hostname_not_echoed(row):
    name = read("/etc/hostname").strip()
    assert not name or name not in row["stderr"].replace("/etc/hostname", ""), row["stderr"]


def band_check_used_band(row):
    """The band check's band is M times the branch's highest Omega (M = 20
    here), not M Omega max = 2e101."""
    line = next(l for l in row["stdout"].splitlines() if "spatial error" in l)
    top = float(re.search(r"branch's highest Omega = (\S+)", line)[1])
    highest = max(float(r.split(",")[1]) for r in read("out/backbone.csv").splitlines()[1:])
    assert abs(top / (20 * highest) - 1) < 1e-3, (line, highest)


def new_rows(executable):
    one_mesh = section("Discretisation", Degree=10, Cells=7)
    return [
        # ---- 1. values the record does not read back -------------------------
        # old: run into results#M10, recorded as results: its record rerun
        # replaced another run's output.
        dict(name="hash_in_directory", cls=1, scene=SPECTRUM, args=["--output", "results#M10"], code=2,
             words=["Output/Directory", "record", "'#'"], before_work=True),
        dict(name="backslash_ending_directory", cls=1, scene=SPECTRUM, args=["--output", "out\\"], code=2,
             words=["Output/Directory", "backslash"], before_work=True),
        dict(name="spaces_around_directory", cls=1, scene=SPECTRUM, args=["--output", "  out  sp  "], code=2,
             words=["Output/Directory", "white space"], before_work=True),
        dict(name="tab_ending_directory", cls=1, scene=SPECTRUM, args=["--output", "out\t"], code=2,
             words=["Output/Directory"], before_work=True),
        dict(name="space_ending_cross_section", cls=1, scene=SPECTRUM, args=["--set", "Bar/Cross section=1.5 - x "],
             code=2, words=["Bar/Cross section", "white space"], before_work=True),
        # A scene file's "set Entry = value" written on the command line.
        dict(name="spaces_around_equals", cls=1, scene=SPECTRUM, args=["--set", "Bar/Cross section = 1.5 - x"],
             code=2, words=["white space", '--set "Bar/Cross section=1.5 - x"'], before_work=True),
        dict(name="hash_in_cross_section", cls=1, scene=SPECTRUM, args=["--set", "Bar/Cross section=1.5 - x#c"],
             code=2, words=["Bar/Cross section", "'#'"], before_work=True),
        dict(name="hash_in_json_value", cls=1, scene_file="scene.json",
             scene='{"Output": {"Directory": "res#1", "Spectrum modes": "2"}, '
                   '"Discretisation": {"Degree": "10", "Cells": "7"}}',
             code=2, words=["Output/Directory", "'#'"], before_work=True),
        dict(name="plain_directory_reads_back", cls=1, scene=SPECTRUM, args=["--output", "out"], code=0,
             leaves={"out"}, check=reads_back),
        # ---- 2. default folders of two scene files -----------------------------
        # old: the second run replaced the first's output/x, exit 0.
        dict(name="same_name_other_folder", cls=2, scene=None, scene_file="b/x.prm",
             setup=lambda row: first_output(executable, "a/x.prm")(row) or
             os.makedirs("b") or write("b/x.prm", SPECTRUM), code=2, words=["Output/Directory", "a/x.prm"],
             leaves={"a", "b", "output"}, before_work=True, check=untouched("output/x", "a/x.prm")),
        dict(name="prm_and_json", cls=2, scene_file="x.json",
             scene='{"Output": {"Spectrum modes": "2"}, "Discretisation": {"Degree": "10", "Cells": "7"}}',
             setup=first_output(executable, "x.prm"), code=2, words=["Output/Directory", "x.prm"],
             leaves={"x.prm", "output"}, before_work=True, check=untouched("output/x", "x.prm")),
        dict(name="dot_names", cls=2, scene=SPECTRUM, scene_file="...prm", setup=first_output(executable, "..prm"),
             code=2, words=["Output/Directory", "..prm"], leaves={"..prm", "output"}, before_work=True,
             check=untouched("output/scene", "..prm")),
        dict(name="explicit_then_default", cls=2, scene=SPECTRUM, scene_file="x.prm",
             setup=first_output(executable, "y.prm", SPECTRUM + output(Directory="output/x")), code=2,
             words=["Output/Directory", "explicit"], leaves={"y.prm", "output"}, before_work=True),
        # The same scene file rerun replaces its own default folder.
        dict(name="same_scene_again", cls=2, scene=SPECTRUM, scene_file="x.prm",
             setup=first_output(executable, "x.prm"), code=0, leaves={"output"},
             check=untouched("output/x", "x.prm")),
        dict(name="resume_keeps_the_default_folder", cls=2, runner=resume_keeps_the_default_folder),
        # A scene file's name the record cannot hold gives no default folder.
        dict(name="hash_in_the_scene_name", cls=2, scene=SPECTRUM, scene_file="a#b.prm", code=2,
             words=["Output/Directory", "a#b"], before_work=True),
        # ---- 3. a record rerun into its own folder -----------------------------
        # old: nsm-bar out/parameters.prm replaced out, exit 0.
        dict(name="record_rerun_in_place", cls=3, scene=None, scene_file="out/parameters.prm",
             setup=earlier_output_with_record(executable), code=2, words=["Output/Directory", "--output"],
             leaves={"out", "first.prm"}, before_work=True),
        dict(name="record_rerun_elsewhere", cls=3, scene=None, scene_file="out/parameters.prm",
             setup=earlier_output_with_record(executable), args=["--output", "again"], code=0,
             leaves={"out", "first.prm", "again"}),
        # ---- 4. two runs into one folder at once ------------------------------
        # old: both exit 0, the last to finish won.
        dict(name="two_runs_one_folder", cls=4, scene=SPECTRUM + output(Directory="same"),
             runner=overlapping_runs),
        dict(name="two_runs_one_new_folder_backbones", cls=4, scene=BACKBONE + output(Directory="same"),
             runner=overlapping_runs),
        dict(name="two_runs_over_an_earlier_output", cls=4, scene=SPECTRUM + output(Directory="same"),
             existing=True, runner=overlapping_runs),
        # ---- 5. memory that grows with points and frequencies ------------------
        # old: estimated at 200 MiB, peaked at 3.97 GB.
        dict(name="max_steps_beyond_the_limit", cls=5,
             scene=BACKBONE + section("Continuation", Max_steps=1000000) + section("Resources", Memory_limit=500),
             code=2, words=["Continuation/Max steps", "Memory limit"], before_work=True),
        dict(name="receptance_frequencies_beyond_the_limit", cls=5,
             scene=SMALL + output(Receptance_frequencies="0:10:1000000") + section("Resources", Memory_limit=300),
             code=2, words=["Output/Receptance frequencies", "Memory limit"], before_work=True),
        dict(name="fields_every_beyond_the_limit", cls=5,
             scene=BACKBONE + section("Continuation", Max_steps=1000000) + output(Fields_every=1) +
             section("Resources", Memory_limit=1000), code=2, words=["Memory limit"], before_work=True),
        # A limit below the process's own share: no scene fits, so the limit
        # itself is named (it said to reduce the mesh).
        dict(name="memory_limit_below_the_process", cls=5, scene=SPECTRUM + section("Resources", Memory_limit=1),
             code=2, words=["Resources/Memory limit' = 1", "allowed at least 200"], before_work=True),
        # ---- 6. a range the branch never reaches --------------------------------
        # old: exit 0, a header-only backbone.csv, no reason.
        dict(name="range_above_the_branch", cls=6,
             scene=SMALL + section("Continuation", Omega_min=2.5, Omega_max=3) + output(Backbone="true"),
             code=2, words=["Continuation/Omega min", "ends at Omega"]),
        dict(name="range_far_above", cls=6,
             scene=SMALL + section("Continuation", Omega_min=1e99, Omega_max=1e100) + output(Backbone="true"),
             code=2, words=["Continuation/Omega min"]),
        # A forced scene whose range lies below grazing: the backbone's range
        # error says the curves need no backbone (they are traced alone with
        # Output/Backbone = false).
        dict(name="forced_range_below_the_branch", cls=6,
             scene=SMALL + section("Continuation", Omega_min=1, Omega_max=1.5) +
             section("Damping", Modal_ratio=0.01) + section("Forcing", Amplitudes="1e-5") +
             output(Backbone="true"),
             code=2, words=["Continuation/Omega max", "Output/Backbone = false"]),
        # A force level or drive frequency listed twice wrote two identical
        # curves that frc.csv cannot tell apart.
        dict(name="forced_amplitude_twice", cls=6,
             scene=SMALL + section("Damping", Modal_ratio=0.01) + section("Forcing", Amplitudes="2e-5, 2e-5"),
             code=2, words=["Forcing/Amplitudes' = 2e-5", "listed twice"], before_work=True),
        dict(name="forced_omega_twice", cls=6,
             scene=SMALL + section("Damping", Modal_ratio=0.01) +
             section("Forcing", Omegas="1.97, 2, 1.97", Amplitude_max="1e-4"),
             code=2, words=["Forcing/Omegas' = 1.97", "listed twice"], before_work=True),
        # ---- 7. the band's cells (Cells = 0) ------------------------------------
        # old: exit 3 "asked for 1 eigenvalues of a pencil with 0 finite ones".
        dict(name="cells_0_defaults", cls=7, scene=section("Discretisation", Cells=0) +
             section("Continuation", Omega_max=2.0) + output(Directory="out", Backbone="true"), code=0,
             leaves={"out"}),
        dict(name="one_linear_cell_automatic_range", cls=7, scene=section("Discretisation", Cells=1, Degree=1) +
             output(Backbone="true"), code=2, words=["Discretisation/Cells", "Mode + 1"], before_work=True),
        # old: ran until killed (LAPACK on meshes no band fits).
        dict(name="cells_0_band_1e9", cls=7, scene=section("Discretisation", Cells=0) +
             section("Harmonic balance", Harmonics=1000) + section("Continuation", Omega_max=1e6) +
             output(Backbone="true"), code=2, words=["Discretisation/Cells", "modes"], before_work=True,
             timeout=60),
        dict(name="cells_0_band_1e103", cls=7, scene=section("Discretisation", Cells=0, Degree=10) +
             section("Harmonic balance", Harmonics=1000) + section("Continuation", Omega_max=1e100) +
             output(Backbone="true"), code=2, words=["Discretisation/Cells", "modes"], before_work=True,
             timeout=60),
        # old: acknowledged, then ignored for 11 minutes.
        dict(name="stop_during_cells_search", cls=7, scene=section("Discretisation", Cells=0) +
             section("Harmonic balance", Harmonics=1000) + output(Directory="out", Backbone="true",
                                                                  Progress_every=1e-9),
             runner=stop_during_cells_search),
        # ---- 8. degenerate lengths and walls ------------------------------------
        # old: exit 3, "NOX::Solver::LineSearchBased::init - Unable to compute F".
        dict(name="length_1e-20", cls=8, scene=one_mesh + section("Bar", Length=1e-20) + output(Backbone="true"),
             code=2, words=["Continuation/Min step", "Bar/Length"]),
        dict(name="length_1e-15", cls=8, scene=one_mesh + section("Bar", Length=1e-15) + output(Backbone="true"),
             code=2, words=["Continuation/Min step"]),
        dict(name="stiffness_1e20", cls=8, scene=one_mesh + section("Bar", Young_modulus=1e20) +
             output(Backbone="true"), code=2, words=["Continuation/Min step"]),
        # old: blamed Omega max, which the scene never set.
        dict(name="wall_stiffness_1e-20", cls=8, scene=one_mesh + section("Contact", Wall="compliant",
                                                                          Wall_stiffness=1e-20) +
             output(Backbone="true"), code=2, words=["Contact/Wall stiffness", "automatic range"]),
        # ---- 9. messages -----------------------------------------------------
        # old: ran, and its own --resume then refused it blaming --set.
        dict(name="scene_name_not_utf8", cls=9, scene=SPECTRUM, scene_file="sc\udce9ne.prm", code=2,
             words=["Output/Directory", "UTF-8"], before_work=True),
        # old: the message echoed the included file's first line.
        dict(name="include_of_a_system_file", cls=9, scene="include /etc/hostname\n" + SPECTRUM, code=2,
             words=["line 1 of '/etc/hostname'", "not a 'set'"], check=hostname_not_echoed),
        dict(name="bad_line_in_an_included_file", cls=9, scene="include inner.prm\n",
             setup=lambda row: write("inner.prm", "subsection Bar\n  set Length = 1\n  a stray line\nend\n"),
             code=2, words=["line 3 of 'inner.prm'"], leaves={"inner.prm"}),
        # old: "eigenfrequencies up to M Omega max = 2e+101 (140 modes) agree to
        # 1.8e+99", no warning: the band check's band is the one the branch used.
        dict(name="omega_max_1e100_band_check", cls=9, scene=SMALL + section("Continuation", Omega_max=1e100,
                                                                          Energy_max=1e-3) +
             output(Directory="out", Backbone="true"), code=0, leaves={"out"}, check=band_check_used_band),
        # old: "is not a regular file" only.
        dict(name="output_folder_as_scene", cls=9, scene=None, scene_file="out",
             setup=earlier_output_with_record(executable), code=2, words=["--resume", "parameters.prm"],
             leaves={"out", "first.prm"}),
    ]


def main():
    executable = os.path.abspath(sys.argv[1])

    def run_one(row):
        if "runner" in row:
            with row_directory({**row, "scene": None}):
                row["runner"](row, executable)
        else:
            run_row(executable, row)
    run_table(new_rows(executable), sys.argv[2:], run_one)


if __name__ == "__main__":
    main()
