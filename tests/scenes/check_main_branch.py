#!/usr/bin/env python3
"""The main branch is the first nonsmooth mode on any bar (doc/method.md,
"Main branch, tongues and other families").

usage: check_main_branch.py NSM_BAR
With default settings on a stepped, a polynomial, an exponential and a
trigonometric section, on the paper's bar's mode 2 and at M = 80 (exit 0 each):
- along the main branch the contact fraction never falls by more than
  Continuation/Main contact drop (0.1) between consecutive main points on one
  side of the accumulation point W_acc = (2 Mode - 1) pi / 2: the mode's contact
  lasts longer as it hardens, and a landing on another family has less (0.15 to
  0.28 less on these bars with the energy envelope alone); across W_acc the
  climb into it (contact near 1/2) gives way to the uniform bar's mode
  continued, whose contact starts near 0 (doc/method.md, "The accumulation
  point");
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
  other, and the summary names the harmonic that leads it; at M = 20 the gap
  search beyond its end counts landings led by a harmonic k > 1 apart; the
  polynomial bar
  (w_1 = 1.344, below pi / 2) crosses the accumulation point, which the Result
  block names;
- on 1 + 0.2 x and 1 + 0.3 x^3 (Omega max 2.05, Energy max 1e-3) main points
  beyond pi / 2 + 0.03 cover at least 0.75 of the rest of the run (0.87, 0.84
  measured), on 1 + x^2 half (0.68), and the contact never falls by more than
  0.1 on either side of pi / 2;
- continuity in the section: on A = 1 + e x, e = -0.05, -0.02, 0, 0.02, 0.05
  (Omega max 2.05, Energy max 1e-3), at W = 1.65, 1.70, 1.80 and 1.90 there is a
  main point within 0.005, and its energy over the uniform bar's exact mode
  E_t = g0^2 / (2 (T - 3)^2) at its own Omega rises strictly with e, within 5 %
  of 1 at e = 0 (the uniform bar's harmonic-balance error, about 3 %,
  doc/accuracy-and-cost.md): the family beyond pi / 2 on the bars thicker
  towards the wall is the one that continues the uniform bar's mode (measured
  at 1.8: 0.909, 0.967, 1.014, 1.062, 1.141).
A control run of the stepped bar with the envelope rule alone (Main contact drop =
1) breaks the first criterion: the check can fail.
"""
import csv
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from branch_measures import measures  # noqa: E402

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




for name, sets in BARS.items():
    stdout, rows = run(name, sets)
    mode = int(next((s.split("=")[1] for s in sets if s.startswith("Continuation/Mode=")), 1))
    main, drop, coverage, start, end = measures(rows, (2 * mode - 1) * math.pi / 2)
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
        check("crosses the accumulation point W_acc = 1.5708" in stdout,
              f"{name}: the Result block does not name the accumulation point")
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

# The seed's mode 2 at M = 20: beyond the mode's end (5.217) the gap search
# lands on other families, 7 of them led by a harmonic k > 1 (measured), which
# the Result block counts apart from those of less contact.
stdout, _ = run("seed_mode_2_m20", ["Continuation/Mode=2", "Harmonic balance/Harmonics=20"])
named = [l for l in stdout.splitlines() if l.startswith("  no main point from Omega = ")]
check(named and "led by a harmonic k > 1)" in named[-1],
      f"seed_mode_2_m20: the last gap does not count a landing led by a harmonic k > 1: {named[-1:]}")

# Bars thicker towards the wall (w_1 below pi / 2), Omega max 2.05, Energy max
# 1e-3: the Result block names the accumulation point, main points beyond
# pi / 2 + 0.03 cover at least 0.75 of the rest of the run, and the contact
# never falls by more than Main contact drop on either side of it.
# On 1 + x^2 the tongues of its strong internal resonances take 32 % of that
# range (0.68 covered, measured): the check asks half there, against 0.03
# before the two sides were labelled apart.
for section, least in (("1 + 0.2 * x", 0.75), ("1 + x^2", 0.5), ("1 + 0.3 * x^3", 0.75)):
    stdout, rows = run("thick_" + section.replace(" ", "").replace("*", "").replace("^", ""),
                       [f"Bar/Cross section={section}", "Continuation/Omega max=2.05", "Continuation/Energy max=1e-3"])
    main, drop, _, start, end = measures(rows)
    beyond = [m[0] for m in main if m[0] > math.pi / 2 + 0.03]
    covered = sum(b - a for a, b in zip(beyond, beyond[1:]) if b - a <= 0.01 * start) / (end - math.pi / 2 - 0.03)
    print(f"{section}: {len(beyond)} main points beyond pi / 2 + 0.03, covering {covered:.2f}; "
          f"largest contact drop on one side {drop:.3f}")
    check("crosses the accumulation point W_acc = 1.5708" in stdout,
          f"{section}: the Result block does not name the accumulation point")
    check(covered >= least, f"{section}: main points beyond pi / 2 + 0.03 cover {covered:.2f} of the rest")
    check(drop <= DROP + 1e-12, f"{section}: the contact fraction falls by {drop:.3f} on one side")

# Continuity in the section: the family beyond pi / 2 continues the uniform
# bar's mode (E_t, exact) as the section changes through it.
GAP = 1e-3
ratios = {}
for e in (-0.05, -0.02, 0.0, 0.02, 0.05):
    _, rows = run(f"section_{e:+.2f}", [f"Bar/Cross section=1 + ({e}) * x", "Continuation/Omega max=2.05",
                                        "Continuation/Energy max=1e-3"])
    main = [(float(r["Omega"]), float(r["energy"])) for r in rows if r["branch"] == "main"]
    for w in (1.65, 1.70, 1.80, 1.90):
        near = [m for m in main if abs(m[0] - w) <= 0.005]
        check(near, f"section 1 + {e} x: no main point within 0.005 of {w}")
        if near:
            omega, energy = min(near, key=lambda m: abs(m[0] - w))
            period = 2 * math.pi / omega
            ratios[(e, w)] = energy / (GAP ** 2 / (2 * (period - 3) ** 2))
for w in (1.65, 1.70, 1.80, 1.90):
    series = [ratios.get((e, w)) for e in (-0.05, -0.02, 0.0, 0.02, 0.05)]
    print(f"continuity at {w}: E / E_t = " + ", ".join("-" if r is None else f"{r:.3f}" for r in series))
    if None in series:
        continue
    check(all(a < b for a, b in zip(series, series[1:])), f"continuity at {w}: E / E_t not rising with e: {series}")
    check(abs(series[2] - 1) <= 0.05, f"continuity at {w}: the uniform bar's main point {series[2]:.3f} E_t")

# The control: the envelope rule alone labels other families main.
_, rows = run("stepped_envelope_rule", BARS["stepped"] + ["Continuation/Main contact drop=1",
                                                         "Continuation/Fill gaps wider than=0"])
_, drop, coverage, _, _ = measures(rows)
print(f"stepped with the envelope rule: coverage {coverage:.2f}, largest contact drop {drop:.3f}")
check(drop > 0.1, f"control: the envelope rule's largest drop {drop:.3f} is within the bound")

if failures:
    sys.exit(f"{len(failures)} failures")
print("main branch: all checks passed")
