#!/usr/bin/env python3
"""Hostile and borderline scenes, one table row each (this file's, then
hostile_round_two.py's).

usage: hostile_inputs.py NSM_BAR [--skip] [NAME_REGEX ...]
Each row runs nsm-bar in a fresh directory on a scene text and checks: the
exit code; for a failure, a single line on stderr naming the parameter (and
the allowed range where the row gives it); that no file is left behind
besides what the row set up; and the row's own check, if any. Uses the
standard library only.
"""
import contextlib
import csv
import math
import re
import os
import resource
import shutil
import signal
import subprocess
import sys
import time

W1 = 1.919137          # method.md: first clamped-free frequency, 6 digits
LN3 = math.log(3.0)    # gamma(0) = int dx / (E A) for A = 1.5 - x

# A small, fast mesh and harmonic balance for the rows that must succeed.
SMALL = """subsection Discretisation
  set Degree = 10
  set Cells = 7
end
subsection Receptance
  set Method = modal
end
subsection Harmonic balance
  set Harmonics = 20
end
"""


def section(name, **values):
    body = "".join(f"  set {k.replace('_', ' ')} = {v}\n" for k, v in values.items())
    return f"subsection {name}\n{body}end\n"


def output(**values):
    return section("Output", **values)


def spectrum_scene(directory="out", modes=2):
    return output(Directory=directory, Spectrum_modes=modes)


def listing(root):
    """Every path under root, hidden ones included."""
    paths = set()
    for base, dirs, files in os.walk(root):
        for n in dirs + files:
            paths.add(os.path.relpath(os.path.join(base, n), root))
    return paths


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


# ---- setups: prepare the row's directory before the run ---------------------

def self_include(_):
    with open("scene.prm", "w") as f:
        f.write("include scene.prm\n")


def mutual_include(_):
    with open("a.prm", "w") as f:
        f.write("include scene.prm\n")
    with open("scene.prm", "w") as f:
        f.write("include a.prm\n")


def scene_is_directory(_):
    os.mkdir("scene.prm")


def garbage(extension):
    def setup(row):
        row["scene_file"] = "scene." + extension
        with open(row["scene_file"], "w") as f:
            f.write("<ParameterHandler><Bar><Length>\n{ not closed")
    return setup


def existing_file(_):
    with open("taken", "w") as f:
        f.write("not a directory\n")


def foreign_directory(_):
    os.mkdir("mine")
    with open("mine/thesis.tex", "w") as f:
        f.write("a user's file\n")


def prepare_run(executable, scene_file):
    """hostile_round_two.prepare_run, imported at the call (it imports this
    file)."""
    import hostile_round_two
    hostile_round_two.prepare_run(executable, scene_file)


def earlier_run(executable, extra_file=False):
    """A complete earlier output, and (extra_file) a file left in it by hand."""
    def setup(_):
        with open("first.prm", "w") as f:
            f.write(SMALL + output(Directory="out", Spectrum_modes=3,
                                   Receptance_frequencies="0, 1"))
        prepare_run(executable, "first.prm")
        if extra_file:
            with open("out/field_9_tip.csv", "w") as f:
                f.write("left by hand\n")
    return setup


def study_folder(_):
    """A study's output (it writes no manifest: its rows resume in place)."""
    os.makedirs("out")
    for name, text in (("study.scene", "subsection Study\nend\n"), ("study.csv", "degree,status\n1,ok\n")):
        with open(os.path.join("out", name), "w") as f:
            f.write(text)


def study_folder_kept(_):
    assert sorted(os.listdir("out")) == ["study.csv", "study.scene"], "a study's folder was changed"


def extra_file_kept(_):
    with open("out/field_9_tip.csv") as f:
        assert f.read() == "left by hand\n", "a file the program did not write was changed"


def earlier_study(executable):
    """Output/Directory holds the study of another base scene."""
    def setup(_):
        with open("first.prm", "w") as f:
            f.write(SMALL + section("Study", Spectrum_modes=2) + output(Directory="out"))
        prepare_run(executable, "first.prm")
    return setup


def snapshot(directory):
    files = {}
    for path in listing(directory):
        full = os.path.join(directory, path)
        if os.path.isfile(full):
            with open(full, "rb") as f:
                files[path] = f.read()
    return files


def complete(directory):
    """A whole output: exactly the files its manifest lists."""
    if not os.path.isfile(os.path.join(directory, "nsm-bar.manifest")):
        return False
    with open(os.path.join(directory, "nsm-bar.manifest")) as f:
        manifest = set(f.read().split())
    return listing(directory) == manifest | {"nsm-bar.manifest"}


def killed_run(executable):
    """An earlier complete output, then a run into it killed by SIGKILL while
    it works: the directory holds the earlier output, byte for byte (or, if
    the killed run had finished, its own complete output)."""
    def setup(_):
        with open("first.prm", "w") as f:
            f.write(SMALL + spectrum_scene("out", 3))
        prepare_run(executable, "first.prm")
        before = snapshot("out")
        with open("second.prm", "w") as f:
            f.write(BACKBONE + output(Directory="out", Backbone="true", Fields_every=1,
                                      VTK="true"))
        second = subprocess.Popen([executable, "second.prm"], stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL)
        time.sleep(0.5)
        second.send_signal(signal.SIGKILL)
        second.wait()
        assert snapshot("out") == before or complete("out"), "a mixture after SIGKILL"
    return setup


# ---- checks: the row's own assertions after the run -------------------------

def no_staging_left(_):
    assert not [p for p in os.listdir(".") if ".nsm-bar-" in p], os.listdir(".")
    assert complete("out")


def no_injection(_):
    assert not os.path.exists("INJECTED"), "a shell ran the commands in Output/Directory"
    assert os.path.exists("out'; touch INJECTED; echo '/backbone.png")


def graded_spectrum_exact(_):
    rows = read_rows("out/spectrum.csv")
    # FE_Q(1), 4000 cells: (w h)^2 / 24 = 1e-8 plus round-off floor 6e-8.
    assert abs(float(rows[1][1]) / W1 - 1) < 2e-7, rows[1]


def modal_static_value(_):
    rows = read_rows("out/receptance.csv")
    # The run estimates the discretisation error of gamma at 2.4e-8 (the
    # round-off floor is 3e-10): within 1e-7 of ln 3. The modal sum was 0.0117
    # off before.
    assert abs(float(rows[1][1]) - LN3) < 1e-7, rows[1]


def field_alone(_):
    files = listing("out")
    assert "fields.csv" in files and "backbone.csv" not in files, files
    header, *rows = read_rows("out/fields.csv")
    omegas = [float(r[header.index("Omega")]) for r in rows]
    assert omegas == [1.92], omegas


def field_at_first_main_point(_):
    """The field sits at the branch's first point, its start a grazing offset
    above w1 (within 1e-3 of it), and is labelled main."""
    header, *rows = read_rows("out/fields.csv")
    omegas = [float(r[header.index("Omega")]) for r in rows]
    branches = [r[header.index("branch")] for r in rows]
    assert len(omegas) == 1 and W1 < omegas[0] < W1 * (1 + 1e-3) and branches == ["main"], (omegas, branches)


def replaced_whole(_):
    files = listing("out")
    with open("out/nsm-bar.manifest") as f:
        manifest = set(f.read().split())
    assert "receptance.csv" not in files, "a file of the earlier run survived"
    assert files == manifest | {"nsm-bar.manifest"}, (files, manifest)


def progress_printed(row):
    assert "nsm-bar: continuation: " in row["stderr"], row["stderr"]


def silent_when_short(row):
    assert row["stderr"] == "", row["stderr"]


def print_parameters_round_trip(row):
    # A full listing of the parameters is a valid scene with the defaults.
    assert "nothing to do" in row["stdout"], row["stdout"]


def quiet_full_disk():
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (1024, 1024))


BACKBONE = SMALL + section("Continuation", Omega_min=1.5, Omega_max=1.93, Energy_max=1e-3)


def rows(executable):
    """name, scene text, exit code, words the one-line message must hold;
    optional: setup(row), check(row), preexec, env, files the run may leave
    (besides the row's own)."""
    graded = lambda layers: section("Discretisation", Cells=4000, Refinement="graded") + \
        "subsection Discretisation\n subsection Graded\n  set Ratio = 0.8\n" \
        f"  set Layers = {layers}\n end\nend\n"
    adaptive = section("Discretisation", Cells=40, Refinement="adaptive") + \
        "subsection Discretisation\n subsection Adaptive\n  set Steps = 15\n" \
        "  set Tolerance = 1e-14\n end\nend\n" + section("Receptance", Method="modal")
    return [
        # 1. no shell
        dict(name="shell_injection", scene=BACKBONE + output(
            Directory="out'; touch INJECTED; echo '", Backbone="true", Plots="true"),
             code=0, check=no_injection, leaves={"out'; touch INJECTED; echo '"}),
        dict(name="plot_fails", scene=BACKBONE + output(Directory="out", Backbone="true",
                                                        Plots="true"),
             env={"MPLBACKEND": "no_such_backend"}, code=5,
             words=["output error", "plots were not drawn", "plotting script failed"], leaves={"out"},
             check=lambda _: read_rows("out/backbone.csv")),
        # 2. full disk (files limited to 1 KiB; backbone.csv needs more): exit 5,
        # nothing left
        dict(name="full_disk", scene=BACKBONE + output(Directory="out", Backbone="true"),
             code=5, words=["output error", "backbone.csv"], preexec=quiet_full_disk),
        # 3. strongly graded meshes
        dict(name="graded_too_fine", scene=graded(60) + spectrum_scene(), code=2,
             words=["Discretisation/Graded/Layers", "at most 52", "Round-off limit"]),
        dict(name="graded_strong", scene=graded(50) + spectrum_scene(), code=0,
             check=graded_spectrum_exact, leaves={"out"}),
        # 4. modal receptance on an adaptive mesh
        dict(name="adaptive_modal", scene=adaptive + output(
            Directory="out", Receptance_frequencies="0"), code=0, check=modal_static_value,
             leaves={"out"}),
        # 5. crashes
        dict(name="alpha_huge", scene=section("Contact", Alpha="1e308") + spectrum_scene(),
             code=2, words=["Contact/Alpha", "a number in [1e-20, 1e+20]"]),
        dict(name="self_include", scene=None, setup=self_include, code=2,
             words=["include", "cycle"]),
        dict(name="mutual_include", scene=None, setup=mutual_include, code=2,
             words=["include", "cycle"]),
        # 6. underflowing values
        dict(name="length_underflow", scene=section("Bar", Length="1e-310") + spectrum_scene(),
             code=2, words=["Bar/Length", "a number in [1e-20, 1e+20]"]),
        dict(name="gap_underflow", scene=section("Contact", Gap="1e-320") + spectrum_scene(),
             code=2, words=["Contact/Gap"]),
        dict(name="density_underflow", scene=section("Bar", Density="1e-400") + spectrum_scene(),
             code=2, words=["Bar/Density"]),
        # 7. messages that name the parameter
        dict(name="density_huge", scene=section("Bar", Density="1e308") + spectrum_scene(),
             code=2, words=["Bar/Density", "[1e-20, 1e+20]"]),
        dict(name="young_tiny", scene=section("Bar", Young_modulus="1e-300") + spectrum_scene(),
             code=2, words=["Bar/Young modulus"]),
        dict(name="length_huge", scene=section("Bar", Length="1e308") + spectrum_scene(),
             code=2, words=["Bar/Length"]),
        dict(name="section_huge", scene=section("Bar", Cross_section="1e300*(1.5-x)") +
             spectrum_scene(), code=2, words=["Bar/Cross section", "1e+20"]),
        dict(name="quadrature_weak", scene=section("Discretisation", Degree=10,
                                                   Quadrature_points=1) + spectrum_scene(),
             code=2, words=["Discretisation/Quadrature points", "[11, 64]"]),
        dict(name="receptance_huge", scene=output(Directory="out",
                                                  Receptance_frequencies="1e200"),
             code=2, words=["Output/Receptance frequencies", "[0, 1e+100]"]),
        dict(name="tolerance_hb", scene=section("Harmonic balance", Tolerance=0) +
             spectrum_scene(), code=2, words=["Harmonic balance/Tolerance", "a number in"]),
        dict(name="tolerance_adaptive", scene="subsection Discretisation\n subsection Adaptive"
             "\n  set Tolerance = 0\n end\nend\n" + spectrum_scene(), code=2,
             words=["Discretisation/Adaptive/Tolerance", "a number in"]),
        dict(name="selection_words", scene=section("Receptance", Method="iterative") +
             spectrum_scene(), code=2, words=["Receptance/Method", "one of direct, modal"]),
        # 8. checked before any work
        dict(name="directory_proc", scene=spectrum_scene("/proc/x"), code=2,
             words=["Output/Directory"]),
        dict(name="directory_is_file", scene=spectrum_scene("taken"), setup=existing_file,
             code=2, words=["Output/Directory", "not a directory"]),
        dict(name="directory_foreign", scene=spectrum_scene("mine"), setup=foreign_directory,
             code=2, words=["Output/Directory", "nsm-bar.manifest"]),
        dict(name="directory_dot", scene=spectrum_scene("."), code=2,
             words=["Output/Directory"]),
        dict(name="mode_beyond_mesh", scene=section("Continuation", Mode=10000) +
             output(Directory="out", Backbone="true"), code=2,
             words=["Continuation/Mode", "[1, 4000]"]),
        # A range that holds none of the branch: physical, it leaves w1 = 1.919137 upwards.
        dict(name="range_below_branch", scene=SMALL + section("Continuation", Omega_min=1.5, Omega_max=1.9) +
             output(Directory="out", Backbone="true"), code=2,
             words=["Continuation/Omega max' = 1.9", "allowed above Omega = 1.91916", "leaves grazing upwards"]),
        # No mode at all below the band: the range is empty, not "1 to 0".
        dict(name="mode_beyond_band", scene=SMALL.replace("Harmonics = 20", "Harmonics = 1") +
             section("Continuation", Omega_min=0.5, Omega_max=1) + output(Directory="out", Backbone="true"),
             code=2, words=["Continuation/Mode", "no clamped-free mode lies below Harmonics x Omega max = 1"]),
        # Tiny energies are printed as numbers, not as 0.000000.
        dict(name="energy_max_below_grazing", scene=BACKBONE.replace("Energy_max", "x") +
             section("Contact", Gap="1e-6") + section("Continuation", Energy_max="1e-20") +
             output(Directory="out", Backbone="true"),
             code=2, words=["Continuation/Energy max' = 1e-20", "above the energy at grazing, 6.6"]),
        # Alpha far from 1 / gamma(0): the start fails, and says over which reach it searched.
        dict(name="no_start_within_reach", scene=SMALL + section("Contact", Alpha="1e12") +
             output(Directory="out", Backbone="true"), code=3,
             words=["no converged non-trivial solution", "Continuation/Search reach = 0.05",
                    "Contact/Alpha = 1e+12"]),
        # A start that Max iterations cut short says so (it named only Alpha).
        dict(name="no_start_iterations", scene=SMALL + section("Harmonic balance", Tolerance="1e-15",
                                                               Max_iterations="1") +
             output(Directory="out", Backbone="true"), code=3,
             words=["no converged non-trivial solution", "Newton solves stopped at Harmonic balance/Max iterations = 1"]),
        dict(name="grazing_offset_beyond_reach", scene=section(
            "Continuation", Grazing_offset="1e-2", Search_reach="1e-3") +
             output(Directory="out", Backbone="true"), code=2,
             words=["Continuation/Grazing offset", "< Search reach = 0.001"]),
        dict(name="fields_outside_range", scene=output(Directory="out", Fields_at=5), code=2,
             words=["Output/Fields at", "[Omega min, Omega max]"]),
        # A field alone traces the backbone it lies on, with the receptance's poles
        # up to Harmonics x Omega max (it used to count none and refuse Mode 1).
        dict(name="field_without_backbone", scene=BACKBONE + output(Directory="out", Fields_at=1.92), code=0,
             check=field_alone, leaves={"out"}),
        # Below w1 the physical branch does not exist: the paper's 1.907 on its
        # bar is off the computed branch, within Search reach (0.05) of its
        # first main point, where the field goes (the summary says so).
        dict(name="fields_off_branch", scene=BACKBONE + output(Directory="out", Fields_at=1.907), code=0,
             check=field_at_first_main_point, leaves={"out"}),
        dict(name="verify_without_backbone", scene=spectrum_scene() +
             output(Verify_in_time="true"), code=2,
             words=["Output/Verify in time", "Backbone = true"]),
        dict(name="verify_steps_few", scene=output(Directory="out", Backbone="true",
                                                   Verify_in_time="true", Verify_steps=3), code=2,
             words=["Output/Verify steps", "[16, 10000000]"]),
        dict(name="refine_without_backbone", scene=spectrum_scene() + output(Refine_in_time="true"), code=2,
             words=["Output/Refine in time", "Backbone = true"]),
        dict(name="refine_every_zero", scene=output(Directory="out", Backbone="true", Refine_in_time="true",
                                                    Refine_every=0), code=2,
             words=["Output/Refine every", "[1, 1000000]"]),
        dict(name="stability_margin_negative", scene=output(Directory="out", Backbone="true", Refine_in_time="true",
                                                            Stability_margin=-1e-3), code=2,
             words=["Output/Stability margin", "[0, 1]"]),
        # The dense modes of the refinement: more than 2001 DoFs are refused
        # before any work (the seed mesh has 4001).
        dict(name="refine_too_many_dofs", scene=section("Discretisation", Degree=1, Cells=4000) +
             output(Directory="out", Backbone="true", Refine_in_time="true"), code=2,
             words=["Output/Refine in time", "2001 DoFs", "4001"]),
        # 9. accepted bad values
        dict(name="tolerance_loose", scene=section("Harmonic balance", Tolerance=1) +
             spectrum_scene(), code=2, words=["Harmonic balance/Tolerance", "1e-06"]),
        # Unbalanced sections: deal.II's message names no entry; the hint
        # says what balances them (it pointed at --print-parameters).
        dict(name="section_without_end", scene="subsection Continuation\n  set Omega min = 1.5\n", code=2,
             words=["unequal numbers of 'subsection' and 'end'", "needs one 'end' line"]),
        dict(name="end_without_section", scene=section("Continuation", Omega_min="1.5") + "end\n", code=2,
             words=["no subsection to leave", "needs one 'end' line"]),
        dict(name="scene_directory", scene=None, setup=scene_is_directory, code=2,
             words=["scene.prm", "is a folder"]),
        dict(name="garbage_xml", scene=None, setup=garbage("xml"), code=2,
             words=["scene.xml"]),
        dict(name="garbage_json", scene=None, setup=garbage("json"), code=2,
             words=["scene.json"]),
        # 10. whole runs or nothing
        dict(name="receptance_overflow", scene=output(Directory="out", Spectrum_modes=2,
                                                      Receptance_frequencies="1, 1e308"),
             code=2, words=["Output/Receptance frequencies"]),
        dict(name="killed_run", scene=SMALL + spectrum_scene("out", 4),
             setup=killed_run(executable), code=0, check=no_staging_left, leaves={"out"}),
        dict(name="earlier_output_replaced", scene=SMALL + spectrum_scene("out", 4),
             setup=earlier_run(executable), code=0, check=replaced_whole, leaves={"out"}),
        # A file the manifest does not list is the user's: the run is refused.
        dict(name="earlier_output_with_a_users_file", scene=SMALL + spectrum_scene("out", 4),
             setup=earlier_run(executable, extra_file=True), code=2, check=extra_file_kept,
             words=["Output/Directory", "field_9_tip.csv"], leaves={"out"}),
        # A study's folder is not a scene's earlier output: named as such.
        dict(name="scene_into_a_study_folder", scene=SMALL + spectrum_scene("out", 4), setup=study_folder,
             code=2, check=study_folder_kept, words=["Output/Directory", "a study's output"], leaves={"out"}),
        # 11. long runs say what they do; short ones say nothing
        dict(name="progress_lines", scene=BACKBONE + output(
            Directory="out", Backbone="true", Progress_every="1e-9"), code=0,
             check=progress_printed, leaves={"out"}),
        dict(name="short_run_silent", scene=BACKBONE + output(Directory="out", Backbone="true"),
             code=0, check=silent_when_short, leaves={"out"}),
        # 13. studies: swept values checked against their parameter's range,
        # every combination checked, before any file is written
        dict(name="study_degree_range", scene=section("Study", Degrees="1, 25",
                                                      Spectrum_modes=2) + output(Directory="out"),
             code=2, words=["Study/Degrees", "Discretisation/Degree", "[1, 20]"]),
        dict(name="study_selection", scene=section("Study", Refinements="none, fancy",
                                                   Spectrum_modes=2) + output(Directory="out"),
             code=2, words=["Study/Refinements", "one of none, graded, adaptive"]),
        # A stray comma or a value listed twice is a typo, not a value (it was
        # dropped, or ran a row twice under a reason that did not apply).
        dict(name="study_empty_value", scene=section("Study", Degrees="1,,2", Spectrum_modes=2) +
             output(Directory="out"), code=2, words=["Study/Degrees", "'1,,2'", "an empty value"]),
        dict(name="study_value_twice", scene=section("Study", Cells="4, 8, 4", Spectrum_modes=2) +
             output(Directory="out"), code=2, words=["Study/Cells", "'4' is listed twice"]),
        # An undamped row of a driven study: named as the swept entry, not
        # as the amplitude the scaling sets to 0.
        dict(name="study_damping_zero",
             scene=section("Damping", Modal_ratio="0.002") + section("Forcing", Amplitudes="1e-5") +
             section("Receptance", Method="modal") +
             section("Continuation", Omega_min="1.5", Omega_max="2.2", Energy_max="1e-3") +
             section("Study", Damping_ratios="0.01, 0", Forced_peaks="true", Forcing_scaled_with_damping="true",
                     Backbone_omegas="1.95") +
             output(Directory="out"), code=2, words=["Study/Damping ratios", "numbers > 0"]),
        dict(name="study_measures_nothing", scene=section("Study", Degrees="1, 2") +
             output(Directory="out"), code=2, words=["Study/Spectrum modes"]),
        dict(name="study_combination", scene=section("Discretisation", Refinement="graded") +
             "subsection Discretisation\n subsection Graded\n  set Layers = 40\n end\nend\n" +
             section("Study", Cells="4000, 10", Spectrum_modes=2) + output(Directory="out"),
             code=2, words=["study row 2", "Discretisation/Graded/Layers"]),
        # A misspelt entry is named with its section, and where the entries are listed.
        dict(name="misspelt_entry", scene=section("Continuation", Omega_maks=2) + output(Directory="out"),
             code=2, words=["line 2", "no parameter 'Continuation/Omega maks'", "--print-parameters"]),
        dict(name="study_omega_range", scene=section("Study", Backbone_omegas="1.95, 3") +
             section("Continuation", Omega_max=2.2, Energy_max=1) +
             output(Directory="out"), code=2, words=["Study/Backbone omegas", "[Omega min, Omega max]"]),
        dict(name="study_verify_without_omegas", scene=section("Study", Spectrum_modes=2, Verify_in_time="true") +
             output(Directory="out"), code=2, words=["Study/Verify in time", "Study/Backbone omegas"]),
        dict(name="study_forced_peaks_without_omegas",
             scene=section("Study", Spectrum_modes=2, Forced_peaks="true") + output(Directory="out"),
             code=2, words=["Study/Forced peaks", "Study/Backbone omegas"]),
        dict(name="study_forced_peaks_without_forcing",
             scene=section("Study", Backbone_omegas="1.95", Forced_peaks="true") +
             section("Continuation", Omega_max=2.2, Energy_max=1) + output(Directory="out"),
             code=2, words=["Forcing/Amplitudes", "Study/Forced peaks"]),
        dict(name="study_forcing_scaled_without_peaks",
             scene=section("Study", Backbone_omegas="1.95", Forcing_scaled_with_damping="true") +
             section("Continuation", Omega_max=2.2, Energy_max=1) + output(Directory="out"),
             code=2, words=["Study/Forcing scaled with damping", "Study/Forced peaks"]),
        dict(name="study_forcing_scaled_by_rayleigh",
             scene=section("Study", Backbone_omegas="1.95", Forced_peaks="true", Forcing_scaled_with_damping="true") +
             section("Damping", Rayleigh_alpha=0.01) + section("Forcing", Amplitudes="1e-5") +
             section("Receptance", Method="modal") +
             section("Continuation", Omega_max=2.2, Energy_max=1) + output(Directory="out"),
             code=2, words=["Damping/Modal ratio", "> 0"]),
        dict(name="study_reference_one_level", scene=section("Study", Backbone_omegas="1.95",
                                                             Reference_cells="28") +
             output(Directory="out"), code=2, words=["Study/Reference cells", "two or more"]),
        dict(name="study_reference_decreasing", scene=section("Study", Backbone_omegas="1.95",
                                                              Reference_cells="28, 14") +
             output(Directory="out"), code=2, words=["Study/Reference cells", "increasing"]),
        dict(name="study_reference_degree", scene=section("Study", Backbone_omegas="1.95", Reference_degree=99,
                                                          Reference_cells="7, 14") +
             output(Directory="out"), code=2, words=["Study/Reference degree", "Discretisation/Degree"]),
        dict(name="study_foreign_directory", scene=section("Study", Spectrum_modes=2) +
             output(Directory="mine"), setup=foreign_directory, code=2,
             words=["Output/Directory", "study.scene"]),
        dict(name="study_other_scene", scene=SMALL + section("Study", Spectrum_modes=3) +
             output(Directory="out"), setup=earlier_study(executable), code=2,
             words=["Output/Directory", "study.scene"], leaves={"out"}),
        # 12. the declared parameters are a valid scene
        dict(name="print_parameters", scene=None, code=0, check=print_parameters_round_trip,
             setup=lambda row: row.update(scene_file="all.prm") or
             subprocess.run([executable, "--print-parameters"], check=True,
                            stdout=open("all.prm", "w"))),
    ]


def signal_name(code):
    if code is not None and code < 0:
        try:
            return f"{code} ({signal.Signals(-code).name})"
        except ValueError:
            pass
    return str(code)


@contextlib.contextmanager
def row_directory(row):
    """./hostile/NAME, made anew, is the working directory while the row runs
    (its scene written there as row["scene_file"]); it is removed after a row
    that passed, and kept for a look after one that failed."""
    directory = os.path.abspath(os.path.join("hostile", row["name"]))
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    home = os.getcwd()
    os.chdir(directory)
    try:
        row.setdefault("scene_file", "scene.prm")
        if row.get("scene") is not None:
            with open(row["scene_file"], "w", errors="surrogateescape") as f:
                f.write(row["scene"])
        yield
    finally:
        os.chdir(home)
    shutil.rmtree(directory, ignore_errors=True)


def run_row(executable, row):
    """Runs the row in ./hostile/NAME and checks it; raises AssertionError with
    every expectation that failed."""
    import hostile_round_two
    with row_directory(row):
        if "setup" in row:
            row["setup"](row)
        before = listing(".")
        preexec = row.get("preexec", hostile_round_two.limits(sigxfsz=signal.SIG_DFL))
        timeout = row.get("timeout", 600)
        # A session of its own: a timeout kills the run and whatever it started.
        process = subprocess.Popen([executable, row["scene_file"], *row.get("args", [])], stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, preexec_fn=preexec, start_new_session=True,
                                   env={**os.environ, **row.get("env", {})})
        try:
            stdout, stderr = process.communicate(timeout=timeout)
            timed_out = False
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            stdout, stderr = process.communicate()
            timed_out = True
        row["stdout"], row["stderr"] = stdout.decode(errors="replace"), stderr.decode(errors="replace")
        lines = row["stderr"].strip().splitlines()
        reasons = []

        def expect(ok, why):
            if not ok:
                reasons.append(why)
        codes = row["code"] if isinstance(row["code"], tuple) else (row["code"],)
        expect(not timed_out, f"no exit within {timeout} s (killed)")
        expect(timed_out or process.returncode in codes,
               f"exit {signal_name(process.returncode)}, expected {row['code']}:\n{row['stderr']}")
        if timed_out or process.returncode != 0:
            expect(len(lines) == 1, f"not one line:\n{row['stderr']}")
            first = lines[0] if lines else ""
            missing = [w for w in row.get("words", []) if w not in first]
            expect(not missing, f"{missing} not in: {first}")
            if row.get("words_any"):
                expect(any(w in first for w in row["words_any"]), f"none of {row['words_any']} in: {first}")
        if row.get("before_work"):
            # Refused before any work: standard output holds at most the
            # program's first line (which scene or study it reads), no stage.
            work = [l for l in row["stdout"].splitlines() if not l.startswith("nsm-bar: ")]
            expect(not work, f"work was done before the refusal: {work[:3]}")
        allowed = set(row.get("leaves", set()))
        left = {p for p in listing(".") - before if p.split(os.sep)[0] not in allowed}
        expect(not left, f"files left behind: {sorted(left)[:6]}")
        if "check" in row and not reasons:
            row["check"](row)
        assert not reasons, f"{row['name']}: " + "; ".join(reasons)


def main():
    """usage: hostile_inputs.py NSM_BAR [--skip] [NAME_REGEX ...]: the rows
    whose name matches one of the patterns (default: all); with --skip, the
    rows whose name matches none of them."""
    import hostile_round_two
    executable = os.path.abspath(sys.argv[1])
    skip = sys.argv[2:3] == ["--skip"]
    patterns = sys.argv[3:] if skip else sys.argv[2:]
    failures = []
    for row in rows(executable) + hostile_round_two.new_rows(executable):
        if patterns and any(re.search(p, row["name"]) for p in patterns) == skip:
            continue
        start = time.time()
        try:
            run_row(executable, row)
            print(f"ok   {row['name']} ({time.time() - start:.1f} s)")
        except Exception as e:  # an assertion, or a row whose setup broke
            failures.append(str(e))
            print(f"FAIL {row['name']}: {e}")
    if failures:
        sys.exit(f"{len(failures)} hostile inputs mishandled")
    print("all hostile inputs handled")


if __name__ == "__main__":
    main()
