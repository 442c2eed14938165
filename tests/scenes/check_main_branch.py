#!/usr/bin/env python3
"""The main branch is the first nonsmooth mode on any bar (doc/method.md,
"Main branch, tongues and other families").

usage: check_main_branch.py NSM_BAR
With default settings on a stepped, a polynomial, an exponential and a
trigonometric section, on the paper's bar's mode 2 and at M = 80 (exit 0 each):
- along the main branch the contact fraction never falls by more than
  Continuation/Main contact drop (0.1) between consecutive main points: the
  mode's contact lasts longer as it hardens, and a landing on another family has
  less (0.15 to 0.28 less on these bars with the energy envelope alone);
- every interval wider than Fill gaps wider than (0.02) without a main point, up
  to the range's end, is named in the Result block with what the search from the
  predicted mode found there;
- the share of [grazing, end of the run] the main points cover (gaps up to 1 % of
  the grazing frequency counted) is printed, and is at least 0.75 on the
  stepped, exponential and trigonometric bars (0.96, 0.85 and 0.82 measured; the
  polynomial bar's mode rises to Energy max at 1.571, far below its automatic
  Omega max 1.789, and the search finds only other families beyond); on the
  stepped bar the search finds the mode beyond 2.2 that the leaps missed;
- no point lies above Energy max;
- on every main point the fundamental carries at least half of the contact
  end's squared amplitude (harmonics k >= 1 of the harmonics table);
- a point labelled other has a contact fraction more than 0.1 below the most
  contact of the mode's family (main and tongue points) before it, or a contact
  end led by a harmonic k > 1; on the seed's mode 2 the
  field asked for at 5.2745, where a leap lands on a higher mode's motion, is
  other, and the summary names the harmonic that leads it; on the polynomial
  bar the last gap's search counts a landing led by a harmonic k > 1 apart.
A control run of the stepped bar with the envelope rule alone (Main contact drop =
1) breaks the first criterion: the check can fail.
"""
import csv
import os
import subprocess
import sys

EXE = sys.argv[1]
BARS = {
    "stepped": ["Bar/Cross section=x < 0.5 ? 2 : 1"],
    "polynomial": ["Bar/Cross section=1 + x^2"],
    "exponential": ["Bar/Cross section=exp(-x)"],
    "trigonometric": ["Bar/Cross section=1.5 + 0.5*sin(2*pi*x)"],
    "seed_mode_2": ["Continuation/Mode=2", "Output/Fields at=5.2745"],
    "seed_m80": ["Harmonic balance/Harmonics=80"],
}
DROP, FILL, SHARE = 0.1, 0.02, 0.5
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def run(name, sets):
    with open("backbone.prm", "w") as f:
        f.write("subsection Output\n  set Backbone = true\n  set Harmonics table = true\nend\n")
    args = [EXE, "backbone.prm", "--output", name]
    for s in sets:
        args += ["--set", s]
    result = subprocess.run(args, capture_output=True, text=True, timeout=900)
    check(result.returncode == 0, f"{name}: exit {result.returncode}: {result.stderr[-300:]}")
    with open(os.path.join(name, "backbone.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    for row, (share, leading) in zip(rows, fundamental_shares(os.path.join(name, "harmonics.csv"), len(rows))):
        row["fundamental_share"], row["led_by"] = share, leading
    return result.stdout, rows


def fundamental_shares(path, count):
    """Per point: harmonic 1's share of the contact end's squared amplitude
    over harmonics k >= 1, and the harmonic of the largest, from the harmonics
    table's displacements."""
    squares = [{} for _ in range(count)]
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            k = int(r["k"])
            if k >= 1:
                point = squares[int(r["point"])]
                point[k] = point.get(k, 0.0) + float(r["displacement"]) ** 2
    return [(p[1] / sum(p.values()), max(sorted(p), key=lambda k: p[k])) for p in squares]


def measures(rows):
    """Main points along Omega; the largest fall of the contact fraction between
    consecutive ones; the coverage; the range's start and end."""
    main = sorted((float(r["Omega"]), float(r["contact_fraction"])) for r in rows if r["branch"] == "main")
    omegas = [float(r["Omega"]) for r in rows]
    start, end = min(omegas), max(omegas)
    drop = max([a[1] - b[1] for a, b in zip(main, main[1:])] + [0.0])
    covered = sum(b[0] - a[0] for a, b in zip(main, main[1:]) if b[0] - a[0] <= 0.01 * start)
    return main, drop, covered / (end - start), start, end


for name, sets in BARS.items():
    stdout, rows = run(name, sets)
    main, drop, coverage, start, end = measures(rows)
    print(f"{name}: {len(main)} main points of {len(rows)}, coverage {coverage:.2f}, largest contact drop {drop:.3f}")
    check(len(main) > 50, f"{name}: {len(main)} main points")
    # No point above Energy max is written (the gap search's landings and
    # segments included); the summary says its value.
    ceiling = [l for l in stdout.splitlines() if "Continuation/Energy max = 0: " in l]
    check(ceiling, f"{name}: the summary does not state Energy max")
    if ceiling:
        energy_max = float(ceiling[0].split("Continuation/Energy max = 0: ")[1].split()[0])
        highest = max(float(r["energy"]) for r in rows)
        check(highest <= energy_max, f"{name}: a point at energy {highest} above Energy max {energy_max}")
    check(drop <= DROP + 1e-12, f"{name}: the contact fraction falls by {drop:.3f} between main points")
    # Omega max is written in the Result block's first line.
    last = [l for l in stdout.splitlines() if "(ended: range: Continuation/Omega max = " in l]
    check(last, f"{name}: the branch did not reach the range's end:\n{stdout[:600]}")
    omega_max = float(last[0].split("Omega max = ")[1].split(")")[0]) if last else end
    gaps = [(a[0], b[0]) for a, b in zip(main, main[1:]) if b[0] - a[0] > FILL]
    if omega_max - main[-1][0] > FILL:
        gaps.append((main[-1][0], omega_max))
    named = [l for l in stdout.splitlines() if l.startswith("  no main point from Omega = ")]
    check(len(named) == len(gaps), f"{name}: {len(named)} gaps named, {len(gaps)} wider than {FILL}: {named}")
    for (a, b), line in zip(gaps, named):
        check(f"from Omega = {a:.6g} to {b:.6g}: " in line and "Newton starts from the predicted mode" in line,
              f"{name}: gap {a:.6g} to {b:.6g} named as {line!r}")
    # The mode's contact end swings once a period: on every main point the
    # fundamental carries most of its amplitude (0.82 at least measured on
    # these bars; the landings led by another harmonic that the labels call
    # other carry 0.001 or less). Half is stricter than the labels' rule (the
    # fundamental leads): on other bars main points carry 0.43 (method.md).
    weakest = min(float(r["fundamental_share"]) for r in rows if r["branch"] == "main")
    check(weakest >= SHARE, f"{name}: a main point whose fundamental carries {weakest:.3g} of its contact end's swing")
    # Other points: less contact than the mode's family before them (its main
    # and tongue points), or a contact end led by another harmonic.
    family = [(float(r["Omega"]), float(r["contact_fraction"])) for r in rows if r["branch"] != "other"]
    for r in rows:
        if r["branch"] != "other" or r["led_by"] != 1:
            continue
        w, c = float(r["Omega"]), float(r["contact_fraction"])
        before = [f[1] for f in family if f[0] < w]
        check(before and c < max(before) - DROP + 1e-12, f"{name}: other point at {w} with contact {c}")
    if name in ("stepped", "exponential", "trigonometric"):
        check(coverage >= 0.75, f"{name}: coverage {coverage:.2f} < 0.75")
    if name == "polynomial":
        # Beyond the mode's rise to Energy max the search lands on other
        # families, one of them led by a higher harmonic (method.md).
        check(named and "led by a harmonic k > 1)" in named[-1],
              f"{name}: the last gap does not count a landing led by a harmonic k > 1: {named[-1:]}")
    if name == "seed_mode_2":
        # The field asked for where a leap landed on a higher mode's motion.
        with open(os.path.join(name, "fields.csv"), newline="") as f:
            field = next(csv.DictReader(f))
        check(field["branch"] == "other", f"{name}: the field at 5.2745 is labelled {field['branch']}")
        check("field at Omega = 5.2745 is on another family, not on the main branch (harmonic " in stdout
              and ", not the fundamental, leads its contact end's swing)" in stdout,
              f"{name}: the summary does not say the field's leading harmonic")
    if name == "stepped":
        check(any(m[0] > 2.2 and m[1] > 0.3 for m in main),
              "stepped: no main point beyond 2.2 with the mode's contact (> 0.3)")

# The control: the envelope rule alone labels other families main.
_, rows = run("stepped_envelope_rule", BARS["stepped"] + ["Continuation/Main contact drop=1",
                                                         "Continuation/Fill gaps wider than=0"])
_, drop, coverage, _, _ = measures(rows)
print(f"stepped with the envelope rule: coverage {coverage:.2f}, largest contact drop {drop:.3f}")
check(drop > 0.1, f"control: the envelope rule's largest drop {drop:.3f} is within the bound")

if failures:
    sys.exit(f"{len(failures)} failures")
print("main branch: all checks passed")
