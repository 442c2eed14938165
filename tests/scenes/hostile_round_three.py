#!/usr/bin/env python3
"""The third table of hostile cases, one class of defect per block: a user's
file in an output subfolder, signals while the plots are drawn, --resume on a
changed model or a damaged checkpoint, subnormal numbers, text that is not
UTF-8 or holds control characters, plots that fail for their environment,
names no file system takes, a live run's staging folder seen from another
PID namespace, mpirun on a scene, and the fallback swap's aside folder.
(A file created during the directory swap: the unit test
UsersFilesAreNeverRemoved.AFileCreatedDuringTheSwapSurvives.)

usage: hostile_round_three.py NSM_BAR [NAME_REGEX ...]
Rows run as hostile_inputs.py's do (its run_row: exit code, one line on
stderr naming the parameter, nothing left behind but `leaves`), with these
keys besides:
  args       arguments after the scene file
  launcher   a command put before the program (mpirun)
  interrupt  (signal, when): run by this file's own runner, which sends
             `signal` to the run's whole process group when `when` says:
             "plots" (the plotting script is running), or "point_then_plots"
             (SIGINT at the continuation's first progress line, then
             `signal` while the plots are drawn)
It prints the number of cases per class at the end.
"""
import collections
import fcntl
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from hostile_inputs import SMALL, listing, output, row_directory, run_row, section  # noqa: E402
from hostile_round_two import SANITIZED, limits, prepare_run, read, write  # noqa: E402
from stop_signals import blocked_writing_stderr, full_pipe  # noqa: E402
import setup_runs  # noqa: E402

BACKBONE = SMALL + section("Continuation", Omega_min=1.5, Omega_max=1.93, Energy_max=1e-3)
PLOTTED = BACKBONE + output(Directory="out", Backbone="true", Plots="true")
VTK = BACKBONE + output(Directory="out", Backbone="true", Fields_at=1.925, VTK="true")
# A continuation that announces every point (Progress every tiny): a full
# stderr pipe stops it at its first (tests/common/stop_signals.py).
ANNOUNCED = SMALL + section("Continuation", Omega_max=2.0, Energy_max=1e-3) + \
    output(Directory="out", Backbone="true", Plots="true", Progress_every=1e-9)
ADAPTIVE = section("Discretisation", Degree=4, Cells=8, Refinement="adaptive") + \
    "subsection Discretisation\n subsection Adaptive\n  set Steps = 6\n  set Tolerance = 1e-8\n end\nend\n" + \
    section("Receptance", Method="modal") + section("Harmonic balance", Harmonics=20) + \
    section("Continuation", Omega_max=2.0, Energy_max=1e-3) + \
    output(Directory="out", Backbone="true", Progress_every=1e-9)
STUDY_PLOTTED = SMALL + section("Study", Degrees="9, 10", Spectrum_modes=2) + \
    output(Directory="out", Plots="true")
CHECKPOINT = "out/continuation.resume"


def fnv1a(data):
    """The checksum the program writes (base/checkpoint_reader.cc)."""
    value = 14695981039346656037
    for byte in data:
        value = ((value ^ byte) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return value


def staging_prefix(name):
    """The program's prefix of the staging siblings of directory `name`."""
    return ".nsm-bar-%016x-" % fnv1a(name.encode())


def complete(directory):
    """A whole output: exactly the files its manifest lists (its notes, lines
    that start with "/ ", aside; a snapshot folder, "FOLDER/ (N snapshots)",
    with its N files)."""
    lines = read(os.path.join(directory, "nsm-bar.manifest")).splitlines()
    expected = {"nsm-bar.manifest"}
    for line in lines:
        if line.startswith("/ "):
            continue
        match = re.fullmatch(r"(.*)/ \((\d+) snapshots\)", line)
        if match:
            expected |= {match[1]} | {f"{match[1]}/snapshot_{j:04d}.vtu" for j in range(int(match[2]))}
        else:
            expected.add(line)
    return listing(directory) == expected


# ---- runs the setups need ----------------------------------------------------

def plot_children(pid):
    """The plotting scripts `pid` started that still run (from /proc)."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                state, parent = f.read().rsplit(")", 1)[1].split()[:2]
                parent = int(parent)
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                command = f.read()
        except (OSError, IndexError, ValueError):
            continue
        if parent == pid and b"plot_results.py" in command and state != "Z":
            found.append(int(entry))
    return found


def wait_for(condition, what, process, limit=300):
    deadline = time.time() + limit
    while not condition():
        assert process.poll() is None, f"the run ended before {what}"
        assert time.time() < deadline, f"never {what}"
        time.sleep(0.005)


def stopped_run(executable, scene=ANNOUNCED, name="first.prm", room_pages=0):
    """A run of `scene` into out stopped by SIGINT at its first progress line
    that finds no room in `room_pages` pages: out holds continuation.resume
    (made once per table for these arguments and a directory state:
    setup_runs.py)."""
    write(name, scene)
    setup_runs.once(("stopped", executable, name, room_pages), lambda: stop_at_a_progress_line(
        executable, name, room_pages))


def stop_at_a_progress_line(executable, name, room_pages):
    read_end, write_end = full_pipe(room_pages)
    process = subprocess.Popen([executable, name], stdout=subprocess.DEVNULL, stderr=write_end)
    os.close(write_end)
    wait_for(lambda: blocked_writing_stderr(process.pid), "a progress line", process)
    process.send_signal(signal.SIGINT)
    with os.fdopen(read_end, "rb") as pipe:
        pipe.read()
    assert process.wait() == 130 and os.path.exists(CHECKPOINT), "the setup's run did not stop with a checkpoint"


def interrupted(row, executable):
    """This file's runner for `interrupt` rows; raises AssertionError."""
    sig, when = row["interrupt"]
    command = [executable, row["scene_file"], *row.get("args", [])]
    reasons = []
    if when == "plots":
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                   start_new_session=True)
        drained = None
    else:  # point_then_plots
        read_end, write_end = full_pipe()
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=write_end, start_new_session=True)
        os.close(write_end)
        wait_for(lambda: blocked_writing_stderr(process.pid), "a progress line", process)
        os.killpg(process.pid, signal.SIGINT)
        drained = []
        reader = threading.Thread(target=lambda: drained.append(os.fdopen(read_end, "rb").read()))
        reader.start()
    wait_for(lambda: plot_children(process.pid), "the plotting script started", process)
    os.killpg(process.pid, sig)
    if drained is None:
        _, stderr = process.communicate(timeout=300)
        stderr = stderr.decode(errors="replace")
    else:
        process.wait(timeout=300)
        reader.join()
        stderr = drained[0].decode(errors="replace").lstrip("x")
    if process.returncode not in row["code"]:
        reasons.append(f"exit {process.returncode}, expected {row['code']}: {stderr[-300:]}")
    for f in row.get("kept", []):
        if not os.path.isfile(f):
            reasons.append(f"{f} not kept: {sorted(listing('.'))[:20]}")
    if row.get("whole", True):
        if not complete("out"):
            reasons.append("out is not a whole output (its manifest and its files differ)")
        elif process.returncode != 0 and "/ interrupted by" not in read("out/nsm-bar.manifest"):
            reasons.append("the manifest does not say the run was interrupted")
    left = [p for p in listing(".") if ".nsm-bar-" in p or p.endswith(".partial")]
    if left:
        reasons.append(f"left behind: {left[:4]}")
    if plot_children(process.pid):
        reasons.append("the plotting script outlived the run")
    assert not reasons, f"{row['name']}: " + "; ".join(reasons)


# ---- setups and checks ---------------------------------------------------------

def vtk_output_with(path, directory=False):
    """An earlier VTK run into out, then the user's `path` inside it."""
    def setup(row):
        write("first.prm", VTK)
        prepare_run(row["executable"], "first.prm")
        if directory:
            os.makedirs(path)
        else:
            write(path, "mine\n")
        row["users"] = path
    return setup


def users_file_intact(row):
    path = row["users"]
    assert os.path.isdir(path) if path.endswith("/") else read(path) == "mine\n", f"{path} was changed or removed"


def checkpoint_edit(edit, checksum, room_pages=0):
    """A stopped run's checkpoint changed by edit(text) -> text, its checksum
    written anew (`checksum`) or left as it was (the file then lies)."""
    def setup(row):
        stopped_run(row["executable"], room_pages=room_pages)
        text = read(CHECKPOINT)
        at = text.rfind("checksum ")
        body, line = (text[:at], text[at:]) if at >= 0 else (text, "")
        changed = edit(body)
        assert changed != body, "the edit changed nothing"
        write(CHECKPOINT, changed + ("checksum %016x\n" % fnv1a(changed.encode()) if checksum else line))
        write("scene.prm", ANNOUNCED)
    return setup


def changed_digit(body):
    """One hexadecimal digit of the first stored point's first unknown changed."""
    start = body.index("\npoint ")
    at = body.index("0x1.", body.index(" 0x", body.index(" 0x", start) + 1) + 1) + 4
    return body[:at] + ("2" if body[at] == "1" else "1") + body[at + 1:]


def point_lines(body):
    lines = body.split("\n")
    return lines, [i for i, line in enumerate(lines) if line.startswith("point ")]


def duplicated_point(body):
    lines, points = point_lines(body)
    lines.insert(points[-1], lines[points[-1]])
    head = lines.index(next(l for l in lines if l.startswith("points ")))
    lines[head] = f"points {len(points) + 1}"
    return "\n".join(lines)


def swapped_points(body):
    lines, points = point_lines(body)
    assert len(points) >= 2
    lines[points[0]], lines[points[1]] = lines[points[1]], lines[points[0]]
    return "\n".join(lines)


def crafted_residual(body):
    lines, points = point_lines(body)
    words = lines[points[-1]].split(" ")
    words[3] = "0x0p+0"
    lines[points[-1]] = " ".join(words)
    return "\n".join(lines)


def flipped_state(body):
    lines = body.split("\n")
    i = next(i for i, line in enumerate(lines) if line.startswith("state "))
    words = lines[i].split(" ")
    words[5] = "1" if words[5] == "0" else "0"
    lines[i] = " ".join(words)
    return "\n".join(lines)


def planted_verification(row):
    """A stopped run without verification points, then a verification.resume
    planted beside its checkpoint, whole (its checksum right) and listed in
    the manifest."""
    scene = ANNOUNCED + output(Verify_in_time="true", Verify_every=50)
    stopped_run(row["executable"], scene)
    body = "nsm-bar verification checkpoint 1\nsettings 2000 2\nend\n"
    write("out/verification.resume", body + "checksum %016x\n" % fnv1a(body.encode()))
    with open("out/nsm-bar.manifest", "a") as f:  # listed, as the run's own would be
        f.write("verification.resume\n")
    write("scene.prm", scene)


def users_lookalike_folder(row):
    name = staging_prefix("out") + "mine"
    os.makedirs(name)
    write(os.path.join(name, "notes.txt"), "mine\n")
    row["users"] = os.path.join(name, "notes.txt")


def manifest_pointing_outside(row):
    write("first.prm", VTK)
    prepare_run(row["executable"], "first.prm")
    os.makedirs("victim")
    for name in ("snapshot_0000.vtu", "snapshot_0001.vtu"):
        write(os.path.join("victim", name), "mine\n")
    with open("out/nsm-bar.manifest", "a") as f:
        f.write("../victim/ (2 snapshots)\n")
    row["users"] = "victim/snapshot_0001.vtu"


def fake_matplotlib_exiting(_):
    os.makedirs("fake/matplotlib")
    write("fake/matplotlib/__init__.py", "import os\nos._exit(0)\n")


def checkpoint_kept(_):
    assert os.path.exists(CHECKPOINT), "the refused resume removed the checkpoint"


def stopped_then(scene):
    def setup(row):
        stopped_run(row["executable"], scene)
        write("scene.prm", scene)
    return setup


def resumed_whole(_):
    assert not os.path.exists(CHECKPOINT) and complete("out"), "the resumed run did not end whole"


def study_done(row):
    write("first.prm", STUDY_PLOTTED)
    prepare_run(row["executable"], "first.prm")
    row["png"] = open("out/study.png", "rb").read()


def study_png_whole(row):
    png = open("out/study.png", "rb").read()
    assert png == row["png"], "study.png was changed by a redraw that failed"
    assert os.path.isfile("out/study.csv")


def fake_matplotlib(_):
    os.makedirs("fake/matplotlib")
    write("fake/matplotlib/__init__.py", "raise ImportError('no matplotlib here')\n")


def backbone_kept(row):
    assert os.path.isfile("out/backbone.csv") and complete("out"), \
        f"the computed files were not kept: {sorted(listing('.'))[:10]}"
    notes = [l for l in read("out/nsm-bar.manifest").splitlines() if l.startswith("/ plots not drawn")]
    assert notes, "the manifest does not say the plots were not drawn"


def locked_sibling(live):
    """A staging sibling of out that another run holds (live: this test's
    process keeps it locked, as a run in another PID namespace would) or
    none does (a dead run's, with a process number that is alive here)."""
    def setup(row):
        # A live one under a process number that does not exist here (its
        # run's PID namespace is another); a dead one under one that does.
        name = staging_prefix("out") + ("4000000" if live else "run-1-0123456789abcdef")
        os.makedirs(name)
        write(os.path.join(name, "backbone.csv.partial"), "half\n")
        if live:
            row["lock"] = os.open(name, os.O_RDONLY)
            fcntl.flock(row["lock"], fcntl.LOCK_EX)
        row["sibling"] = name
    return setup


def sibling_state(kept):
    def check(row):
        exists = os.path.isdir(row["sibling"])
        if "lock" in row:
            os.close(row["lock"])
            shutil.rmtree(row["sibling"], ignore_errors=True)
        assert exists == kept, f"{row['sibling']} {'removed' if kept else 'left'}"
    return check


def aside_output(target_exists):
    """An earlier output, with a file of the user's in it, left aside by a
    run killed in its fallback swap; a newer output in its place, or none."""
    def setup(row):
        write("first.prm", SMALL + output(Directory="out", Spectrum_modes=2))
        prepare_run(row["executable"], "first.prm")
        aside = staging_prefix("out") + "aside-1-0123456789abcdef"
        (shutil.copytree if target_exists else os.rename)("out", aside)
        write(os.path.join(aside, "notes.txt"), "mine\n")
        row["aside"] = aside
    return setup


def aside_resolved(row):
    assert not os.path.exists(row["aside"]), "the aside folder is still there"
    assert read("out/notes.txt") == "mine\n", "the user's file in the earlier output was lost"


def no_control_characters(row):
    assert not re.search(r"[\x00-\x08\x0b-\x1f\x7f]", row["stderr"].rstrip("\n")), repr(row["stderr"])


def launched(row, executable):
    """A row under an MPI launcher: the launcher adds lines of its own on
    stderr; the program's (lines that start with "nsm-bar:") must be one."""
    run = subprocess.run([*row["launcher"], executable, row["scene_file"]], capture_output=True, text=True,
                         timeout=row.get("timeout", 120), errors="replace")
    own = [line for line in run.stderr.splitlines() if line.startswith("nsm-bar:")]
    reasons = []
    if run.returncode not in row["code"]:
        reasons.append(f"exit {run.returncode}, expected {row['code']}: {run.stderr[-300:]}")
    if len(own) != 1 or any(w not in own[0] for w in row["words"]):
        reasons.append(f"not one line naming {row['words']}: {own}")
    if [p for p in listing(".") if p != row["scene_file"]]:
        reasons.append(f"files left: {sorted(listing('.'))[:5]}")
    assert not reasons, f"{row['name']}: " + "; ".join(reasons)


# ---- the rows ----------------------------------------------------------------

def new_rows(executable):
    mpirun = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2"]
    latin1 = "out\xe9".encode("latin-1").decode("utf-8", "surrogateescape")
    return [
        # ---- 1. a user's file in an output subfolder --------------------------
        # old: the next run deleted each (the folder's files were checked by type).
        *[dict(name=f"users_file_in_snapshots_{tag}", cls=1, scene=VTK, code=2,
               words=["Output/Directory", shown], leaves={"out"},
               setup=vtk_output_with(path, directory=path.endswith("/")), check=users_file_intact)
          for tag, path, shown in [("notes", "out/field_0_snapshots/notes.txt", "notes.txt"),
                                   ("beyond_count", "out/field_0_snapshots/snapshot_9999.vtu", "snapshot_9999"),
                                   ("hidden", "out/field_0_snapshots/.notes", ".notes"),
                                   ("folder", "out/field_0_snapshots/mine/", "mine")]],
        # An edited manifest pointing outside the directory; a folder of the
        # user's named like a staging one. old: both deleted.
        dict(name="manifest_line_outside_the_directory", cls=1, scene=VTK, code=(0, 2), leaves={"out", "victim"},
             setup=manifest_pointing_outside, check=users_file_intact),
        dict(name="users_folder_named_like_a_staging_one", cls=1, scene=PLOTTED, code=0, leaves={"out"},
             setup=users_lookalike_folder, check=users_file_intact),
        # ---- 3. signals while the plots are drawn ---------------------------
        # old: exit 3 "the plotting script failed: KeyboardInterrupt", nothing kept.
        *[dict(name=f"{sig.name.lower()}_during_plots", cls=3, scene=PLOTTED, interrupt=(sig, "plots"),
               code=(128 + sig.value, 0), kept=["out/backbone.csv"]) for sig in
          (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)],
        # old: the second Ctrl-C threw the output and continuation.resume away.
        dict(name="second_sigint_during_plots", cls=3, scene=ANNOUNCED, interrupt=(signal.SIGINT, "point_then_plots"),
             code=(130,), kept=["out/backbone.csv", CHECKPOINT]),
        # old: exit 3, the study's plots lost with it.
        dict(name="sigint_during_study_plots", cls=3, scene=STUDY_PLOTTED, interrupt=(signal.SIGINT, "plots"),
             code=(130, 0), kept=["out/study.csv"], whole=False),
        # ---- 4. --resume on another model -----------------------------------
        # old: exit 0 with points of two meshes (adaptive), or rows that differ
        # in their last digits (not adaptive).
        dict(name="resume_receptance_band_changed", cls=4, scene=None, setup=stopped_then(ANNOUNCED),
             args=["--resume", "--set", "Output/Receptance frequencies=300"], code=2,
             words=["--resume", "receptance band", "Output/Receptance frequencies"], leaves={"out"},
             check=checkpoint_kept),
        dict(name="resume_adaptive_band_changed", cls=4, scene=None, setup=stopped_then(ADAPTIVE),
             args=["--resume", "--set", "Output/Receptance frequencies=300", "--set", "Output/Progress every=1e6"],
             code=2, words=["--resume", "band"], leaves={"out"}, check=checkpoint_kept),
        # Both sides of the check: the same scene resumes.
        dict(name="resume_adaptive_same_model", cls=4, scene=None, setup=stopped_then(ADAPTIVE),
             args=["--resume", "--set", "Output/Progress every=1e6"], code=0, leaves={"out"}, check=resumed_whole),
        # ---- 5. damaged or crafted checkpoints ------------------------------
        # old: each was read and resumed from, exit 0.
        dict(name="checkpoint_one_digit", cls=5, scene=None, setup=checkpoint_edit(changed_digit, False),
             args=["--resume"], code=2, words=["--resume", "checksum"], leaves={"out"}, check=checkpoint_kept),
        dict(name="checkpoint_one_digit_checksum_redone", cls=5, scene=None,
             setup=checkpoint_edit(changed_digit, True), args=["--resume"], code=2,
             words=["--resume", "model"], leaves={"out"}, check=checkpoint_kept),
        dict(name="checkpoint_state_flipped", cls=5, scene=None, setup=checkpoint_edit(flipped_state, False),
             args=["--resume"], code=2, words=["--resume"], leaves={"out"}, check=checkpoint_kept),
        dict(name="checkpoint_state_flipped_checksum_redone", cls=5, scene=None,
             setup=checkpoint_edit(flipped_state, True), args=["--resume"], code=2, words=["--resume"],
             leaves={"out"}, check=checkpoint_kept),
        dict(name="checkpoint_residual_crafted", cls=5, scene=None, setup=checkpoint_edit(crafted_residual, True),
             args=["--resume"], code=2, words=["--resume"], leaves={"out"}, check=checkpoint_kept),
        dict(name="checkpoint_point_duplicated", cls=5, scene=None, setup=checkpoint_edit(duplicated_point, True),
             args=["--resume"], code=2, words=["--resume"], leaves={"out"}, check=checkpoint_kept),
        dict(name="checkpoint_points_swapped", cls=5, scene=None, setup=checkpoint_edit(swapped_points, True, room_pages=1),
             args=["--resume"], code=2, words=["--resume"], leaves={"out"}, check=checkpoint_kept),
        # A verification.resume the interrupted run did not write. old: its
        # points were taken as verified.
        dict(name="checkpoint_planted_verification", cls=5, scene=None, setup=planted_verification,
             args=["--resume", "--set", "Output/Progress every=1e6"], code=2, words=["--resume", "verification.resume"],
             leaves={"out"}, check=checkpoint_kept),
        dict(name="checkpoint_cut_short", cls=5, scene=None,
             setup=checkpoint_edit(lambda b: b[:len(b) // 2] + "\n", False), args=["--resume"], code=2,
             words=["--resume"], leaves={"out"}, check=checkpoint_kept),
        # ---- 6. subnormal numbers -------------------------------------------
        # old: exit 4 and a 20-line deal.II trace.
        *[dict(name=f"subnormal_{entry.split('/')[1].replace(' ', '_').lower()}", cls=6, scene=PLOTTED,
               args=["--set", f"{entry}={value}"], code=2, words=[entry, "subnormal"], before_work=True)
          for entry, value in [("Continuation/Energy max", "1e-310"), ("Output/Progress every", "4.9e-324"),
                               ("Continuation/Fill gaps wider than", "2e-308"),
                               ("Continuation/Energy max", "-1e-320")]],
        # Lists too. old: accepted (the subnormal written into receptance.csv).
        *[dict(name=f"subnormal_in_{tag}", cls=6, scene=scene, args=["--set", f"{entry}={value}"], code=2,
               words=[entry, "subnormal"], before_work=True)
          for tag, scene, entry, value in [
              ("receptance_list", PLOTTED, "Output/Receptance frequencies", "0.5, 1e-310"),
              ("underflow_in_list", PLOTTED, "Output/Receptance frequencies", "1e-400"),
              ("study_list", SMALL + section("Study", Spectrum_modes=2) + output(Directory="out"),
               "Study/Receptance frequencies", "1e-310"),
              ("cross_section", PLOTTED, "Bar/Cross section", "1.5 - x + 1e-310 * x"),
              ("cross_section_underflow", PLOTTED, "Bar/Cross section", "1.5 - 1e-400 * x")]],
        # ---- 7. text that is not UTF-8 --------------------------------------
        # old: exit 4 "<unspecified file>(354): invalid code sequence".
        dict(name="not_utf8_output_option", cls=7, scene=PLOTTED, args=["--output", latin1], code=2,
             words=["Output/Directory", "UTF-8", "\\xe9"], before_work=True),
        dict(name="not_utf8_directory_in_scene", cls=7, scene=BACKBONE + output(Directory=latin1, Backbone="true"),
             code=2, words=["Output/Directory", "UTF-8"], before_work=True),
        dict(name="not_utf8_cross_section", cls=7, scene=PLOTTED,
             args=["--set", "Bar/Cross section=1.5 - x" + "\udcff"], code=2, words=["Bar/Cross section", "UTF-8"],
             before_work=True),
        dict(name="not_utf8_study_list", cls=7, scene=SMALL + section("Study", Spectrum_modes=2,
                                                                       Receptance_methods="modal, \udce9") +
             output(Directory="out"), code=2, words=["Study/Receptance methods", "UTF-8"], before_work=True),
        # ---- 8. control characters in a value -------------------------------
        # old: accepted, and its own checkpoint then refused --resume.
        dict(name="newline_in_cross_section", cls=8, scene=PLOTTED, args=["--set", "Bar/Cross section=1.5 - x\n+0"],
             code=2, words=["Bar/Cross section", "control character"], before_work=True),
        dict(name="escape_in_cross_section", cls=8, scene=PLOTTED, args=["--set", "Bar/Cross section=1.5\x1b- x"],
             code=2, words=["Bar/Cross section", "control character"], before_work=True),
        # C1 controls (CSI, NEL) in UTF-8. old: accepted, and printed raw.
        dict(name="c1_control_in_cross_section", cls=8, scene=PLOTTED, args=["--set", "Bar/Cross section=1.5\x9b- x"],
             code=2, words=["Bar/Cross section", "control character", "\\xc2\\x9b"], before_work=True,
             check=no_control_characters),
        dict(name="c1_control_in_directory", cls=8, scene=PLOTTED, args=["--output", "out\x85x"], code=2,
             words=["Output/Directory", "control character"], before_work=True, check=no_control_characters),
        # ---- 9. a redrawn study.png is whole or untouched -------------------
        # old: rewritten in place, a kill or a full disk left it truncated.
        dict(name="study_png_redraw_fails", cls=9, scene=STUDY_PLOTTED, setup=study_done,
             preexec=limits(fsize=20000), code=5, words=["output error", "plots"], leaves={"out"},
             check=study_png_whole),
        # ---- 10. the plotting environment fails ------------------------------
        # old: exit 3 "numerical failure", every computed file discarded.
        dict(name="plots_without_matplotlib", cls=10, scene=PLOTTED, setup=fake_matplotlib,
             env={"PYTHONPATH": os.path.abspath("hostile/plots_without_matplotlib/fake")}, code=5,
             words=["output error", "plots"], leaves={"out", "fake"}, check=backbone_kept),
        dict(name="plots_warnings_are_errors", cls=10, scene=PLOTTED, env={"PYTHONWARNINGS": "error",
                                                                          "MPLBACKEND": "no_such_backend"},
             code=5, words=["output error", "plots"], leaves={"out"}, check=backbone_kept),
        *([] if SANITIZED else [
            dict(name="plots_file_limit", cls=10, scene=PLOTTED, preexec=limits(nofile=6), code=5,
                 words=["output error", "plots"], leaves={"out"}, check=backbone_kept)]),
        # A script that ends with status 0 before drawing. old: exit 0, no plots, no word.
        dict(name="plots_script_exits_early", cls=10, scene=PLOTTED, setup=fake_matplotlib_exiting,
             env={"PYTHONPATH": os.path.abspath("hostile/plots_script_exits_early/fake")}, code=5,
             words=["output error", "plots"], leaves={"out", "fake"}, check=backbone_kept),
        # Four open files: the run cannot write, and leaves no staging folder.
        # old: .nsm-bar-HASH-PID left behind at every run.
        # Not under the sanitizers, whose runtime needs more files before main.
        *([] if SANITIZED else [
            dict(name="nofile_4_leaves_no_staging", cls=10, scene=BACKBONE + output(Directory="out", Backbone="true"),
                 preexec=limits(nofile=4), code=5, words=["output error"])]),
        # ---- 11. names no file system takes, folders a failed run made -------
        # old: refused after all the work (exit 5).
        dict(name="directory_name_256_bytes", cls=11, scene=PLOTTED, args=["--output", "new/" + "a" * 256],
             code=2, words=["Output/Directory", "256 bytes"], before_work=True),
        # A study's directory too: the refusal leaves no folder it made (new/).
        dict(name="study_directory_name_256_bytes", cls=11, scene=STUDY_PLOTTED,
             args=["--output", "new/" + "a" * 256], code=2, words=["Output/Directory", "cannot be created"]),
        # A long path ending in a short name. old: exit 5 after the work
        # (the staging name is longer than the last component).
        dict(name="directory_path_4000_bytes", cls=11, scene=PLOTTED,
             args=["--output", "/".join(["d" * 200] * 19) + "/o"], code=2, words=["Output/Directory", "bytes long"],
             before_work=True),
        # old: new/deeper was left behind by the failed run.
        dict(name="failed_run_removes_its_folders", cls=11,
             scene=SMALL + section("Contact", Alpha="1e12") + output(Directory="new/deeper/out", Backbone="true"),
             code=3, words=["no converged"]),
        # ---- 12. a live run's staging folder, seen from another PID namespace --
        # old: a run whose process number did not exist here was taken for dead.
        dict(name="live_staging_of_another_namespace", cls=12, scene=PLOTTED, setup=locked_sibling(True), code=0,
             leaves={"out"}, check=sibling_state(kept=True)),
        dict(name="dead_staging_with_a_live_number", cls=12, scene=PLOTTED, setup=locked_sibling(False), code=0,
             leaves={"out"}, check=sibling_state(kept=False)),
        # ---- 13. mpirun on a scene --------------------------------------------
        # old: the scene ran once per rank into one folder; bad input was said per rank.
        dict(name="mpirun_scene", cls=13, scene=PLOTTED, launcher=mpirun, code=(2,),
             words=["mpirun", "one process"]),
        dict(name="mpirun_bad_input", cls=13, scene=STUDY_PLOTTED + section("Harmonic balance", Harmonics=-1),
             launcher=mpirun, code=(2,), words=["Harmonic balance/Harmonics"]),
        # ---- 14. control characters from an unparsable line -------------------
        # old: copied raw into the message.
        dict(name="control_characters_in_a_bad_line", cls=14,
             scene="subsection Bar\n  \x1b[2J\x1b[31mset garbage\x07 = 1\nend\n" + PLOTTED, code=2,
             words=["scene"], check=no_control_characters),
        dict(name="control_characters_in_a_set_path", cls=14, scene=PLOTTED, args=["--set", "Bar/\x1b[2JX=1"],
             code=2, words=["--set"], check=no_control_characters),
        # ---- 15. the fallback swap's aside folder ------------------------------
        # old: a kill between the fallback's renames left no output and the
        # previous one hidden in .nsm-bar-aside-PID for good.
        dict(name="aside_output_put_back", cls=15, scene=SMALL + output(Directory="out", Spectrum_modes=2),
             setup=aside_output(False), code=2, words=["Output/Directory", "notes.txt"], leaves={"out"},
             check=aside_resolved),
        dict(name="aside_output_beside_a_new_one", cls=15, scene=SMALL + output(Directory="out", Spectrum_modes=2),
             setup=aside_output(True), code=2, words=["Output/Directory", "notes.txt"], leaves={"out"},
             check=aside_resolved),
    ]


def run_table(rows, patterns, run_one):
    """Runs each row whose name matches one of `patterns` (all without) by
    `run_one(row)`; prints a line per row and the cases per class, and exits
    nonzero if any row failed."""
    failures, counts = [], collections.Counter()
    for row in rows:
        if patterns and not any(re.search(p, row["name"]) for p in patterns):
            continue
        start = time.time()
        try:
            run_one(row)
            counts[row["cls"]] += 1
            print(f"ok   {row['name']} ({time.time() - start:.1f} s)")
        except Exception as e:  # an assertion, or a row whose setup broke
            failures.append(str(e))
            print(f"FAIL {row['name']}: {e}")
    print("cases per class: " + ", ".join(f"{c}: {n}" for c, n in sorted(counts.items())))
    if failures:
        sys.exit(f"{len(failures)} hostile inputs mishandled")
    print("all hostile inputs handled")


def main():
    executable = os.path.abspath(sys.argv[1])

    def run_one(row):
        row["executable"] = executable
        if "interrupt" in row or "launcher" in row:
            with row_directory(row):
                (interrupted if "interrupt" in row else launched)(row, executable)
        else:
            run_row(executable, row)
    run_table(new_rows(executable), sys.argv[2:], run_one)


if __name__ == "__main__":
    main()
