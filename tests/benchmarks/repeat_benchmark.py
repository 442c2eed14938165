#!/usr/bin/env python3
"""Runs a benchmark program N times and prints its output once, each number
that differs between the runs as min / median / max (doc/studies.md).

    python3 tests/benchmarks/repeat_benchmark.py 5 ./build/tests/benchmark_backbone

The runs follow one another on an otherwise idle machine; a number that is the
same in every run (a point count) is printed once, so what varies is only the
timing. Lines whose text (numbers aside) differs between runs are printed from
each run, marked, since they are not the same measure."""
import re
import statistics
import subprocess
import sys

NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def spread(values):
    if len(set(values)) == 1:
        return values[0]
    numbers = sorted(float(v) for v in values)
    # As many decimals as the program printed, in its notation.
    mantissas = [v.split("e")[0] for v in values]
    digits = max(len(m.split(".")[1]) if "." in m else 0 for m in mantissas)
    kind = "e" if any("e" in v for v in values) else "f"
    return " / ".join(f"{x:.{digits}{kind}}" for x in (numbers[0], statistics.median(numbers), numbers[-1]))


def merged(lines):
    templates = [NUMBER.sub("#", line) for line in lines]
    if len(set(templates)) > 1:
        return [f"{line}  [run {i + 1}]" for i, line in enumerate(lines)]
    columns = zip(*(NUMBER.findall(line) for line in lines))
    parts = templates[0].split("#")
    out = parts[0]
    for values, text in zip(columns, parts[1:]):
        out += spread(list(values)) + text
    return [out]


def main():
    if len(sys.argv) < 3 or not sys.argv[1].isdigit() or int(sys.argv[1]) < 2:
        sys.exit("usage: repeat_benchmark.py N PROGRAM [ARGUMENTS...] (N >= 2)")
    runs = [subprocess.run(sys.argv[2:], check=True, capture_output=True, text=True).stdout.splitlines()
            for _ in range(int(sys.argv[1]))]
    if len({len(r) for r in runs}) > 1:
        sys.exit("the runs printed different numbers of lines: not the same measures")
    for lines in zip(*runs):
        for line in merged(list(lines)):
            print(line)


if __name__ == "__main__":
    main()
