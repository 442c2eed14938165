#!/usr/bin/env python3
"""The command line: --set and --output against an edited file, bad overrides,
no scene.

usage: check_command_line.py NSM_BAR
Runs in the current directory (a fresh one per CTest run). Checks that
`--set "Section/Entry=value" --output DIR` writes byte-identical CSVs to the
same scene with the value edited into the file; that the summary's first
line names the overrides; that a bad, unknown or malformed override and an
unknown option exit 2 with one line naming it and leave no directory; and
that no scene prints the usage and exits 2. Standard library only.
"""
import csv
import filecmp
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from failures import report  # noqa: E402
from small_scene import small_seed_scene  # noqa: E402



def scene(harmonics, directory):
    return small_seed_scene({"Directory": directory, "Backbone": "true", "Spectrum modes": 5}, harmonics=harmonics)


def run(executable, *arguments):
    return subprocess.run([executable, *arguments], capture_output=True, text=True, timeout=600)


def main():
    executable = sys.argv[1]
    failures = []

    def check(condition, what):
        if not condition:
            failures.append(what)

    for d in ("base", "edited", "overridden", "bad"):
        shutil.rmtree(d, ignore_errors=True)
    with open("base.prm", "w") as f:
        f.write(scene(20, "base"))
    with open("edited.prm", "w") as f:
        f.write(scene(30, "edited"))

    edited = run(executable, "edited.prm")
    overridden = run(executable, "base.prm", "--set", "Harmonic balance/Harmonics=30", "--output", "overridden")
    check(edited.returncode == 0 and overridden.returncode == 0,
          f"runs failed: {edited.returncode} {overridden.returncode} {overridden.stderr}")
    check(not os.path.exists("base"), "the file's own Output/Directory was written despite --output")
    for name in ("backbone.csv", "spectrum.csv", "tongues.csv", "resonances.csv"):
        a, b = f"edited/{name}", f"overridden/{name}"
        same = os.path.exists(a) and os.path.exists(b) and filecmp.cmp(a, b, shallow=False)
        check(same, f"{name} differs between --set and the edited file")
    first = overridden.stdout.splitlines()[0] if overridden.stdout else ""
    check("Harmonic balance/Harmonics = 30" in first and "Output/Directory = overridden" in first,
          f"the summary's first line does not name the overrides: {first!r}")

    bad_rows = [
        (["--set", "Harmonic balance/Harmonics=0"], ["'Harmonic balance/Harmonics' = 0", "[1, 1000]", "--set"]),
        (["--set", "Harmonic balance/Harmonix=30"], ["'Harmonic balance/Harmonix'", "no such parameter"]),
        (["--set", "Harmonics"], ["'Harmonics'", "Section/Entry=value"]),
        (["--set"], ["--set needs a value"]),
        (["--bogus"], ["'--bogus'"]),
        (["--output", "bad2"], ["--output given twice"]),
        (["--set", "Output/Fields at=1.9,,2.0"], ["'Output/Fields at'", "has an empty item"]),
    ]
    for extra, needles in bad_rows:
        result = run(executable, "base.prm", "--output", "bad", *extra)
        lines = result.stderr.strip().splitlines()
        check(result.returncode == 2, f"{extra}: exit {result.returncode}, not 2")
        check(len(lines) == 1 and all(n in result.stderr for n in needles),
              f"{extra}: stderr {result.stderr!r} lacks {needles} or is not one line")
        check(not os.path.exists("bad") and not os.path.exists("base"), f"{extra}: a directory was left behind")

    # An empty --output (an unset shell variable) would write the scene's
    # default folder: refused.
    result = run(executable, "base.prm", "--output", "")
    check(result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1
          and "--output has an empty folder name" in result.stderr and not os.path.exists("base"),
          f"--output '': exit {result.returncode}, {result.stderr!r}")

    # A run into an earlier run's output replaces it, and says whose.
    shutil.rmtree("again", ignore_errors=True)
    first_run = run(executable, "base.prm", "--output", "again")
    second = run(executable, "base.prm", "--output", "again", "--set", "Harmonic balance/Harmonics=10")
    check(first_run.returncode == 0 and second.returncode == 0 and
          "Output/Directory held an earlier run's output (command: " in second.stdout and
          "--output again): this run replaces it" in second.stdout and "held an earlier" not in first_run.stdout,
          f"the second run into one folder does not say it replaces the first: {second.stdout[-600:]}")

    # The summary's Result block on the uniform bar: the main points' median
    # energy error against the exact mode E = g0^2 / (2 (T - 3)^2), recomputed
    # here from backbone.csv (unit bar, T = 2 pi / Omega in (3, 4)).
    with open("uniform.prm", "w") as f:
        f.write(scene(20, "uniform").replace(
            "subsection Output", "subsection Bar\n  set Cross section = 1\nend\n"
            "subsection Continuation\n  set Omega min = 1.6\n  set Omega max = 1.8\nend\nsubsection Output"))
    shutil.rmtree("uniform", ignore_errors=True)
    uniform = run(executable, "uniform.prm")
    errors = []
    with open("uniform/backbone.csv", newline="") as f:
        for r in csv.DictReader(f):
            period = 2 * math.pi / float(r["Omega"])
            if r["branch"] == "main" and 3 < period < 4:
                exact = 1e-3 ** 2 / (2 * (period - 3) ** 2)
                errors.append(abs(float(r["energy"]) - exact) / exact)
    errors.sort()
    line = [x for x in uniform.stdout.splitlines() if "against the exact mode" in x]
    expected = f"median {100 * errors[len(errors) // 2]:.3g} %"
    check(uniform.returncode == 0 and line and expected in line[0] and f"of {len(errors)}" in line[0],
          f"Result block: {line}, expected {expected!r} of {len(errors)}")
    # ... and the widest gap between its main points, recomputed from backbone.csv.
    with open("uniform/backbone.csv", newline="") as f:
        main = sorted(float(r["Omega"]) for r in csv.DictReader(f) if r["branch"] == "main")
    widest = max(b - a for a, b in zip(main, main[1:]))
    # Every gap wider than Fill gaps wider than (0.02) is named with its search.
    gaps = [(a, b) for a, b in zip(main, main[1:]) if b - a > 0.02] + ([(main[-1], 1.8)] if 1.8 - main[-1] > 0.02 else [])
    lines = [x for x in uniform.stdout.splitlines() if x.startswith("  no main point from Omega = ")]
    check(len(lines) == len(gaps) and all(f"from Omega = {a:.6g} to {b:.6g}: " in l and "Newton starts" in l
                                          for (a, b), l in zip(gaps, lines)),
          f"Result block: {lines}, expected the main gaps {gaps}")
    check(uniform.stdout.startswith("nsm-bar: scene uniform.prm\nResult\n  backbone from Omega = "),
          f"the summary does not open with the Result block: {uniform.stdout[:200]!r}")

    usage = run(executable)
    check(usage.returncode == 2 and usage.stderr.startswith("usage: nsm-bar SCENE.prm"),
          f"no scene: exit {usage.returncode}, stderr {usage.stderr!r}")

    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
