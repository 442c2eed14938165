"""What a backbone.csv's main branch covers, as scene.main_branch
(tests/scenes/check_main_branch.py) and doc/method.md's table "On other bars"
(tests/benchmarks/main_branch_table.py) measure it."""
import math

# The accumulation point counts as passed at W_acc (1 + 4 / M^2) (M = 40:
# continuation_constants::accumulation_reach); consecutive main points across
# that are on two sides.
ZONE = 4 / 40 ** 2


def measures(rows, accumulation=math.pi / 2):
    """Main points along Omega; the largest fall of the contact fraction between
    consecutive ones on one side of the accumulation point; the coverage (the
    share of the run's Omega range between main points at most 1 % of its start
    apart); the range's start and end."""
    main = sorted((float(r["Omega"]), float(r["contact_fraction"])) for r in rows if r["branch"] == "main")
    omegas = [float(r["Omega"]) for r in rows]
    start, end = min(omegas), max(omegas)
    drop = max([a[1] - b[1] for a, b in zip(main, main[1:])
                if not a[0] <= accumulation * (1 + ZONE) < b[0]] + [0.0])
    covered = sum(b[0] - a[0] for a, b in zip(main, main[1:]) if b[0] - a[0] <= 0.01 * start)
    return main, drop, covered / (end - start), start, end
