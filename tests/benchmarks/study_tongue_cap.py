#!/usr/bin/env python3
"""Study (not a test): would a causal cap on the energy keep the continuation
off the tongues? Replays written backbones (backbone.csv, in the order the
continuation wrote them) with a rule the continuation could apply as it goes:
a point is refused, and its segment ends there, where its energy exceeds

    (1 + a) min_i E_i exp(s (Omega - Omega_i))

over the points kept before it (in the segment only, or in the whole run), a
branch allowed to harden by at most s in ln E per unit Omega. Prints, per
backbone, the main and tongue points the rule cuts and the main share of the
points it keeps. A replay, not a run: a real cap would leap on from the cut,
so it bounds what the rule can do only roughly (doc/method.md, "The automatic
range").

    python3 tests/benchmarks/study_tongue_cap.py DIR/backbone.csv ...
"""
import csv
import math
import sys

SHARES = (0.1, 0.2, 0.5, 1.0)
SLOPES = (20, 40, 80, 160)


def load(path):
    with open(path) as f:
        return [(int(r["segment"]), float(r["Omega"]), float(r["energy"]), r["branch"] == "main")
                for r in csv.DictReader(f)]


def replay(points, share, slope, whole_run):
    """(main points cut, tongue points cut, main share of the points kept)."""
    kept, reference, cut_segment = [], [], None
    cut_main = cut_tongue = 0
    for segment, omega, energy, main in points:
        if not whole_run and (not kept or kept[-1][0] != segment):
            reference = []
        allowed = min((e * math.exp(slope * (omega - w)) for w, e in reference), default=math.inf)
        if segment == cut_segment or energy > (1 + share) * allowed:
            cut_segment = segment
            cut_main += main
            cut_tongue += not main
            continue
        kept.append((segment, main))
        reference.append((omega, energy))
    kept_main = sum(m for _, m in kept)
    return cut_main, cut_tongue, kept_main / len(kept) if kept else 0.0


def main():
    runs = {path: load(path) for path in sys.argv[1:]}
    for path, points in runs.items():
        main_points = sum(p[3] for p in points)
        print(f"{path}: {len(points)} points, {main_points} main ({100 * main_points / len(points):.0f} %)")
    for whole_run in (False, True):
        reference = "every earlier point kept" if whole_run else "the segment's earlier points"
        print(f"\nreference: {reference}")
        print("| a | s | " + " | ".join(f"run {i + 1}: cut main / tongue, main share" for i in range(len(runs))) + " |")
        for share in SHARES:
            for slope in SLOPES:
                cells = []
                for points in runs.values():
                    cm, ct, kept_share = replay(points, share, slope, whole_run)
                    cells.append(f"{cm} / {ct}, {100 * kept_share:.0f} %")
                print(f"| {share} | {slope} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
