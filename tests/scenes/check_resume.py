#!/usr/bin/env python3
"""--resume goes on with an interrupted run's continuation and ends with the
output an uninterrupted run writes.

usage: check_resume.py NSM_BAR
For each continuation method, the small seed scene runs whole, then again
stopped by SIGINT in its continuation, then with --resume. The stop is put
at a place the run's own output sets, not a timer: the run's stderr is a
pipe with a few free pages, and SIGINT goes once the run waits to write a
progress line that finds no room. The resumed run's backbone.csv,
tongues.csv and continuation.log must equal the whole run's byte for byte
(a shorter, or any other, branch fails), and it must leave no checkpoint.
A run stopped in its verification in time (the continuation complete) is
resumed the same way, and keeps the points verified before the stop
(verification.resume) instead of integrating them again. A scene changed outside Output, a missing checkpoint
and a damaged one each exit 2 with one line naming --resume, and leave the
output as it was. Standard library only.
"""
import csv
import filecmp
import os
import re
import shutil
import signal
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from failures import report  # noqa: E402
from small_scene import small_seed_scene  # noqa: E402
from stop_signals import PAGE, signal_when_blocked  # noqa: E402

COMPARED = ("backbone.csv", "tongues.csv", "continuation.log")
CHECKPOINT = "continuation.resume"


def scene(method, verify, omega_max):
    text = small_seed_scene({"Directory": "whole", "Backbone": "true", "Plots": "false", "Progress every": 1e-9,
                             "Verify in time": verify, "Verify steps": 256}, omega_max=omega_max)
    return text.replace("  set Energy max = 1e-3\n", f"  set Energy max = 1e-3\n  set Method = {method}\n")


def lines(path):
    with open(path) as f:
        return f.read().splitlines()


def verified_rows(path):
    with open(path) as f:
        return sum(1 for row in csv.DictReader(f) if row.get("verified"))


def stop_and_resume(executable, name, text, room_pages, failures, stopped_in):
    """Whole run, stopped run, resumed run; the comparisons. Returns the
    stopped and whole backbones' lengths."""
    for d in ("whole", name):
        shutil.rmtree(d, ignore_errors=True)
    with open(f"{name}.prm", "w") as f:
        f.write(text)
    whole = subprocess.run([executable, f"{name}.prm"], capture_output=True, text=True, timeout=600)
    assert whole.returncode == 0, whole.stderr
    if callable(room_pages):
        room_pages = room_pages(whole.stderr)
    code, stdout, stderr = signal_when_blocked([executable, f"{name}.prm", "--output", name], signal.SIGINT,
                                               f"a progress line past {room_pages} pages", room_pages=room_pages)
    if code != 130 or not os.path.exists(f"{name}/{CHECKPOINT}"):
        failures.append(f"{name}: the stopped run exited {code} with no {CHECKPOINT}: {stderr[-300:]!r}")
        return 0, 0, 0
    stopped, expected = len(lines(f"{name}/backbone.csv")), len(lines("whole/backbone.csv"))
    verified_before = verified_rows(f"{name}/backbone.csv")
    if not stopped_in(stopped, expected):
        failures.append(f"{name}: stopped with {stopped} of {expected} backbone lines: not where the check "
                        f"meant to stop it")
    resumed = subprocess.run([executable, f"{name}.prm", "--output", name, "--resume"], capture_output=True,
                             text=True, timeout=600)
    if resumed.returncode != 0 or "resumed from continuation.resume" not in resumed.stdout:
        failures.append(f"{name}: --resume exited {resumed.returncode}: {resumed.stderr[-300:]!r}")
    for f in COMPARED:
        if not filecmp.cmp(f"whole/{f}", f"{name}/{f}", shallow=False):
            failures.append(f"{name}: the resumed {f} differs from the uninterrupted run's")
    for checkpoint in (CHECKPOINT, "verification.resume"):
        if os.path.exists(f"{name}/{checkpoint}"):
            failures.append(f"{name}: the resumed run, complete, still holds {checkpoint}")
    # The points the stopped run verified are taken, not integrated again.
    kept = re.search(r"resumed verification in time: (\d+) points", resumed.stdout)
    integrated = sum(1 for l in resumed.stderr.splitlines() if l.startswith("nsm-bar: verification in time: point"))
    if verified_before and integrated != verified_rows("whole/backbone.csv") - verified_before:
        failures.append(f"{name}: the resumed run integrated {integrated} points in time, not only the "
                        f"{verified_rows('whole/backbone.csv') - verified_before} the stopped run had not")
    if verified_before and (not kept or int(kept.group(1)) != verified_before):
        failures.append(f"{name}: the stopped run verified {verified_before} points; the resumed run kept "
                        f"{kept.group(1) if kept else 'none'}")
    return stopped, expected, verified_before


def verification_room(stderr):
    """Pages for every line of the continuation and of the error estimate
    (the stage between) and one more: the run then waits in its
    verification's lines (checked: they fill more than two pages)."""
    continuation = sum(len(l) + 1 for l in stderr.splitlines()
                       if l.startswith(("nsm-bar: continuation", "nsm-bar: error estimate")))
    verification = sum(len(l) + 1 for l in stderr.splitlines() if l.startswith("nsm-bar: verification"))
    assert verification > 2 * PAGE, f"the verification writes only {verification} bytes of progress"
    return continuation // PAGE + 2


def refusals(executable, failures):
    """Bad resumes: exit 2, one line naming --resume, the output untouched."""
    shutil.rmtree("refused", ignore_errors=True)
    with open("refused.prm", "w") as f:
        f.write(scene("sequential", "false", 2.2).replace("Directory = whole", "Directory = refused"))
    signal_when_blocked([executable, "refused.prm"], signal.SIGINT, "the first point", room_pages=2)
    path = f"refused/{CHECKPOINT}"
    with open(path) as f:
        checkpoint = f.read()
    before = {n: open(f"refused/{n}").read() for n in os.listdir("refused")}
    cases = [("a changed entry", ["--set", "Harmonic balance/Harmonics=10"], "Harmonic balance/Harmonics = 10"),
             ("no checkpoint", [], "does not exist"),
             ("a damaged checkpoint", [], "is not a checkpoint nsm-bar wrote")]
    for what, extra, expected in cases:
        if what == "no checkpoint":
            os.rename(path, "checkpoint.away")
        if what == "a damaged checkpoint":
            os.rename("checkpoint.away", path)
            with open(path, "w") as f:
                f.write(checkpoint[: len(checkpoint) * 2 // 3])
            before[CHECKPOINT] = open(path).read()
        r = subprocess.run([executable, "refused.prm", "--resume"] + extra, capture_output=True, text=True,
                           timeout=600)
        message = r.stderr.strip().splitlines()
        if r.returncode != 2 or len(message) != 1 or "--resume" not in message[0] or expected not in message[0]:
            failures.append(f"--resume with {what}: exit {r.returncode}, {r.stderr[-300:]!r}")
        after = {n: open(f"refused/{n}").read() for n in os.listdir("refused")}
        if what != "no checkpoint" and after != before:
            failures.append(f"--resume with {what} changed the output directory")
        if any(n.startswith(".") for n in os.listdir(".")):
            failures.append(f"--resume with {what} left a staging directory behind")
    # A stopped run's folder resumes in place: another --output would hold no
    # checkpoint, so it is refused, naming both.
    r = subprocess.run([executable, "refused", "--resume", "--output", "elsewhere"], capture_output=True, text=True,
                       timeout=600)
    message = r.stderr.strip().splitlines()
    if r.returncode != 2 or len(message) != 1 or "--output with --resume 'refused'" not in message[0] or \
            os.path.exists("elsewhere"):
        failures.append(f"DIR --resume --output: exit {r.returncode}, {r.stderr[-300:]!r}")


def main():
    executable = sys.argv[1]
    failures, said = [], []
    for method in ("sequential", "arclength"):
        stopped, whole, _ = stop_and_resume(executable, method, scene(method, "false", 2.2), 3, failures,
                                         lambda s, e: 2 <= s < e)
        said.append(f"{method}: stopped at {stopped - 1} of {whole - 1} points")
    _, _, verified = stop_and_resume(executable, "verification", scene("sequential", "true", 2.2),
                                     verification_room, failures, lambda s, e: s == e)
    if not verified:
        failures.append("verification: the run was not stopped after verifying a point")
    said.append(f"verification: stopped after {verified} points verified, kept on --resume")
    refusals(executable, failures)
    return report(failures, "; ".join(said) + "; resumed runs equal the whole runs")


if __name__ == "__main__":
    sys.exit(main())
