#!/usr/bin/env python3
"""Floquet multipliers of the forced response (doc/method.md, "The forced response").

usage: check_forced_floquet.py NSM_BAR SCENE
Runs prm/forced-floquet.prm (the seed bar, FE_Q(10) x 20, M = 40, zeta =
0.002, on a compliant wall of k = 100, Forcing/Floquet): at every 20th point
of each curve the stepped model's orbit by shooting and its multipliers
(frc.csv's floquet_ columns), and checks (exit 0):
- off the wall the largest multiplier is the first mode's free decay over a
  period, exp(-zeta w1 T) (w1 from grazing.csv), to 1e-3: the trapezoidal
  rule keeps a mode's decay to (w1 dt)^2 relative;
- the fold test's parity: an odd number of real multipliers beyond +1 where
  det J < 0 (`stable` 0), at every point where the shooting converged, but
  within 0.005 of an Omega where the curve's verdict changes (a corner or a
  fold, where det J jumps or vanishes; measured: 44 of 45 agree, the other at
  1.9392 beside the changes at 1.9382 and 1.9395); both verdicts occur;
- the multipliers against the integration in time from the same points:
  where the fold test says stable and every multiplier lies inside the unit
  circle by enough for 430 periods (the fewest integrated) to take a start's
  error down to 1e-3 (|mu| <= 1e-3^(1/430) = 0.984), the integration ends
  periodic (drift <= 1e-4 g0); where a complex pair lies outside it
  (Neimark-Sacker, which the fold test cannot see), it does not (drift
  > 1e-4 g0); at least 3 points each;
- the shooting converged at half the points or more (measured 45 of 49), and at
  every point stable by the fold test where the integration stays on the point
  and ends periodic: it found the orbit there (measured: one of those points,
  1.98945, needs the integration's end as the shooting's start);
- the Result line and the events.
A planted error in the steps' tangents or the shooting's start breaks the
decay or the parity (and Floquet.* fails).
"""
import csv
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from failures import report  # noqa: E402

EXE, SCENE = sys.argv[1], sys.argv[2]
OUT = os.path.abspath("floquet")
ZETA = 0.002
PERIODS = 430  # the fewest periods the verification integrates at this damping
SETTLED = 1e-3 ** (1 / PERIODS)
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)


def main():
    shutil.rmtree(OUT, ignore_errors=True)
    run = subprocess.run([EXE, SCENE, "--output", OUT, "--set", "Output/Plots=false"], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"nsm-bar {SCENE} exited {run.returncode}: {run.stderr.strip()}")
    with open(os.path.join(OUT, "frc.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(OUT, "grazing.csv")) as f:
        w1 = float(next(csv.DictReader(f))["omega"])
    verified = [r for r in rows if r["verified_tip_amplitude"]]
    converged = [r for r in verified if r["floquet_largest"]]
    check(len(verified) >= 30, f"{len(verified)} points verified")
    check(2 * len(converged) >= len(verified), f"the shooting converged at {len(converged)} of {len(verified)}")
    changes = {}
    for a, b in zip(rows, rows[1:]):
        if a["forcing"] == b["forcing"] and a["segment"] == b["segment"] and a["stable"] != b["stable"]:
            changes.setdefault(a["forcing"], []).append(float(b["Omega"]))
    agree = {"0": 0, "1": 0}
    settled = outside = 0
    for r in converged:
        omega, largest = float(r["Omega"]), float(r["floquet_largest"])
        if float(r["contact_fraction"]) == 0:
            decay = math.exp(-ZETA * w1 * 2 * math.pi / omega)
            check(abs(largest / decay - 1) <= 1e-3, f"off the wall at W = {omega}: largest |mu| {largest}, "
                                                    f"the first mode's decay {decay}")
        odd = int(float(r["floquet_beyond_one"])) % 2 == 1
        if odd == (r["stable"] == "0"):
            agree[r["stable"]] += 1
        else:
            near = min((abs(omega - w) for w in changes.get(r["forcing"], [])), default=1)
            check(near <= 0.005, f"F = {r['forcing']}, W = {omega}: stable {r['stable']} but "
                                 f"{r['floquet_beyond_one']} real multipliers beyond +1, {near:.4f} from a verdict change")
        if r["stable"] == "1":
            drift = float(r["verified_drift"])
            if largest <= SETTLED:
                settled += 1
                check(drift <= 1e-4, f"W = {omega}: every multiplier inside ({largest:.4f}) but drift {drift:.2g}")
            elif largest > 1 and float(r["floquet_imag"]) != 0:
                outside += 1
                check(drift > 1e-4, f"W = {omega}: a Neimark-Sacker pair ({largest:.4f}) but drift {drift:.2g}")
    check(agree["0"] >= 5 and agree["1"] >= 5, f"parity agrees at {agree['0']} unstable and {agree['1']} stable points")
    # Where the fold test calls the point stable and the integration in time
    # stays on it (tip amplitude within 1 %) and ends periodic (drift <= 1e-4
    # g0), the integration has found the point's orbit of the stepped model:
    # the shooting finds it too (from the integration's end where the
    # point's own start stalls).
    periodic = [r for r in verified if r["stable"] == "1" and float(r["verified_drift"]) <= 1e-4
                and abs(float(r["verified_tip_amplitude"]) / float(r["tip_amplitude"]) - 1) <= 0.01]
    missed = [float(r["Omega"]) for r in periodic if not r["floquet_largest"]]
    check(not missed and len(periodic) >= 10,
          f"the shooting missed the orbit the integration settled on at {missed} ({len(periodic)} such points)")
    check(settled >= 3 and outside >= 3, f"{settled} stable points inside and {outside} Neimark-Sacker points checked")
    print(f"{len(converged)} of {len(verified)} converged; parity agrees at {agree['0']} unstable and "
          f"{agree['1']} stable points; {settled} settled and {outside} Neimark-Sacker points against the integration")
    with open(os.path.join(OUT, "summary.txt")) as f:
        summary = f.read()
    check("forced response's Floquet multipliers" in summary, "no Floquet Result line")
    with open(os.path.join(OUT, "continuation.log")) as f:
        check("Floquet, the largest multiplier outside the unit circle" in f.read(), "no Floquet event")
    return report(failures, "Floquet multipliers")


if __name__ == "__main__":
    sys.exit(main())
