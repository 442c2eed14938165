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
    return report(failures, f"stopped after {len(stopped) - 1} of {len(expected) - 1} points")


if __name__ == "__main__":
    sys.exit(main())
