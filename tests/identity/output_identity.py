#!/usr/bin/env python3
"""Do two builds write the same results? Runs every scene of prm/ and compares
the CSV files it writes, cell by cell, with those one recorded earlier.

usage: output_identity.py record  NSM_BAR RECORD_DIRECTORY [SCENE.prm ...]
       output_identity.py compare [--common-columns] NSM_BAR RECORD_DIRECTORY [SCENE.prm ...]
Without scenes, every prm/*.prm. `record` keeps each scene's CSV files in
RECORD_DIRECTORY/SCENE/; `compare` runs the scenes again and fails unless
every file, every column and every cell is the same text. Costs are left
out: columns named wall_*, cpu_*, peak_* or *_seconds, which vary from run to
run (study_row.h). With --common-columns, a column only one side has is named
but not compared (a build that adds a column). Uses the standard library only.
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def is_cost(column):
    return column.startswith(("wall_", "cpu_", "peak_")) or column.endswith("_seconds")


def run_scene(executable, scene, work):
    """Runs the scene in `work`; returns {relative CSV path: rows}."""
    shutil.copy(scene, work)
    start = time.time()
    result = subprocess.run([executable, os.path.basename(scene)], cwd=work, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{scene}: exit {result.returncode}\n{result.stderr}")
    tables = {}
    for base, _, files in os.walk(work):
        for name in files:
            if name.endswith(".csv"):
                path = os.path.join(base, name)
                with open(path, newline="") as f:
                    tables[os.path.relpath(path, work)] = list(csv.reader(f))
    return tables, time.time() - start


def without_costs(rows):
    if not rows:
        return rows
    keep = [i for i, c in enumerate(rows[0]) if not is_cost(c)]
    return [[row[i] for i in keep if i < len(row)] for row in rows]


def common_columns(a, b, name, path):
    """Both tables cut to the columns they share; prints the others."""
    shared = [c for c in a[0] if c in b[0]]
    for c in sorted(set(a[0]) ^ set(b[0])):
        print(f"  {name}: {path}: column {c} {'recorded only' if c in a[0] else 'new'}, not compared")
    cut = lambda rows: [[row[rows[0].index(c)] for c in shared] for row in rows]
    return cut(a), cut(b)


def differences(name, recorded, now, common=False):
    found = []
    for path in sorted(set(recorded) | set(now)):
        if path not in now or path not in recorded:
            found.append(f"{name}: {path} {'missing' if path not in now else 'new'}")
            continue
        a, b = without_costs(recorded[path]), without_costs(now[path])
        if common and a and b:
            a, b = common_columns(a, b, name, path)
        if a[:1] != b[:1]:
            found.append(f"{name}: {path}: columns differ: {a[:1]} against {b[:1]}")
        elif len(a) != len(b):
            found.append(f"{name}: {path}: {len(a) - 1} rows recorded, {len(b) - 1} now")
        else:
            cells = [(r, c) for r in range(len(a)) for c in range(len(a[r])) if a[r][c] != b[r][c]]
            if cells:
                r, c = cells[0]
                found.append(f"{name}: {path}: {len(cells)} cells differ, first row {r} column "
                             f"{a[0][c]}: {a[r][c]} against {b[r][c]}")
    return found


def main():
    arguments = sys.argv[1:]
    common = "--common-columns" in arguments
    arguments = [a for a in arguments if a != "--common-columns"]
    if len(arguments) < 3 or arguments[0] not in ("record", "compare"):
        sys.exit(__doc__)
    mode, executable, store = arguments[0], os.path.abspath(arguments[1]), os.path.abspath(arguments[2])
    scenes = arguments[3:] or sorted(os.path.join(ROOT, "prm", f) for f in os.listdir(os.path.join(ROOT, "prm"))
                                    if f.endswith(".prm"))
    failures = []
    for scene in scenes:
        name = os.path.basename(scene)[:-4]
        with tempfile.TemporaryDirectory() as work:
            tables, seconds = run_scene(executable, scene, work)
            kept = os.path.join(store, name)
            if mode == "record":
                shutil.rmtree(kept, ignore_errors=True)
                for path, rows in tables.items():
                    os.makedirs(os.path.dirname(os.path.join(kept, path)), exist_ok=True)
                    with open(os.path.join(kept, path), "w", newline="") as f:
                        csv.writer(f).writerows(rows)
                print(f"recorded {name}: {len(tables)} CSV files ({seconds:.1f} s)", flush=True)
                continue
            recorded = {}
            for base, _, files in os.walk(kept):
                for f in files:
                    with open(os.path.join(base, f), newline="") as handle:
                        recorded[os.path.relpath(os.path.join(base, f), kept)] = list(csv.reader(handle))
            found = differences(name, recorded, tables, common) if recorded else [f"{name}: nothing recorded"]
            failures += found
            print(f"{'same' if not found else 'DIFFERENT'} {name}: {len(tables)} CSV files ({seconds:.1f} s)",
                  flush=True)
            for line in found:
                print("  " + line, flush=True)
    if failures:
        sys.exit(f"{len(failures)} differences")
    if mode == "compare":
        print("every scene writes the same values")


if __name__ == "__main__":
    main()
