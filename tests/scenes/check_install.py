#!/usr/bin/env python3
"""An installed program plots with its own scripts; a program copied alone
says where it looked for them.

usage: check_install.py BUILD_DIR WORK_DIR
`cmake --install BUILD_DIR --prefix WORK_DIR/prefix` gives prefix/bin/nsm-bar
and prefix/share/nsm-bar/plot_results.py; the installed program, run where no
source tree is near, draws backbone.png, and its plots.log names the plot at
its final path. A copy of the program alone in a folder of its own writes
every other file and exits 5, naming where it looked for plot_results.py.
Standard library only.
"""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hostile_inputs import SMALL, section  # noqa: E402

SCENE = SMALL.replace("Harmonics = 20", "Harmonics = 10") + \
    section("Continuation", Omega_max=1.95, Energy_max=1e-3) + section("Output", Backbone="true", Plots="true")


def main():
    build, work = (os.path.abspath(a) for a in sys.argv[1:3])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    prefix = os.path.join(work, "prefix")
    subprocess.run(["cmake", "--install", build, "--prefix", prefix], check=True, capture_output=True)
    installed = os.path.join(prefix, "bin", "nsm-bar")
    assert os.path.isfile(os.path.join(prefix, "share", "nsm-bar", "plot_results.py")), os.listdir(prefix)
    with open(os.path.join(work, "scene.prm"), "w") as f:
        f.write(SCENE)
    run = subprocess.run([installed, "scene.prm", "--output", "installed"], cwd=work, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    out = os.path.join(work, "installed")
    assert os.path.isfile(os.path.join(out, "backbone.png")), os.listdir(out)
    with open(os.path.join(out, "plots.log")) as f:
        log = f.read()
    assert f"wrote {out}/backbone.png" in log, log
    alone = os.path.join(work, "alone")
    os.makedirs(alone)
    shutil.copy(installed, alone)
    run = subprocess.run([os.path.join(alone, "nsm-bar"), "scene.prm", "--output", "copied"], cwd=work,
                         capture_output=True, text=True)
    assert run.returncode == 5 and "plot_results.py is neither in" in run.stderr, (run.returncode, run.stderr)
    assert os.path.isfile(os.path.join(work, "copied", "backbone.csv")), "the other files were not written"
    print("installed: plots drawn, plots.log at final paths; copied alone: exit 5 naming where it looked")


if __name__ == "__main__":
    main()
