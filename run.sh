#!/usr/bin/env bash
# Installs what is missing, builds, and runs one scene (default: prm/seed.prm).
set -euo pipefail
cd "$(dirname "$0")"
source scripts/install-and-build.sh
./build/nsm-bar "${1:-prm/seed.prm}"
