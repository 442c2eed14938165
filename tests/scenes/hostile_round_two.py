#!/usr/bin/env python3
"""The second table of hostile and borderline scenes (hostile_inputs.py runs
it after its own): include cycles and nesting, links and special files in a
study's directory, directory names, resource limits, cross sections, requests
the mesh cannot meet, values spelled twice, memory. Each row says in a comment
what the program did before it handled the case (every such row failed then).

Rows may use, besides hostile_inputs.py's keys:
  timeout    seconds before the run (its whole process group) is killed: a
             failure (default 60)
  code       an int, or a tuple of allowed exit codes
  words_any  at least one of these words must be in the one-line message
  before_work  the run is refused before any work: its standard output has no
             line beyond the program's first (no stage, no run summary)
Every run (setups' runs too) has RLIMIT_AS <= 2 GiB (MEMORY_CAP), except under
AddressSanitizer, which reserves more; a row's preexec may lower it.
"""
import json
import os
import re
import resource
import shutil
import signal
import stat
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import setup_runs  # noqa: E402
from hostile_inputs import (BACKBONE, SMALL, complete, listing, output,  # noqa: E402
                            read_rows, section, snapshot, spectrum_scene)

MEMORY_CAP = 2 << 30      # never let a run grow beyond 2 GiB of address space
SETUP_TIMEOUT = 60


# AddressSanitizer reserves terabytes of address space: no cap under it.
SANITIZED = "ASAN_OPTIONS" in os.environ


def cap_memory():
    if SANITIZED:
        return
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    limit = MEMORY_CAP if soft == resource.RLIM_INFINITY else min(soft, MEMORY_CAP)
    resource.setrlimit(resource.RLIMIT_AS, (limit, hard))


def limits(fsize=None, nofile=None, address_space=None, sigxfsz=signal.SIG_DFL):
    """A preexec: SIGXFSZ's disposition (default: SIG_DFL, as after `ulimit -f`
    in a shell: the kernel kills a process that writes past the limit unless
    it ignores or handles the signal), then the resource limits."""
    def preexec():
        signal.signal(signal.SIGXFSZ, sigxfsz)
        cap_memory()
        if fsize is not None:
            resource.setrlimit(resource.RLIMIT_FSIZE, (fsize, fsize))
        if nofile is not None:
            resource.setrlimit(resource.RLIMIT_NOFILE, (nofile, nofile))
        if address_space is not None and not SANITIZED:
            resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))
    return preexec


def prepare_run(executable, scene_file):
    """A run made by a setup: must succeed, within SETUP_TIMEOUT, under the cap
    (made once per table for a scene and a directory state: setup_runs.py)."""
    setup_runs.once(("run", executable, scene_file), lambda: subprocess.run(
        [executable, scene_file], capture_output=True, check=True, timeout=SETUP_TIMEOUT,
        preexec_fn=cap_memory))


def write(path, text):
    with open(path, "w", errors="surrogateescape") as f:
        f.write(text)


def read(path):
    with open(path) as f:
        return f.read()


# ---- scenes -----------------------------------------------------------------

SPECTRUM = SMALL + spectrum_scene("out", 2)
SMALL_BACKBONE = BACKBONE + output(Directory="out", Backbone="true")
STUDY = SMALL + section("Study", Spectrum_modes=2) + output(Directory="out", Plots="true")
STUDY_QUIET = SMALL + section("Study", Spectrum_modes=2) + output(Directory="out")
# Two rows: an interrupted run (one row kept) makes the rerun write study.csv.
STUDY_TWO_ROWS = SMALL + section("Study", Degrees="9, 10", Spectrum_modes=2) + \
    output(Directory="out", Plots="true")
# A study with a fine backbone reference (reference.csv), kept small.
STUDY_REFERENCE = BACKBONE + section("Study", Backbone_omegas="1.92",
                                     Reference_cells="7, 14") + output(Directory="out")


def mangle(name):
    """ParameterHandler's tree names: '_' and two hex digits for each character
    that is not a letter or digit."""
    return "".join(c if c.isascii() and c.isalnum() else "_%02x" % ord(c) for c in name)


def json_scene(sections):
    """{"Section": {"Entry": value}} in deal.II's JSON layout."""
    return json.dumps({mangle(s): {mangle(k): {"value": str(v)} for k, v in entries.items()}
                       for s, entries in sections.items()}, indent=1)


JSON_BACKBONE = {
    "Discretisation": {"Degree": 10, "Cells": 7},
    "Receptance": {"Method": "modal"},
    "Harmonic balance": {"Harmonics": 20},
    "Continuation": {"Omega min": 1.5, "Omega max": 1.93, "Energy max": 1e-3},
}


def json_directory(directory):
    def setup(row):
        row["scene_file"] = "scene.json"
        write("scene.json", json_scene({**JSON_BACKBONE, "Output": {
            "Directory": directory, "Backbone": "true", "Plots": "true"}}))
    return setup


# ---- setups -----------------------------------------------------------------

def files(contents):
    """Writes the files {name: text} (the row's scene.prm among them)."""
    def setup(_):
        for name, text in contents.items():
            write(name, text)
    return setup


def include_cycle_via_link(kind):
    """scene.prm includes NAME, a symbolic or hard link to scene.prm."""
    def setup(_):
        write("scene.prm", "include link.prm\n")
        (os.symlink if kind == "symbolic" else os.link)("scene.prm", "link.prm")
    return setup


def include_chain(depth):
    """f0.prm includes f1.prm ... f{depth-1}.prm includes f{depth}.prm, a real
    small spectrum scene: `depth` nested includes."""
    def setup(row):
        row["scene_file"] = "f0.prm"
        for i in range(depth):
            write(f"f{i}.prm", f"include f{i + 1}.prm\n")
        write(f"f{depth}.prm", SPECTRUM)
    return setup


def deep_json(_row):
    _row["scene_file"] = "scene.json"
    write("scene.json", '{"a":' * 100000 + "1" + "}" * 100000)


def deep_xml(_row):
    _row["scene_file"] = "scene.xml"
    write("scene.xml", "<ParameterHandler>" + "<a>" * 100000 + "1" + "</a>" * 100000 +
          "</ParameterHandler>")


def earlier_study_with_link(executable, planted, scene=STUDY, interrupted=False):
    """An earlier complete run of the row's study (scene.prm), then
    out/`planted` made a symbolic link to ../victim.txt ("precious"). With
    `interrupted`, study.csv keeps its header and first row only (a run stopped
    after one row), so that the rerun writes study.csv again."""
    def setup(_):
        prepare_run(executable, "scene.prm")
        if interrupted:
            with open("out/study.csv") as f:
                lines = f.readlines()
            write("out/study.csv", "".join(lines[:2]))
        write("victim.txt", "precious")
        target = os.path.join("out", planted)
        if os.path.lexists(target):
            os.remove(target)
        os.symlink("../victim.txt", target)
    return setup


def victim_intact(_):
    with open("victim.txt", "rb") as f:
        text = f.read()
    assert text == b"precious", "the victim was written through the link: " + repr(text[:60])


def earlier_study_with_special(executable, name, make):
    """An earlier complete run of the row's study, then out/`name` replaced by
    a special file made by make(path); the inodes of out's entries are
    recorded for special_intact."""
    def setup(row):
        prepare_run(executable, "scene.prm")
        path = os.path.join("out", name)
        if os.path.isdir(path) and not os.path.islink(path):
            os.rmdir(path)
        elif os.path.lexists(path):
            os.remove(path)
        make(path)
        row["inodes"] = inodes("out")
    return setup


def inodes(directory):
    return {p: os.lstat(os.path.join(directory, p)).st_ino for p in listing(directory)}


def special_intact(name, kind):
    """out/`name` is still the special file the setup made."""
    def check(row):
        path = os.path.join("out", name)
        ok = {"fifo": lambda: stat.S_ISFIFO(os.lstat(path).st_mode),
              "dev_zero": lambda: os.path.islink(path) and os.readlink(path) == "/dev/zero",
              "directory": lambda: os.path.isdir(path) and not os.path.islink(path)}[kind]
        assert os.path.lexists(path) and ok(), f"out/{name} is no longer the {kind} planted"
        changed = sorted(p for p, i in row["inodes"].items()
                         if not os.path.lexists(os.path.join("out", p)) or
                         os.lstat(os.path.join("out", p)).st_ino != i)
        assert not changed, f"files of out replaced or removed (work was done): {changed}"
    return check


def to_dev_zero(path):
    os.symlink("/dev/zero", path)


def make_parent(name):
    def setup(_):
        os.mkdir(name)
    return setup


def plots_in(directory, plot):
    def check(_):
        assert os.path.isfile(os.path.join(directory, plot)), \
            f"{directory}/{plot} missing: {sorted(listing(directory)) if os.path.isdir(directory) else 'no directory'}"
    return check


def earlier_output(executable, scene):
    """An earlier complete run of `scene` (first.prm) into out; its files are
    recorded for untouched()."""
    def setup(row):
        write("first.prm", scene)
        prepare_run(executable, "first.prm")
        row["before_out"] = snapshot("out")
    return setup


def untouched(row):
    assert snapshot("out") == row["before_out"], "the earlier output in out was changed"


def nothing_half_written(_):
    left = [p for p in listing(".") if ".nsm-bar-" in p or p.endswith(".partial")]
    assert not left, f"left behind: {sorted(left)[:5]}"


def no_mpi_text(row):
    for word in ("PMIX", "ORTE", "MPI", "orte_init", "mpirun"):
        assert word not in row["stderr"], f"MPI text on stderr: {row['stderr'][:200]}"


def mentions_position(low, high):
    """The one-line message names a position x in (low, high) where A(x) <= 0."""
    def check(row):
        numbers = [float(n) for n in re.findall(r"[-+]?\d*\.\d+(?:[eE][-+]?\d+)?", row["stderr"])]
        assert any(low < n < high for n in numbers), \
            f"no position in ({low}, {high}) in: {row['stderr'].strip()}"
    return check


def mentions_number(*maxima):
    """The message gives the allowed maximum, one of `maxima` (as a number of
    its own)."""
    def check(row):
        assert any(re.search(rf"(?<![\w.+-]){n}(?![\w.])", row["stderr"]) for n in maxima), \
            f"none of the maxima {maxima} in: {row['stderr'].strip()}"
    return check


def dangling_link(name):
    def setup(_):
        os.symlink("nowhere", name)
    return setup


def thesis_directory(_):
    os.makedirs("mine/nsm-bar.manifest")
    write("mine/thesis.tex", "my thesis\n")


def thesis_intact(_):
    assert read("mine/thesis.tex") == "my thesis\n", "mine/thesis.tex was changed"


def partial_manifest(_):
    os.mkdir("out")
    write("out/nsm-bar.manifest", "spectrum.csv\n")
    write("out/spectrum.csv", "mode,omega\n1,1.919\n")
    write("out/notes.txt", "my notes\n")


def notes_intact(_):
    assert read("out/notes.txt") == "my notes\n", "out/notes.txt was changed or deleted"


def receptance_at(value):
    def check(_):
        rows = read_rows("out/receptance.csv")
        assert float(rows[1][0]) == float(value), rows[1]
    return check


LONG_NAME = "d" * 250


def startup_address_space(executable):
    """The least RLIMIT_AS under which `nsm-bar --print-parameters` runs (it
    loads every library and starts deal.II), to 4 MiB."""
    def starts(limit):
        return subprocess.run([executable, "--print-parameters"], capture_output=True,
                              preexec_fn=limits(address_space=limit)).returncode == 0
    low, high = 64 << 20, MEMORY_CAP
    while high - low > 4 << 20:
        middle = (low + high) // 2
        low, high = (low, middle) if starts(middle) else (middle, high)
    return high


def complete_named(directory):
    def check(_):
        assert complete(directory), f"{directory} is not a complete output"
    return check


def estimate_bounds_peak(executable):
    """The summary's memory estimate lies above the run's measured peak
    resident memory, and within 3 times it (an estimate that refuses only
    scenes that would not fit)."""
    def check(row):
        estimate = float(re.search(r"memory: about ([0-9.e+]+) MiB", row["stdout"]).group(1))
        shutil.rmtree("out", ignore_errors=True)
        pid = os.fork()
        if pid == 0:
            try:  # the child never returns into the table (nor runs its atexit)
                os.execv(executable, [executable, "scene.prm"])
            finally:
                os._exit(127)
        _, status, usage = os.wait4(pid, 0)
        peak = usage.ru_maxrss / 1024
        assert os.waitstatus_to_exitcode(status) == 0
        assert peak <= estimate <= 3 * peak, f"estimate {estimate} MiB, measured peak {peak:.0f} MiB"
    return check


def include_fan_out(levels):
    """f0.prm includes f1.prm twice, f1 includes f2 twice, ...: 2^levels
    includes in all, each file a few lines."""
    def setup(row):
        row["scene_file"] = "f0.prm"
        for i in range(levels):
            write(f"f{i}.prm", f"include f{i + 1}.prm\ninclude f{i + 1}.prm\n")
        write(f"f{levels}.prm", "# empty\n")
    return setup


def deep_xml_underscore(row):
    row["scene_file"] = "scene.xml"
    write("scene.xml", "<ParameterHandler>" + "<_>" * 100000 + "1" + "</_>" * 100000 + "</ParameterHandler>")


def earlier_vtk_run(executable, scene):
    """An earlier complete run of `scene` (with VTK snapshots in a folder)."""
    def setup(_):
        write("first.prm", scene)
        prepare_run(executable, "first.prm")
    return setup


def vtk_output_complete(_):
    """The rerun's output: the files and the snapshot folder its manifest lists."""
    listed = read("out/nsm-bar.manifest").splitlines()
    top = {line.split("/")[0].split(" ")[0] for line in listed}
    assert set(os.listdir("out")) == top | {"nsm-bar.manifest"}, (sorted(os.listdir("out")), sorted(top))
    assert any(line.startswith("field_0_snapshots/") for line in listed), listed


def json_section_newline(row):
    row["scene_file"] = "scene.json"
    write("scene.json", json_scene({"Bar": {"Cross section": "1.5 - y\n+ 1"}, "Output": {"Directory": "out"}}))


def json_value_not_utf8(row):
    """A byte that is not UTF-8 (0xFF, written through surrogateescape) in a
    value, after a value that holds an escaped quote, a colon and a brace."""
    row["scene_file"] = "scene.json"
    text = json_scene({"Contact": {"Force sign": 'physical\\" : {'}, "Bar": {"Cross section": "1.5 - x BYTE"},
                       "Output": {"Directory": "out"}})
    write("scene.json", text.replace("BYTE", "\udcff"))


def new_rows(executable):
    """The rows; executable is used by the setups that need an earlier run."""
    narrow_step = "1.5 - x - 2*(abs(x - 0.5005) < 4e-4)"       # A < 0 on (0.5001, 0.5009)
    narrow_smooth = "1.5 - x - 2*exp(-((x - 0.5005)/1e-4)^2)"  # A < 0 on about 0.5005 -+ 8.3e-5
    linear = lambda cells: section("Discretisation", Degree=1, Cells=cells)
    big = section("Discretisation", Degree=20, Cells=1000000)
    rows = [
        # ---- 1. include cycles ------------------------------------------------
        # deal.II turns tabs into spaces before it looks for "include "; the old
        # check looks for "include " only, misses the cycle, and deal.II recurses.
        # old: SIGSEGV (-11), no message, 0.2 s.
        dict(name="include_tab_self", scene="include\tscene.prm\n", code=2,
             words=["include", "cycle"]),
        # The old check follows the includes of .prm files only; deal.II reads an
        # included a.txt as PRM text, which includes scene.prm again.
        # old: SIGSEGV, no message, 0.2 s.
        dict(name="include_txt_cycle", scene=None, code=2, words=["include", "cycle"],
             setup=files({"scene.prm": "include a.txt\n", "a.txt": "include scene.prm\n"})),
        # deal.II 9.4 (ParameterHandler::parse_input) trims each line (std::isspace)
        # and joins a line whose last character is '\' to the next, the '\'
        # removed and no space added: "incl\" + "ude scene.prm" = "include
        # scene.prm" (checked: "incl\"/"ude real.prm" includes real.prm, "incl \"
        # does not parse). The old check reads raw lines.
        # old: SIGSEGV, no message, 0.2 s.
        dict(name="include_backslash_cycle", scene="incl\\\nude scene.prm\n", code=2,
             words=["include", "cycle"]),
        # deal.II trims \v and \f too; the old check skips " \t" only.
        # old: SIGSEGV, no message, 0.2 s (both rows).
        dict(name="include_vtab_cycle", scene="\vinclude scene.prm\n", code=2,
             words=["include", "cycle"]),
        dict(name="include_formfeed_cycle", scene="\finclude scene.prm\n", code=2,
             words=["include", "cycle"]),
        # The old check keeps a trailing \v in the name; deal.II trims it.
        # old: exit 2 "scene 'scene.prm\v' does not exist": no "cycle", and the raw
        # \v splits the message in two lines (str.splitlines).
        dict(name="include_trailing_vtab_cycle", scene="include scene.prm\v\n", code=2,
             words=["include", "cycle"]),
        # Paths spelled differently. The old check compares canonical paths, and a
        # hard link's text names itself, so all three are caught already:
        # regression rows. old: exit 2 "... inside itself (an include cycle)": PASS.
        dict(name="include_dot_slash_cycle", scene="include ./scene.prm\n", code=2,
             words=["include", "cycle"]),
        dict(name="include_symlink_cycle", scene=None, setup=include_cycle_via_link("symbolic"),
             code=2, words=["include", "cycle"]),
        dict(name="include_hardlink_cycle", scene=None, setup=include_cycle_via_link("hard"),
             code=2, words=["include", "cycle"]),
        # A legal but absurd chain, refused by a depth limit (at most 32 nested
        # includes). old: SIGSEGV after 3 s (the check recurses, one open file
        # per level; RLIMIT_NOFILE here is 20000).
        dict(name="include_chain_30000", scene=None, setup=include_chain(30000), code=2,
             words=["include", "deeper than"]),
        # The first depth beyond the limit. old: exit 0.
        dict(name="include_chain_33", scene=None, setup=include_chain(33), code=2,
             words=["include", "deeper than"]),
        # SANE: chains within the limit run. old: exit 0: PASS.
        dict(name="include_chain_20", scene=None, setup=include_chain(20), code=0,
             leaves={"out"}),
        dict(name="include_chain_32", scene=None, setup=include_chain(32), code=0,
             leaves={"out"}),
        # Every include doubles: 2^20 includes of small files. Refused by a
        # limit on the files included in all.
        dict(name="include_fan_out", scene=None, setup=include_fan_out(20), code=2,
             words=["includes more than"], before_work=True),
        # ---- 2. deep nesting ----------------------------------------------------
        # Element names need not start with a letter.
        dict(name="xml_nested_underscore", scene=None, setup=deep_xml_underscore, code=2,
             words=["scene.xml", "nested"]),
        # old: SIGSEGV in boost's recursive JSON / XML parsers, 0.2 s.
        dict(name="json_nested_100000", scene=None, setup=deep_json, code=2,
             words=["scene.json", "nested"]),
        dict(name="xml_nested_100000", scene=None, setup=deep_xml, code=2,
             words=["scene.xml", "nested"]),
        # ---- 3. a study never writes through a link ------------------------------
        # A study writes straight into Output/Directory (no staging): every file it
        # opens follows a planted link. old: exit 0 and ../victim.txt overwritten
        # with, in turn, the plot log, study.csv, study.scene, study.png.
        dict(name="study_link_plots_log", scene=STUDY, code=2, words=["Output/Directory"],
             setup=earlier_study_with_link(executable, "plots.log"), check=victim_intact),
        # study.csv.partial is opened only when a row is computed: the earlier run
        # is cut back to one of its two rows (an interrupted study).
        dict(name="study_link_csv_partial", scene=STUDY_TWO_ROWS, code=2,
             words=["Output/Directory"], check=victim_intact,
             setup=earlier_study_with_link(executable, "study.csv.partial", interrupted=True)),
        dict(name="study_link_scene_partial", scene=STUDY, code=2, words=["Output/Directory"],
             setup=earlier_study_with_link(executable, "study.scene.partial"),
             check=victim_intact),
        dict(name="study_link_png", scene=STUDY, code=2, words=["Output/Directory"],
             setup=earlier_study_with_link(executable, "study.png"), check=victim_intact),
        # ---- 4. special files in a study's directory ------------------------------
        # Refused at once, before any work: before_work and special_intact (the
        # special file, and the inode of every other file of out, unchanged:
        # the old binary rewrites study.scene first).
        # old: hangs opening the FIFO (killed after 20 s).
        dict(name="study_csv_fifo", scene=STUDY_QUIET, code=2, timeout=20, before_work=True,
             words_any=["Output/Directory", "study.csv"], check=special_intact("study.csv", "fifo"),
             setup=earlier_study_with_special(executable, "study.csv", os.mkfifo)),
        # old: reads /dev/zero until std::getline's bad_alloc (under the 2 GiB
        # cap; the istream swallows it), takes the file as empty, recomputes the
        # row, replaces the link with a regular study.csv: exit 0, 1.1 to 1.9 s.
        dict(name="study_csv_dev_zero", scene=STUDY_QUIET, code=2, timeout=30, before_work=True,
             words_any=["Output/Directory", "study.csv"],
             check=special_intact("study.csv", "dev_zero"),
             setup=earlier_study_with_special(executable, "study.csv", to_dev_zero)),
        # old: the same reading, then exit 2 "reference.csv has no column
        # energy_cells_14" (names the file), 1.1 to 1.9 s, study.scene rewritten:
        # fails only by before_work and special_intact.
        dict(name="reference_csv_dev_zero", scene=STUDY_REFERENCE, code=2, timeout=30,
             before_work=True, words_any=["Output/Directory", "reference.csv"],
             check=special_intact("reference.csv", "dev_zero"),
             setup=earlier_study_with_special(executable, "reference.csv", to_dev_zero)),
        # old: computes the row, then exit 5 "cannot write out/study.csv whole".
        dict(name="study_csv_directory", scene=STUDY_QUIET, code=2, before_work=True,
             words_any=["Output/Directory", "study.csv"],
             check=special_intact("study.csv", "directory"),
             setup=earlier_study_with_special(executable, "study.csv", os.mkdir)),
        # ---- 5. directories whose name starts with '-' (SANE input) -------------------
        # A scene's plots are made in the staging directory "./.-h.nsm-bar-PID",
        # which argparse reads as a path: old: exit 0 with backbone.png: PASS for
        # -h, --gap, -x.
        dict(name="dash_h_backbone", scene=BACKBONE + output(Directory="-h", Backbone="true",
                                                             Plots="true"),
             code=0, leaves={"-h"}, check=plots_in("-h", "backbone.png")),
        dict(name="dash_gap_backbone", scene=BACKBONE + output(Directory="--gap", Backbone="true",
                                                               Plots="true"),
             code=0, leaves={"--gap"}, check=plots_in("--gap", "backbone.png")),
        dict(name="dash_x_backbone", scene=BACKBONE + output(Directory="-x", Backbone="true",
                                                             Plots="true"),
             code=0, leaves={"-x"}, check=plots_in("-x", "backbone.png")),
        # Staging "-a/.b.nsm-bar-PID" starts with '-'. old: exit 3 "the plotting
        # script failed: ... the following arguments are required: directory".
        dict(name="dash_a_b_backbone", scene=BACKBONE + output(Directory="-a/b", Backbone="true",
                                                               Plots="true"),
             setup=make_parent("-a"), code=0, leaves={"-a"}, check=plots_in("-a/b", "backbone.png")),
        # A study plots into "-h" itself: argparse prints its help and exits 0.
        # old: exit 0 without -h/study.png.
        dict(name="dash_h_study", scene=SMALL + section("Study", Spectrum_modes=2) +
             output(Directory="-h", Plots="true"), code=0, leaves={"-h"},
             check=plots_in("-h", "study.png")),
        # ---- 6. control characters in Output/Directory (JSON scene) ------------------
        # old: runs, the plot script's "wrote PATH" line splits at the newline,
        # commit takes a substr of it: exit 4 "basic_string::substr: __pos ...".
        dict(name="json_directory_newline", scene=None, setup=json_directory("a\nb"), code=2,
             words=["Output/Directory"]),
        # old: the paths end at the NUL (".a"): exit 5 "output error: cannot write ./.a".
        dict(name="json_directory_nul", scene=None, setup=json_directory("a\0b"), code=2,
             words=["Output/Directory"]),
        # ---- 7. a scene's output and a study's never mix ------------------------------
        # Regression rows: old refuses both (no study.scene; no nsm-bar.manifest),
        # out untouched: PASS.
        dict(name="study_into_scene_output", scene=STUDY_QUIET, code=2,
             words=["Output/Directory"], leaves={"out"},
             setup=earlier_output(executable, SMALL + spectrum_scene("out", 3)), check=untouched),
        dict(name="scene_into_study_output", scene=SPECTRUM, code=2,
             words=["Output/Directory"], leaves={"out"},
             setup=earlier_output(executable, STUDY), check=untouched),
        # ---- 8. resource limits ---------------------------------------------------
        # SIGXFSZ at its default disposition (as after `ulimit -f`).
        # old: killed by SIGXFSZ (-25), .out.nsm-bar-PID/backbone.csv.partial left.
        dict(name="fsize_1024_backbone_sigdfl", scene=SMALL_BACKBONE, code=5,
             words=["output error"], preexec=limits(fsize=1024), check=nothing_half_written),
        # 16 KiB: backbone.csv (4.2 KB) fits, backbone.png (50 KB) does not. Python
        # ignores SIGXFSZ itself: the plots fail, the CSVs are kept. old: exit 3
        # "numerical failure: the plotting script failed: OSError: [Errno 27] File
        # too large", nothing kept.
        dict(name="fsize_16k_plots", scene=BACKBONE + output(Directory="out", Backbone="true",
                                                            Plots="true"),
             code=5, words=["output error", "plots"], preexec=limits(fsize=16384), leaves={"out"},
             check=lambda row: nothing_half_written(row) or read_rows("out/backbone.csv")),
        # 16 KiB: the CSVs (at most 7.3 KB) fit, field_0.vtu (131 KB) does not.
        # old: killed by SIGXFSZ, staging directory with field_0.vtu.partial left.
        dict(name="fsize_16k_vtk", scene=BACKBONE + output(Directory="out", Backbone="true",
                                                          Fields_at=1.92, VTK="true"),
             code=5, words=["output error"], preexec=limits(fsize=16384),
             check=nothing_half_written),
        # old: Open MPI's singleton MPI_Init cannot write its PMIx segments:
        # exit 1, 48 lines of PMIX/ORTE/MPI_INIT text.
        dict(name="fsize_1024_study_serial", scene=STUDY_QUIET, code=5, words=["output error"],
             preexec=limits(fsize=1024), check=no_mpi_text),
        # RLIMIT_NOFILE: a plain scene (no plots) runs from 5 (4 and its staging
        # folder's lock: hostile_round_three.py's nofile_4; at 3 the dynamic
        # loader fails before main, exit 127); with plots from 7 or 8 (Python's);
        # the old study needs 24 (MPI singleton init).
        # old: exit 1, 29 lines of ORTE errors.
        dict(name="nofile_10_study_serial", scene=STUDY_QUIET, code=(0, 5), leaves={"out"},
             preexec=limits(nofile=10), check=no_mpi_text),
        # ---- 9. Bar/Cross section --------------------------------------------------
        # muparser's assignment, comma list and rand(). old: exit 0 for all three.
        dict(name="section_assignment", scene=section("Bar", Cross_section="x = 1") + SPECTRUM,
             code=2, words=["Bar/Cross section"]),
        dict(name="section_comma_list", scene=section("Bar", Cross_section="1.5 - x, 2") +
             SPECTRUM, code=2, words=["Bar/Cross section"]),
        dict(name="section_random", scene=section("Bar", Cross_section="1 + 0.1*rand()") +
             SPECTRUM, code=2, words=["Bar/Cross section"]),
        # A(x) < 0 on (0.5001, 0.5009) only: between the 1001 check points (0.500,
        # 0.501), and no node or Gauss point of 7 FE_Q(10) cells falls in it.
        # The message must give a position inside. old: exit 0.
        dict(name="section_narrow_step_7_cells", scene=section("Bar", Cross_section=narrow_step) +
             SPECTRUM, code=2, words=["Bar/Cross section", "A(x) > 0"],
             check=mentions_position(0.5001, 0.5009)),
        # A smooth dip, negative within about 8.3e-5 of 0.5005. old: exit 0.
        dict(name="section_narrow_dip_7_cells", scene=section("Bar", Cross_section=narrow_smooth) +
             SPECTRUM, code=2, words=["Bar/Cross section", "A(x) > 0"],
             check=mentions_position(0.5005 - 1e-4, 0.5005 + 1e-4)),
        # CONTROL: on 4000 linear cells a quadrature point falls in the step.
        # old: exit 2 "... allowed A(x) > 0, ... but A(0.50012499999997262) =
        # -1.00012...": PASS.
        dict(name="section_narrow_step_4000_cells", scene=section("Bar", Cross_section=narrow_step) +
             linear(4000) + spectrum_scene("out", 2), code=2,
             words=["Bar/Cross section", "A(x) > 0"], check=mentions_position(0.5001, 0.5009)),
        # ---- 10. requests the mesh cannot meet ----------------------------------------
        # The message gives the maximum: Cells x Degree clamped-free modes, or
        # Cells x Degree - 1, the rows spectrum.csv can hold (each row pairs a
        # clamped-free with a clamped-clamped frequency, and the clamped-clamped
        # mesh has one mode fewer). old: exit 0, silently fewer rows: 3999 rows
        # for 5000 asked; on 1 linear cell a header and no row at all.
        dict(name="spectrum_modes_5000_on_4000", scene=linear(4000) + spectrum_scene("out", 5000),
             code=2, words=["Output/Spectrum modes"], check=mentions_number(4000, 3999)),
        dict(name="spectrum_modes_5_on_1_cell", scene=linear(1) + spectrum_scene("out", 5),
             code=2, words=["Output/Spectrum modes"], check=mentions_number(1, 0)),
        # old: exit 0, spectrum_error over the 2 modes there are.
        dict(name="study_spectrum_modes_10_on_2", scene=linear(2) + section("Study", Spectrum_modes=10) +
             output(Directory="out"), code=2, words=["Study/Spectrum modes"],
             check=mentions_number(2, 1)),
        # ---- 11. one value spelled twice --------------------------------------------
        # The old check compares the text only. old: exit 0 for all five (the same
        # run repeated under two spellings).
        dict(name="study_degrees_2_02", scene=SMALL + section("Study", Degrees="2, 02", Spectrum_modes=2) +
             output(Directory="out"), code=2, words=["Study/Degrees", "listed twice"]),
        dict(name="study_degrees_4_plus4", scene=SMALL + section("Study", Degrees="4, +4", Spectrum_modes=2) +
             output(Directory="out"), code=2, words=["Study/Degrees", "listed twice"]),
        dict(name="study_graded_ratios_half", scene=SMALL + section("Discretisation", Refinement="graded") +
             "subsection Discretisation\n subsection Graded\n  set Layers = 3\n end\nend\n" +
             section("Study", Graded_ratios="0.5, 0.50, 5e-1", Spectrum_modes=2) + output(Directory="out"),
             code=2, words=["Study/Graded ratios", "listed twice"]),
        dict(name="study_adaptive_tolerances_1e8", scene=SMALL +
             section("Discretisation", Refinement="adaptive") +
             section("Study", Adaptive_tolerances="1e-8, 1E-8", Spectrum_modes=2) + output(Directory="out"),
             code=2, words=["Study/Adaptive tolerances", "listed twice"]),
        # Backbone omegas are not checked for repeats at all (even "1.92, 1.92").
        dict(name="study_backbone_omegas_1920", scene=BACKBONE + section("Study", Backbone_omegas="1.92, 1.920") +
             output(Directory="out"), code=2, words=["Study/Backbone omegas", "listed twice"]),
        # A range and a single value that print as one column (energy_at_1.7).
        dict(name="study_backbone_omegas_range_and_value", scene=BACKBONE + section(
            "Study", Backbone_omegas="1.6:2.0:9, 1.7") + output(Directory="out"), code=2,
             words=["Study/Backbone omegas", "listed twice"]),
        # A newline inside a value: the message still one line.
        dict(name="json_section_newline", scene=None, setup=json_section_newline, code=2,
             words=["Bar/Cross section"]),
        # A byte that is not UTF-8: the message names the entry and the line.
        dict(name="json_value_not_utf8", scene=None, setup=json_value_not_utf8, code=2,
             words=["parameter 'Bar/Cross section' (line", "not valid UTF-8"]),
        # ---- 12. Output/Directory ------------------------------------------------------
        # A VTK run's snapshots are a folder its manifest lists: a rerun
        # replaces the earlier output.
        dict(name="vtk_output_rerun", scene=BACKBONE + output(Directory="out", Fields_at=1.92, VTK="true"),
             setup=earlier_vtk_run(executable, BACKBONE + output(Directory="out", Fields_at=1.92, VTK="true")),
             code=0, leaves={"out"}, check=vtk_output_complete),
        # old: runs everything (plots included), then exit 5 "output error: cannot
        # move the new output into out: ... cannot rename: Not a directory", 0.7 s.
        dict(name="directory_dangling_link", scene=BACKBONE + output(Directory="out", Backbone="true",
                                                                     Plots="true"),
             setup=dangling_link("out"), code=2, words=["Output/Directory"]),
        # SANE: a 250-character name. old: exit 2 "... cannot be written: File name
        # too long" (the staging name ".NAME.nsm-bar-PID" exceeds NAME_MAX = 255).
        dict(name="directory_250_characters", scene=SMALL + spectrum_scene(LONG_NAME, 2), code=0,
             leaves={LONG_NAME}, check=complete_named(LONG_NAME)),
        # THE THESIS CASE: nsm-bar.manifest is a directory, not a run's manifest.
        # old: exit 0, mine replaced whole: thesis.tex deleted.
        dict(name="directory_manifest_is_directory", scene=SMALL + spectrum_scene("mine", 2),
             setup=thesis_directory, code=2, words=["Output/Directory"], check=thesis_intact),
        # A manifest that does not list every file: an unlisted file refuses the run.
        # old: exit 0, notes.txt deleted. NOTE: contradicts the existing row
        # earlier_output_replaced (an unlisted field_9_tip.csv, exit 0 expected).
        dict(name="directory_unlisted_file", scene=SPECTRUM, setup=partial_manifest, code=2,
             words=["Output/Directory"], check=notes_intact),
        # ---- 13. subnormal frequencies ----------------------------------------------
        # Refused naming the entry, as every subnormal scene value is (a scalar
        # one ended in exit 4 in deal.II's get_double; a list's reached the
        # Bessel reference: hostile_round_three.py). 1e-308 is subnormal; 0
        # and 2.3e-308 are numbers.
        *[dict(name=f"receptance_{value}", scene=SMALL + output(Directory="out", Receptance_frequencies=value),
               code=2, words=["Output/Receptance frequencies", "subnormal"], before_work=True)
          for value in ("1e-308", "4.9e-324")],
        dict(name="receptance_2.3e-308", scene=SMALL + output(Directory="out", Receptance_frequencies="2.3e-308"),
             code=0, leaves={"out"}, check=receptance_at("2.3e-308")),
        # ---- 14. memory ------------------------------------------------------------
        # 1e6 cells of FE_Q(20), 2e7 DoFs: refused before any work
        # (RLIMIT_AS 2 GiB keeps the old binary from hurting the machine).
        # old: exit 4 "nsm-bar: error: std::bad_alloc", 1.9 s (both rows).
        dict(name="memory_spectrum_1e6_q20", scene=big + spectrum_scene("out", 2), code=2,
             words=["memory", "Discretisation/Cells", "Discretisation/Degree"], before_work=True,
             preexec=limits(address_space=MEMORY_CAP)),
        dict(name="memory_backbone_1e6_q20", scene=big + output(Directory="out", Backbone="true"),
             code=2, words=["memory", "Discretisation/Cells", "Discretisation/Degree"], before_work=True,
             preexec=limits(address_space=MEMORY_CAP)),
        # bad_alloc inside a run: 200000 linear cells need about 90 MB beyond
        # what the program needs to start; the limit leaves it 40 MB. The run
        # is refused (2: its estimate exceeds the limit) or runs out (5, or 3),
        # in one line, never 4. Skipped under AddressSanitizer (no cap there).
        # old: exit 4 "nsm-bar: error: std::bad_alloc" (5 of 5 runs).
    ] + ([] if SANITIZED else [
        # Four open files (a plain scene's least). Not under the sanitizers:
        # their runtime needs more, and UBSan then reports Trilinos' static
        # initialisers before main.
        # old: exit 1, "[warn] evutil_make_internal_pipe_: pipe: Too many open files" + 1 line.
        dict(name="nofile_4_study_serial", scene=STUDY_QUIET, code=(0, 5), leaves={"out"},
             preexec=limits(nofile=4), check=no_mpi_text),
        # The estimate that refuses a scene, against the peak it measures:
        # FE_Q(20) x 1e4 cells (2e5 DoFs, 8e6 nonzeros), one direct receptance.
        dict(name="memory_estimate_bounds_peak", scene=section("Discretisation", Degree=20, Cells=10000) +
             section("Receptance", Method="direct") + output(Directory="out", Receptance_frequencies="1"), code=0, leaves={"out"},
             check=estimate_bounds_peak(executable)),
        dict(name="memory_bad_alloc_in_run", scene=linear(200000) + spectrum_scene("out", 2),
             code=(2, 3, 5), preexec=limits(address_space=startup_address_space(executable) + (40 << 20))),
    ])
    return rows
