#!/usr/bin/env python3
"""Study runs, checked from their study.csv.

usage: check_study.py NSM_BAR STUDIES_DIR {rates|ranks|resume|reference|harmonics|unused}
  rates   space.prm: the eigenfrequency error falls like h^(2p) (rate within
          10 % of 2p) and exponentially in p, against the exact Bessel roots;
  ranks   ranks.prm serially and on 2 MPI ranks: identical rows, costs aside;
  resume  resume.prm stopped by SIGTERM after its first rows, then rerun: the
          rerun computes only the missing rows, keeps the earlier ones byte
          for byte, and ends with the rows of an uninterrupted run;
  reference reference.prm: the seed bar's fine backbone reference has converged
          (FE_Q(10) x 14 against x 28), the rows' errors are against it, and a
          rerun reads it from reference.csv instead of computing it again;
  harmonics harmonics.prm: on the uniform bar's main branch, the energy error
          against the exact mode g0^2 / (2 (T - 3)^2) falls from M = 10 to 20
          to 40 at every Omega that all three find on it, and so does the one-period
          defect in time of the main points at the Backbone omegas, which equals
          the defect a plain run reports for its fields at those Omega;
  ended   ended.prm: each row says how its continuation ended; at M = 160
          the seed bar's is lost, and the row says so, with the Omega where a
          plain run of that scene says it was lost and its last point;
          at M = 40 the row reaches Omega max; ended_energy.prm: on the
          uniform bar a row that ends at Energy max inside the Backbone
          omegas is left out of the energy error's Pareto front;
  unused  unused.prm: of 16 combinations, the 7 that differ from an earlier one
          only in values their run does not use (Time samples under exact
          integration, graded ratios without grading) are left out, the rest
          run once each; the summary names the spectrum error's Pareto front
          as study.csv gives it, without the values a row does not use.
"""
import csv
import math
import os
import re
import shutil
import signal
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from stop_signals import signal_when_blocked  # noqa: E402

import numpy as np
from scipy.optimize import brentq
from scipy.special import j0, j1, y0, y1

EPS = np.finfo(float).eps


def run(command, cwd):
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=900)
    assert result.returncode == 0, f"{command}: exit {result.returncode}\n{result.stderr}"
    return result


def fresh(name, studies, scene):
    directory = os.path.abspath(os.path.join("study", name))
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    shutil.copy(os.path.join(studies, scene), directory)
    return directory


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def reproducible(row):
    """A row without its costs (wall and CPU times, memory)."""
    return {k: v for k, v in row.items() if not k.startswith(("wall_", "cpu_", "peak_"))}


def bessel_roots(count):
    """Clamped-free frequencies of A = 1.5 - x (E = rho = L = 1), by scipy."""
    f = lambda w: j0(1.5 * w) * y1(0.5 * w) - y0(1.5 * w) * j1(0.5 * w)
    grid = np.arange(0.01, 60, 0.01)
    roots = [brentq(f, a, b, xtol=1e-15) for a, b in zip(grid[:-1], grid[1:])
             if np.sign(f(a)) != np.sign(f(b))]
    return roots[:count]


def rates(executable, studies):
    directory = fresh("rates", studies, "space.prm")
    run([executable, "space.prm"], directory)
    rows = read(os.path.join(directory, "out", "study.csv"))
    assert all(r["status"] == "ok" and r["reference"] == "linear taper (Bessel)" for r in rows)
    # Every row's peak resident memory holds at least its stiffness and mass
    # matrices' values: 2 (2 p + 1) (cells p + 1) doubles (8 bytes each).
    for r in rows:
        p, cells = int(r["degree"]), int(r["cells"])
        assert float(r["peak_memory_mib"]) >= 16 * (2 * p + 1) * (cells * p + 1) / 2 ** 20, r
        assert float(r["peak_memory_mib"]) > 1, r  # the process itself: libraries, MiB of them
    w_last = bessel_roots(5)[-1]
    error = {(int(r["degree"]), int(r["cells"])): float(r["spectrum_error"]) for r in rows}

    def above_floor(p, cells, e):
        # The round-off floor of the eigenvalues, eps p^2 L / h (method.md),
        # with a margin of 100.
        return e > 100 * EPS * p * p * cells

    checked = 0
    for (p, cells), e in sorted(error.items()):
        fine = error.get((p, 2 * cells))
        # Asymptotic once the highest mode has w h / p <= 1/2.
        if fine is None or w_last / cells / p > 0.5 or not above_floor(p, 2 * cells, fine):
            continue
        rate = math.log2(e / fine)
        print(f"p = {p}, cells {cells} -> {2 * cells}: rate {rate:.3f} (2p = {2 * p})")
        assert abs(rate - 2 * p) <= 0.1 * 2 * p, f"p = {p}, cells {cells}: rate {rate}"
        checked += 1
    assert checked >= 8, f"only {checked} rates in the asymptotic range"

    # Exponential in p at 8 cells: a factor 10 at least per degree down to
    # the floor (an algebraic rate in p would slow down as p grows).
    steps = 0
    for p in range(1, 8):
        e, next_e = error[(p, 8)], error[(p + 1, 8)]
        if not above_floor(p + 1, 8, next_e):
            break
        print(f"cells 8, p = {p} -> {p + 1}: error ratio {next_e / e:.3g}")
        assert next_e / e <= 0.1, f"p = {p} -> {p + 1}: ratio {next_e / e}"
        steps += 1
    assert steps >= 4, f"only {steps} degrees above the round-off floor"


def ranks(executable, studies):
    serial = fresh("ranks_serial", studies, "ranks.prm")
    run([executable, "ranks.prm"], serial)
    parallel = fresh("ranks_mpi", studies, "ranks.prm")
    result = run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2", executable,
                  "ranks.prm"], parallel)
    assert "on 2 ranks" in result.stdout, result.stdout
    a = read(os.path.join(serial, "out", "study.csv"))
    b = read(os.path.join(parallel, "out", "study.csv"))
    assert len(a) == 8 and [reproducible(r) for r in a] == [reproducible(r) for r in b]
    assert all(r["status"] == "ok" and r["energy_error_max"] != "" for r in a), a
    print(f"{len(a)} rows identical, costs aside")


def resume(executable, studies):
    whole = fresh("resume_whole", studies, "resume.prm")
    run([executable, "resume.prm"], whole)
    expected = read(os.path.join(whole, "out", "study.csv"))

    # The study announces each row it wrote on stderr (Progress every is
    # tiny). With stderr a full pipe, it waits in its first announcement,
    # after its first row: SIGTERM sent then must stop it after that row,
    # whatever the machine's load. No timer races the study.
    directory = fresh("resume_stopped", studies, "resume.prm")
    study = os.path.join(directory, "out", "study.csv")
    returncode, _, stderr = signal_when_blocked([executable, "resume.prm"], signal.SIGTERM, "a row", cwd=directory)
    assert returncode == 128 + signal.SIGTERM, (returncode, stderr)
    assert stderr.strip().splitlines()[-1].startswith("nsm-bar: stopped by SIGTERM"), stderr
    stopped = read(study)  # complete CSV: read_csv would fail on a half row
    with open(study) as f:
        text = f.read()
    assert text.endswith("\n") and len(stopped) == 1 < len(expected), len(stopped)

    result = run([executable, "resume.prm"], directory)
    done = len(stopped)
    note = f"{len(expected)} rows, {len(expected) - done} run now on 1 rank, {done} from an earlier run"
    assert note in result.stdout, result.stdout
    final = read(study)
    # Their own columns: the shared errors depend on every row, and change
    # with the rows added (study_shared_errors.h).
    own = [{k: v for k, v in r.items() if k not in SHARED_COLUMNS} for r in final[:done]]
    assert own == [{k: v for k, v in r.items() if k not in SHARED_COLUMNS} for r in stopped], \
        "rows of the stopped run were recomputed"
    assert [reproducible(r) for r in final] == [reproducible(r) for r in expected]
    print(f"stopped after {done} of {len(expected)} rows; the rerun ran the others")


SHARED_COLUMNS = ("shared_omegas", "energy_error_max_shared", "energy_error_median_shared")


def relative(a, b):
    return abs(a - b) / abs(b)


def reference(executable, studies):
    directory = fresh("reference", studies, "reference.prm")
    out = os.path.join(directory, "out")
    result = run([executable, "reference.prm"], directory)
    assert "fine reference: FE_Q(10) x 28 cells at M = 40, computed in" in result.stdout, result.stdout
    levels = read(os.path.join(out, "reference.csv"))
    omegas = [float(r["Omega"]) for r in levels]
    fine = {float(r["Omega"]): float(r["energy_cells_28"]) for r in levels if r["energy_cells_28"]}
    # The reference has converged far below the errors the rows are judged
    # by: FE_Q(10) resolves gamma over the band to 1e-12 on 28 cells
    # (doc/accuracy-and-cost.md), so halving its cells moves the main branch
    # by round-off and the solver's tolerance, not by 1e-6.
    assert len(fine) >= 8, f"the reference is on the main branch at only {len(fine)} Omega"
    for r in levels:
        if r["energy_change"]:
            change = relative(float(r["energy_cells_14"]), float(r["energy_cells_28"]))
            assert abs(change - float(r["energy_change"])) <= 1e-12 * change, r
            for q in ("energy_change", "max_contact_force_change", "contact_fraction_change"):
                assert 0 <= float(r[q]) <= 1e-6, (r["Omega"], q, r[q])
    rows = {(r["degree"], r["cells"]): r for r in read(os.path.join(out, "study.csv"))}
    assert all(r["status"] == "ok" for r in rows.values())

    def energy_errors(row):
        errors = []
        for omega in omegas:
            cell = row[next(k for k in row if k.startswith("energy_at_") and abs(float(k[10:]) - omega) < 1e-9)]
            if cell and omega in fine:
                errors.append(relative(float(cell), fine[omega]))
        return errors

    for key, row in rows.items():
        errors = energy_errors(row)
        assert row["reference"].endswith("backbone: FE_Q(10) x 28 cells at M = 40 (reference.csv)"), row["reference"]
        if errors:
            assert abs(float(row["energy_error_max"]) - max(errors)) <= 1e-9 * max(errors), key
    same = rows[("10", "28")]
    assert float(same["energy_error_max"]) == 0 and float(same["force_error_max"]) == 0, same
    # FE_Q(1) on 7 cells misses the first 10 modes by up to 20 % (Bessel
    # roots); FE_Q(10) on 7 cells has them to 1e-13: a reference that cannot
    # tell them apart by at least a factor 100 in energy is not the converged one.
    coarse, good = float(rows[("1", "7")]["energy_error_max"]), float(rows[("10", "7")]["energy_error_max"])
    assert good <= 1e-3 and coarse >= 100 * good, (coarse, good)

    # Kept: a rerun reads reference.csv (then every row comes from study.csv).
    path = os.path.join(out, "reference.csv")
    stamp = os.stat(path).st_mtime_ns
    result = run([executable, "reference.prm"], directory)
    assert "read from out/reference.csv" in result.stdout and os.stat(path).st_mtime_ns == stamp, result.stdout
    # ... and the rows are measured against it: with its energies scaled by
    # 1.01 and the rows recomputed, the row equal to the reference is 1/1.01 - 1 off.
    with open(path) as f:
        table = list(csv.reader(f))
    column = table[0].index("energy_cells_28")
    for line in table[1:]:
        if line[column]:
            line[column] = repr(float(line[column]) * 1.01)
    with open(path, "w", newline="") as f:
        csv.writer(f, lineterminator="\n").writerows(table)
    os.remove(os.path.join(out, "study.csv"))
    run([executable, "reference.prm"], directory)
    rows = {(r["degree"], r["cells"]): r for r in read(os.path.join(out, "study.csv"))}
    shifted = float(rows[("10", "28")]["energy_error_max"])
    assert abs(shifted - (1 - 1 / 1.01)) < 1e-9, shifted
    print(f"reference at {len(fine)} of {len(omegas)} Omega; FE_Q(10) x 7 within {good:.2e}, "
          f"FE_Q(1) x 7 {coarse:.2e}; kept and read on rerun")


def harmonics(executable, studies):
    directory = fresh("harmonics", studies, "harmonics.prm")
    run([executable, "harmonics.prm"], directory)
    rows = {int(r["harmonics"]): r for r in read(os.path.join(directory, "out", "study.csv"))}
    assert sorted(rows) == [10, 20, 40] and all(r["status"] == "ok" for r in rows.values())
    columns = [k for k in rows[10] if k.startswith("energy_at_")]
    common = [k for k in columns if all(rows[m][k] for m in rows)]
    assert len(common) >= 2, f"only {common} on the main branch at every M"
    for k in common:
        omega = float(k[len("energy_at_"):])
        exact = exact_uniform_energy(omega, 1e-3)
        error = {m: abs(float(rows[m][k]) / exact - 1) for m in rows}
        # A fall, not noise: strictly at each doubling, and by at least a
        # factor 2 from M = 10 to 40 (a 1/M law gives 4); at M = 40 within the
        # 5 % that the truncated series reaches (doc/studies.md).
        assert error[10] > error[20] > error[40] and error[10] >= 2 * error[40], (omega, error)
        assert error[40] <= 0.05, (omega, error)
        print(f"Omega {omega}: energy error " + ", ".join(f"M = {m}: {e:.2e}" for m, e in error.items()))
    main_points_error_falls(executable, directory, rows)
    time_defects_fall(executable, directory, rows)


def plain_run(executable, directory, name, output, study="harmonics.prm", harmonics=40):
    """The study scene without its Study section, at M = `harmonics`, as a
    plain run writing its backbone to directory/name, with `output` added
    to Output."""
    with open(os.path.join(directory, study)) as f:
        scene = f.read().split("subsection Study")[0]
    with open(os.path.join(directory, name + ".prm"), "w") as f:
        f.write(scene + f"subsection Harmonic balance\n  set Harmonics = {harmonics}\nend\n"
                f"subsection Output\n  set Directory = {name}\n  set Backbone = true\n  set Plots = false\n"
                + output + "end\n")
    return run([executable, name + ".prm", "--verbose"], directory)


def time_defects_fall(executable, directory, rows):
    """The HB point's state at t = 0 integrated over one period comes back the
    closer, the nearer the truncated series is to the exact mode (whose defect
    is the time integration's alone: doubling Verify steps moves the seed bar's
    defect by 7 % of itself). The M = 40 row's median and largest defect equal
    those of a plain run's fields at the Omega it found on the main branch."""
    defects = {m: (float(rows[m]["main_time_defect_median"]), float(rows[m]["main_time_defect_max"]))
               for m in rows}
    print("one-period defect / g0, median and largest: " +
          ", ".join(f"M = {m}: {d[0]:.2e}, {d[1]:.2e}" for m, d in defects.items()))
    for i in range(2):
        assert defects[10][i] > defects[20][i] > defects[40][i] > 0, defects
    found = [k[len("energy_at_"):] for k in rows[40] if k.startswith("energy_at_") and rows[40][k]]
    summary = plain_run(executable, directory, "fields",
                        f"  set Fields at = {', '.join(found)}\n  set Verify in time = true\n"
                        "  set Verify every = 1000000\n  set Verify periods = 1\n").stdout
    plain = sorted(float(line.split("one-period defect / g0 ")[1].split()[0])
                   for line in summary.splitlines() if "verified in time: one-period defect" in line)
    assert len(plain) == len(found), (summary, found)
    # The summary prints 6 digits.
    for ours, theirs in ((defects[40][0], plain[len(plain) // 2]), (defects[40][1], plain[-1])):
        assert abs(ours - theirs) <= 1e-5 * theirs, (ours, theirs, plain)


def exact_uniform_energy(omega, gap):
    period = 2 * math.pi / omega  # L = c = 1
    return gap ** 2 / (2 * (period - 3) ** 2)


def main_points_error_falls(executable, directory, rows):
    """Over every main point written, not only at the Backbone omegas: the
    median energy error falls with M, and the M = 40 row's column equals the
    median recomputed here from the same scene's backbone.csv."""
    median = {m: float(rows[m]["main_energy_error_median"]) for m in rows}
    print("main points' median energy error: " + ", ".join(f"M = {m}: {e:.2e}" for m, e in median.items()))
    assert median[10] > median[20] > median[40], median
    assert median[40] <= 0.05, median  # what the truncated series reaches (doc/studies.md)
    plain_run(executable, directory, "base", "")
    errors = sorted(abs(float(p["energy"]) / exact_uniform_energy(float(p["Omega"]), 1e-3) - 1)
                    for p in read(os.path.join(directory, "base", "backbone.csv")) if p["branch"] == "main")
    assert len(errors) == int(rows[40]["main_points"]), (len(errors), rows[40]["main_points"])
    # Two runs of one scene agree to the Newton tolerance (measured: 3e-10 relative).
    assert abs(errors[len(errors) // 2] - median[40]) <= 1e-8 * median[40], (errors[len(errors) // 2], median[40])


def ended(executable, studies):
    directory = fresh("ended", studies, "ended.prm")
    result = run([executable, "ended.prm"], directory)
    assert "0 failed; 1 row ended before the Omega range's end (backbone_end)" in result.stdout, result.stdout
    # A rerun computes nothing and still counts it, from study.csv.
    rerun = run([executable, "ended.prm"], directory).stdout
    assert "0 run now" in rerun and "1 row ended before the Omega range's end" in rerun, rerun
    rows = {int(r["harmonics"]): r for r in read(os.path.join(directory, "out", "study.csv"))}
    assert all(r["status"] == "ok" for r in rows.values()), rows
    # The scene's Omega max; the last point lands on it exactly.
    assert rows[40]["backbone_end"] == "range" and float(rows[40]["omega_reached"]) == 2.2, rows[40]
    summary = plain_run(executable, directory, "plain", "", study="ended.prm", harmonics=160).stdout
    lost = re.search(r"branch lost after the fold at Omega = ([0-9.]+)", summary)
    assert lost, summary
    omegas = [float(r["Omega"]) for r in read(os.path.join(directory, "plain", "backbone.csv"))]
    reached = float(rows[160]["omega_reached"])
    assert rows[160]["backbone_end"] == "lost" and reached == max(omegas), (rows[160], max(omegas))
    # Lost between the Backbone omegas 1.93 and 2.1: its energy error covers 1.93 alone.
    assert (rows[40]["energy_error_partial"], rows[160]["energy_error_partial"]) == ("no", "yes"), rows
    # The summary prints Omega to 8 significant digits.
    assert abs(reached - float(lost.group(1))) <= 1e-7 and reached < 2.2, (reached, lost.group(1))
    print(f"M = 40: range, {rows[40]['omega_reached']}; M = 160: lost at {reached}")
    energy_front_leaves_out_partial_rows(executable, studies)


def energy_front_leaves_out_partial_rows(executable, studies):
    directory = fresh("ended_energy", studies, "ended_energy.prm")
    summary = run([executable, "ended_energy.prm"], directory).stdout
    rows = {int(r["harmonics"]): r for r in read(os.path.join(directory, "out", "study.csv"))}
    assert [rows[m]["backbone_end"] for m in (10, 20, 40)] == ["range", "range", "energy_max"], rows
    # The exact mode crosses Energy max between the M = 40 row's end and the
    # last Backbone omega: its energy g0^2 / (2 (T - 3)^2) at both.
    reached = float(rows[40]["omega_reached"])
    assert exact_uniform_energy(reached, 1e-3) < 1e-3 < exact_uniform_energy(2.079, 1e-3), reached
    # (M = 10's main branch, the mode with the exact contact fraction (4 - T) / T
    # that the gap search finds, also ends short of it; M = 20 reaches it.)
    assert rows[40]["energy_at_2.079"] == "" and rows[20]["energy_at_2.079"], rows
    # study.csv marks it, alone, whatever reads the file (study.png rings it grey).
    assert [rows[m]["energy_error_partial"] for m in (10, 20, 40)] == ["no", "no", "yes"], rows
    # Left out, it would have led the front: its error over two Omega is the least.
    errors = {m: float(r["energy_error_max"]) for m, r in rows.items()}
    assert errors[40] < min(errors[10], errors[20]), errors
    front = [line for line in summary.splitlines() if line.startswith("    energy_error_max_shared ")]
    assert front and not any("harmonics 40" in line for line in front), summary
    words = "1 row left out: its continuation ended"
    for error in ("energy_error_max_shared", "energy_error_median_shared"):
        assert f"({error}: {words} inside the Backbone omegas" in summary, summary
    # The others are compared over the Backbone omegas they all share with
    # the reference (the exact mode), not left out for having fewer: the
    # shared errors recomputed here from energy_at_ and the exact energy.
    shared = [k for k in rows[10] if k.startswith("energy_at_") and all(rows[m][k] for m in (10, 20))]
    assert shared and all(rows[m]["shared_omegas"] == str(len(shared)) for m in (10, 20)), rows
    assert rows[40]["energy_error_max_shared"] == "", rows[40]
    for m in (10, 20):
        errors = sorted(abs(float(rows[m][k]) / exact_uniform_energy(float(k[10:]), 1e-3) - 1) for k in shared)
        assert abs(float(rows[m]["energy_error_max_shared"]) / errors[-1] - 1) < 1e-9, (m, errors)
        assert abs(float(rows[m]["energy_error_median_shared"]) / errors[len(errors) // 2] - 1) < 1e-9, (m, errors)
    front = [line for line in summary.splitlines() if line.startswith("    energy_error_max_shared ")]
    assert front and f"over the {len(shared)} Backbone omegas every row shares with the reference" in summary, summary
    print(f"energy front: {front}; M = 40 ended at {reached}, left out")


def unused(executable, studies):
    directory = fresh("unused", studies, "unused.prm")
    result = run([executable, "unused.prm"], directory)
    assert "study: 9 rows" in result.stdout and "7 combinations left out" in result.stdout, result.stdout
    rows = read(os.path.join(directory, "out", "study.csv"))
    keys = [(r["refinement"], r["graded_ratio"], r["integration"], r["time_samples"]) for r in rows]
    assert len(set(keys)) == 9, keys
    for refinement, ratio, integration, samples in keys:
        assert (ratio == "-") == (refinement == "none"), keys
        assert (samples == "-") == (integration == "exact"), keys
    # No harmonic balance, no continuation to end.
    assert all(r["backbone_end"] == r["omega_reached"] == r["energy_error_partial"] == "" for r in rows), rows
    # The graded rows are other meshes: their errors differ from the uniform one's.
    errors = {r["refinement"] + r["graded_ratio"]: float(r["spectrum_error"]) for r in rows}
    assert len(set(errors.values())) == 3, errors
    # The summary's Pareto front, recomputed from study.csv: the rows that no
    # faster row beats in error, each named by the swept parameters that take
    # more than one value, a value its run does not use ("-") left out.
    swept = ["refinement", "graded_ratio", "integration", "time_samples"]
    front, best = [], math.inf
    for r in sorted(rows, key=lambda r: float(r["wall_total_median"])):
        if float(r["spectrum_error"]) < best:
            best = float(r["spectrum_error"])
            front.append(" ".join(f"{c} {r[c]}" for c in swept if r[c] != "-"))
    named = re.findall(r"^ +spectrum_error \S+ in \S+ s: (.*)$", result.stdout, re.M)
    assert named == front, (named, front)
    print(f"{len(rows)} rows of 16 combinations: {sorted(set(keys))}")


if __name__ == "__main__":
    executable, studies, mode = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
    {"rates": rates, "ranks": ranks, "resume": resume, "reference": reference,
     "harmonics": harmonics, "ended": ended, "unused": unused}[mode](executable, studies)
    print(f"study {mode}: ok")
