#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole CTest suite.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/install-and-build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
