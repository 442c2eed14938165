#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole CTest suite.
#   ./test.sh              the suite (Release build in build/)
#   ./test.sh --debug      the suite in a Debug build (build-debug/): the
#                          kernels' Asserts and deal.II's own checks
#   ./test.sh --all        the suite under AddressSanitizer and UBSan
#                          (build-sanitize/)
#   ./test.sh --all K/N    the same, with only the K-th of N parts of that suite
#                          (every N-th test from the K-th: CI runs it in fifths)
# With --debug or --all, every test runs once: in the checked build, or in the
# Release build where the checked suite leaves it out (the tests excluded
# below, and with K/N the other parts), so that each CI turn stays under 25
# minutes.
set -euo pipefail
cd "$(dirname "$0")"
part=""
case "${1:-}" in
  "" | --debug) [ $# -le 1 ] || { echo "usage: ./test.sh [--debug | --all [K/N]]" >&2; exit 2; } ;;
  --all)
    if [ $# -eq 2 ] && [[ "$2" =~ ^([1-9][0-9]*)/([1-9][0-9]*)$ ]] \
      && [ "${BASH_REMATCH[1]}" -le "${BASH_REMATCH[2]}" ]; then
      part="${BASH_REMATCH[1]},,${BASH_REMATCH[2]}"
    elif [ $# -ne 1 ]; then
      echo "usage: ./test.sh [--debug | --all [K/N]] (K/N: the K-th of N parts, 1 <= K <= N)" >&2; exit 2
    fi ;;
  *) echo "usage: ./test.sh [--debug | --all [K/N]]" >&2; exit 2 ;;
esac
# What the suite runs: the program and the unit tests (the benchmark programs,
# run by hand, are built by `cmake --build build`, and by CI in turn).
NSM_BUILD_TARGETS="nsm-bar unit_tests" source scripts/install-and-build.sh

# valgrind's memcheck case runs on the Release build only: under the Debug
# library it takes minutes, and it does not mix with the sanitizers. The M =
# 160 leap test is left to the plain suite: it runs the seed bar's whole
# backbone at M = 160 twice (95 s under the sanitizers, a tenth of that
# suite's work), and its leaps from the branch with half the harmonics are the
# code of the M = 80 leap test, which runs here.
excluded="memcheck|Leap.ALostBranchGoesOnFromTheBranchWithHalfTheHarmonics"
release_suite() { ctest --test-dir build --output-on-failure --timeout 900 -j "$(nproc)" "$@"; }
case "${1:-}" in
  "") release_suite ;;
  *)
    release_suite -R "$excluded"
    if [ -n "$part" ]; then
      # The parts other than K of the tests the checked suite runs (ctest's -I
      # counts the positions among the tests that -E leaves).
      k=${part%%,*} n=${part##*,}
      total=$(ctest --test-dir build -N -E "$excluded" | sed -n 's/^Total Tests: //p')
      others=$(seq 1 "$total" | awk -v k="$k" -v n="$n" '($1 - k) % n != 0' | paste -sd,)
      first=${others%%,*}
      [ -z "$others" ] || release_suite -E "$excluded" -I "$first,$first,1${others#"$first"}"
    fi ;;
esac

# The suite again in another build of the program and the unit tests:
# checked_suite DIR CMAKE_OPTIONS EXCLUDED_TESTS [CTEST_OPTIONS...].
checked_suite() {
  echo "building nsm-bar and the unit tests in $1/ (log in build.log)"
  cmake -S . -B "$1" $(generator "$1") -DNSM_FAST_START=ON $2 >> build.log 2>&1 || { tail -50 build.log; exit 1; }
  cmake --build "$1" -j "$(nproc)" --target nsm-bar unit_tests >> build.log 2>&1 \
    || { tail -50 build.log; exit 1; }
  ctest --test-dir "$1" --output-on-failure --timeout 900 -j "$(nproc)" -E "$3" "${@:4}"
}

case "${1:-}" in
  --debug) checked_suite build-debug "-DCMAKE_BUILD_TYPE=Debug" "$excluded" ;;
  --all)
    # Leak checking is off: MPI and Trilinos keep their start-up allocations
    # to the end.
    export ASAN_OPTIONS=detect_leaks=0:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1
    checked_suite build-sanitize "-DCMAKE_BUILD_TYPE=Release -DNSM_SANITIZE=ON" "$excluded" \
      ${part:+-I "$part"} ;;
esac
