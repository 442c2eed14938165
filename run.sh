#!/usr/bin/env bash
# Installs what is missing, builds the program, and runs it with the arguments
# given (default: the scene prm/seed.prm), e.g.
#   ./run.sh prm/uniform.prm --output DIR --set "Harmonic balance/Harmonics=80"
set -euo pipefail
cd "$(dirname "$0")"
NSM_BUILD_TARGETS=nsm-bar source scripts/install-and-build.sh
if [ "$#" -eq 0 ]; then set -- prm/seed.prm; fi
exec ./build/nsm-bar "$@"
