#!/usr/bin/env python3
"""Benchmark (not a test): whole runs of a scene by one or more nsm-bar
binaries, interleaved, with min / median / max over the repeats of the wall
time, the peak memory and every stage of the run summary, and the ratios of
the medians to the first binary's (a baseline built from an earlier commit,
for example, measured in the same session).

usage: benchmark_runs.py [--repeats N] SCENE BINARY [BINARY ...]
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import tempfile
import time


def one_run(binary, scene, directory):
    start = time.perf_counter()
    process = subprocess.Popen([binary, scene], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, cwd=directory)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    out = process.stdout.read()
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        raise SystemExit(f"{binary} {scene}: exit {process.returncode}: {process.stderr.read()}")
    stages = {m.group(1).strip(): float(m.group(2))
              for m in re.finditer(r"^  (\S[\w \-]*?)\s{2,}([0-9.]+)\s+[0-9.]+$", out, re.MULTILINE)}
    return {"whole run [s]": wall, "peak memory [MiB]": usage.ru_maxrss / 1024, **stages}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("scene")
    parser.add_argument("binaries", nargs="+")
    args = parser.parse_args()
    results = {b: [] for b in args.binaries}
    scene = os.path.abspath(args.scene)
    # Each binary in its own working directory: its outputs never meet another's.
    directories = {b: tempfile.mkdtemp(prefix="benchmark_runs_") for b in args.binaries}
    for _ in range(args.repeats):
        for binary in args.binaries:  # interleaved: drifts hit every binary alike
            results[binary].append(one_run(os.path.abspath(binary), scene, directories[binary]))
    for d in directories.values():
        shutil.rmtree(d)
    baseline = args.binaries[0]
    print(f"scene {args.scene}, {args.repeats} interleaved repeats; min / median / max")
    for binary in args.binaries:
        print(f"\n{binary}")
        for key in results[binary][0]:
            values = [r[key] for r in results[binary] if key in r]
            median = statistics.median(values)
            line = f"  {key:28s} {min(values):9.4f} {median:9.4f} {max(values):9.4f}"
            base = [r[key] for r in results[baseline] if key in r]
            if binary != baseline and base and statistics.median(base) > 0:
                line += f"   ratio to baseline {median / statistics.median(base):6.3f}"
            print(line)


if __name__ == "__main__":
    main()
