#!/usr/bin/env python3
"""SIGINT stops a run at a point of the continuation, and the run writes
what it has.

usage: check_interrupt.py NSM_BAR
The run announces each continuation point on stderr (Progress every is
tiny). With stderr a full pipe it waits in its first announcement; SIGINT
sent then stops the continuation at that point, whatever the machine's
load (no timer races the run). The stopped run must exit 130, say so on
stderr, in the summary and in its manifest, and write a backbone.csv whose
rows are the first rows of an uninterrupted run's, byte for byte, and fewer
(but for the error estimate's last column, which the stopped run leaves out).
The stop points to --resume and leaves continuation.resume.
Then the same for the forced stage, in a run without the backbone: SIGINT at
its first progress line, after its first curve, leaves the second curve and
the curve in F out, and the first curve as an uninterrupted run writes it,
and says it leaves no resume file (no backbone to go on from); and SIGINT while it
verifies the first curve's points in time leaves both curves written and
the verification's rest and the curve in F out, both named.
Standard library only.
"""
import os
import shutil
import signal
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from failures import report  # noqa: E402
from small_scene import small_seed_scene  # noqa: E402
from stop_signals import signal_when_blocked  # noqa: E402

SCENE = small_seed_scene({"Directory": "whole", "Backbone": "true", "Plots": "false", "Progress every": 1e-9},
                         omega_max=2.2)


def main():
    executable = sys.argv[1]
    for d in ("whole", "stopped"):
        shutil.rmtree(d, ignore_errors=True)
    with open("scene.prm", "w") as f:
        f.write(SCENE)
    whole = subprocess.run([executable, "scene.prm"], capture_output=True, text=True, timeout=600)
    assert whole.returncode == 0, whole.stderr

    returncode, stdout, stderr = signal_when_blocked([executable, "scene.prm", "--output", "stopped"],
                                                     signal.SIGINT, "a point")

    failures = []
    if returncode != 128 + signal.SIGINT:
        failures.append(f"exit {returncode}, not 130: {stderr[-300:]}")
    if not stderr.strip().splitlines()[-1].startswith("nsm-bar: stopped by SIGINT"):
        failures.append(f"stderr does not end with the stop: {stderr[-300:]!r}")
    elif "--resume goes on from it" not in stderr.strip().splitlines()[-1] or \
            not os.path.exists("stopped/continuation.resume"):
        failures.append(f"the stop does not point to --resume, or left no continuation.resume: {stderr[-300:]!r}")
    if "interrupted by SIGINT" not in stdout:
        failures.append("the summary does not say the run was interrupted")
    with open("stopped/nsm-bar.manifest") as f:
        if "/ interrupted by SIGINT" not in f.read():
            failures.append("the manifest does not mark the run interrupted")
    # The error estimate, a stage after the continuation, is left out of the
    # stopped run: the whole run's rows without its column.
    if "left out: error estimate" not in stdout:
        failures.append("the summary does not say the error estimate was left out")
    with open("whole/backbone.csv") as f:
        expected = [line.rsplit(",", 1)[0] for line in f.read().splitlines()]
    if not expected[0].endswith(",leading_harmonic"):
        failures.append(f"the whole run's last column but one is not leading_harmonic: {expected[0]}")
    with open("stopped/backbone.csv") as f:
        stopped = f.read().splitlines()
    if not 2 <= len(stopped) < len(expected) or stopped != expected[:len(stopped)]:
        failures.append(f"stopped backbone ({len(stopped)} lines) is not a shorter prefix of the whole "
                        f"({len(expected)} lines)")
    for name in ("tongues.csv", "resonances.csv"):
        if not os.path.exists(f"stopped/{name}"):
            failures.append(f"{name} missing from the stopped run")
    failures += forced_stop(executable)
    failures += verification_stop(executable)
    return report(failures, f"stopped after {len(stopped) - 1} of {len(expected) - 1} points")


FORCED = SCENE.replace("subsection Output\n", "subsection Damping\n  set Modal ratio = 0.002\nend\n"
                       "subsection Forcing\n  set Amplitudes = 1e-5, 2e-5\n  set Omegas = 1.97\n"
                       "  set Amplitude max = 1e-4\nend\nsubsection Output\n") \
    .replace("set Backbone = true", "set Backbone = false").replace("set Directory = whole", "set Directory = forced-whole")


def whole_then_stopped(executable, name, text, what, room_pages=0):
    """Writes `text` to NAME.prm (its Directory NAME-whole), runs it whole,
    then again into NAME-stopped with SIGINT at its progress line `what`
    (signal_when_blocked's `room_pages`). Returns the whole run's failure
    ("" if it ran) and the stopped run's exit code, stdout and stderr."""
    for d in (f"{name}-whole", f"{name}-stopped"):
        shutil.rmtree(d, ignore_errors=True)
    with open(f"{name}.prm", "w") as f:
        f.write(text)
    whole = subprocess.run([executable, f"{name}.prm"], capture_output=True, text=True, timeout=600)
    if whole.returncode != 0:
        return f"the {name} run exited {whole.returncode}: {whole.stderr.strip()[-300:]}", (None, "", "")
    return "", signal_when_blocked([executable, f"{name}.prm", "--output", f"{name}-stopped"], signal.SIGINT, what,
                                   room_pages=room_pages)


def forced_stop(executable):
    """SIGINT while the forced stage announces its first curve (the first
    progress line of a run without the backbone): the run stops before the
    second, exits 130, says what it left out, and writes the first curve as
    an uninterrupted run does, byte for byte, and no curve in F."""
    failed, (returncode, stdout, stderr) = whole_then_stopped(executable, "forced", FORCED, "a forced curve")
    if failed:
        return [failed]
    failures = []
    if returncode != 128 + signal.SIGINT:
        failures.append(f"forced: exit {returncode}, not 130: {stderr[-300:]}")
    # Without a backbone there is no continuation to go on from: the stop
    # says so, and leaves no resume file.
    last = stderr.strip().splitlines()[-1] if stderr.strip() else ""
    if "no backbone was traced to go on from, so it leaves no continuation.resume" not in last or \
            "--resume" in last or os.path.exists("forced-stopped/continuation.resume"):
        failures.append(f"forced: the stop's line or resume file: {last!r}")
    if "left out: forced response's curves from F = 2e-05 on" not in stdout:
        failures.append(f"forced: the summary does not say the second curve was left out: {stdout[-500:]}")
    with open("forced-whole/frc.csv") as f:
        lines = f.read().splitlines()
    first = [line for line in lines[1:] if float(line.split(",")[0]) < 1.5e-5]
    with open("forced-stopped/frc.csv") as f:
        stopped = f.read().splitlines()
    if stopped != lines[:1] + first or not first:
        failures.append(f"forced: the stopped frc.csv ({len(stopped)} lines) is not the whole run's first curve "
                        f"({len(first)} points)")
    if not os.path.exists("forced-whole/force_response.csv") or os.path.exists("forced-stopped/force_response.csv"):
        failures.append("forced: force_response.csv written by the stopped run, or not by the whole one")
    return failures


VERIFIED = FORCED.replace("  set Omegas = 1.97\n", "  set Omegas = 1.97\n  set Verify every = 1\n  set Verify periods = 2\n") \
    .replace("set Directory = forced-whole", "set Directory = verified-whole\n  set Verify steps = 100")


def verification_stop(executable):
    """SIGINT while the forced stage verifies its first curve's points in
    time (each point's progress line; the stop waits in the first line that
    finds no room in one page of the pipe, some 50 lines in, after the two
    curves' lines and within the first curve's 150 points): the run exits
    130, says where the verification stopped, and writes both curves as an
    uninterrupted run does (the verified columns empty from the stop on). A
    verification that kept an entry only for the curves it reached left the
    table reading past them. The curves start at Omega min = 0 (the
    default): the static response there has no period, and is not
    integrated (its non-finite step made the whole run fail)."""
    failed, (returncode, stdout, stderr) = whole_then_stopped(executable, "verified", VERIFIED, "a verified point",
                                                              room_pages=1)
    if failed:
        return [failed]
    failures = []
    if returncode != 128 + signal.SIGINT:
        return [f"verification: exit {returncode}, not 130: {stderr[-300:]}"]
    if "left out: the forced response's verification in time from F = 1e-05, Omega = " not in stdout:
        failures.append(f"verification: the summary does not say where it stopped: {stdout[-500:]}")
    # The curve in F after it is left out too, and said so.
    if "; force response's curves from Omega = 1.97 on" not in stdout or \
            os.path.exists("verified-stopped/force_response.csv"):
        failures.append(f"verification: the curve in F after the stop is not named left out: {stdout[-500:]}")
    with open("verified-whole/frc.csv") as f:
        whole_lines = f.read().splitlines()
    whole_rows = [line.split(",")[:12] for line in whole_lines]
    with open("verified-stopped/frc.csv") as f:
        stopped_lines = f.read().splitlines()
    stopped_rows = [line.split(",")[:12] for line in stopped_lines]
    if stopped_rows != whole_rows:
        failures.append(f"verification: the stopped frc.csv's curves ({len(stopped_rows)} lines) are not the whole "
                        f"run's ({len(whole_rows)})")
    unverified = sum(line.split(",")[12] == "" for line in stopped_lines[1:])
    if whole_lines[1].split(",")[2] != "0" or whole_lines[1].split(",")[12] != "":
        failures.append(f"verification: the whole run's first point is not the static one, unverified: {whole_lines[1]}")
    if not 0 < unverified < len(stopped_lines) - 1:
        failures.append(f"verification: {unverified} of {len(stopped_lines) - 1} points without a verification")
    return failures


if __name__ == "__main__":
    sys.exit(main())
