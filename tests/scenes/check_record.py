#!/usr/bin/env python3
"""Each output folder says how it was made (doc/output.md, "The run's record").

usage: check_record.py NSM_BAR
- A run with a --set writes parameters.prm and summary.txt. Its
  parameters.prm, run again into another folder, writes a backbone.csv equal
  to the run's byte for byte, while the scene without the --set writes
  another: the record carries the --set.
- summary.txt opens with the command line, the code's version, deal.II's and
  Trilinos's, the date and the machine, then holds the run summary as
  printed on standard output (with the continuation's events).
- Two scenes without Output/Directory, run from one folder, keep two
  folders, output/NAME each.
- A run stopped by SIGINT in its continuation resumes with
  `nsm-bar DIR --resume` alone, from its record, and ends whole.
- scripts/compare_backbones.py answers --help, takes folders, and draws the
  two runs in one PNG.
- Output/VTK time = t/T puts the VTK files' time in periods, as the plots.
"""
import filecmp
import os
import re
import shutil
import signal
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
from small_scene import small_seed_scene  # noqa: E402
from stop_signals import signal_when_blocked  # noqa: E402

COMPARE = os.path.join(HERE, "..", "..", "scripts", "compare_backbones.py")


def run(command, code=0):
    result = subprocess.run(command, capture_output=True, text=True, timeout=600)
    assert result.returncode == code, f"{command}: exit {result.returncode}, expected {code}\n{result.stderr}"
    return result


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def read(path):
    with open(path) as f:
        return f.read()


def record_reproduces(executable):
    write("scene.prm", small_seed_scene({"Directory": "recorded", "Backbone": "true"}, omega_max=1.93))
    first = run([executable, "scene.prm", "--set", "Harmonic balance/Harmonics=16"])
    assert "set Harmonics" in read("recorded/parameters.prm") and \
        re.search(r"set Harmonics\s*= 16\n", read("recorded/parameters.prm")), "the --set is not in the record"
    run([executable, "recorded/parameters.prm", "--output", "again"])
    assert filecmp.cmp("recorded/backbone.csv", "again/backbone.csv", shallow=False), \
        "the recorded parameters did not reproduce backbone.csv"
    run([executable, "scene.prm", "--output", "without_set"])
    assert not filecmp.cmp("recorded/backbone.csv", "without_set/backbone.csv", shallow=False), \
        "the --set changed nothing: the check above proves nothing"

    summary = read("recorded/summary.txt").splitlines()
    keys = [line.split(":")[0] for line in summary[:6]]
    assert keys == ["command", "version", "deal.II", "Trilinos", "date", "machine"], summary[:6]
    assert "--set 'Harmonic balance/Harmonics=16'" in summary[0], summary[0]
    assert summary[1] != "version: " and summary[2] == "deal.II: 9.4.1", summary[1:3]
    assert re.fullmatch(r"date: \d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", summary[4]), summary[4]
    printed = first.stdout.splitlines()
    # The record holds the summary as printed: every line of standard output
    # that is not the continuation-events count (the record lists the events).
    body = summary[6:]
    missing = [line for line in printed[1:] if line not in body and "continuation events" not in line]
    assert not missing, f"printed but not in summary.txt: {missing[:3]}"
    listed_files = [line.strip() for line in body]
    assert "recorded/summary.txt" in listed_files and "recorded/parameters.prm" in listed_files, body[-6:]
    listed = read("recorded/nsm-bar.manifest").split()
    assert "summary.txt" in listed and "parameters.prm" in listed, listed
    print("the record reproduces backbone.csv byte for byte; summary.txt holds the record and the summary")


def default_directories(executable):
    for name in ("bar_a", "bar_b"):
        write(f"{name}.prm", small_seed_scene({"Spectrum modes": 2}))
        run([executable, f"{name}.prm"])
    for name in ("bar_a", "bar_b"):
        assert os.path.isfile(f"output/{name}/spectrum.csv"), sorted(os.listdir("output"))
    print("two scenes without a Directory kept output/bar_a and output/bar_b")


def resume_from_record(executable):
    shutil.rmtree("stopped", ignore_errors=True)
    write("long.prm", small_seed_scene({"Directory": "stopped", "Backbone": "true", "Progress every": 1e-9},
                                       omega_max=2.0))
    code, _, stderr = signal_when_blocked([executable, "long.prm"], signal.SIGINT, "a progress line")
    assert code == 130 and os.path.exists("stopped/continuation.resume"), (code, stderr[-300:])
    resumed = run([executable, "stopped", "--resume", "--set", "Output/Progress every=1e6"])
    assert "resumed from continuation.resume" in resumed.stdout, resumed.stdout
    assert not os.path.exists("stopped/continuation.resume")
    assert "is a folder" in run([executable, "recorded"], code=2).stderr  # a folder alone is no scene
    print("nsm-bar DIR --resume went on from the record")


def compare_script():
    help_text = run([sys.executable, COMPARE, "--help"]).stdout
    assert "usage:" in help_text and "--plot" in help_text, help_text
    result = run([sys.executable, COMPARE, "recorded", "without_set", "--plot", "overlay.png"])
    assert re.search(r"\d+ of A's \d+ main points lie inside a main piece of B", result.stdout), result.stdout
    with open("overlay.png", "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", "overlay.png is no PNG"
    bad = subprocess.run([sys.executable, COMPARE, "recorded", "nowhere"], capture_output=True, text=True)
    assert bad.returncode != 0 and "nowhere" in bad.stderr and "Traceback" not in bad.stderr, bad.stderr
    print("compare_backbones.py: --help, folders, overlay.png")


def vtk_time_axis(executable):
    """Output/VTK time = t/T: the space-time mesh spans one unit of time and
    the snapshots' times are fractions of the period; with t, one period."""
    import vtk  # Debian's python3-vtk9
    from vtk.util.numpy_support import vtk_to_numpy
    spans = {}
    for axis in ("t", "t/T"):
        directory = "vtk_" + axis.replace("/", "_")
        write("vtk.prm", small_seed_scene({"Directory": directory, "Fields at": 1.925, "VTK": "true",
                                           "VTK time": axis}, omega_max=1.93))
        run([executable, "vtk.prm"])
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(f"{directory}/field_0.vtu")
        reader.Update()
        times = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())[:, 1]
        steps = [float(t) for t in re.findall(r'timestep="([^"]+)"', read(f"{directory}/field_0_snapshots.pvd"))]
        spans[axis] = (times.min(), times.max(), max(steps))
    period = 2 * 3.141592653589793 / 1.925
    low, high, last = spans["t"]
    assert low == 0 and abs(high - period) < 1e-5 * period and period * 0.9 < last < period, spans
    low, high, last = spans["t/T"]
    assert low == 0 and abs(high - 1) < 1e-6 and 0.9 < last < 1, spans
    print(f"VTK time axis: t spans {spans['t'][1]:.6g} (the period), t/T spans {spans['t/T'][1]:.6g}")


def main():
    executable = os.path.abspath(sys.argv[1])
    for directory in ("recorded", "again", "without_set", "output", "stopped"):
        shutil.rmtree(directory, ignore_errors=True)
    record_reproduces(executable)
    default_directories(executable)
    resume_from_record(executable)
    compare_script()
    vtk_time_axis(executable)


if __name__ == "__main__":
    main()
