#!/usr/bin/env bash
# Runs the whole PERIDEM test suite (installs and builds first when needed).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PERIDEM_BUILD_DIR:-$here/build}"
"$here/scripts/build.sh"
cd "$build"
ctest -j "$(nproc)" --output-on-failure --timeout 900
