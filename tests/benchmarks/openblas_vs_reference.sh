#!/bin/bash
# Interleaved runs of benchmark_backbone with Debian's reference BLAS/LAPACK and with
# OpenBLAS (serial), the same binary: OpenBLAS is unpacked, not installed, so the
# system alternatives stay as they are:
#   cd /tmp/ob && apt-get download libopenblas0-serial && dpkg -x libopenblas0-serial_*.deb root
# Prints the FE_Q(10) sequential row: backbone time, linear-solve share, cost per solve.
OB=${OB:-/tmp/ob/root/usr/lib/x86_64-linux-gnu/openblas-serial}
for i in 1 2 3 4 5; do
  for v in reference openblas; do
    if [ $v = openblas ]; then L=$OB; else L=; fi
    env LD_LIBRARY_PATH=$L "$(dirname "$0")/../../build/tests/benchmark_backbone" 2>/dev/null | grep "FE_Q(10), 7 cells | sequential" | awk -F'|' -v v=$v '{print v, "backbone_s", $10, "linear", $15, "ms_per_solve", $18}'
  done
done
