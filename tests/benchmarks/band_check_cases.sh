#!/bin/bash
# The band check's verdicts of doc/method.md ("The band check"): each mesh of
# the seed scene at its M, then its main branch against FE_Q(10) x 40 at the
# same M (scripts/compare_backbones.py's median). Run from the source folder
# after a build: tests/benchmarks/band_check_cases.sh [NSM_BAR] (about 40 s).
set -euo pipefail
B=${1:-build/nsm-bar}
P=prm/seed.prm
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { # name degree cells M [quiet: no estimate]
  "$B" "$P" --set "Discretisation/Degree=$2" --set "Discretisation/Cells=$3" --set "Harmonic balance/Harmonics=$4" \
    --set "Output/Plots=false" --set "Output/Fields at=" --set "Output/Spectrum modes=0" ${5:+--set "Output/Error estimate=false"} \
    --output "$work/$1"
}
for M in 40 80 160; do run "ref-M$M" 10 40 "$M" quiet > /dev/null; done
for c in "1 25 40" "1 50 40" "1 100 40" "1 4000 80" "2 10 80" "2 20 80" "10 10 80" "10 20 80" "10 20 160"; do
  set -- $c
  echo "== FE_Q($1) x $2, M = $3"
  run "p$1x$2-M$3" "$1" "$2" "$3" | grep -E "estimated energy error|spatial error|warning" | sed 's/; the largest tenth.*//'
  python3 scripts/compare_backbones.py "$work/p$1x$2-M$3" "$work/ref-M$3" 0.01 | sed -n 2p
done
